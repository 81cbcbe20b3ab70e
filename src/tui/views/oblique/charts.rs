//! The oblique view's charts, drawn from its impact's history with ratatui's own `Chart` and
//! `Canvas` (as the drop view draws): F_n and F_t against time with the friction's reversals
//! marked, v_c and ω against time, and the incoming and outgoing paths over the surface with
//! their angles. Each legend names its line's look, so it reads without colour (NO_COLOR).

use crate::oblique::{ObliqueHistory, ObliqueResponse};
use crate::text::short;
use crate::tui::format::value;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Rect};
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine};
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, Widget};

/// The times (s) where F_t changes sign: the friction's reversals, each found by linear
/// interpolation between the history's samples on either side.
pub fn reversals(h: &ObliqueHistory) -> Vec<f64> {
    let f = &h.friction_force;
    // a sign change of a force a millionth of the largest is noise around zero
    let tiny = 1e-6 * f.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut out = Vec::new();
    let mut last: Option<(f64, f64)> = None;
    for (&t, &v) in h.t.iter().zip(f) {
        if v.abs() <= tiny {
            continue;
        }
        if let Some((t0, v0)) = last
            && v0.signum() != v.signum()
        {
            out.push(t0 + (t - t0) * v0 / (v0 - v));
        }
        last = Some((t, v));
    }
    out
}

/// Bounds a little wider than the data, never empty.
fn bounds(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !lo.is_finite() || !hi.is_finite() {
        return [0.0, 1.0];
    }
    let pad = ((hi - lo) * 0.05)
        .max(hi.abs().max(lo.abs()) * 1e-3)
        .max(1e-12);
    [lo - pad, hi + pad]
}

/// Labels over `[lo, hi]` to three digits: the ends and the middle, or the ends alone on a
/// chart narrower than `MIDDLE_FROM` columns (at 60 × 20 three labels read "0 0").
fn labels(b: [f64; 2], width: u16) -> Vec<String> {
    let mid = 0.5 * (b[0] + b[1]);
    let at: &[f64] = if width >= MIDDLE_FROM {
        &[b[0], mid, b[1]]
    } else {
        &[b[0], b[1]]
    };
    at.iter().map(|&v| value(v)).collect()
}

/// Round ticks over `b`: a step of 1, 1.5, 2,
/// 2.5, 3, 4, 5, 6 or 8 × 10^k giving about three intervals, the axis widened to the ticks
/// around the data; every tick labelled (ratatui spreads labels evenly), or the ends alone on a
/// chart narrower than `MIDDLE_FROM` (`round_ticks_hold_the_data`).
///
/// Not `figure::ticks::fitted`, the explorer's other charts' rule, because of how the labels
/// are placed: `widgets::plot` writes each label at its own tick, while these are ratatui
/// `Chart`s, which spread their labels evenly from end to end. Evenly spread labels read true
/// only when both ends are ticks and every tick is labelled, which this rule holds by widening
/// the axis to whole steps; `fitted` ends a range on a finer grain when whole ticks would
/// waste room (`fitted(0.0, 4.8, 5)` spans 0…5 with ticks 0, 2, 4), and its 1, 2, 2.5, 5 steps
/// would leave a 0…4.8 axis one coarse interval or a wasted one where 1.5, 3, 6 fit.
fn round_axis(b: [f64; 2], width: u16) -> ([f64; 2], Vec<String>) {
    let span = b[1] - b[0];
    if !(span.is_finite() && span > 0.0) {
        return (b, labels(b, width));
    }
    let raw = span / 3.0;
    let k = 10f64.powf(raw.log10().floor());
    let step = [1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0]
        .iter()
        .map(|m| m * k)
        .find(|&s| s >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0 * k);
    let (k0, k1) = ((b[0] / step).floor(), (b[1] / step).ceil());
    let at: Vec<f64> = if width >= MIDDLE_FROM {
        (k0 as i64..=k1 as i64).map(|i| i as f64 * step).collect()
    } else {
        vec![k0 * step, k1 * step]
    };
    let text = at.iter().map(|&v| short(v, 3)).collect();
    ([k0 * step, k1 * step], text)
}

/// Narrowest chart with a middle label on its axes.
const MIDDLE_FROM: u16 = 30;

/// One chart against time in ms: `sets` are (legend, points, style, dotted).
fn time_chart<'a>(
    title: &str,
    sets: Vec<Dataset<'a>>,
    (t_ms, y): (f64, [f64; 2]),
    width: u16,
    theme: Theme,
) -> Chart<'a> {
    Chart::new(sets)
        .hidden_legend_constraints((Constraint::Ratio(1, 2), Constraint::Ratio(1, 2)))
        .block(Block::bordered().title(Span::styled(title.to_string(), theme.title())))
        .x_axis({
            let (bounds, text) = round_axis([0.0, t_ms], width);
            Axis::default()
                .style(theme.axis())
                .bounds(bounds)
                .labels(text)
        })
        .y_axis({
            let (bounds, text) = round_axis(y, width);
            Axis::default()
                .style(theme.axis())
                .bounds(bounds)
                .labels(text)
        })
}

