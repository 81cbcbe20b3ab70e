//! The drop view (`d`, src/tui/views/drop/state.rs): height against time in braille with the
//! standard's window as a band on the first rebound, the ball on a ratatui Canvas above the
//! plate, and a readout with the bounces and the verdict. Reads the state only, and draws with
//! ratatui's own `Chart` and `Canvas`, so it stands apart from the explorer's chart module.

use crate::drop::standards::Test;
use crate::text::sig;
use crate::tui::format::fit_lines;
use crate::tui::theme::Theme;
use crate::tui::views::drop::state::DropView;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Circle, Line as CanvasLine};
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, Paragraph, Widget, Wrap};

/// Width of the ball's column and of the readout.
const BALL_WIDTH: u16 = 18;
const READOUT_WIDTH: u16 = 38;

/// The drop view in its area (between the header and the status line).
#[derive(Debug, Clone, Copy)]
pub struct DropPanel<'a> {
    pub drop: &'a DropView,
    /// The ball's name, for the readout's title.
    pub ball: &'a str,
    pub theme: Theme,
}

impl Widget for DropPanel<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        render(self, area, buf);
    }
}

fn render(p: DropPanel, area: Rect, buf: &mut Buffer) {
    let (d, theme) = (p.drop, p.theme);
    let wide = area.width >= 90;
    let (left, readout) = if wide {
        let [l, r] = Layout::horizontal([Constraint::Fill(1), Constraint::Length(READOUT_WIDTH)])
            .areas(area);
        (l, r)
    } else {
        // below the chart: the setting and verdict beside the rebounds, as many rows as the
        // longer needs and the chart can spare (at 80 × 24 seven rows cut off the rebounds,
        // the verdict and the keys)
        let rows = (area.height * 45 / 100).clamp(7, 10);
        let [l, r] = Layout::vertical([Constraint::Fill(1), Constraint::Length(rows)]).areas(area);
        (l, r)
    };
    let [chart, ball] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(BALL_WIDTH)]).areas(left);
    render_chart(d, theme, chart, buf);
    render_ball(d, theme, ball, buf);
    if wide {
        render_readout(p.ball, d, theme, readout, buf);
    } else {
        render_readout_beside(p.ball, d, theme, readout, buf);
    }
}

/// What the height–time chart draws, in m and s.
struct Curves {
    all: Vec<(f64, f64)>,
    flown: Vec<(f64, f64)>,
    now: Vec<(f64, f64)>,
    band: Option<[Vec<(f64, f64)>; 2]>,
    t_hi: f64,
    h_hi: f64,
}

/// The curves of `d` for a chart `width` cells wide.
fn curves(d: &DropView, width: u16) -> Curves {
    let mut c = Curves {
        all: Vec::new(),
        flown: Vec::new(),
        now: Vec::new(),
        band: None,
        t_hi: 1e-3,
        h_hi: 1e-3,
    };
    if let Some(run) = d.sequence() {
        c.t_hi = run.duration().max(1e-3);
        c.h_hi = run.setup.height * 1.05;
        c.all = run
            .trajectory(c.t_hi / 400.0)
            .iter()
            .map(|s| (s.t, s.height))
            .collect();
        c.flown = c.all.iter().copied().filter(|p| p.0 <= d.t).collect();
        c.flown.push((d.t, d.height_now()));
        c.now = vec![(d.t, d.height_now())];
    }
    if let Some((lo, hi)) = d.band() {
        // dotted, as the explorer draws thresholds: told apart from the flight without colour;
        // a dot every third braille column of the chart
        let n = (f64::from(width) * 2.0 / 3.0).max(2.0);
        let dots = |h: f64| -> Vec<(f64, f64)> {
            let n = n as u32;
            (0..=n)
                .map(|i| (c.t_hi * f64::from(i) / f64::from(n), h))
                .collect()
        };
        c.band = Some([dots(lo), dots(hi)]);
        c.h_hi = c.h_hi.max(hi * 1.05);
    }
    c
}

