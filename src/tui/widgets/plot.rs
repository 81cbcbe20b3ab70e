//! A braille line plot on ratatui's Canvas with axes, ticks and labels we place ourselves, so a
//! label sits over the column where the curve's dot for its value lands. Pinned (ghost) series
//! are drawn dimmed behind the live ones.

use super::axis::{Axis, AxisSpec};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{self, Canvas, Context};
use ratatui::widgets::{Block, Widget};

/// A curve in plot units (log10 on a decade axis).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub points: Vec<(f64, f64)>,
    pub color: Color,
    /// Pinned: drawn dimmed, behind the live series.
    pub ghost: bool,
}

impl Series {
    pub fn live(points: Vec<(f64, f64)>, color: Color) -> Series {
        Series {
            points,
            color,
            ghost: false,
        }
    }
    pub fn ghost(points: Vec<(f64, f64)>) -> Series {
        Series {
            points,
            color: Color::Reset,
            ghost: true,
        }
    }
}

/// A dotted line across the whole plot: a measured value or a threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// x of a vertical rule, y of a horizontal one (plot units).
    pub at: f64,
    pub vertical: bool,
    pub color: Color,
    /// Printed at the top of a vertical rule (right of it), at the left end of a horizontal one
    /// (above it).
    pub label: Option<String>,
}

/// Text at a point (its first character on the point's cell): markers and labels.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    pub x: f64,
    pub y: f64,
    pub text: String,
    pub style: Style,
}

/// Where the legend goes inside the plot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    TopLeft,
    TopRight,
    BottomLeft,
    BottomRight,
}

