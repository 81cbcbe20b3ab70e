//! The map view's panel: the heat map of one quantity over (λ, ζ) in half blocks (`▀`, the
//! upper cell as foreground, the lower as background: two λ rows per character; without
//! colour a shade ramp, one row per character), λ labels on the left, ζ labels below, the
//! colour bar with its numbers on the right, the marks (cursor, iso-COR line, feasible
//! outline, other presets by their number) and the line of values under the cursor.

use crate::figure::ticks::{Ticks, fitted, log};
use crate::map::{Axis, Map};
use crate::text::sig_trim;
use crate::tui::format::value as value_on_screen;
use crate::tui::theme::Theme;
use crate::tui::views::map::cells::{
    CURSOR, ISO, OUTLINE, Raster, cell_of_slot, colour, contrast, dimmed, rgb, shade, slot_of_cell,
};
use crate::tui::views::map::state::{Geometry, MapView, cell_of, geometry, unit};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// What the panel shows.
pub struct MapPanel<'a> {
    pub view: &'a MapView,
    /// The current ball's (λ, ζ): the cursor.
    pub point: (f64, f64),
    /// The other presets: (the key that loads it, λ, ζ).
    pub presets: Vec<(usize, f64, f64)>,
    /// "superball at v0 = 3.12 m/s, linear law".
    pub about: String,
    pub theme: Theme,
}

impl Widget for &MapPanel<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let (label, _) = unit(self.view.quantity);
        let full = format!(" map of {label} over (λ ↑, ζ →) · {} ", self.about);
        let title = if full.chars().count() + 2 <= usize::from(area.width) {
            full
        } else {
            format!(" map of {label} ")
        };
        let block = Block::bordered()
            .border_style(self.theme.dim())
            .title(Line::styled(title, self.theme.title()));
        let inner = block.inner(area);
        block.render(area, buf);
        let note = |text: String, buf: &mut Buffer| {
            Paragraph::new(text)
                .wrap(Wrap { trim: true })
                .render(inner, buf)
        };
        let Some(g) = geometry(area) else {
            return note("enlarge the terminal for the map".into(), buf);
        };
        match &self.view.map {
            None => note("computing the map…".into(), buf),
            Some(Err(e)) => note(format!("no map: {e}"), buf),
            Some(Ok(map)) => self.draw(map, &g, buf),
        }
    }
}

/// The span of the values shown, as the colour bar's ticks (as the SVG heat map's bar).
fn bar_ticks(values: &[f64], rows: u16) -> Ticks {
    let (lo, hi) = values
        .iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let n = usize::from(rows / 3).clamp(2, 6);
    if lo.is_finite() && hi > lo {
        fitted(lo, hi, n)
    } else if lo.is_finite() {
        fitted(
            lo - 0.5 * lo.abs().max(1e-9),
            hi + 0.5 * hi.abs().max(1e-9),
            n,
        )
    } else {
        fitted(0.0, 1.0, n)
    }
}