/// The axis' top and its labels, evenly spaced from 0 as ratatui places them: 2 to 4 round
/// steps (1, 2, 2.5, 5 × 10^k), the count that wastes the least room above `hi` ("0 0.716
/// 1.43" became "0 0.5 1 1.5").
fn axis_labels(hi: f64) -> (f64, Vec<String>) {
    let (top, step) = (2..=4)
        .map(|n| {
            let step = crate::figure::ticks::nice_ceil(hi / f64::from(n));
            (f64::from(n) * step, step)
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((hi, hi));
    let n = (top / step).round() as usize;
    let labels = (0..=n)
        .map(|i| crate::figure::ticks::step_label(i as f64 * step, step))
        .collect();
    (top, labels)
}

/// Height (m) against time (s) on ratatui's braille `Chart`: the whole sequence dimmed, the
/// part already flown bright, the ball now as a dot, the standard's window as two lines.
fn render_chart(d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let c = curves(d, area.width);
    let ((t_top, t_labels), (h_top, h_labels)) = (axis_labels(c.t_hi), axis_labels(c.h_hi));
    let live = Style::default().fg(theme.current());
    let drawn = |name: Option<String>, data, style, graph| {
        let set = Dataset::default()
            .marker(Marker::Braille)
            .graph_type(graph)
            .style(style)
            .data(data);
        match name {
            Some(n) => set.name(n),
            None => set,
        }
    };
    let line = |name, data, style| drawn(name, data, style, GraphType::Line);
    // each name with its line's look, so the legend reads without colour (NO_COLOR)
    let mut sets = vec![
        line(None, &c.all, theme.ghost()),
        line(Some("━ bottom of the ball".into()), &c.flown, live),
        Dataset::default()
            .marker(Marker::Dot)
            .graph_type(GraphType::Scatter)
            .style(live)
            .data(&c.now),
    ];
    if let (Some([lo, hi]), Some((s, _))) = (&c.band, d.verdict) {
        let dotted = |name, data| drawn(name, data, theme.measured(), GraphType::Scatter);
        sets.push(dotted(Some(format!("┄ {} window", s.name)), hi));
        sets.push(dotted(None, lo));
    }
    Chart::new(sets)
        .hidden_legend_constraints((Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)))
        .block(Block::bordered().title(Span::styled("Drop · height [m] vs t [s]", theme.title())))
        .x_axis(
            Axis::default()
                .style(theme.axis())
                .bounds([0.0, t_top])
                .labels(t_labels),
        )
        .y_axis(
            Axis::default()
                .style(theme.axis())
                .bounds([0.0, h_top])
                .labels(h_labels),
        )
        .render(area, buf);
}

/// The ball (to scale in height: its bottom at the current height) above the plate.
fn render_ball(d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let top = d.sequence().map_or(1.0, |r| r.setup.height) + 2.0 * d.radius;
    let h = d.height_now();
    // the drawn radius: the true one, or at least a few cells so the ball stays visible
    let inner = Block::bordered().inner(area);
    let rows = f64::from(inner.height.max(1));
    let cell = top / rows;
    let r = d.radius.max(1.2 * cell);
    // the plate one braille dot row (a quarter cell) below the ball's lowest point, so a
    // ball at rest (the reduced-motion picture) is a whole circle standing on the plate
    // (tests/tui_drop.rs: `the_ball_at_rest_is_round_on_its_plate`)
    let plate_y = -cell / 4.0;
    // braille dots are about square (a cell is 2 dots wide, 4 tall, and twice as tall as
    // wide): equal metres per dot across and up keeps the ball round
    let half_width = top * f64::from(inner.width.max(1)) / (4.0 * rows);
    let color = theme.current();
    let plate = theme.c(Color::Gray);
    Canvas::default()
        .block(Block::bordered().title(Span::styled("ball", theme.title())))
        .marker(Marker::Braille)
        .x_bounds([-half_width, half_width])
        .y_bounds([plate_y, top])
        .paint(move |ctx| {
            ctx.draw(&CanvasLine {
                x1: -half_width,
                y1: plate_y,
                x2: half_width,
                y2: plate_y,
                color: plate,
            });
            ctx.draw(&Circle {
                x: 0.0,
                y: h + r,
                radius: r,
                color,
            });
        })
        .render(area, buf);
}

/// The readout in one column (wide screens): the setting, the rebounds, the verdict, the keys.
fn render_readout(ball: &str, d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let mut lines = setting_lines(ball, d, theme);
    lines.push(Line::raw(""));
    lines.extend(bounce_lines(d, theme));
    lines.push(Line::raw(""));
    lines.extend(verdict_lines(d, theme));
    lines.push(Line::raw(""));
    lines.push(keys_line(d, theme));
    // broken between fields, never inside a value (`+0.225` and its `m` on two lines)
    let lines = fit_lines(lines, usize::from(area.width.saturating_sub(2)));
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(Block::bordered())
        .render(area, buf);
}

/// The readout under the chart (narrow screens): the setting and the verdict on the left,
/// the rebounds on the right, so both show in a few rows; the status line has the keys.
fn render_readout_beside(ball: &str, d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let block = Block::bordered();
    let inner = block.inner(area);
    block.render(area, buf);
    let [left, right] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(22)]).areas(inner);
    let mut lines = setting_lines(ball, d, theme);
    lines.extend(verdict_lines(d, theme));
    if !d.motion {
        lines.push(keys_line(d, theme));
    }
    Paragraph::new(fit_lines(lines, usize::from(left.width)))
        .wrap(Wrap { trim: true })
        .render(left, buf);
    Paragraph::new(bounce_lines(d, theme)).render(right, buf);
}

