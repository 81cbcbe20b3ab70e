//! `fit --plot`: the data with the fitted model, and the residuals under them, as one SVG
//! (two figures of the shared SVG renderer, stacked). The user's data are labelled by their
//! file name.

use super::Loaded;
use crate::analysis::fit::MultiFit;
use crate::analysis::sweep::lin_space;
use crate::api::Ball;
use crate::cli::output::human;
use crate::figure::{Axis, BLACK, Figure, Kind, Marker, Series, Style, svg};
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};

/// Points along the model's COR-against-speed curve.
const CURVE_POINTS: usize = 120;

/// The ball and law, then each fitted value with its 95 % interval as the text report gives
/// them (value to 5 digits, its unit, the interval to 4; an exact solve's words in its place),
/// "; " between them, where the SVG may break the subtitle (`figure::svg`).
fn subtitle(ball: &Ball, f: &MultiFit, speeds: &[f64]) -> String {
    let fitted: Vec<String> = f
        .fitted
        .iter()
        .map(|e| {
            let interval = if f.exact() {
                super::report_text::exact_text(f).to_string()
            } else {
                format!("95 %: {}", super::report_text::interval(e))
            };
            format!("{} = {} {} ({interval})", e.name, human(e.value, 5), e.unit)
        })
        .collect();
    format!(
        "{}, {} law; fitted {}{}",
        ball.name.as_deref().unwrap_or("ball"),
        ball.law,
        fitted.join("; "),
        radius_note(ball, f, speeds)
    )
}

/// "; outside the model's range at v0 = 45 m/s: z_m 32.81 mm > radius 21.55 mm": the fitted
/// ball at the fastest of the data's `speeds` past its radius, as the report's warning
/// (`Ball::fitted_warnings`) says (`figure::history::radius_note`); empty within.
fn radius_note(ball: &Ball, f: &MultiFit, speeds: &[f64]) -> String {
    let v0 = speeds.iter().copied().fold(f64::NAN, f64::max);
    let p = ImpactParams { v0, ..f.params };
    let note = simulate(&p, ball.law, &SolveOptions::default())
        .ok()
        .and_then(|r| crate::figure::history::radius_note(&p, ball.radius(), &r));
    note.map_or(String::new(), |n| {
        let outside = crate::figure::history::OUTSIDE.trim_end_matches(": ");
        format!("; {outside} at v0 = {} m/s: {n}", crate::text::number(v0))
    })
}

/// The user's data as markers, labelled by `label` (the file name).
fn data_series(label: &str, id: &str, points: Vec<(f64, f64)>) -> Series {
    Series::new(
        label,
        id,
        Kind::Measured,
        Style::Markers(Marker::Circle),
        BLACK,
    )
    .with_points(points)
}

/// The residuals figure under the data: measured − model against the data's x.
fn residuals(x: Axis, y_label: &str, label: &str, rms: String, points: Vec<(f64, f64)>) -> Figure {
    Figure::new(
        "Residuals: measured − model".into(),
        rms,
        x,
        Axis::linear(y_label, "residual", 1.0),
        vec![data_series(label, "residual", points)],
    )
}

/// (data and model, residuals) for a trace.
fn trace_figures(ball: &Ball, data: &Loaded, f: &MultiFit) -> Option<(Figure, Figure)> {
    let t = data.trace.as_ref()?;
    let over_time =
        |y: &[f64]| -> Vec<(f64, f64)> { t.time.iter().copied().zip(y.iter().copied()).collect() };
    let (measured, model) = (over_time(&t.force), over_time(&f.model));
    let resid: Vec<(f64, f64)> = t
        .time
        .iter()
        .zip(t.force.iter().zip(&f.model))
        .map(|(&x, (d, m))| (x, d - m))
        .collect();
    let top = Figure::new(
        format!("Force against time: {}", data.label),
        subtitle(ball, f, &[f.params.v0]),
        Axis::linear("t (ms)", "t", 1e3),
        Axis::linear("F (N)", "force", 1.0),
        vec![
            data_series(&data.label, "measured", measured),
            Series::new("model (fitted)", "model", Kind::Model, Style::Solid, 0).with_points(model),
        ],
    );
    let rms = format!(
        "rms {} N over {} points",
        crate::text::short(f.rms_residual, 3),
        f.points
    );
    let x = Axis::linear("t (ms)", "t", 1e3);
    let bottom = residuals(x, "F − model (N)", &data.label, rms, resid);
    Some((top, bottom))
}

