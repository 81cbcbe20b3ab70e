//! A plot's legend (`Plot::draw_legend`): an entry a line in the corner that covers no label
//! and the fewest drawn cells, on one line when the stack does not fit, the pins as one entry
//! when even that does not (tests/tui/tui_render.rs: `legends_stay_with_eight_pins`).

use super::{Plot, PlotLayout};
use crate::figure::{Corner, Sample, Tone};
use crate::tui::widgets::marks::stacked_or_in_one;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};

impl Plot<'_> {
    /// The figure's legend, a line an entry; with `pins_in_one`, the pins' entries ("p1
    /// golf", "p2 golf", …) as one ("┄ p1–p8 pinned") — their tags on the curves and the
    /// readout's pin table name each (tests/tui/tui_render.rs: `legends_stay_with_eight_pins`).
    fn legend_lines(&self, pins_in_one: bool) -> Vec<Line<'static>> {
        let mut entries = self.figure.legend();
        let pins: Vec<usize> = (0..entries.len())
            .filter(|&i| {
                entries[i].tone == Tone::Ghost && !matches!(entries[i].sample, Sample::Marks(_))
            })
            .collect();
        if pins_in_one && pins.len() > 1 {
            let tag = |i: usize| entries[i].key.split(' ').next().unwrap_or("").to_string();
            let key = format!("{}–{} pinned", tag(pins[0]), tag(pins[pins.len() - 1]));
            entries[pins[0]].key = key;
            for &i in pins[1..].iter().rev() {
                entries.remove(i);
            }
        }
        entries
            .into_iter()
            .map(|e| {
                let style = self.theme.tone(e.tone);
                let sample = match e.sample {
                    Sample::Line => "━".to_string(),
                    Sample::Dotted => "┄".to_string(),
                    Sample::Dashed => "╍".to_string(),
                    Sample::LongDashed => "═".to_string(),
                    Sample::Marks(texts) => texts.join(" "),
                };
                Line::from(vec![
                    Span::styled(sample, style),
                    Span::raw(" "),
                    Span::raw(e.key),
                ])
            })
            .collect()
    }

    /// The legend in its corner, one entry a line; on one line when that does not fit; not at
    /// all when neither does.
    /// It keeps off the cells of `labels` (tags and markers' texts) where a corner allows.
    pub(super) fn draw_legend(
        &self,
        l: &PlotLayout,
        (labels, dropped): (&[(u16, u16)], Vec<Line<'static>>),
        buf: &mut Buffer,
    ) {
        let p = l.plot;
        // bottom legends keep clear of the lowest row, where curves often run along zero
        let room = p.height.saturating_sub(2);
        // a legend may take half the plot's rows and half its width; value labels that found
        // no place beside their points (alone, when the whole legend has no room) its width
        let half = |rows: u16, w: u16| rows <= room && 2 * rows <= p.height && 2 * w <= p.width;
        let whole = |rows: u16, w: u16| rows <= room && w + 2 <= p.width;
        let legend = |pins_in_one: bool| {
            let mut lines = self.legend_lines(pins_in_one);
            lines.extend(dropped.iter().cloned());
            lines
        };
        let Some(lines) = stacked_or_in_one(legend(false), &half)
            .or_else(|| stacked_or_in_one(legend(true), &half))
            .or_else(|| stacked_or_in_one(dropped, &whole))
        else {
            return;
        };
        let width = lines.iter().map(Line::width).max().unwrap_or(0) as u16;
        let h = lines.len() as u16;
        let place = |corner: Corner| {
            let top = matches!(corner, Corner::TopLeft | Corner::TopRight);
            let left = matches!(corner, Corner::TopLeft | Corner::BottomLeft);
            let x = if left { p.x + 1 } else { p.right() - width - 1 };
            let y0 = if top { p.y } else { p.bottom() - 1 - h };
            (left, Rect::new(x - 1, y0, width + 2, h))
        };
        // the corner where the legend covers no label and the fewest drawn cells; the
        // figure's on a tie
        let covered = |r: Rect| {
            let over_labels = labels.iter().filter(|&&(x, y)| r.contains((x, y).into()));
            1000 * over_labels.count() + r.positions().filter(|&q| buf[q].symbol() != " ").count()
        };
        let preferred = self.figure.legend_corner;
        let corner = [
            preferred,
            Corner::TopRight,
            Corner::TopLeft,
            Corner::BottomRight,
            Corner::BottomLeft,
        ]
        .into_iter()
        .min_by_key(|&c| covered(place(c).1))
        .unwrap_or(preferred);
        let (left, r) = place(corner);
        let x = r.x + 1;
        for (i, line) in lines.iter().enumerate() {
            let y = r.y + i as u16;
            buf.set_string(r.x, y, " ".repeat(usize::from(r.width)), Style::default());
            let w = line.width() as u16;
            buf.set_line(if left { x } else { x + width - w }, y, line, w);
        }
    }
}
