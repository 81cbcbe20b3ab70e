//! The field's contact models calibrated to one ball, drawn beside the Christoforou–Yigit
//! model (docs/peers.md): COR against impact speed on a log axis, and force against time at
//! v0. Built from solver output like [`super::paper`]; nothing here touches files.

use super::{Axis, BLACK, Corner, Figure, GREY, Kind, Marker, Series, Style};
use crate::analysis::sweep::cor_vs_velocity;
use crate::ball::Ball;
use crate::model::params::ImpactParams;
use crate::peers::calibrate::{self, christoforou_yigit_cor};
use crate::peers::{PeerBall, PeerError, PeerModel, cor, impact};
use crate::solver::{SolveOptions, simulate};
use crate::text::short;

/// Why a figure could not be built (a calibration or a solve failed), as one line.
fn error(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// Line style and colour of the k-th model: style and colour both change (greyscale print).
fn style(k: usize) -> (Style, usize) {
    const STYLES: [Style; 3] = [Style::Solid, Style::Dashed, Style::Dotted];
    (STYLES[k % 3], k + 1)
}

fn peer_ball(b: &Ball) -> PeerBall {
    PeerBall::from_params(&b.params, b.measured.as_ref().map_or(1.0, |m| m.radius))
}

/// COR against impact speed, `speeds` log-spaced: the Christoforou–Yigit curve, each peer
/// calibrated exactly to `target` at the ball's v0 (flat: their COR does not depend on v0),
/// and Hunt–Crossley with its damping kept as the material constant α = χ/v0 of that
/// calibration (falls with speed: the calibration holds at v0 only).
pub fn cor_velocity(b: &Ball, target: f64, speeds: &[f64]) -> Result<Figure, String> {
    let ball = peer_ball(b);
    // the Christoforou–Yigit impacts whole (the COR is christoforou_yigit_cor's, one
    // simulate each), so that the curve past the radius can say so (push_speed_radius_note)
    let rows = cor_vs_velocity(&b.params, b.law, speeds).map_err(error)?;
    let cy: Vec<(f64, f64)> = rows.iter().map(|r| (r.v0, r.cor)).collect();
    let mut series = vec![
        Series::new(
            "Christoforou–Yigit",
            "christoforou-yigit",
            Kind::Model,
            Style::Solid,
            0,
        )
        .with_points(cy),
    ];
    for (k, model) in PeerModel::ALL.into_iter().enumerate() {
        let d = calibrate::exact(model, target).map_err(error)?;
        let e = cor(model, d).map_err(error)?;
        let (st, c) = style(k);
        series.push(
            Series::new(
                &format!("{model} (exact)"),
                model.name(),
                Kind::Model,
                st,
                c,
            )
            .with_points(speeds.iter().map(|&v| (v, e)).collect()),
        );
    }
    let chi = calibrate::exact(PeerModel::HuntCrossley, target).map_err(error)?;
    let alpha = chi / ball.v0;
    let fixed: Vec<(f64, f64)> = speeds
        .iter()
        .map(|&v| cor(PeerModel::HuntCrossley, alpha * v).map(|e| (v, e)))
        .collect::<Result<_, PeerError>>()
        .map_err(error)?;
    series.push(
        Series::new(
            &format!("hunt-crossley, fixed α = χ/v0 = {} s/m", short(alpha, 3)),
            "hunt-crossley-fixed-alpha",
            Kind::Model,
            Style::Dashed,
            GREY,
        )
        .with_points(fixed),
    );
    if let Some((v, e)) = b.measured.as_ref().and_then(|m| Some((m.v0, m.cor?))) {
        series.push(
            Series::new(
                b.measured_label(),
                "measured cor",
                Kind::Measured,
                Style::Markers(Marker::Circle),
                BLACK,
            )
            .with_points(vec![(v, e)]),
        );
    }
    let (lo, hi) = (speeds[0], speeds[speeds.len() - 1]);
    let mut fig = Figure::new(
        format!(
            "Contact models calibrated to e = {}: {}",
            short(target, 3),
            b.name
        ),
        format!(
            "COR against impact speed; peers calibrated at v0 = {} m/s",
            short(ball.v0, 3)
        ),
        Axis::log("impact speed v0 (m/s)", "v0", lo, hi),
        Axis::linear("coefficient of restitution e", "cor", 1.0).with_range(0.0, 1.05),
        series,
    );
    fig.screen_title = format!("peers: COR e vs v0 [m/s] · {}", b.name);
    fig.legend_corner = Corner::BottomLeft;
    super::history::push_speed_radius_note(&mut fig, b, &rows);
    Ok(fig)
}

/// Force against time at the ball's v0: the Christoforou–Yigit impact and each peer
/// calibrated exactly to `target`, `samples` points each.
pub fn force_time(b: &Ball, target: f64, samples: usize) -> Result<Figure, String> {
    let ball = peer_ball(b);
    let opts = SolveOptions::default().with_samples(samples);
    let r = simulate(&b.params, b.law, &opts).map_err(error)?;
    let mut series = vec![history("Christoforou–Yigit", "christoforou-yigit", 0, &r)];
    for (k, model) in PeerModel::ALL.into_iter().enumerate() {
        let d = calibrate::exact(model, target).map_err(error)?;
        let r = impact(model, &ball, ball.damping_si(model, d), samples).map_err(error)?;
        let (st, c) = style(k);
        let mut s = history(&format!("{model} (exact)"), model.name(), c, &r);
        s.style = st;
        series.push(s);
    }
    let mut fig = Figure::new(
        format!("Contact force against time: {}", b.name),
        format!(
            "v0 = {} m/s; peers calibrated exactly to e = {}",
            short(ball.v0, 3),
            short(target, 3)
        ),
        Axis::linear("time t (ms)", "t", 1e3),
        Axis::linear("contact force F (N)", "force", 1.0),
        series,
    );
    fig.screen_title = format!("peers: F [N] vs t [ms] · {}", b.name);
    super::history::push_radius_note(&mut fig, b, &r);
    Ok(fig)
}

fn history(label: &str, id: &str, color: usize, r: &crate::ImpactResponse) -> Series {
    let h = &r.history;
    Series::new(label, id, Kind::Model, Style::Solid, color)
        .with_points(h.t.iter().copied().zip(h.force.iter().copied()).collect())
}

/// The target of both figures: the measured COR when the ball has one at its v0 and
/// `is_measured` (no condition or override changed the ball: `peers`'s rule, docs/peers.md),
/// else the Christoforou–Yigit model's COR there.
pub fn target(b: &Ball, is_measured: bool) -> Result<f64, String> {
    let measured = b.measured_at(b.params.v0).filter(|_| is_measured);
    match measured.and_then(|m| m.cor) {
        Some(e) => Ok(e),
        None => christoforou_yigit_cor(&b.params, b.law, b.params.v0).map_err(error),
    }
}

/// The default speeds of [`cor_velocity`]: v0/10 … 10 v0.
pub fn default_range(params: &ImpactParams) -> (f64, f64) {
    (0.1 * params.v0, 10.0 * params.v0)
}