fn set<'a>(name: Option<String>, data: &'a [(f64, f64)], style: Style, line: bool) -> Dataset<'a> {
    let d = Dataset::default()
        .marker(Marker::Braille)
        .graph_type(if line {
            GraphType::Line
        } else {
            GraphType::Scatter
        })
        .style(style)
        .data(data);
    match name {
        Some(n) => d.name(n),
        None => d,
    }
}

/// Every k-th of `pts`, about one a third of the braille dots across a chart `width` cells
/// wide: drawn as points they read dotted (`┄`), apart from a solid line also without colour
/// (NO_COLOR; issue 29 item 12: every series its own look; `f_t_is_dotted_beside_solid_f_n`).
fn dotted(pts: Vec<(f64, f64)>, width: u16) -> Vec<(f64, f64)> {
    let dots = 2 * usize::from(width.max(1));
    let k = (3 * pts.len()).div_ceil(dots).max(1);
    pts.into_iter().step_by(k).collect()
}

/// The points of `ys` against the history's t in ms.
fn points(h: &ObliqueHistory, ys: &[f64]) -> Vec<(f64, f64)> {
    h.t.iter().zip(ys).map(|(&t, &y)| (t * 1e3, y)).collect()
}

/// F_n (solid) and F_t (dotted) in N against t in ms, each reversal of F_t a dotted vertical
/// line named with its time.
pub fn render_forces(r: &ObliqueResponse, theme: Theme, area: Rect, buf: &mut Buffer) {
    let Some(h) = &r.history else { return };
    let t_ms = r.contact_time * 1e3;
    let fnp = points(h, &h.normal_force);
    let ftp = dotted(points(h, &h.friction_force), area.width);
    let y = bounds(h.normal_force.iter().chain(&h.friction_force).copied());
    let rev = reversals(h);
    let ticks: Vec<Vec<(f64, f64)>> = rev
        .iter()
        .map(|&t| {
            (0..=24)
                .map(|k| (t * 1e3, y[0] + (y[1] - y[0]) * f64::from(k) / 24.0))
                .collect()
        })
        .collect();
    let live = Style::default().fg(theme.current());
    let second = Style::default().fg(theme.secondary());
    let mut sets = vec![
        set(Some("━ F_n".into()), &fnp, live, true),
        set(Some("┄ F_t".into()), &ftp, second, false),
    ];
    for (i, (t, pts)) in rev.iter().zip(&ticks).enumerate() {
        let name = (i == 0).then(|| format!("┊ reversal {} ms", value(t * 1e3)));
        sets.push(set(name, pts, theme.measured(), false));
    }
    // the names in the title too: a small chart hides its legend
    let title = "Forces · ━ F_n ┄ F_t [N] vs t [ms]";
    time_chart(title, sets, (t_ms, y), area.width, theme).render(area, buf);
}

/// v_c = v_x − Rω in m/s against t in ms, the zero line dotted (the point sticks on it).
pub fn render_slip(r: &ObliqueResponse, theme: Theme, area: Rect, buf: &mut Buffer) {
    let Some(h) = &r.history else { return };
    let t_ms = r.contact_time * 1e3;
    let vc = points(h, &h.slip_velocity);
    let zero: Vec<(f64, f64)> = (0..=40)
        .map(|k| (t_ms * f64::from(k) / 40.0, 0.0))
        .collect();
    let y = bounds(h.slip_velocity.iter().copied().chain([0.0]));
    let sets = vec![
        set(
            Some("━ v_c".into()),
            &vc,
            Style::default().fg(theme.current()),
            true,
        ),
        set(None, &zero, theme.dim(), false),
    ];
    let title = "Slip · v_c [m/s] vs t [ms]";
    time_chart(title, sets, (t_ms, y), area.width, theme).render(area, buf);
}

/// ω in rad/s against t in ms.
pub fn render_spin(r: &ObliqueResponse, theme: Theme, area: Rect, buf: &mut Buffer) {
    let Some(h) = &r.history else { return };
    let t_ms = r.contact_time * 1e3;
    let w = points(h, &h.spin);
    let y = bounds(h.spin.iter().copied());
    let sets = vec![set(
        Some("━ ω".into()),
        &w,
        Style::default().fg(theme.current()),
        true,
    )];
    let title = "Spin · ω [rad/s] vs t [ms]";
    time_chart(title, sets, (t_ms, y), area.width, theme).render(area, buf);
}