impl MapPanel<'_> {
    fn draw(&self, map: &Map, g: &Geometry, buf: &mut Buffer) {
        let (_, scale) = unit(self.view.quantity);
        let r = Raster::new(map, self.view.quantity, scale, self.view.targets.as_ref());
        let bar = bar_ticks(&r.values, g.plot.height);
        self.cells(&r, &bar, g.plot, buf);
        self.marks(&r, g.plot, buf);
        self.labels(map, g, buf);
        self.bar(&bar, g.bar, buf);
        self.info(map, &r, g.info, buf);
    }

    /// Half-block rows: 2 per character with colour, 1 without.
    fn per_char(&self) -> usize {
        if self.theme.color { 2 } else { 1 }
    }

    /// The map cell a half row `y` (0 at the top) and a column `x` of the plot show.
    fn cell_at(&self, r: &Raster, plot: Rect, x: usize, y: usize) -> (usize, usize) {
        let h = usize::from(plot.height) * self.per_char();
        let i = cell_of_slot(h - 1 - y, h, r.rows());
        (i, cell_of_slot(x, usize::from(plot.width), r.cols()))
    }

    /// The screen position (column, row) of cell (i, j).
    fn pos_of(&self, r: &Raster, plot: Rect, (i, j): (usize, usize)) -> (u16, u16) {
        let h = usize::from(plot.height) * self.per_char();
        let y = h - 1 - slot_of_cell(i, r.rows(), h);
        let x = slot_of_cell(j, r.cols(), usize::from(plot.width));
        (plot.x + x as u16, plot.y + (y / self.per_char()) as u16)
    }

    fn cells(&self, r: &Raster, bar: &Ticks, plot: Rect, buf: &mut Buffer) {
        let m = r.cols();
        for row in 0..plot.height {
            for col in 0..plot.width {
                let (x, y) = (usize::from(col), usize::from(row) * self.per_char());
                let cell = &mut buf[(plot.x + col, plot.y + row)];
                let (i, j) = self.cell_at(r, plot, x, y);
                if self.theme.color {
                    let paint = |(i, j): (usize, usize)| {
                        let c = colour(r.at(i, j), bar.lo, bar.hi);
                        rgb(if r.feasible[i * m + j] { c } else { dimmed(c) })
                    };
                    let below = self.cell_at(r, plot, x, y + 1);
                    cell.set_symbol("▀")
                        .set_style(Style::default().fg(paint((i, j))).bg(paint(below)));
                } else {
                    let dim = if r.feasible[i * m + j] {
                        Style::default()
                    } else {
                        Style::default().add_modifier(Modifier::DIM)
                    };
                    cell.set_symbol(shade(r.at(i, j), bar.lo, bar.hi))
                        .set_style(dim);
                }
            }
        }
    }

    /// A mark over the heat map at cell (i, j): black or white on the cell's colour.
    fn mark(&self, r: &Raster, plot: Rect, at: (usize, usize), symbol: &str, buf: &mut Buffer) {
        let (x, y) = self.pos_of(r, plot, at);
        let cell = &mut buf[(x, y)];
        let style = if self.theme.color {
            let bg = cell.bg;
            let rgb = match bg {
                ratatui::style::Color::Rgb(r, g, b) => (r, g, b),
                _ => (0, 0, 0),
            };
            Style::default().fg(contrast(rgb)).bg(bg)
        } else {
            Style::default()
        };
        cell.set_symbol(symbol)
            .set_style(style.add_modifier(Modifier::BOLD));
    }

    fn marks(&self, r: &Raster, plot: Rect, buf: &mut Buffer) {
        if self.view.targets.is_some() {
            for at in r.outline() {
                self.mark(r, plot, at, OUTLINE, buf);
            }
        }
        let level = match &self.view.sensitivity {
            Some(Ok(s)) => Some(s.cor),
            _ => None,
        };
        if let Some(level) = level.filter(|e| e.is_finite()) {
            for at in r.iso_cor(level) {
                self.mark(r, plot, at, ISO, buf);
            }
        }
        let map = r.map;
        let inside = |l: f64, z: f64| {
            let (a, b) = (&map.spec.lambda, &map.spec.zeta);
            l >= a.from && l <= a.to && z >= b.from && z <= b.to
        };
        for &(key, l, z) in &self.presets {
            if inside(l, z) {
                let digit = char::from_digit(key as u32 % 10, 10).unwrap_or('?');
                self.mark(r, plot, cell_of(map, l, z), &digit.to_string(), buf);
            }
        }
        let (l, z) = self.point;
        self.mark(r, plot, cell_of(map, l, z), CURSOR, buf);
        if !self.theme.color {
            let (x, y) = self.pos_of(r, plot, cell_of(map, l, z));
            buf[(x, y)].modifier.insert(Modifier::REVERSED);
        }
    }
}