/// A chart: a bordered block with a title, axes and series.
#[derive(Debug, Clone)]
pub struct Plot {
    pub title: String,
    /// For narrow charts.
    pub short_title: String,
    pub x: AxisSpec,
    pub y: AxisSpec,
    pub series: Vec<Series>,
    /// Drawn under the live series.
    pub rules: Vec<Rule>,
    pub marks: Vec<Mark>,
    pub legend: Vec<Line<'static>>,
    pub legend_at: Corner,
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

impl Plot {
    /// The layout for `area`, or `None` when there is no room for axes and a plot.
    pub fn layout(&self, area: Rect) -> Option<PlotLayout> {
        let inner = Block::bordered().inner(area);
        if inner.width < 10 || inner.height < 4 {
            return None;
        }
        let plot_h = inner.height - 2;
        let y = self.y.build(usize::from(plot_h / 2).clamp(2, 11));
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
        let plot = Rect::new(inner.x + gutter, inner.y, inner.width - gutter, plot_h);
        let x = self.x.build(usize::from(plot.width / 8).max(2));
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

    /// The series of one kind (ghost or live; rules go with the live ones) on a scratch canvas.
    fn canvas(&self, l: &PlotLayout, ghost: bool) -> Buffer {
        let area = l.plot;
        let mut scratch = Buffer::empty(area);
        let ([x0, x1], [y0, y1]) = (l.x.bounds, l.y.bounds);
        // every third braille dot
        let n = usize::from(area.width.max(area.height)) * 4 / 3 + 1;
        let paint = |ctx: &mut Context| {
            if !ghost {
                for r in &self.rules {
                    let coords: Vec<(f64, f64)> = (0..=n)
                        .map(|i| {
                            let t = i as f64 / n as f64;
                            if r.vertical {
                                (r.at, y0 + t * (y1 - y0))
                            } else {
                                (x0 + t * (x1 - x0), r.at)
                            }
                        })
                        .collect();
                    ctx.draw(&canvas::Points {
                        coords: &coords,
                        color: r.color,
                    });
                }
            }
            for s in self.series.iter().filter(|s| s.ghost == ghost) {
                for w in s.points.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    if [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
                        ctx.draw(&canvas::Line::new(a.0, a.1, b.0, b.1, s.color));
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
            .series
            .iter()
            .any(|s| s.ghost)
            .then(|| self.canvas(l, true));
        let ghost_style = self.theme.ghost();
        for pos in l.plot.positions() {
            let cell = &live[pos];
            if cell.symbol() != " " {
                buf[pos] = cell.clone();
            } else if let Some(g) = &ghost
                && g[pos].symbol() != " "
            {
                buf[pos].set_symbol(g[pos].symbol()).set_style(ghost_style);
            }
        }
    }

    /// Rule labels, then marks; a mark whose cell another mark took moves right, so both show.
    fn draw_marks(&self, l: &PlotLayout, buf: &mut Buffer) {
        for r in &self.rules {
            let Some(text) = &r.label else { continue };
            let at = if r.vertical {
                l.col(r.at).map(|c| (c + 1, l.plot.y))
            } else {
                l.row(r.at)
                    .map(|row| (l.plot.x + 1, row.saturating_sub(1).max(l.plot.y)))
            };
            if let Some((col, row)) = at
                && col < l.plot.right()
            {
                let room = usize::from(l.plot.right() - col);
                buf.set_stringn(col, row, text, room, Style::default().fg(r.color));
            }
        }
        let mut taken: Vec<(u16, u16)> = Vec::new();
        for m in &self.marks {
            if let (Some(mut col), Some(row)) = (l.col(m.x), l.row(m.y)) {
                while taken.contains(&(col, row)) && col + 1 < l.plot.right() {
                    col += 1;
                }
                let room = usize::from(l.plot.right() - col);
                let (end, _) = buf.set_stringn(col, row, &m.text, room, m.style);
                taken.extend((col..end).map(|c| (c, row)));
            }
        }
    }

    /// The legend in its corner, one entry a line; on one line when that does not fit; not at
    /// all when neither does.
    fn draw_legend(&self, l: &PlotLayout, buf: &mut Buffer) {
        let p = l.plot;
        let top = matches!(self.legend_at, Corner::TopLeft | Corner::TopRight);
        let left = matches!(self.legend_at, Corner::TopLeft | Corner::BottomLeft);
        // bottom legends keep clear of the lowest row, where curves often run along zero
        let room = p.height.saturating_sub(if top { 1 } else { 2 });
        let width = self.legend.iter().map(Line::width).max().unwrap_or(0) as u16;
        // a legend may take half the plot's rows and half its width
        let fits = |rows: u16, w: u16| rows <= room && 2 * rows <= p.height && 2 * w <= p.width;
        let lines = if fits(self.legend.len() as u16, width) {
            self.legend.clone()
        } else {
            let mut spans = Vec::new();
            for (i, line) in self.legend.iter().enumerate() {
                if i > 0 {
                    spans.push(Span::raw("  "));
                }
                spans.extend(line.spans.iter().cloned());
            }
            let one = Line::from(spans);
            if !fits(1, one.width() as u16) {
                return;
            }
            vec![one]
        };
        let width = lines.iter().map(Line::width).max().unwrap_or(0) as u16;
        let x = if left { p.x + 1 } else { p.right() - width - 1 };
        let y0 = if top {
            p.y
        } else {
            p.bottom() - 1 - lines.len() as u16
        };
        for (i, line) in lines.iter().enumerate() {
            let y = y0 + i as u16;
            buf.set_string(
                x - 1,
                y,
                " ".repeat(usize::from(width + 2)),
                Style::default(),
            );
            let w = line.width() as u16;
            buf.set_line(if left { x } else { x + width - w }, y, line, w);
        }
    }
}

impl Widget for &Plot {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        Block::bordered()
            .border_style(self.theme.dim())
            .title(Line::styled(
                format!(" {} ", self.title),
                self.theme.title(),
            ))
            .render(area, buf);
        let Some(l) = self.layout(area) else { return };
        self.draw_axes(&l, buf);
        self.draw_series(&l, buf);
        self.draw_marks(&l, buf);
        self.draw_legend(&l, buf);
    }
}
