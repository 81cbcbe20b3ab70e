//! The oblique view's charts, drawn from its impact's history: F_n and F_t against time with
//! the friction's reversals marked, v_c and ω against time (figures drawn by the explorer's
//! plot widget), and the incoming and outgoing paths over the surface with their angles (a
//! ratatui `Canvas`). Each legend names its line's look, so it reads without colour (NO_COLOR).

use crate::figure::{Figure, GREY, Look, Role, Series, Style as Stroke, Tone};
use crate::oblique::{ObliqueHistory, ObliqueResponse};
use crate::tui::format::value;
use crate::tui::theme::Theme;
use crate::tui::widgets::plot::Plot;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine};
use ratatui::widgets::{Block, Widget};

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

/// The oblique view's time charts as figures (the ones `e` exports, src/tui/views/oblique/
/// export.rs, with their terminal looks): F_n and F_t with each reversal of F_t a dotted
/// vertical line named with its time, v_c with its zero line, ω. Drawn by the explorer's one
/// plot widget (`widgets::plot`), so their ticks are the other charts' (`figure::ticks`), each
/// label at its value's column (tests/tui/tui_ticks.rs); ratatui's `Chart` spread its labels
/// evenly whatever their values.
pub fn time_figures(r: &ObliqueResponse) -> Option<[Figure; 3]> {
    let h = r.history.as_ref()?;
    let mut figs = super::export::figures(r, "")?.into_iter().map(|(_, f)| f);
    let (mut forces, mut slip, mut spin) = (figs.next()?, figs.next()?, figs.next()?);
    let key = |s: &mut Series, tone: Tone, key: &str| s.look = Look::new(tone, Some(key), None);
    key(&mut forces.series[0], Tone::Current, "F_n");
    key(&mut forces.series[1], Tone::Secondary, "F_t");
    let (lo, hi) = h
        .normal_force
        .iter()
        .chain(&h.friction_force)
        .fold((0.0_f64, 0.0_f64), |(a, b), &v| (a.min(v), b.max(v)));
    for (i, t) in reversals(h).into_iter().enumerate() {
        let name = format!("reversal {} ms", value(t * 1e3));
        // dashed, where F_t is dotted: the legend's samples tell them apart without colour
        let line = Series::new(&name, "reversal", Role::Model, Stroke::Dashed, GREY)
            .with_points(vec![(t, lo), (t, hi)])
            .with_look(Look::new(Tone::Measured, (i == 0).then_some(&*name), None));
        forces.series.push(line);
    }
    forces.screen_title = "Forces · F_n F_t [N] vs t [ms]".into();
    key(&mut slip.series[0], Tone::Current, "v_c");
    let t_end = h.t.last().copied().unwrap_or(0.0);
    slip.series.push(
        Series::new("0", "zero", Role::Reference, Stroke::Dotted, GREY)
            .with_points(vec![(0.0, 0.0), (t_end, 0.0)])
            .with_look(Look::new(Tone::Ghost, None, None)),
    );
    slip.screen_title = "Slip · v_c [m/s] vs t [ms]".into();
    key(&mut spin.series[0], Tone::Current, "ω");
    spin.screen_title = "Spin · ω [rad/s] vs t [ms]".into();
    Some([forces, slip, spin])
}

/// One of [`time_figures`] in `area`.
pub fn render_time(fig: &Figure, theme: Theme, area: Rect, buf: &mut Buffer) {
    (&Plot::new(fig, theme)).render(area, buf);
}

/// The surface, the incoming path (ending at the contact, length 1) and the outgoing one
/// (length v_out/v_in), each labelled with its angle to the surface. Braille dots are about
/// square (a cell is 2 dots wide, 4 tall, twice as tall as wide), so equal units across and
/// up keep the angles true.
pub fn render_paths(r: &ObliqueResponse, theme: Theme, area: Rect, buf: &mut Buffer) {
    let title = crate::tui::widgets::title::framed("Paths · angles to the surface", area.width);
    let block = Block::bordered().title(Span::styled(title, theme.title()));
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
    use super::reversals;
    use crate::oblique::ObliqueHistory;

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