/// The ball, the drop and the air.
fn setting_lines(ball: &str, d: &DropView, theme: Theme) -> Vec<Line<'static>> {
    let mut lines = vec![Line::styled(format!("{ball} · drop test"), theme.title())];
    match (&d.run, d.sequence()) {
        (Err(e), _) => lines.push(Line::styled(e.clone(), theme.error())),
        (_, Some(run)) => {
            lines.push(Line::raw(format!(
                "H {} m → v_in {} m/s",
                sig(run.setup.height, 4),
                sig(run.bounces[0].v_in, 4)
            )));
            lines.push(Line::styled("drag ½ρC_dAv², C_d 0.47", theme.dim()));
        }
        _ => {}
    }
    lines
}

/// The first six rebounds: height and COR.
fn bounce_lines(d: &DropView, theme: Theme) -> Vec<Line<'static>> {
    let Some(run) = d.sequence() else {
        return Vec::new();
    };
    let mut lines = vec![Line::styled(" #  rebound m    COR", theme.dim())];
    for (i, b) in run.bounces.iter().enumerate().take(6) {
        lines.push(Line::raw(format!(
            "{:>2}  {:<10}  {}",
            i + 1,
            sig(b.rebound_height, 4),
            sig(b.cor, 4)
        )));
    }
    lines
}

/// The standard's verdict on the model's prediction.
fn verdict_lines(d: &DropView, theme: Theme) -> Vec<Line<'static>> {
    let Some((s, v)) = d.verdict else {
        return vec![Line::styled("no standard for this ball", theme.dim())];
    };
    let unit = match s.test {
        Test::Drop { .. } => " m",
        Test::Cor { .. } => "",
    };
    let (word, style) = if v.pass {
        ("PASS", theme.info())
    } else {
        ("FAIL", theme.error())
    };
    vec![
        Line::from(vec![
            Span::raw(format!("{} ", s.name)),
            Span::styled(word, style),
            // a field of its own (two spaces): the line breaks before it, not inside it
            Span::raw(format!("  margin {:+.3}{unit}", v.margin)),
        ]),
        // the model's value where the standard measures one
        Line::raw(format!("predicted {}{unit}", sig(v.measured, 4))),
        Line::styled("(at the standard's own height)", theme.dim()),
    ]
}

fn keys_line(d: &DropView, theme: Theme) -> Line<'static> {
    let keys = if d.motion {
        "space pause · b replay · d back"
    } else {
        "reduced motion · d back"
    };
    Line::styled(keys, theme.key())
}
