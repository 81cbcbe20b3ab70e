//! The paper's figures (docs/model.md §6) as [`Figure`]s, built from solver output: COR and
//! normalized peak force against ζ (Figs. 2, 3), COR against impact speed (Fig. 4), force
//! against time and against displacement (Figs. 5–8), each with the measured values of the
//! balls (Cross 1999, docs/model.md §7).
//!
//! Figs. 5–8 live in [`super::history`] and are re-exported here.
//!
//! The builders take computed data (sweep rows, an [`crate::solver::ImpactResponse`]) and return a figure, so
//! a caller that already holds a response (the explorer) draws it without re-solving.

use super::{Axis, BLACK, Corner, Figure, GREY, Kind, Look, Marker, Series, Style, Tone};
use crate::analysis::sweep::{VelocityPoint, ZetaPoint};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::SolveError;
use crate::solver::{SolveOptions, simulate};
use crate::text::short;

pub use super::history::{force_displacement, force_time};

pub use crate::ball::Ball;

/// Line styles and colours of successive model curves: style and colour both change, so the
/// curves stay apart in greyscale print too.
fn curve_style(i: usize) -> (Style, usize) {
    const STYLES: [Style; 3] = [Style::Solid, Style::Dashed, Style::Dotted];
    (STYLES[i % 3], i)
}

const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
];

/// The λ values of ζ-sweep rows, in order of first appearance.
fn lambdas(rows: &[ZetaPoint]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for r in rows {
        if !out.contains(&r.lambda) {
            out.push(r.lambda);
        }
    }
    out
}

/// Figs. 2 and 3 share everything but the quantity on the y axis.
fn zeta_figure(
    rows: &[ZetaPoint],
    balls: &[Ball],
    law: ContactLaw,
    title: &str,
    y: Axis,
    model: fn(&ZetaPoint) -> f64,
    measured: fn(&Ball) -> Option<f64>,
) -> Figure {
    let series = zeta_series(rows, balls, model, measured);
    let (lo, hi) = rows.iter().fold((f64::INFINITY, 0.0f64), |(a, b), r| {
        (a.min(r.zeta), b.max(r.zeta))
    });
    let at = if balls.is_empty() {
        String::new()
    } else {
        let first = balls[0].measured_label();
        let what = if balls.iter().all(|b| b.measured_label() == first) {
            first
        } else {
            "Cross 1999 or standard's mid-window"
        };
        format!("; markers: {what}, at the {} ζ", balls[0].source)
    };
    Figure::new(
        title.into(),
        format!("normalized ball, no flattening, {law} law{at}"),
        Axis::log("damping factor ζ (–)", "zeta", lo.min(hi), hi.max(lo)),
        y,
        series,
    )
}

/// One curve per λ (the i-th in the i-th reference tone on screen), then each ball's measured
/// value at its ζ (its initial on screen).
fn zeta_series(
    rows: &[ZetaPoint],
    balls: &[Ball],
    model: fn(&ZetaPoint) -> f64,
    measured: fn(&Ball) -> Option<f64>,
) -> Vec<Series> {
    let mut series = Vec::new();
    for (i, l) in lambdas(rows).into_iter().enumerate() {
        let (style, color) = curve_style(i);
        let pts = rows
            .iter()
            .filter(|r| r.lambda == l)
            .map(|r| (r.zeta, model(r)))
            .collect();
        series.push(
            Series::new(
                &format!("model, λ = {}", short(l, 3)),
                &format!("model lambda={}", short(l, 6)),
                Kind::Model,
                style,
                color,
            )
            .with_points(pts)
            .with_look(Look::new(
                Tone::Reference(i),
                Some(&format!("λ={}", short(l, 4))),
                None,
            )),
        );
    }
    let names: Vec<&str> = balls.iter().map(|b| b.name.as_str()).collect();
    let letters = marks(&names);
    for (i, b) in balls.iter().enumerate() {
        let Some(value) = measured(b) else { continue };
        let n = b.params.normalized();
        let mut s = Series::new(
            &format!("{} (λ = {})", b.name, short(n.lambda, 2)),
            &format!("measured {}", b.name),
            Kind::Measured,
            Style::Markers(MARKERS[i % MARKERS.len()]),
            BLACK,
        )
        .with_points(vec![(n.zeta, value)])
        .with_look(measured_look(&letters[i]));
        s.annotations = vec![b.name.clone()];
        series.push(s);
    }
    series
}

/// A ball's measured marker on screen, `letters` from [`initials`]: in the legend as
/// "S G B measured".
fn measured_look(letters: &str) -> Look {
    Look::new(Tone::Measured, Some("measured"), Some(letters))
}