/// The labelled values of a log axis with the slot each stands at (of `slots` along the
/// axis): the map's labels are `figure::ticks::log::labels`, neighbours `room` slots apart.
fn log_ticks(a: &Axis, slots: usize, room: usize) -> Vec<(usize, f64)> {
    let slot =
        |v: f64| (a.index_of(v) / (a.n.max(2) - 1) as f64 * (slots - 1) as f64).round() as usize;
    let apart = |values: &[f64]| values.windows(2).all(|w| slot(w[1]) >= slot(w[0]) + room);
    log::labels(a.from, a.to, apart)
        .into_iter()
        .map(|v| (slot(v), v))
        .collect()
}

impl MapPanel<'_> {
    fn labels(&self, map: &Map, g: &Geometry, buf: &mut Buffer) {
        let axis = self.theme.axis();
        let rows = usize::from(g.plot.height);
        // λ: the top row is the largest value
        let w = usize::from(g.gutter.width) - 1;
        let ticks = log_ticks(&map.spec.lambda, rows, 2);
        for &(slot, v) in &ticks {
            let y = g.plot.bottom() - 1 - slot as u16;
            let text = format!("{:>w$}", sig_trim(v, 2));
            buf.set_stringn(g.gutter.x, y, text, w, axis);
        }
        // the top row labelled with its own λ, as every chart's top row is (issue 51 item 1;
        // it showed only the name "λ": tests/tui/tui_ticks.rs reads the map's axes); the name
        // beside it where the number leaves a cell, else in the corner under the λ labels
        let top = match ticks.iter().find(|&&(slot, _)| slot + 1 == rows) {
            Some(&(_, v)) => sig_trim(v, 2),
            None => {
                let top = sig_trim(map.spec.lambda.to, 2);
                buf.set_stringn(g.gutter.x, g.plot.y, format!("{top:>w$}"), w, axis);
                top
            }
        };
        let name_on_top = top.chars().count() + 2 <= w;
        let name_at = if name_on_top {
            g.gutter.y
        } else {
            g.x_labels.y
        };
        buf.set_string(g.gutter.x, name_at, "λ", self.theme.title());
        // where the cursor is, on both axes; a ζ label the ▲ would cut or touch is left out
        // (tests/tui/tui_render.rs: `the_map_cursor_never_cuts_a_tick_label`)
        let r = Raster {
            map,
            values: Vec::new(),
            feasible: Vec::new(),
        };
        let (cx, cy) = self.pos_of(&r, g.plot, cell_of(map, self.point.0, self.point.1));
        let cols = usize::from(g.plot.width);
        let mut free = 0u16;
        for (slot, v) in log_ticks(&map.spec.zeta, cols, 7) {
            let text = sig_trim(v, 2);
            let w = text.chars().count() as u16;
            let x = (g.plot.x + slot as u16).saturating_sub(w / 2).max(free);
            if x + w <= g.plot.right() + 2 && !(x.saturating_sub(1)..=x + w).contains(&cx) {
                buf.set_stringn(x, g.x_labels.y, &text, usize::from(w), axis);
                free = x + w + 1;
            }
        }
        buf.set_string(g.plot.right() + 3, g.x_labels.y, "ζ", self.theme.title());
        buf.set_string(g.gutter.right() - 1, cy, "▶", self.theme.warning());
        buf.set_string(cx, g.x_labels.y, "▲", self.theme.warning());
    }

    /// The colour bar (top: the high end) and its numbers.
    fn bar(&self, t: &Ticks, area: Rect, buf: &mut Buffer) {
        let h = f64::from(area.height) * self.per_char() as f64;
        let value = |y: f64| t.hi - (y + 0.5) / h * (t.hi - t.lo);
        for row in 0..area.height {
            let y = f64::from(row) * self.per_char() as f64;
            for dx in 1..3 {
                let cell = &mut buf[(area.x + dx, area.y + row)];
                if self.theme.color {
                    let (a, b) = (
                        colour(value(y), t.lo, t.hi),
                        colour(value(y + 1.0), t.lo, t.hi),
                    );
                    cell.set_symbol("▀")
                        .set_style(Style::default().fg(rgb(a)).bg(rgb(b)));
                } else {
                    cell.set_symbol(shade(value(y), t.lo, t.hi));
                }
            }
        }
        let rows = f64::from(area.height);
        for &m in &t.major {
            let row = ((t.hi - m) / (t.hi - t.lo) * rows)
                .floor()
                .clamp(0.0, rows - 1.0) as u16;
            let w = usize::from(area.width.saturating_sub(4));
            buf.set_stringn(area.x + 4, area.y + row, t.label(m), w, self.theme.axis());
        }
    }
}

