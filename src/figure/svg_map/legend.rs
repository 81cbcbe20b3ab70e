//! The legend strip under the design map's SVG ([`crate::figure::svg_map`]): what each kind of line
//! means.

use super::{LEGEND_H, View};
use crate::figure::PALETTE;
use crate::figure::svg::{LEGEND_PX, RenderError, SIDE_PX, err, font, px};
use crate::map::Quantity;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The legend strip: what each kind of line means.
pub(super) fn draw(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    v: &View,
) -> Result<(), RenderError> {
    let mut items: Vec<(&str, RGBColor, u32)> = vec![("iso-lines", BLACK, 1)];
    if let Some(t) = v.targets {
        if t.0.iter().any(|k| k.quantity == Quantity::Cor) {
            let (r, g, b) = PALETTE[1];
            items.push(("target COR", RGBColor(r, g, b), 3));
        }
        items.push(("feasible region", WHITE, 2));
    }
    let y = px(LEGEND_H / 2);
    let mut x = px(SIDE_PX + 40);
    for (text, colour, w) in items {
        if colour == WHITE {
            area.draw(&PathElement::new(
                vec![(x, y), (x + px(30), y)],
                BLACK.stroke_width(px(4) as u32),
            ))
            .map_err(err)?;
        }
        area.draw(&PathElement::new(
            vec![(x, y), (x + px(30), y)],
            colour.stroke_width(px(w as i32) as u32),
        ))
        .map_err(err)?;
        let style = font(LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(text, (x + px(38), y), style))
            .map_err(err)?;
        x += px(38 + (text.chars().count() as i32 * LEGEND_PX * 52) / 100 + 30);
    }
    if v.own.is_some() {
        area.draw(&Circle::new((x + px(8), y), px(6), WHITE.filled()))
            .map_err(err)?;
        area.draw(&Circle::new(
            (x + px(8), y),
            px(6),
            BLACK.stroke_width(px(2) as u32),
        ))
        .map_err(err)?;
        let style = font(LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new("this ball", (x + px(20), y), style))
            .map_err(err)?;
    }
    Ok(())
}
