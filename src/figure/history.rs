//! Figs. 5–8 of the paper: the contact force of one impact against time and against
//! displacement, drawn from the sampled history of an [`ImpactResponse`].

use super::{Axis, BLACK, Corner, Figure, GREY, Kind, Look, Marker, Series, Style, Tone};
use crate::ball::Ball;
use crate::model::contact::ContactLaw;
use crate::solver::ImpactResponse;
use crate::text::short;

/// "adopted parameters, linear law, v0 = 3.12 m/s (measured speed)"
fn at_speed(ball: &Ball, v0: f64) -> String {
    let measured = if ball.measured_at(v0).is_some() {
        " (measured speed)"
    } else {
        ""
    };
    format!("{}, v0 = {} m/s{measured}", ball.describe(), short(v0, 4))
}

/// A measured value drawn as a horizontal line from x0 to x1 at y.
fn measured_line(label: &str, id: &str, y: f64, x0: f64, x1: f64) -> Series {
    Series::new(label, id, Kind::Measured, Style::Dashed, BLACK)
        .with_points(vec![(x0, y), (x1, y)])
        .with_look(measured())
}

/// Measured values on screen: dotted, in the legend once as "┄ measured".
fn measured() -> Look {
    Look::new(Tone::Measured, Some("measured"), None)
}

/// Figs. 5, 7: force against time, with the measured peak force and contact time as reference
/// lines (at the measured speed only).
pub fn force_time(ball: &Ball, r: &ImpactResponse) -> Figure {
    let h = &r.history;
    let pts: Vec<(f64, f64)> = h.t.iter().copied().zip(h.force.iter().copied()).collect();
    let mut series = vec![
        Series::new("model", "model", Kind::Model, Style::Solid, 0)
            .with_points(pts)
            .with_look(Look::new(Tone::Current, Some("model"), None)),
    ];
    let t_end = r.duration;
    if let Some(m) = ball.measured_at(ball.params.v0) {
        let right = m.contact_time.map_or(t_end, |t| t_end.max(t));
        if let Some(f) = m.max_force {
            series.push(measured_line(
                &format!("measured peak force ({} N)", short(f, 4)),
                "measured max_force",
                f,
                0.0,
                right,
            ));
        }
        if let Some(t) = m.contact_time {
            let top = m.max_force.unwrap_or(0.0).max(r.max_force);
            series.push(
                Series::new(
                    &format!("measured contact time ({} ms)", short(t * 1e3, 3)),
                    "measured contact_time",
                    Kind::Measured,
                    Style::Dotted,
                    1,
                )
                .with_points(vec![(t, 0.0), (t, top)])
                .with_look(measured()),
            );
        }
    }
    let mut fig = Figure {
        series,
        ..frame(false, ball)
    };
    push_radius_note(&mut fig, ball, r);
    fig
}

/// The note of an impact `r` of `ball` past the ball's radius, as `run` warns of it
/// (`api::reach`): "outside the model's range: z_m 31.05 mm > radius 21.55 mm" (or the
/// centre's α_max), after a "; " the SVG may break the subtitle at. Nothing within the radius
/// or with no radius known. tests/figures/figure_radius.rs.
pub fn push_radius_note(fig: &mut Figure, ball: &Ball, r: &ImpactResponse) {
    let radius = ball.measured.as_ref().map_or(f64::NAN, |m| m.radius);
    if let Some(note) = radius_note(&ball.params, radius, r) {
        fig.subtitle.push_str(&format!("; {OUTSIDE}{note}"));
    }
}

/// The impact `r` of `params` past `radius` (m), in a figure's words (`api::reach`): "z_m
/// 31.05 mm > radius 21.55 mm", "centre's α_max 34.97 mm > radius 21.55 mm"; `None` within.
pub fn radius_note(
    params: &crate::model::params::ImpactParams,
    radius: f64,
    r: &ImpactResponse,
) -> Option<String> {
    let (z_m, t_f) = (r.max_indentation, r.duration);
    let reach = crate::api::reach(params, r.law, r.method, z_m, t_f, radius)?;
    Some(reach_words(&reach, radius))
}