impl MapPanel<'_> {
    /// The values under the cursor, the sensitivities, the targets and the map's progress.
    fn info(&self, map: &Map, r: &Raster, area: Rect, buf: &mut Buffer) {
        let (i, j) = cell_of(map, self.point.0, self.point.1);
        // the quantity as the readout writes it: its symbol, the value, its unit after it
        // ("F_m 117.3 N", issue 51 item 4; it read "F_m (N) 117.3")
        let (symbol, unit_after) = match self.view.quantity {
            crate::map::Quantity::Cor => ("e", ""),
            crate::map::Quantity::MaxForce => ("F_m", " N"),
            crate::map::Quantity::ContactTime => ("t_f", " ms"),
        };
        let v = r.at(i, j);
        let approx = if map.cell(i, j).is_some() { "" } else { "≈" };
        let value = if v.is_nan() {
            "none".to_string()
        } else {
            format!("{approx}{}{unit_after}", value_on_screen(v))
        };
        let meets = match self.view.targets {
            Some(_) if r.feasible[i * r.cols() + j] => " · meets the targets",
            Some(_) => " · misses the targets",
            None => "",
        };
        // the cell's own (λ, ζ): the ball's once the arrows have moved it onto the grid; every
        // number in the readout's one format, four significant digits (issue 51 item 4: it
        // read "λ 1.45 ζ 0.17", "∂e/∂ln ζ -0.085"; tests/tui/tui_map.rs,
        // `the_map_cell_line_writes_four_significant_digits`)
        let first = format!(
            " cell λ {} ζ {} · {symbol} {value}{meets}",
            value_on_screen(map.lambdas[i]),
            value_on_screen(map.zetas[j])
        );
        let signed = |x: f64| {
            let sign = if x >= 0.0 { "+" } else { "" };
            format!("{sign}{}", value_on_screen(x))
        };
        let sens = match &self.view.sensitivity {
            Some(Ok(s)) => format!(
                " ∂e/∂ln λ {}  ∂e/∂ln ζ {}",
                signed(s.d_ln_lambda),
                signed(s.d_ln_zeta)
            ),
            Some(Err(e)) => format!(" no sensitivities: {e}"),
            None => String::new(),
        };
        let targets = match &self.view.targets {
            Some(t) => format!(" · where {}", super::targets::text(t)),
            None => " · t: targets".to_string(),
        };
        let second = match &self.view.job.stopped {
            _ if map.is_complete() => {
                let (cols, rows) = (map.zetas.len(), map.lambdas.len());
                format!("{sens}{targets} · {cols}×{rows} cells")
            }
            // first on its line: the stop and why are not cut off
            Some(why) => format!(" refining stopped: {why} (R retries) ·{sens}{targets}"),
            None => format!("{sens}{targets} · refining…"),
        };
        // cut at a word with "…" where the line is too long (80 × 24 ended in "· t:")
        let fit = |s: &str| crate::tui::format::clip(s, usize::from(area.width));
        let lines = if area.height >= 2 {
            vec![
                Line::raw(fit(&first)),
                Line::styled(fit(&second), self.theme.dim()),
            ]
        } else {
            vec![Line::raw(fit(&format!("{first} ·{second}")))]
        };
        Paragraph::new(lines).render(area, buf);
    }
}
