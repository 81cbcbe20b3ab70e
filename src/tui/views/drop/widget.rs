//! The drop view (`d`, src/tui/views/drop/state.rs): height against time in braille with the
//! standard's window as a band on the first rebound, the ball on a ratatui Canvas above the
//! plate, and a readout with the bounces and the verdict. Reads the state only; the chart is
//! a figure drawn by the explorer's plot widget, the ball a ratatui `Canvas`.

use crate::drop::standards::Test;
use crate::figure::{
    Axis as FigAxis, Figure, GREY, Look, Marker as Glyph, Role, Series, Style as Stroke, Tone,
};
use crate::text::sig;
use crate::tui::layout::charts_and_readout;
use crate::tui::theme::Theme;
use crate::tui::views::drop::state::DropView;
use crate::tui::widgets::plot::Plot;
use crate::tui::widgets::{fitted, readout_column, readout_columns};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Color;
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Circle, Line as CanvasLine};
use ratatui::widgets::{Block, Paragraph, Widget};

/// Width of the ball's column and of the readout.
const BALL_WIDTH: u16 = 18;
const READOUT_WIDTH: u16 = 38;

/// The drop view in its area (between the header and the status line).
#[derive(Debug, Clone, Copy)]
pub struct DropPanel<'a> {
    pub drop: &'a DropView,
    /// The ball's name, for the readout's title.
    pub ball: &'a str,
    /// The height chart as drawn ([`height_figure`] with its zoom and crosshair:
    /// src/tui/app/charts.rs).
    pub chart: &'a Figure,
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
    // below the chart (narrow): the setting and verdict beside the rebounds, as many rows as
    // the longer needs and the chart can spare (at 80 × 24 seven rows cut off the rebounds,
    // the verdict and the keys)
    let rows = (area.height * 45 / 100).clamp(7, 10);
    let (left, readout) = charts_and_readout(area, wide, READOUT_WIDTH, rows);
    let [chart, ball] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(BALL_WIDTH)]).areas(left);
    (&Plot::new(p.chart, theme)).render(chart, buf);
    render_ball(d, theme, ball, buf);
    if wide {
        render_readout(p.ball, d, theme, readout, buf);
    } else {
        render_readout_beside(p.ball, d, theme, readout, buf);
    }
}

/// Height (m) against time (s) as a figure: the whole sequence dimmed (drawn as a pinned
/// curve is, behind), the part already flown bright, the ball now as a dot, the standard's
/// window as two dotted lines across. Drawn by the explorer's one plot widget
/// (`widgets::plot`), so its ticks are the other charts' (`figure::ticks`), each label at its
/// value's place (tests/tui/tui_ticks.rs); ratatui's `Chart` spread them evenly, so "2" sat at
/// 1.8 s on the 80 × 24 screen.
pub fn height_figure(d: &DropView) -> Figure {
    let mut series = Vec::new();
    let mut t_hi = 1e-3;
    if let Some(run) = d.sequence() {
        t_hi = run.duration().max(1e-3);
        let all: Vec<(f64, f64)> = run
            .trajectory(t_hi / 400.0)
            .iter()
            .map(|s| (s.t, s.height))
            .collect();
        let mut flown: Vec<(f64, f64)> = all.iter().copied().filter(|p| p.0 <= d.t).collect();
        let now = (d.t, d.height_now());
        flown.push(now);
        series
            .push(Series::new("", "sequence", Role::Pinned, Stroke::Solid, GREY).with_points(all));
        series.push(
            Series::new("", "flown", Role::Model, Stroke::Solid, 0)
                .with_points(flown)
                .with_look(Look::new(Tone::Current, Some("bottom of the ball"), None)),
        );
        series.push(
            Series::new("", "now", Role::ThisRun, Stroke::Markers(Glyph::Circle), 0)
                .with_points(vec![now])
                .with_look(Look::new(Tone::Current, None, Some("●"))),
        );
    }
    // the standard's window only over a drop: over an empty chart it was a legend of nothing
    if let (Some((lo, hi)), Some((s, _)), true) = (d.band(), d.verdict, d.sequence().is_some()) {
        let name = format!("{} window", s.name);
        for (h, key) in [(hi, Some(name.as_str())), (lo, None)] {
            series.push(
                Series::new("", "window", Role::Reference, Stroke::Dotted, GREY)
                    .with_points(vec![(0.0, h), (t_hi, h)])
                    .with_look(Look::new(Tone::Measured, key, None)),
            );
        }
    }
    let mut fig = Figure::new(
        "Drop".into(),
        String::new(),
        FigAxis::linear("t (s)", "t", 1.0),
        FigAxis::linear("height (m)", "height", 1.0),
        series,
    );
    fig.screen_title = match (&d.run, d.paused()) {
        (Err(_), _) => "Drop · no drop reaches this v0 (see the readout)".into(),
        (_, true) => "Drop · height [m] vs t [s] · paused".into(),
        _ => "Drop · height [m] vs t [s]".into(),
    };
    fig
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
    // (tests/tui/tui_drop.rs: `the_ball_at_rest_is_round_on_its_plate`)
    let plate_y = -cell / 4.0;
    // braille dots are about square (a cell is 2 dots wide, 4 tall, and twice as tall as
    // wide): equal metres per dot across and up keeps the ball round
    let half_width = top * f64::from(inner.width.max(1)) / (4.0 * rows);
    let color = theme.current();
    let plate = theme.c(Color::Gray);
    Canvas::default()
        .block(Block::bordered().title(Span::styled(
            crate::tui::widgets::title::framed("ball", area.width),
            theme.title(),
        )))
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
    readout_column(lines, area, buf);
}

/// The readout under the chart (narrow screens): the setting and the verdict on the left,
/// the rebounds on the right, so both show in a few rows; the status line has the keys.
fn render_readout_beside(ball: &str, d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let [left, right] = readout_columns(
        area,
        buf,
        None,
        [Constraint::Fill(1), Constraint::Length(22)],
    );
    let mut lines = setting_lines(ball, d, theme);
    lines.extend(verdict_lines(d, theme));
    if !d.motion {
        lines.push(keys_line(d, theme));
    }
    fitted(lines, left, buf);
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
            // the constant the drop flies with, in the one format (issue 51 item 4: a typed
            // "C_d 0.47"; tests/tui/tui_drop.rs,
            // `the_drop_view_writes_the_drag_coefficient_it_uses_in_four_digits`)
            let c_d = crate::tui::format::value(crate::drop::flight::SPHERE_DRAG_COEFFICIENT);
            lines.push(Line::styled(
                format!("drag ½ρC_dAv², C_d {c_d}"),
                theme.dim(),
            ));
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
    // no drop at this v0: no verdict beside it (the readout's first line says why)
    if d.run.is_err() {
        return Vec::new();
    }
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
    let keys = if d.paused() {
        "paused · space play · b replay · d back"
    } else if d.motion {
        "space pause · b replay · d back"
    } else {
        "reduced motion · d back"
    };
    Line::styled(keys, theme.key())
}