/// (data and model, residuals) for COR against speed.
fn cor_figures(
    ball: &Ball,
    data: &Loaded,
    f: &MultiFit,
    p: &ImpactParams,
) -> anyhow::Result<(Figure, Figure)> {
    let speeds: Vec<f64> = data.points.iter().map(|q| q.v0).collect();
    let lo = speeds.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = speeds.iter().cloned().fold(0.0, f64::max);
    let curve: Vec<(f64, f64)> = lin_space(0.5 * lo, 1.2 * hi, CURVE_POINTS)
        .into_iter()
        .filter_map(|v0| {
            let r = simulate(
                &ImpactParams { v0, ..*p },
                ball.law,
                &SolveOptions::default(),
            )
            .ok()?;
            Some((v0, r.cor))
        })
        .collect();
    let measured: Vec<(f64, f64)> = data.points.iter().map(|q| (q.v0, q.cor)).collect();
    let resid: Vec<(f64, f64)> = data
        .points
        .iter()
        .zip(&f.model)
        .map(|(q, m)| (q.v0, q.cor - m))
        .collect();
    let top = Figure::new(
        format!("COR against impact speed: {}", data.label),
        subtitle(ball, f, &speeds),
        Axis::linear("v0 (m/s)", "v0", 1.0),
        Axis::linear("COR e", "cor", 1.0),
        vec![
            Series::new("model (fitted)", "model", Kind::Model, Style::Solid, 0).with_points(curve),
            data_series(&data.label, "measured", measured),
        ],
    );
    let rms = format!(
        "rms {} over {} points",
        crate::text::short(f.rms_residual, 3),
        data.points.len()
    );
    let x = Axis::linear("v0 (m/s)", "v0", 1.0);
    let bottom = residuals(x, "e − model", &data.label, rms, resid);
    Ok((top, bottom))
}

/// Two rendered figures stacked in one SVG document (nested `<svg>` elements).
fn stack(top: &str, bottom: &str) -> String {
    let size = |s: &str, key: &str| -> f64 {
        s.split(&format!("{key}=\""))
            .nth(1)
            .and_then(|r| r.split('"').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or(0.0)
    };
    let (w, h1, h2) = (
        size(top, "width"),
        size(top, "height"),
        size(bottom, "height"),
    );
    let bottom = bottom.replacen("<svg ", &format!("<svg y=\"{h1}\" "), 1);
    format!(
        "<svg width=\"{w}\" height=\"{}\" viewBox=\"0 0 {w} {}\" xmlns=\"http://www.w3.org/2000/svg\">\n{top}\n{bottom}\n</svg>\n",
        h1 + h2,
        h1 + h2
    )
}

pub fn svg(ball: &Ball, data: &Loaded, f: &MultiFit, p: &ImpactParams) -> anyhow::Result<String> {
    let (top, bottom) = match trace_figures(ball, data, f) {
        Some(figs) => figs,
        None => cor_figures(ball, data, f, p)?,
    };
    // a figure that cannot be drawn is not the input's fault: exit 1 (cli::exit_code)
    // both plots start at one x: each takes the wider of the two label areas (the
    // residuals' "-0.0005" is wider than the COR's "0.6")
    let left = svg::label_area(&top).max(svg::label_area(&bottom));
    let render = |fig: &Figure| {
        crate::cli::budget::stop_if_interrupted()?;
        svg::render_aligned(fig, left).map_err(anyhow::Error::from)
    };
    Ok(stack(&render(&top)?, &render(&bottom)?))
}