/// The letter that marks a ball's measured point on screen: its name's initial.
pub fn initial(name: &str) -> String {
    name.chars()
        .next()
        .map_or("?".into(), |c| c.to_uppercase().collect())
}

/// The marks of several balls' measured points on screen, one per name and no two alike: the
/// initial when it is free ("S" superball), else the initials of the name's words ("SC"
/// superball-custom, "TT" table-tennis), else its first two letters ("So" softball), else the
/// initial and a number. A name of several words whose initial is another name's initial
/// takes its words' initials whatever the order: table tennis is "TT" beside tennis's "T",
/// never "T" beside "Te" (issue 51 item 6, `table_tennis_is_tt_in_any_order`).
pub fn initials(names: &[&str]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for (i, name) in names.iter().enumerate() {
        let shared = names
            .iter()
            .enumerate()
            .any(|(j, other)| j != i && initial(other) == initial(name));
        let words: String = name
            .split(|c: char| !c.is_alphanumeric())
            .filter_map(|w| w.chars().next())
            .flat_map(char::to_uppercase)
            .collect();
        let first_two: String = initial(name) + &name.chars().skip(1).take(1).collect::<String>();
        let numbered = (2..).map(|k| format!("{}{k}", initial(name)));
        let several_words = words.chars().count() > 1;
        let order = if shared && several_words {
            [words.clone(), initial(name), first_two]
        } else {
            [initial(name), words, first_two]
        };
        let mark = order
            .into_iter()
            .chain(numbered)
            .find(|m| !m.is_empty() && !out.contains(m))
            .unwrap_or_default();
        out.push(mark);
    }
    out
}

/// The marks of the balls `names` drawn: their [`initials`] among themselves and every
/// embedded preset's name after them, so that a ball has the mark docs/explorer.md gives it
/// whichever balls are drawn: table tennis is "TT" though tennis is not drawn beside it (the
/// explorer draws the paper's three balls and the one it started on).
pub fn marks(names: &[&str]) -> Vec<String> {
    let mut all = names.to_vec();
    let others = crate::preset::EMBEDDED.iter().map(|(n, _)| *n);
    all.extend(others.filter(|n| !names.contains(n)));
    let mut out = initials(&all);
    out.truncate(names.len());
    out
}

/// The COR axis, 0 … 1 with a sliver below 0 so that a COR of 0 (no rebound) shows as a
/// line rather than hiding in the frame.
fn cor_axis() -> Axis {
    Axis::linear("coefficient of restitution e (–)", "cor", 1.0).with_range(-0.02, 1.05)
}

/// Fig. 2: COR against ζ, one curve per λ, with the balls' measured COR at their ζ.
pub fn cor_zeta(rows: &[ZetaPoint], balls: &[Ball], law: ContactLaw) -> Figure {
    let mut fig = zeta_figure(
        rows,
        balls,
        law,
        "Coefficient of restitution against damping factor",
        cor_axis(),
        |r| r.cor,
        |b| b.measured.as_ref()?.cor,
    );
    fig.screen_title = format!("COR e vs ζ (log) · {law} law, no flattening");
    fig.legend_corner = Corner::BottomRight;
    fig
}

/// Fig. 3: normalized peak force F̄_m = F_m/(m v0 ω0) against ζ, with the balls' measured peak
/// force normalized by their own m, v0 and ω0 = √(K_p/m).
pub fn force_zeta(rows: &[ZetaPoint], balls: &[Ball], law: ContactLaw) -> Figure {
    let mut fig = zeta_figure(
        rows,
        balls,
        law,
        "Normalized peak force against damping factor",
        Axis::linear(
            "normalized peak force F̄m = Fm/(m v0 ω0) (–)",
            "max_force_normalized",
            1.0,
        )
        .with_range(0.0, 1.05),
        |r| r.max_force_normalized,
        |b| {
            let m = b.measured.as_ref()?;
            let p = &b.params;
            Some(m.max_force? / (p.mass * m.v0 * p.omega0()))
        },
    );
    fig.screen_title = format!("Normalized peak force Fm/(m v0 ω0) vs ζ (log) · {law} law");
    fig.legend_corner = Corner::BottomLeft;
    fig
}