/// A reach past `radius` (m) in a figure's words ([`radius_note`]).
fn reach_words(reach: &crate::api::Reach, radius: f64) -> String {
    use crate::api::Reach;
    let mm = |x: f64| crate::text::sig(x * 1e3, 4);
    match reach {
        Reach::Indentation(z) => format!("z_m {} mm > radius {} mm", mm(*z), mm(radius)),
        Reach::Displacement(a) => {
            format!("centre's α_max {} mm > radius {} mm", mm(*a), mm(radius))
        }
        Reach::Unchecked(_) => format!("α_max not checked against radius {} mm", mm(radius)),
    }
}

/// The note of a speed sweep of `ball` (`rows` in rising speed: Fig. 4) whose impacts pass
/// the ball's radius from some speed on, as `sweep velocity` warns of each row: "; outside
/// the model's range from v0 = 45.2 m/s: z_m 21.6 mm > radius 21.55 mm", at the first such
/// row. Nothing when every row is within, or with no radius known. tests/figures/figure_radius.rs.
pub fn push_speed_radius_note(
    fig: &mut Figure,
    ball: &Ball,
    rows: &[crate::analysis::sweep::VelocityPoint],
) {
    let radius = ball.measured.as_ref().map_or(f64::NAN, |m| m.radius);
    let method = match ball.law {
        ContactLaw::Linear => crate::solver::Method::Exact,
        _ => crate::solver::Method::Numeric,
    };
    let first = rows.iter().find_map(|row| {
        let p = crate::model::params::ImpactParams {
            v0: row.v0,
            ..ball.params
        };
        let t_f = row.contact_time.unwrap_or(f64::INFINITY);
        let reach = crate::api::reach(&p, ball.law, method, row.max_indentation, t_f, radius)?;
        Some((row.v0, reach))
    });
    if let Some((v0, reach)) = first {
        let outside = OUTSIDE.trim_end_matches(": ");
        let words = reach_words(&reach, radius);
        fig.subtitle.push_str(&format!(
            "; {outside} from v0 = {} m/s: {words}",
            short(v0, 4)
        ));
    }
}

/// How a figure's subtitle begins its note of an impact past the ball's radius
/// ([`push_radius_note`]); a figure of several balls keeps each ball's (`cli::figure::balls`).
pub const OUTSIDE: &str = "outside the model's range: ";

/// Figs. 5–8 without data: titles and axes, for a chart whose impact could not be computed.
/// `displacement`: force against displacement (Figs. 6, 8), else against time (5, 7).
pub fn frame(displacement: bool, ball: &Ball) -> Figure {
    let (what, x, screen_title, corner) = if displacement {
        (
            "displacement",
            Axis::linear("indentation z, displacement α (mm)", "displacement", 1e3),
            "Force–displacement · F [N] vs α, z [mm]",
            Corner::TopLeft,
        )
    } else {
        (
            "time",
            Axis::linear("time t (ms)", "t", 1e3),
            "Force–time · F [N] vs t [ms]",
            Corner::TopRight,
        )
    };
    let mut fig = Figure::new(
        format!("Contact force against {what}: {}", ball.name),
        at_speed(ball, ball.params.v0),
        x,
        Axis::linear("contact force F (N)", "force", 1.0),
        Vec::new(),
    );
    fig.screen_title = screen_title.into();
    fig.legend_corner = corner;
    fig
}

/// The force on the loading branch where the indentation first reaches `z` (the sample at or
/// just past it): where the flattening-threshold line meets the curve.
fn force_at(indentation: &[f64], force: &[f64], z: f64) -> f64 {
    indentation
        .iter()
        .position(|&x| x >= z)
        .and_then(|i| force.get(i).copied())
        .unwrap_or(0.0)
}

