//! The legend strip under the plot ([`super`]'s layout): each labelled series' glyph and
//! label, in rows that fit the picture's width, each row centred.

use super::{Figure, RenderError, Style};
use super::{LEGEND_PX, LINE_PX, SIDE_PX, WIDTH, color, err, font, marker, px, stroke, text_width};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A legend row's height, CSS pixels.
pub(super) const LEGEND_ROW_PX: i32 = 24;
/// A glyph's width (its line or marker), CSS pixels.
const LEGEND_GLYPH_PX: i32 = 30;
/// The gap between two entries of a row, CSS pixels.
const LEGEND_GAP_PX: i32 = 26;
/// Space between the x axis' label and the legend strip.
pub(super) const LEGEND_TOP_PX: i32 = 8;

/// Legend entries laid out in rows that fit the width: (row, x offset) per labelled series,
/// and the width of each row, in CSS pixels.
pub(super) fn legend_layout(fig: &Figure) -> (Vec<(usize, i32)>, Vec<i32>) {
    let avail = WIDTH as i32 - 2 * SIDE_PX;
    let (mut places, mut rows) = (Vec::new(), vec![0]);
    for s in fig.series.iter().filter(|s| !s.label.is_empty()) {
        let w = LEGEND_GLYPH_PX + 8 + text_width(&s.label, LEGEND_PX);
        let row = rows.len() - 1;
        let x = rows[row] + if rows[row] > 0 { LEGEND_GAP_PX } else { 0 };
        if rows[row] > 0 && x + w > avail {
            rows.push(w);
            places.push((row + 1, 0));
        } else {
            rows[row] = x + w;
            places.push((row, x));
        }
    }
    if places.is_empty() {
        rows.clear();
    }
    (places, rows)
}

/// The legend strip under the plot, each row centred.
pub(super) fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    fig: &Figure,
) -> Result<(), RenderError> {
    let (places, rows) = legend_layout(fig);
    let labelled = fig.series.iter().filter(|s| !s.label.is_empty());
    for (s, &(row, x)) in labelled.zip(&places) {
        let left = (WIDTH as i32 - rows[row]) / 2 + x;
        let y = px(LEGEND_TOP_PX + LEGEND_ROW_PX / 2 + LEGEND_ROW_PX * row as i32);
        let (x0, x1) = (px(left), px(left + LEGEND_GLYPH_PX));
        let c = color(s.color);
        let glyph = match s.style {
            Style::Markers(shape) => {
                EmptyElement::at(((x0 + x1) / 2, y)) + marker(shape, c.filled())
            }
            style => {
                EmptyElement::at((0, 0))
                    + stroke(
                        style,
                        c.stroke_width(px(LINE_PX) as u32),
                        vec![(x0, y), (x1, y)],
                    )
            }
        };
        area.draw(&glyph).map_err(err)?;
        let text = font(LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(s.label.as_str(), (x1 + px(8), y), text))
            .map_err(err)?;
    }
    Ok(())
}
