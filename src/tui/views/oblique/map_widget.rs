//! The oblique view's (angle, μ) map on screen: θ across (1° … 90°), μ up (0.02 … 1), each
//! screen cell the nearest map cell's value — in colour two map rows a character (half
//! blocks, the λ–ζ map's palette: src/tui/views/map/cells.rs), without colour one shade a
//! character — the cursor ╋ at (θ, μ), the range of the quantity and the cell's values under
//! the map.

use crate::text::sig_trim;
use crate::tui::format::value;
use crate::tui::theme::Theme;
use crate::tui::views::map::cells::{self, CURSOR, NAN_COLOR, NAN_SHADE};
use crate::tui::views::oblique::map::{
    ANGLES, FRICTIONS, ObliqueMap, Quantity, angle_at, friction_at,
};
use crate::tui::views::oblique::state::ObliqueView;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

/// Columns left of the raster for the μ labels.
const GUTTER: u16 = 5;
/// Rows under the θ labels: the quantity's range, the cursor's cell and its values.
const INFO_ROWS: u16 = 3;

#[derive(Debug, Clone, Copy)]
pub struct MapRaster<'a> {
    pub view: &'a ObliqueView,
    pub theme: Theme,
}

/// The map cell (angle index, friction index) a screen slot shows: the nearest.
fn nearest(slot: usize, slots: usize, cells: usize) -> usize {
    cells::cell_of_slot(slot, slots, cells)
}

impl Widget for MapRaster<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let q = self.view.quantity;
        // `t` (back to the charts) is on the key bar at every size; `n` only here
        let title = format!("(θ, μ) map · {} · n next", q.label());
        let title = crate::tui::widgets::title::framed(&title, area.width);
        let block = Block::bordered().title(Span::styled(title, self.theme.title()));
        let inner = block.inner(area);
        block.render(area, buf);
        if inner.width <= GUTTER + 4 || inner.height < INFO_ROWS + 3 {
            return;
        }
        let map = match &self.view.map {
            Some(Ok(m)) => m,
            Some(Err(e)) => {
                Paragraph::new(Line::styled(e.clone(), self.theme.error())).render(inner, buf);
                return;
            }
            None => {
                Paragraph::new(Line::styled("computing the map…", self.theme.dim()))
                    .render(inner, buf);
                return;
            }
        };
        let plot = Rect::new(
            inner.x + GUTTER,
            inner.y,
            inner.width - GUTTER,
            inner.height - 1 - INFO_ROWS,
        );
        self.raster(map, q, plot, buf);
        self.labels(plot, inner, buf);
        self.info(
            map,
            q,
            Rect::new(inner.x, plot.bottom() + 1, inner.width, INFO_ROWS),
            buf,
        );
    }
}

impl MapRaster<'_> {
    fn raster(&self, map: &ObliqueMap, q: Quantity, plot: Rect, buf: &mut Buffer) {
        let (lo, hi) = map.range(q).unwrap_or((0.0, 1.0));
        let color = self.theme.color;
        let per_char = if color { 2 } else { 1 };
        let rows = usize::from(plot.height) * per_char;
        let cols = usize::from(plot.width);
        let (ci, cj) = self.view.cursor();
        let value = |row: usize, col: usize| {
            // row 0 at the top: the largest μ
            let j = nearest(rows - 1 - row, rows, FRICTIONS);
            let i = nearest(col, cols, ANGLES);
            map.at(i, j).and_then(|c| q.of(c))
        };
        let rgb = |v: Option<f64>| v.map_or(NAN_COLOR, |v| cells::colour(v, lo, hi));
        for y in 0..plot.height {
            for x in 0..cols {
                let cell = &mut buf[(plot.x + x as u16, plot.y + y)];
                let r = usize::from(y) * per_char;
                if color {
                    cell.set_symbol("▀")
                        .set_fg(cells::rgb(rgb(value(r, x))))
                        .set_bg(cells::rgb(rgb(value(r + 1, x))));
                } else {
                    cell.set_symbol(value(r, x).map_or(NAN_SHADE, |v| cells::shade(v, lo, hi)));
                }
            }
        }
        // the cursor: the screen cell showing (θ, μ)'s map cell
        let x = cells::slot_of_cell(ci, ANGLES, cols);
        let y = (rows - 1 - cells::slot_of_cell(cj, FRICTIONS, rows)) / per_char;
        if x < cols && y < usize::from(plot.height) {
            let cell = &mut buf[(plot.x + x as u16, plot.y + y as u16)];
            cell.set_symbol(CURSOR);
            if color {
                let under = rgb(map.at(ci, cj).and_then(|c| q.of(c)));
                cell.set_fg(cells::contrast(under))
                    .set_bg(cells::rgb(under));
            }
        }
    }

    /// μ at the top and bottom of the gutter, θ under the plot.
    fn labels(&self, plot: Rect, inner: Rect, buf: &mut Buffer) {
        let dim = self.theme.dim();
        let top = sig_trim(friction_at(FRICTIONS - 1), 2);
        let bottom = sig_trim(friction_at(0), 2);
        buf.set_stringn(
            inner.x,
            plot.y,
            format!("μ {top}"),
            usize::from(GUTTER),
            dim,
        );
        buf.set_stringn(inner.x, plot.bottom() - 1, bottom, usize::from(GUTTER), dim);
        let y = plot.bottom();
        buf.set_string(plot.x, y, format!("{}°", angle_at(0)), dim);
        let end = format!("θ {}°", angle_at(ANGLES - 1));
        let x = plot.right().saturating_sub(end.chars().count() as u16);
        buf.set_string(x, y, end, dim);
    }

    /// The quantity's range and the cursor's cell.
    fn info(&self, map: &ObliqueMap, q: Quantity, area: Rect, buf: &mut Buffer) {
        let (ci, cj) = self.view.cursor();
        let range = map.range(q).map_or("no value".into(), |(lo, hi)| {
            format!("{} … {}", value(lo), value(hi))
        });
        let (first, second) = match map.at(ci, cj) {
            Some(c) => (
                format!("angle out {}°", value(c.angle_out)),
                format!(
                    "spin out {} rad/s, e_x {}",
                    value(c.spin_out),
                    c.ex.map_or("—".into(), value)
                ),
            ),
            None => ("no answer".into(), String::new()),
        };
        let scale = if self.theme.color {
            "viridis, dark to light"
        } else {
            "shades ░▒▓█, low to high"
        };
        let lines = vec![
            Line::styled(
                format!(" {} {range} ({scale})", q.label()),
                self.theme.dim(),
            ),
            // the cell nearest to (θ, μ): a μ typed between the grid's shows its neighbour
            Line::raw(format!(
                " ╋ cell θ {}°, μ {}: {first}",
                angle_at(ci),
                value(friction_at(cj))
            )),
            Line::raw(format!("   {second}")),
        ];
        Paragraph::new(lines).render(area, buf);
    }
}
