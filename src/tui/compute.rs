//! The numbers behind the charts, computed with the library (`simulate`, `cor_vs_zeta`) when
//! the state changes — never while drawing. SI units throughout. The sweeps view's COR
//! against speed is [`crate::tui::views::sweeps::speed`].

use crate::analysis::sweep::{ZetaPoint, cor_vs_zeta, log_space};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{ImpactResponse, SolveOptions, simulate};
use std::sync::OnceLock;

/// History samples of one impact (force–time, force–displacement).
pub const HISTORY_SAMPLES: usize = 400;
/// The ζ sweeps run over 1e-3 … 1e3 (the whole accepted range), 20 points per decade.
pub const ZETA_SWEEP: (f64, f64, usize) = (1e-3, 1e3, 121);
/// The fixed curves of Fig. 2: they depend on λ alone, not on the ball.
pub const REFERENCE_LAMBDAS: [f64; 3] = [0.0, 0.4, 1.0];

/// COR and F̄_m against ζ for one λ (linear law, no flattening: Figs. 2, 3).
#[derive(Debug, Clone, PartialEq)]
pub struct ZetaCurve {
    pub lambda: f64,
    pub points: Vec<ZetaPoint>,
}

/// One impact with its history and energy budget (the budget `run` prints: the same solver
/// options but the number of samples).
pub fn impact(params: &ImpactParams, law: ContactLaw) -> Result<ImpactResponse, String> {
    simulate(
        params,
        law,
        &SolveOptions::default()
            .with_samples(HISTORY_SAMPLES)
            .with_energy(),
    )
    .map_err(|e| e.to_string())
}

/// The λ = 0, 0.4, 1 curves, computed once per process.
pub fn reference_curves() -> &'static [ZetaCurve] {
    static CURVES: OnceLock<Vec<ZetaCurve>> = OnceLock::new();
    CURVES.get_or_init(|| {
        REFERENCE_LAMBDAS
            .iter()
            .map(|&l| sweep_zeta(l).expect("the reference λ are valid"))
            .collect()
    })
}

fn sweep_zeta(lambda: f64) -> Result<ZetaCurve, String> {
    let (lo, hi, n) = ZETA_SWEEP;
    let points = cor_vs_zeta(&[lambda], &log_space(lo, hi, n), ContactLaw::Linear)
        .map_err(|e| e.to_string())?;
    Ok(ZetaCurve { lambda, points })
}

/// The ζ curve for `lambda`, reusing a reference curve when λ is one of them.
pub fn zeta_curve(lambda: f64) -> Result<ZetaCurve, String> {
    match reference_curves().iter().find(|c| c.lambda == lambda) {
        Some(c) => Ok(c.clone()),
        None => sweep_zeta(lambda),
    }
}
