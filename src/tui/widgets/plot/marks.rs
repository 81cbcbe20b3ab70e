//! A plot's marks (`Plot::draw_marks`): the lines' tags, then the markers and their texts,
//! each kept off the others' cells.

use super::{Plot, PlotLayout};
use crate::figure::Style as Stroke;
use crate::tui::widgets::marks::marker_place;
use crate::tui::widgets::tags;
use ratatui::buffer::Buffer;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use std::collections::{HashMap, HashSet};

/// The cell of a point in plot units, when it lies on the plot.
fn cell(l: &PlotLayout, p: Option<(f64, f64)>) -> Option<(u16, u16)> {
    Some((l.col(p?.0)?, l.row(p?.1)?))
}

impl Plot<'_> {
    /// Line tags (a threshold's name, a curve's λ) at the line's last point — right of it, or
    /// ending left of it at the plot's edge, a row up or down when another tag is there — then
    /// markers; a marker whose cell another took moves right, so both show.
    /// Returns the cells the tags and markers took, and the labels that found no room (the
    /// legend shows those).
    pub(super) fn draw_marks(
        &self,
        l: &PlotLayout,
        buf: &mut Buffer,
    ) -> (Vec<(u16, u16)>, Vec<Line<'static>>) {
        let points = self.marker_cells(l);
        let tagged = self.draw_tags(l, buf, &points);
        // every cell a tag or a marker's text took: nothing later writes over them, and the
        // legend keeps off them (tests/tui/tui_render.rs:
        // `value_labels_show_whole_beside_legends_and_pins`)
        let mut taken: Vec<(u16, u16)> = tagged
            .iter()
            .flat_map(|&(y, a, b)| (a..b).map(move |x| (x, y)))
            .collect();
        let dropped = self.draw_markers(l, buf, &points, &mut taken);
        (taken, dropped)
    }

    /// The markers' own cells: a tag keeps off them, as a marker's glyph stays on its
    /// point (tests/tui/tui_render.rs: `tags_keep_off_the_markers`).
    fn marker_cells(&self, l: &PlotLayout) -> Vec<(u16, u16)> {
        self.figure
            .series
            .iter()
            .filter(|s| matches!(s.style, Stroke::Markers(_)))
            .flat_map(|s| self.drawn(s))
            .filter_map(|p| cell(l, p))
            .collect()
    }

    /// Every line's cells, one list a series (empty for markers): a tag goes where its own
    /// curve runs apart from the others (one pass over the lines a frame)
    /// (none on a chart without tagged lines: the force charts with a dense measured trace).
    fn line_cells(&self, l: &PlotLayout) -> Vec<Vec<(u16, u16)>> {
        let any_tag = self
            .figure
            .series
            .iter()
            .any(|s| s.look.text.is_some() && !matches!(s.style, Stroke::Markers(_)));
        self.figure
            .series
            .iter()
            .map(|s| match s.style {
                Stroke::Markers(_) => Vec::new(),
                _ if !any_tag => Vec::new(),
                _ => tags::along(
                    &self
                        .drawn(s)
                        .into_iter()
                        .filter_map(|p| cell(l, p))
                        .collect::<Vec<_>>(),
                ),
            })
            .collect()
    }

    /// The lines' tags, each on its own curve where it runs apart from the others and off
    /// the markers' `points`; a tag with no room is left to the legend (its key and glyph).
    /// Returns the spans the tags took: (row, first column, column past the end).
    fn draw_tags(
        &self,
        l: &PlotLayout,
        buf: &mut Buffer,
        points: &[(u16, u16)],
    ) -> Vec<(u16, u16, u16)> {
        let lines = self.line_cells(l);
        let sets: Vec<HashSet<(u16, u16)>> =
            lines.iter().map(|c| c.iter().copied().collect()).collect();
        let mut passing: HashMap<(u16, u16), u16> = HashMap::new();
        for &c in sets.iter().flatten() {
            *passing.entry(c).or_default() += 1;
        }
        let mut tagged: Vec<(u16, u16, u16)> = Vec::new();
        for (i, s) in self.figure.series.iter().enumerate() {
            let (Stroke::Solid | Stroke::Dashed | Stroke::Dotted | Stroke::LongDashed, Some(tag)) =
                (s.style, &s.look.text)
            else {
                continue;
            };
            let w = tag.chars().count() as u16;
            let taken = tags::Taken {
                tags: &tagged,
                points,
                passing: &passing,
            };
            let own = tags::Curve {
                cells: &lines[i],
                set: &sets[i],
            };
            let Some((x, y)) = tags::place(l.plot, &own, w, buf, &taken) else {
                continue;
            };
            let room = usize::from(l.plot.right() - x);
            let style = Style::default().fg(self.color(s));
            buf.set_stringn(x, y, tag, room, style);
            tagged.push((y, x, x + w));
        }
        tagged
    }

    /// The markers and their texts, each text kept off the cells in `taken` (which grows by
    /// the cells it takes). Returns the labels that found no room, as legend lines.
    fn draw_markers(
        &self,
        l: &PlotLayout,
        buf: &mut Buffer,
        points: &[(u16, u16)],
        taken: &mut Vec<(u16, u16)>,
    ) -> Vec<Line<'static>> {
        let mut dropped = Vec::new();
        for s in &self.figure.series {
            let Stroke::Markers(_) = s.style else {
                continue;
            };
            let text = s.look.text.as_deref().unwrap_or("●");
            let style = self.theme.series(s.look.tone, s.color);
            for p in self.drawn(s) {
                let Some((col, row)) = cell(l, p) else {
                    continue;
                };
                let bounds = (l.plot.x, l.plot.right(), l.plot.y, l.plot.bottom());
                // a text keeps off every other marker's glyph too, drawn or still to come:
                // each glyph stays on its point and each label reads whole
                // (tests/tui/tui_marks.rs)
                let blocked: Vec<(u16, u16)> = taken
                    .iter()
                    .copied()
                    .chain(points.iter().copied().filter(|&c| c != (col, row)))
                    .collect();
                let pieces = marker_place(text, (col, row), bounds, &blocked);
                if pieces.len() == 1 && pieces[0].2.chars().count() < text.chars().count() {
                    dropped.push(glyph_and_label(text, style));
                }
                for (x, y, piece) in pieces {
                    let room = usize::from(l.plot.right() - x);
                    let (end, _) = buf.set_stringn(x, y, &piece, room, style);
                    taken.extend((x..end).map(|c| (c, y)));
                }
            }
        }
        dropped
    }
}

/// A marker's text shown as its glyph alone: the legend's line for it (the glyph in the
/// marker's style, then its label).
fn glyph_and_label(text: &str, style: Style) -> Line<'static> {
    let mut chars = text.chars();
    let glyph = chars.next().map(String::from).unwrap_or_default();
    let label = chars.as_str().to_string();
    Line::from(vec![
        Span::styled(glyph, style),
        Span::raw(" "),
        Span::raw(label),
    ])
}
