//! The drop view (`d`, src/tui/drop_view.rs): height against time in braille with the
//! standard's window as a band on the first rebound, the ball on a ratatui Canvas above the
//! plate, and a readout with the bounces and the verdict. Reads the state only.

use super::axis::AxisSpec;
use super::legend;
use super::plot::{Corner, Mark, Plot, Rule, Series};
use crate::drop::standards::Test;
use crate::tui::app::App;
use crate::tui::drop_view::DropView;
use crate::tui::format::sig;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::canvas::{Canvas, Circle, Line as CanvasLine};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// Width of the ball's column and of the readout.
const BALL_WIDTH: u16 = 18;
const READOUT_WIDTH: u16 = 38;

/// The drop view in `area` (between the header and the status line).
pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let d = app.drop_view();
    let theme = Theme::new(app.color());
    let wide = area.width >= 90;
    let (left, readout) = if wide {
        let [l, r] = Layout::horizontal([Constraint::Fill(1), Constraint::Length(READOUT_WIDTH)])
            .areas(area);
        (l, r)
    } else {
        let [l, r] = Layout::vertical([Constraint::Fill(1), Constraint::Length(7)]).areas(area);
        (l, r)
    };
    let [chart, ball] =
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(BALL_WIDTH)]).areas(left);
    plot(d, theme).render(chart, buf);
    render_ball(d, theme, ball, buf);
    render_readout(app, d, theme, readout, buf);
}

/// Height (m) against time (s): the whole sequence dimmed, the part already flown live, the
/// ball now as a mark, the standard's window as two rules.
fn plot(d: &DropView, theme: Theme) -> Plot {
    let (mut series, mut marks, mut rules, mut legend_lines) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut t_hi, mut h_hi) = (1e-3, 1e-3);
    if let Some(run) = d.sequence() {
        t_hi = run.duration().max(1e-3);
        h_hi = run.setup.height * 1.05;
        let traj = run.trajectory(t_hi / 400.0);
        let all: Vec<(f64, f64)> = traj.iter().map(|s| (s.t, s.height)).collect();
        let mut flown: Vec<(f64, f64)> = all.iter().copied().filter(|p| p.0 <= d.t).collect();
        flown.push((d.t, d.height_now()));
        series.push(Series::ghost(all));
        series.push(Series::live(flown, theme.current()));
        legend_lines.push(legend(
            "━",
            Style::default().fg(theme.current()),
            "bottom of the ball",
        ));
        marks.push(Mark {
            x: d.t,
            y: d.height_now(),
            text: "●".into(),
            style: Style::default().fg(theme.current()),
        });
    }
    if let (Some((lo, hi)), Some((s, _))) = (d.band(), d.verdict) {
        let color = theme.measured().fg.unwrap_or_default();
        for (at, label) in [(hi, Some(format!("{} window", s.name))), (lo, None)] {
            rules.push(Rule {
                at,
                vertical: false,
                color,
                label,
            });
        }
        legend_lines.push(legend("┄", theme.measured(), "1st rebound window"));
        h_hi = h_hi.max(hi * 1.05);
    }
    Plot {
        title: "Drop · height [m] vs t [s]".into(),
        short_title: "drop · m, s".into(),
        x: AxisSpec::Linear { lo: 0.0, hi: t_hi },
        y: AxisSpec::Linear { lo: 0.0, hi: h_hi },
        series,
        rules,
        marks,
        legend: legend_lines,
        legend_at: Corner::TopRight,
        theme,
    }
}

/// The ball (to scale in height: its bottom at the current height) above the plate.
fn render_ball(d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let top = d.sequence().map_or(1.0, |r| r.setup.height) + 2.0 * d.radius;
    let h = d.height_now();
    // the drawn radius: the true one, or at least a few cells so the ball stays visible
    let inner = Block::bordered().inner(area);
    let rows = f64::from(inner.height.max(1));
    let cell = top / rows;
    let r = d.radius.max(0.8 * cell);
    // braille dots are about square (a cell is 2 dots wide, 4 tall, and twice as tall as
    // wide): equal metres per dot across and up keeps the ball round
    let half_width = top * f64::from(inner.width.max(1)) / (4.0 * rows);
    let color = theme.current();
    let plate = theme.c(Color::Gray);
    Canvas::default()
        .block(Block::bordered().title(Span::styled("ball", theme.title())))
        .marker(Marker::Braille)
        .x_bounds([-half_width, half_width])
        .y_bounds([0.0, top])
        .paint(move |ctx| {
            ctx.draw(&CanvasLine {
                x1: -half_width,
                y1: 0.0,
                x2: half_width,
                y2: 0.0,
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

fn render_readout(app: &App, d: &DropView, theme: Theme, area: Rect, buf: &mut Buffer) {
    let mut lines = vec![Line::styled(
        format!("{} · drop test", app.preset().name),
        theme.title(),
    )];
    match (&d.run, d.sequence()) {
        (Err(e), _) => lines.push(Line::styled(e.clone(), theme.error())),
        (_, Some(run)) => {
            lines.push(Line::raw(format!(
                "H {} m → v_in {} m/s",
                sig(run.setup.height, 4),
                sig(run.bounces[0].v_in, 4)
            )));
            lines.push(Line::styled("drag ½ρC_dAv², C_d 0.47", theme.dim()));
            lines.push(Line::raw(""));
            lines.push(Line::styled(" #  rebound m    COR", theme.dim()));
            for (i, b) in run.bounces.iter().enumerate().take(6) {
                lines.push(Line::raw(format!(
                    "{:>2}  {:<10}  {}",
                    i + 1,
                    sig(b.rebound_height, 4),
                    sig(b.cor, 4)
                )));
            }
        }
        _ => {}
    }
    lines.push(Line::raw(""));
    match d.verdict {
        Some((s, v)) => {
            let unit = match s.test {
                Test::Drop { .. } => " m",
                Test::Cor { .. } => "",
            };
            lines.push(Line::raw(format!("standard {}", s.name)));
            lines.push(Line::raw(format!("measured {}{unit}", sig(v.measured, 4))));
            let (word, style) = if v.pass {
                ("PASS", theme.info())
            } else {
                ("FAIL", theme.error())
            };
            lines.push(Line::from(vec![
                Span::styled(word, style),
                Span::raw(format!(" margin {:+.3}{unit}", v.margin)),
            ]));
            lines.push(Line::styled("(at the standard's own height)", theme.dim()));
        }
        None => lines.push(Line::styled("no standard for this ball", theme.dim())),
    }
    lines.push(Line::raw(""));
    let keys = if d.motion {
        "space pause · b replay · d back"
    } else {
        "reduced motion · d back"
    };
    lines.push(Line::styled(keys, theme.key()));
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(Block::bordered())
        .render(area, buf);
}
