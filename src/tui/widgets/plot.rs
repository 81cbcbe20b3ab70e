//! A figure ([`crate::figure::Figure`], the description the SVG export renders too) as a
//! braille line plot on ratatui's Canvas, with axes, ticks and labels we place ourselves, so a
//! label sits over the column where the curve's dot for its value lands. Pinned series are
//! drawn dimmed behind the live ones; measured values and thresholds dotted; markers as text.

mod draw;
mod legend;
mod marks;

use super::strokes::{Pattern, patterned};
use crate::figure::look::{dashed, dotted, long_dashed};
use crate::figure::ticks::{Room, ticks};
use crate::figure::{Figure, Role, Series, Style as Stroke};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::widgets::canvas::{self, Canvas, Context};
use ratatui::widgets::{Block, Widget};

/// An axis ready to draw: bounds in plot units (log10 on a decade axis) and labelled ticks.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub bounds: [f64; 2],
    /// (position in plot units, label)
    pub ticks: Vec<(f64, String)>,
    /// The power of ten the labels are written in (shown on the frame as "×10⁻¹⁵"), when
    /// the values are too large or small to read as they are.
    pub exponent: Option<i32>,
}

/// A figure drawn in a terminal.
#[derive(Debug, Clone, Copy)]
pub struct Plot<'a> {
    pub figure: &'a Figure,
    pub theme: Theme,
}

/// Where things go for one area.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotLayout {
    /// Inside the border.
    pub inner: Rect,
    /// The braille area: x axis line below it, y axis line left of it.
    pub plot: Rect,
    pub x: Axis,
    pub y: Axis,
}

impl PlotLayout {
    /// Column of x (plot units): the cell of the braille dot Canvas paints for it.
    pub fn col(&self, x: f64) -> Option<u16> {
        let [lo, hi] = self.x.bounds;
        let dots = 2.0 * f64::from(self.plot.width);
        let dot = ((x - lo) * (dots - 1.0) / (hi - lo)).round();
        (x >= lo && x <= hi).then(|| self.plot.x + (dot as u16) / 2)
    }

    /// Row of y (plot units): the cell of the braille dot Canvas paints for it.
    pub fn row(&self, y: f64) -> Option<u16> {
        let [lo, hi] = self.y.bounds;
        let dots = 4.0 * f64::from(self.plot.height);
        let dot = ((hi - y) * (dots - 1.0) / (hi - lo)).round();
        (y >= lo && y <= hi).then(|| self.plot.y + (dot as u16) / 4)
    }
}

/// Whether `v` falls on the top row of a y axis from `lo` to `hi` over `rows` rows, as
/// [`PlotLayout::row`] places it.
fn on_top_row(lo: f64, hi: f64, v: f64, rows: u16) -> bool {
    let dots = 4.0 * f64::from(rows);
    ((hi - v) * (dots - 1.0) / (hi - lo)).round() < 4.0
}