/// Figs. 6, 8: force against the contact indentation z (the contact law's loading and
/// unloading branches; the permanent indentation z_f once the ball flattens) and against the
/// ball's displacement α, whose loop encloses the energy the impact lost.
pub fn force_displacement(ball: &Ball, r: &ImpactResponse) -> Figure {
    let h = &r.history;
    let with_force =
        |v: &[f64]| -> Vec<(f64, f64)> { v.iter().copied().zip(h.force.iter().copied()).collect() };
    let mut series = vec![
        Series::new(
            "contact indentation z",
            "model indentation",
            Kind::Model,
            Style::Solid,
            0,
        )
        .with_points(with_force(&h.indentation))
        .with_look(Look::new(Tone::Secondary, Some("contact z"), None)),
        Series::new(
            "ball displacement α",
            "model displacement",
            Kind::Model,
            Style::Dashed,
            2,
        )
        .with_points(with_force(&h.displacement))
        .with_look(Look::new(Tone::Current, Some("ball α"), None)),
    ];
    let right = h
        .displacement
        .iter()
        .chain(&h.indentation)
        .fold(0.0f64, |a, &b| a.max(b));
    series.extend(flattening(ball, r, right));
    if let Some(f) = ball.measured_at(ball.params.v0).and_then(|m| m.max_force) {
        series.push(measured_line(
            &format!("measured peak force ({} N)", short(f, 4)),
            "measured max_force",
            f,
            0.0,
            right,
        ));
    }
    let mut fig = frame(true, ball);
    let (z_m, z_p) = (r.max_indentation, ball.params.z_p);
    if ball.law != ContactLaw::Hertz {
        fig.subtitle
            .push_str(&format!("; {}", flattening_note(z_m, z_p)));
    }
    fig.series = series;
    push_radius_note(&mut fig, ball, r);
    fig
}

/// Whether the ball flattened, with z_m and z_p (m) in mm: "no flattening: z_m = 0.383 mm <
/// z_p = 3 mm". Three significant digits, more where three would print the two equal, so
/// that the sign between them holds for the numbers shown ("z_m = 3.996 mm < z_p = 4 mm",
/// not "4 mm < 4 mm"; `bouncelab run` prints 3.996); "≈" for a z_m equal to z_p to nine.
fn flattening_note(z_m: f64, z_p: f64) -> String {
    let (a, b) = (3..=9)
        .map(|d| (short(z_m * 1e3, d), short(z_p * 1e3, d)))
        .find(|(a, b)| a != b)
        .unwrap_or_else(|| (short(z_m * 1e3, 9), short(z_p * 1e3, 9)));
    let word = if z_m > z_p {
        "flattened"
    } else {
        "no flattening"
    };
    let cmp = match (z_m > z_p, a == b) {
        (_, true) => "≈",
        (true, false) => ">",
        (false, false) => "<",
    };
    format!("{word}: z_m = {a} mm {cmp} z_p = {b} mm")
}

/// The flattening threshold z_p up to where it meets the loading curve, when it falls inside
/// the picture (otherwise the subtitle says it), and the permanent indentation z_f once the
/// ball flattened.
fn flattening(ball: &Ball, r: &ImpactResponse, right: f64) -> Vec<Series> {
    let (h, z_p) = (&r.history, ball.params.z_p);
    let mut series = Vec::new();
    let zp_shown = ball.law != ContactLaw::Hertz && z_p <= right;
    if zp_shown {
        series.push(
            Series::new(
                &format!("flattening threshold z_p ({} mm)", short(z_p * 1e3, 3)),
                "flattening_threshold",
                Kind::Reference,
                Style::Dotted,
                GREY,
            )
            .with_points(vec![
                (z_p, 0.0),
                (z_p, force_at(&h.indentation, &h.force, z_p)),
            ])
            .with_look(Look::new(Tone::Rule, None, Some("z_p"))),
        );
    }
    if r.permanent_indentation > 1e-6 * r.max_indentation {
        let z_f = r.permanent_indentation;
        let mut s = Series::new(
            &format!("permanent indentation z_f ({} mm)", short(z_f * 1e3, 3)),
            "model permanent_indentation",
            Kind::Model,
            Style::Markers(Marker::Diamond),
            1,
        )
        .with_points(vec![(z_f, 0.0)])
        .with_look(Look::new(
            Tone::Highlight,
            None,
            Some(&format!("▲z_f {} mm", short(z_f * 1e3, 3))),
        ));
        s.annotations = vec!["z_f".into()];
        series.push(s);
    }
    series
}