/// The impact speed at which the peak indentation reaches `ratio` × z_p (`None` without a
/// finite z_p). Found by bisection on the solver's z_m, which grows with v0 for every law
/// (for the linear law z_m ∝ v0 exactly, since loading is linear).
pub fn speed_for_indentation(
    params: &ImpactParams,
    law: ContactLaw,
    ratio: f64,
) -> Result<Option<f64>, SolveError> {
    if !params.z_p.is_finite() {
        return Ok(None);
    }
    let target = ratio * params.z_p;
    let z_m = |v0: f64| -> Result<f64, SolveError> {
        let r = simulate(
            &ImpactParams { v0, ..*params },
            law,
            &SolveOptions::default(),
        )?;
        Ok(r.max_indentation)
    };
    let (mut lo, mut hi) = (params.v0, params.v0);
    for _ in 0..60 {
        if z_m(hi)? >= target {
            break;
        }
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..60 {
        if z_m(lo)? < target {
            break;
        }
        hi = lo;
        lo /= 2.0;
    }
    // a plot range needs three digits, not fifteen
    while hi / lo > 1.0 + 1e-4 {
        let mid = (lo * hi).sqrt();
        if z_m(mid)? < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(hi))
}

/// The speed `v` at which flattening starts, as a dotted line across the COR axis.
fn flattening_onset(v: f64) -> Series {
    Series::new(
        &format!("flattening starts, z_m = z_p ({} m/s)", short(v, 3)),
        "flattening_onset",
        Kind::Reference,
        Style::Dotted,
        GREY,
    )
    .with_points(vec![(v, 0.0), (v, 1.05)])
    .with_look(Look::new(Tone::Rule, None, Some("flattens")))
}

/// Fig. 4: COR against impact speed for one ball, with the flattening onset (z_m = z_p) and
/// the measured COR.
pub fn cor_velocity(ball: &Ball, rows: &[VelocityPoint], onset: Option<f64>) -> Figure {
    let mut series = vec![
        Series::new("model", "model", Kind::Model, Style::Solid, 0)
            .with_points(rows.iter().map(|r| (r.v0, r.cor)).collect())
            .with_look(Look::new(
                Tone::Current,
                Some(&format!("e(v0), {} law", ball.law)),
                None,
            )),
    ];
    let first = rows.first().map_or(0.0, |r| r.v0);
    let last = rows.last().map_or(1.0, |r| r.v0);
    // from 0 unless the sweep starts far from it
    let left = if first <= 0.25 * last { 0.0 } else { first };
    if let Some(v) = onset.filter(|&v| v <= last && ball.law != ContactLaw::Hertz) {
        series.push(flattening_onset(v));
    }
    if let Some((v, e)) = ball.measured.as_ref().and_then(|m| Some((m.v0, m.cor?))) {
        let mut s = Series::new(
            ball.measured_label(),
            "measured cor",
            Kind::Measured,
            Style::Markers(Marker::Circle),
            BLACK,
        )
        .with_points(vec![(v, e)])
        .with_look(measured_look(&initial(&ball.name)));
        s.annotations = vec![format!("e = {}", short(e, 3))];
        series.push(s);
    }
    let n = ball.params.normalized();
    let mut fig = Figure::new(
        format!(
            "Coefficient of restitution against impact speed: {}",
            ball.name
        ),
        format!(
            "{} (λ = {}, ζ = {}, z_p = {} mm)",
            ball.describe(),
            short(n.lambda, 3),
            short(n.zeta, 3),
            short(ball.params.z_p * 1e3, 3)
        ),
        Axis::linear("impact speed v0 (m/s)", "v0", 1.0).with_range(left, last),
        cor_axis(),
        series,
    );
    fig.screen_title = format!("COR e vs impact speed v0 [m/s] · {}", ball.name);
    fig.legend_corner = Corner::BottomLeft;
    fig
}

#[cfg(test)]
mod tests {
    use super::initials;

    /// Issue 51 item 6: table tennis is "TT" beside tennis in either order (it was "T" beside
    /// "Te" when it came first); a ball alone keeps its initial.
    #[test]
    fn table_tennis_is_tt_in_any_order() {
        assert_eq!(initials(&["table-tennis", "tennis"]), ["TT", "T"]);
        assert_eq!(initials(&["tennis", "table-tennis"]), ["T", "TT"]);
        assert_eq!(initials(&["superball", "superball-custom"]), ["S", "SC"]);
        assert_eq!(initials(&["softball", "softball-44"]), ["S", "S4"]);
        assert_eq!(initials(&["table-tennis"]), ["T"]);
    }

    /// A ball's mark does not depend on which others are drawn: table tennis beside the paper's
    /// three is "TT" (docs/explorer.md), their marks stay S, G, B.
    #[test]
    fn marks_are_the_same_whichever_balls_are_drawn() {
        let drawn = ["superball", "golf", "baseball", "table-tennis"];
        assert_eq!(super::marks(&drawn), ["S", "G", "B", "TT"]);
        assert_eq!(
            super::marks(&["superball", "golf", "baseball", "superball-custom"]),
            ["S", "G", "B", "SC"]
        );
        assert_eq!(super::marks(&["superball", "softball"]), ["S", "So"]);
    }
}