impl<'a> Plot<'a> {
    pub fn new(figure: &'a Figure, theme: Theme) -> Plot<'a> {
        Plot { figure, theme }
    }

    /// The x (`x: true`) or y axis with room for about `labels` tick labels; a y axis over
    /// `rows` rows.
    /// A linear y axis ends on a labelled tick: its top is raised to the next major tick when
    /// the data's margin left it above the last one (force–time's top row had no label), or,
    /// for a fixed range, when the last tick's label is not on the top row (the COR axes' 0 …
    /// 1.05 left a blank top row above `1.0` at 200×60; tests/tui/tui_ticks.rs).
    fn axis(&self, x: bool, labels: usize, rows: u16) -> Axis {
        let mut t = ticks(self.figure, x, Room::Labels(labels));
        let fitted = if x { &self.figure.x } else { &self.figure.y };
        if let (false, false, [.., a, b]) = (x, fitted.log, t.major.as_slice()) {
            let (a, b) = (*a, *b);
            let next = b + (b - a);
            let above = t.hi > b + 1e-9 * (b - a);
            let unlabelled = fitted.range.is_none() || !on_top_row(t.lo, t.hi, b, rows);
            if above && unlabelled && next.is_finite() {
                t.major.push(next);
                t.hi = next;
            }
        }
        let (exponent, ticks) = t.scaled_labels();
        Axis {
            bounds: [t.lo, t.hi],
            ticks,
            exponent,
        }
    }

    /// The layout for `area`, or `None` when there is no room for axes and a plot: rows kept
    /// above the plot for the legend when it would hide data anywhere else (legend.rs).
    pub fn layout(&self, area: Rect) -> Option<PlotLayout> {
        let first = self.layout_below(area, 0)?;
        match self.legend_rows(area, &first) {
            0 => Some(first),
            rows => self.layout_below(area, rows).or(Some(first)),
        }
    }

    /// The layout with the first `top` rows inside the frame kept for the legend.
    fn layout_below(&self, area: Rect, top: u16) -> Option<PlotLayout> {
        let inner = Block::bordered().inner(area);
        if inner.width < 10 || inner.height < 4 + top {
            return None;
        }
        let plot_h = inner.height - 2 - top;
        let y = self.axis(false, usize::from(plot_h / 2).clamp(2, 11), plot_h);
        let gutter = y
            .ticks
            .iter()
            .map(|t| t.1.chars().count())
            .max()
            .unwrap_or(0) as u16
            + 1;
        if inner.width < gutter + 6 {
            return None;
        }
        let plot = Rect::new(
            inner.x + gutter,
            inner.y + top,
            inner.width - gutter,
            plot_h,
        );
        let x = self.axis(true, usize::from(plot.width / 8).max(2), 0);
        Some(PlotLayout { inner, plot, x, y })
    }

    fn draw_axes(&self, l: &PlotLayout, buf: &mut Buffer) {
        let style = self.theme.axis();
        let (p, axis_x, axis_y) = (l.plot, l.plot.x - 1, l.plot.bottom());
        for row in p.y..p.bottom() {
            buf[(axis_x, row)].set_symbol("│").set_style(style);
        }
        for col in p.x..p.right() {
            buf[(col, axis_y)].set_symbol("─").set_style(style);
        }
        buf[(axis_x, axis_y)].set_symbol("└").set_style(style);
        let mut last_row = None;
        for (v, label) in &l.y.ticks {
            let Some(row) = l.row(*v) else { continue };
            buf[(axis_x, row)].set_symbol("┤");
            if last_row == Some(row) {
                continue;
            }
            let w = label.chars().count() as u16;
            buf.set_stringn(axis_x.saturating_sub(w), row, label, usize::from(w), style);
            last_row = Some(row);
        }
        let mut free_from = l.inner.x;
        for (v, label) in &l.x.ticks {
            let Some(col) = l.col(*v) else { continue };
            buf[(col, axis_y)].set_symbol("┴");
            let w = label.chars().count() as u16;
            let start = col
                .saturating_sub(w.saturating_sub(1) / 2)
                .min(l.inner.right().saturating_sub(w))
                .max(l.inner.x);
            if start < free_from || start + w > l.inner.right() {
                continue;
            }
            buf.set_stringn(start, axis_y + 1, label, usize::from(w), style);
            free_from = start + w + 1;
        }
    }

    /// A series' points in plot units; `None` where the axes cannot show one.
    fn drawn(&self, s: &Series) -> Vec<Option<(f64, f64)>> {
        let (fx, fy) = (&self.figure.x, &self.figure.y);
        s.points
            .iter()
            .map(|&(x, y)| Some((fx.drawn(x)?, fy.drawn(y)?)))
            .collect()
    }

    fn color(&self, s: &Series) -> Color {
        self.theme
            .series(s.look.tone, s.color)
            .fg
            .unwrap_or_default()
    }

    /// The lines of one layer (pinned or live) on a scratch canvas: dotted ones (measured
    /// values, thresholds) under solid ones.
    fn canvas(&self, l: &PlotLayout, ghost: bool) -> Buffer {
        let area = l.plot;
        let mut scratch = Buffer::empty(area);
        // a dot every third braille dot along the plot's longer side
        let n = (usize::from(area.width.max(area.height)) * 4 / 3 + 1) as f64;
        let lines: Vec<&Series> = self
            .figure
            .series
            .iter()
            .filter(|s| !matches!(s.style, Stroke::Markers(_)))
            .filter(|s| (s.kind == Role::Pinned) == ghost)
            .collect();
        let paint = |ctx: &mut Context| {
            for pass_dotted in [true, false] {
                for s in lines.iter().filter(|s| dotted(s) == pass_dotted) {
                    let color = self.color(s);
                    let pattern = if dashed(s) {
                        Some(Pattern::Dashed)
                    } else if long_dashed(s) {
                        Some(Pattern::LongDashed)
                    } else {
                        pass_dotted.then_some(Pattern::Dotted)
                    };
                    if let Some(pattern) = pattern {
                        let bounds = (l.x.bounds, l.y.bounds);
                        let coords = patterned(&self.drawn(s), pattern, n, bounds);
                        ctx.draw(&canvas::Points {
                            coords: &coords,
                            color,
                        });
                        continue;
                    }
                    for w in self.drawn(s).windows(2) {
                        let (Some(a), Some(b)) = (w[0], w[1]) else {
                            continue;
                        };
                        ctx.draw(&canvas::Line::new(a.0, a.1, b.0, b.1, color));
                    }
                }
            }
        };
        Canvas::default()
            .marker(Marker::Braille)
            .x_bounds(l.x.bounds)
            .y_bounds(l.y.bounds)
            .paint(paint)
            .render(area, &mut scratch);
        scratch
    }

    fn draw_series(&self, l: &PlotLayout, buf: &mut Buffer) {
        let live = self.canvas(l, false);
        let ghost = self
            .figure
            .series
            .iter()
            .any(|s| s.kind == Role::Pinned)
            .then(|| self.canvas(l, true));
        for pos in l.plot.positions() {
            let cell = &live[pos];
            if cell.symbol() != " " {
                buf[pos] = cell.clone();
            } else if let Some(g) = &ghost
                && g[pos].symbol() != " "
            {
                // dimmed, in the pin's own colour (`Theme::series`)
                let style = Style::default().fg(g[pos].fg).add_modifier(Modifier::DIM);
                buf[pos].set_symbol(g[pos].symbol()).set_style(style);
            }
        }
    }
}
