//! A plot's legend (`Plot::draw_legend`): an entry a line in the corner that covers no label
//! and the fewest drawn cells, on one line when the stack does not fit, the pins as one entry
//! when even that does not (tests/tui/tui_render.rs: `legends_stay_with_eight_pins`). Where
//! every corner would hide some of the data, or none has room, the legend goes outside the
//! plot, on one line in the frame's bottom border (issue 51 item 6, tests/tui/tui_legend.rs).

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
                let style = self.theme.series(e.tone, e.color);
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

    /// The legend where it hides no data: in the rows kept for it above the plot when the
    /// layout has them; else in its corner, one entry a line (on one line when that does not
    /// fit), keeping off the cells of `labels` (tags and markers' texts) where a corner
    /// allows; else on the frame. Where none of these is free of data, the legend is drawn in
    /// the corner that hides least and the rows it asks for above the plot are returned
    /// ([`Plot::layout`] then keeps them); 0 otherwise.
    pub(super) fn draw_legend(
        &self,
        l: &PlotLayout,
        (labels, dropped): (&[(u16, u16)], Vec<Line<'static>>),
        buf: &mut Buffer,
    ) -> u16 {
        let p = l.plot;
        let legend = |pins_in_one: bool| {
            let mut lines = self.legend_lines(pins_in_one);
            lines.extend(dropped.iter().cloned());
            lines
        };
        let kept = p.y - l.inner.y;
        if kept > 0 {
            draw_in_rows_kept(l, &legend, kept, buf);
            return 0;
        }
        // bottom legends keep clear of the lowest row, where curves often run along zero
        let room = p.height.saturating_sub(2);
        // a legend may take half the plot's rows and half its width; value labels that found
        // no place beside their points (alone, when the whole legend has no room) its width
        let half = |rows: u16, w: u16| rows <= room && 2 * rows <= p.height && 2 * w <= p.width;
        let whole = |rows: u16, w: u16| rows <= room && w + 2 <= p.width;
        // the rows asked for above the plot, where a plot of four rows at least stays; none
        // (the corner, as before) where the whole legend does not fit there
        let rows_above = || {
            let rows = above(&legend, p.width, 3).map_or(0, |lines| lines.len() as u16);
            if rows + 4 <= p.height { rows } else { 0 }
        };
        let on_frame = |buf: &mut Buffer| {
            [legend(false), legend(true)]
                .iter()
                .any(|one| self.draw_legend_on_frame(l, one, buf))
        };
        let Some(lines) = stacked_or_in_one(legend(false), &half)
            .or_else(|| stacked_or_in_one(legend(true), &half))
            .or_else(|| stacked_or_in_one(dropped.clone(), &whole))
        else {
            // no room inside: on the frame, else above the plot
            return if on_frame(buf) { 0 } else { rows_above() };
        };
        let width = lines.iter().map(Line::width).max().unwrap_or(0) as u16;
        let h = lines.len() as u16;
        let (left, r) = self.quietest_corner(p, (width, h), labels, buf);
        // every corner hides some of the data: the legend goes outside the plot, on the
        // frame's bottom border, else in rows above the plot (issue 51 item 6: at 80 × 24
        // "━ model" hid the force–time curve's rise; tests/tui/tui_legend.rs)
        let drawn = r.positions().filter(|&q| buf[q].symbol() != " ").count();
        if drawn > 0 {
            if on_frame(buf) {
                return 0;
            }
            let rows = rows_above();
            if rows > 0 {
                return rows;
            }
        }
        draw_in_box(&lines, (left, r), width, buf);
        0
    }

    /// Where a legend of `width` columns and `h` rows goes in plot `p`: the corner where it
    /// covers no label and the fewest drawn cells; the figure's on a tie. Whether that is on
    /// the left, and the legend's box (a column of margin either side).
    fn quietest_corner(
        &self,
        p: Rect,
        (width, h): (u16, u16),
        labels: &[(u16, u16)],
        buf: &Buffer,
    ) -> (bool, Rect) {
        let place = |corner: Corner| {
            let top = matches!(corner, Corner::TopLeft | Corner::TopRight);
            let left = matches!(corner, Corner::TopLeft | Corner::BottomLeft);
            let x = if left { p.x + 1 } else { p.right() - width - 1 };
            let y0 = if top { p.y } else { p.bottom() - 1 - h };
            (left, Rect::new(x - 1, y0, width + 2, h))
        };
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
        place(corner)
    }

    /// The legend on one line in the frame's bottom border, right-aligned (left of the x
    /// axis' power of ten, left-aligned, when there is one); false when it does not fit.
    fn draw_legend_on_frame(
        &self,
        l: &PlotLayout,
        lines: &[Line<'static>],
        buf: &mut Buffer,
    ) -> bool {
        let mut spans = vec![Span::raw(" ")];
        for (i, line) in lines.iter().enumerate() {
            if i > 0 {
                spans.push(Span::raw("  "));
            }
            spans.extend(line.spans.iter().cloned());
        }
        spans.push(Span::raw(" "));
        let one = Line::from(spans);
        let w = one.width() as u16;
        // the border's corners and a dash either side stay, and the x axis' power of ten
        let factor = l.x.exponent.map_or(0, |e| {
            crate::figure::ticks::factor_label(e).chars().count() + 5
        });
        if w + 4 + factor as u16 > l.inner.width {
            return false;
        }
        let y = l.inner.bottom();
        let x = if l.x.exponent.is_some() {
            l.inner.x + 1
        } else {
            l.inner.right() - 1 - w
        };
        buf.set_line(x, y, &one, w);
        true
    }
}

/// The legend in the `kept` rows above the plot: as many entries as they hold, should the
/// marks' texts have moved.
fn draw_in_rows_kept(
    l: &PlotLayout,
    legend: &dyn Fn(bool) -> Vec<Line<'static>>,
    kept: u16,
    buf: &mut Buffer,
) {
    let p = l.plot;
    let lines = above(legend, p.width, kept).unwrap_or_else(|| legend(false));
    for (i, line) in lines.iter().take(usize::from(kept)).enumerate() {
        buf.set_line(p.x, l.inner.y + i as u16, line, p.width);
    }
}

/// The legend's `lines` in box `r` (cleared first), aligned to its side (`left`, else
/// right-aligned within the legend's `width`).
fn draw_in_box(lines: &[Line<'static>], (left, r): (bool, Rect), width: u16, buf: &mut Buffer) {
    let x = r.x + 1;
    for (i, line) in lines.iter().enumerate() {
        let y = r.y + i as u16;
        buf.set_string(r.x, y, " ".repeat(usize::from(r.width)), Style::default());
        let w = line.width() as u16;
        buf.set_line(if left { x } else { x + width - w }, y, line, w);
    }
}

/// The legend in at most `rows` rows of `width` columns above the plot: on one line when it
/// fits (the pins as one entry if need be), else one entry a line; `None` when neither fits.
fn above(
    legend: &dyn Fn(bool) -> Vec<Line<'static>>,
    width: u16,
    rows: u16,
) -> Option<Vec<Line<'static>>> {
    let one_line = |r: u16, w: u16| r == 1 && w <= width;
    stacked_or_in_one(legend(false), &one_line)
        .or_else(|| stacked_or_in_one(legend(true), &one_line))
        .or_else(|| stacked_or_in_one(legend(false), &|r, w| r <= rows && w <= width))
}

impl Plot<'_> {
    /// The rows the legend asks for above the plot on layout `l` of `area` (0: it has a
    /// place that hides no data): known only once the data are drawn, on a scratch buffer.
    pub(super) fn legend_rows(&self, area: Rect, l: &PlotLayout) -> u16 {
        let mut scratch = Buffer::empty(area);
        self.draw_in(area, Some(l), &mut scratch)
    }
}