/// The surface, the incoming path (ending at the contact, length 1) and the outgoing one
/// (length v_out/v_in), each labelled with its angle to the surface. Braille dots are about
/// square (a cell is 2 dots wide, 4 tall, twice as tall as wide), so equal units across and
/// up keep the angles true.
pub fn render_paths(r: &ObliqueResponse, theme: Theme, area: Rect, buf: &mut Buffer) {
    let block =
        Block::bordered().title(Span::styled("Paths · angles to the surface", theme.title()));
    let inner = block.inner(area);
    let (w, h) = (
        f64::from(inner.width.max(1)),
        f64::from(inner.height.max(1)),
    );
    let y_span = 1.25;
    let x_half = y_span * (2.0 * w) / (4.0 * h) / 2.0;
    let (a_in, a_out) = (r.angle_in_deg.to_radians(), r.angle_out_deg.to_radians());
    let out_len = (r.v_out / r.v_in).clamp(0.05, 1.0);
    // the longer path fits: scaled down when the window is narrow
    let reach = x_half.min(1.0) * 0.95;
    let (x_in, y_in) = (-reach * a_in.cos(), reach * a_in.sin());
    let (x_out, y_out) = (reach * out_len * a_out.cos(), reach * out_len * a_out.sin());
    let (live, second) = (theme.current(), theme.secondary());
    let ground = theme.c(Color::Gray);
    let (lab_in, lab_out) = (
        format!("in {}°", value(r.angle_in_deg)),
        format!("out {}°", value(r.angle_out_deg)),
    );
    let (t_in, t_out) = (theme.fg(live), theme.fg(second));
    Canvas::default()
        .block(block)
        .marker(Marker::Braille)
        .x_bounds([-x_half, x_half])
        .y_bounds([-0.1, y_span - 0.1])
        .paint(move |ctx| {
            ctx.draw(&CanvasLine::new(-x_half, 0.0, x_half, 0.0, ground));
            ctx.draw(&CanvasLine::new(x_in, y_in, 0.0, 0.0, live));
            ctx.draw(&CanvasLine::new(0.0, 0.0, x_out, y_out, second));
            // "in" at the top left, "out" under it at the right (a narrow canvas keeps both)
            let cell = 2.0 * x_half / w;
            let right = x_half - cell * (lab_out.chars().count() as f64 + 0.5);
            ctx.print(-x_half, y_span - 0.15, Span::styled(lab_in.clone(), t_in));
            ctx.print(
                right,
                y_span - 0.15 - 1.25 / h,
                Span::styled(lab_out.clone(), t_out),
            );
        })
        .render(area, buf);
}

#[cfg(test)]
mod tests {
    #[test]
    fn round_ticks_hold_the_data() {
        let (b, t) = super::round_axis([-157.0, 249.0], 40);
        assert_eq!(b, [-300.0, 300.0]);
        assert_eq!(t, ["-300", "-150", "0", "150", "300"]);
        let (b, t) = super::round_axis([0.0, 4.8], 40);
        assert_eq!(
            (b, t),
            (
                [0.0, 6.0],
                vec!["0".to_string(), "2".into(), "4".into(), "6".into()]
            )
        );
        let (b, t) = super::round_axis([-1.2, 25.2], 10);
        assert_eq!(
            (b, t),
            ([-10.0, 30.0], vec!["-10".to_string(), "30".into()])
        );
    }

    use super::reversals;
    use crate::oblique::ObliqueHistory;

    #[test]
    fn f_t_is_dotted_beside_solid_f_n() {
        // 400 samples on a chart 60 cells (120 dots) wide: a point every 10 samples, 40
        // points, three dots apart — a dotted line, where all 400 read as a solid one
        let pts: Vec<(f64, f64)> = (0..400).map(|i| (f64::from(i), 0.0)).collect();
        let d = super::dotted(pts.clone(), 60);
        assert_eq!(d.len(), 40);
        assert_eq!(d[1].0 - d[0].0, 10.0);
        assert!(super::dotted(pts[..20].to_vec(), 60).len() == 20);
    }

    #[test]
    fn a_reversal_is_where_the_friction_changes_sign() {
        let h = ObliqueHistory {
            t: vec![0.0, 1.0, 2.0, 3.0, 4.0],
            friction_force: vec![0.0, -2.0, -1.0, 3.0, 0.0],
            ..Default::default()
        };
        // from −1 at t = 2 to 3 at t = 3: zero at 2.25; the zeros at the ends are no reversal
        assert_eq!(reversals(&h), vec![2.25]);
        let none = ObliqueHistory {
            t: vec![0.0, 1.0, 2.0],
            friction_force: vec![0.0, -1.0, 0.0],
            ..Default::default()
        };
        assert!(reversals(&none).is_empty());
    }
}
