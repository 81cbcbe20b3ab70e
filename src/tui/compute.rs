//! The numbers behind the charts, computed with the library (`simulate`, `cor_vs_zeta`,
//! `cor_vs_velocity`) when the state changes — never while drawing. SI units throughout.

use super::format::nice_ceil;
use crate::analysis::sweep::{
    VelocityPoint, ZetaPoint, cor_vs_velocity, cor_vs_zeta, lin_space, log_space,
};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{ImpactResponse, SolveOptions, simulate, simulate_normalized};
use std::sync::OnceLock;

/// History samples of one impact (force–time, force–displacement).
pub const HISTORY_SAMPLES: usize = 400;
/// The ζ sweeps run over 1e-3 … 1e3 (the whole accepted range), 20 points per decade.
pub const ZETA_SWEEP: (f64, f64, usize) = (1e-3, 1e3, 121);
/// The fixed curves of Fig. 2: they depend on λ alone, not on the ball.
pub const REFERENCE_LAMBDAS: [f64; 3] = [0.0, 0.4, 1.0];
/// Points of the COR-vs-speed sweep.
pub const SPEED_POINTS: usize = 40;

/// COR and F̄_m against ζ for one λ (linear law, no flattening: Figs. 2, 3).
#[derive(Debug, Clone, PartialEq)]
pub struct ZetaCurve {
    pub lambda: f64,
    pub points: Vec<ZetaPoint>,
}

/// COR against impact speed for one ball (Fig. 4).
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedCurve {
    /// The sweep runs over (0, v_max] (m/s).
    pub v_max: f64,
    /// Speed at which the linear law starts to flatten (m/s), when the ball can flatten.
    pub v_flat: Option<f64>,
    pub points: Vec<VelocityPoint>,
    /// What it was computed for: the parameters (v0 ignored) and the law.
    key: (ImpactParams, ContactLaw),
}

/// One impact with its history.
pub fn impact(params: &ImpactParams, law: ContactLaw) -> Result<ImpactResponse, String> {
    simulate(
        params,
        law,
        &SolveOptions::default().with_samples(HISTORY_SAMPLES),
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

/// Speed at which the ball starts to flatten under the linear law. Below flattening the peak
/// indentation scales with v0 (z_m = z̄_m(λ, ζ) v0/ω0, MODEL.md §5), so z_m = z_p at
/// v = z_p ω0 / z̄_m. `None` when the ball cannot flatten (z_p = ∞).
pub fn flattening_speed(params: &ImpactParams) -> Option<f64> {
    if !params.z_p.is_finite() {
        return None;
    }
    let n = params.normalized();
    let r = simulate_normalized(
        n.lambda,
        n.zeta,
        ContactLaw::Linear,
        &SolveOptions::default(),
    )
    .ok()?;
    let v = params.z_p * params.omega0() / r.max_indentation;
    (v.is_finite() && v > 0.0).then_some(v)
}

impl SpeedCurve {
    /// The sweep up to a speed that shows the flattening drop, the measured speed and the current
    /// one: v_max = max(2.5 v_flat, 1.5 v_measured, 1.2 v0), rounded up, at most 100 m/s.
    pub fn compute(
        params: &ImpactParams,
        law: ContactLaw,
        measured_v0: f64,
    ) -> Result<SpeedCurve, String> {
        let (v_max, v_flat) = Self::range(params, measured_v0);
        let speeds = lin_space(v_max / SPEED_POINTS as f64, v_max, SPEED_POINTS);
        let points = cor_vs_velocity(params, law, &speeds).map_err(|e| e.to_string())?;
        Ok(SpeedCurve {
            v_max,
            v_flat,
            points,
            key: (
                ImpactParams {
                    v0: v_max,
                    ..*params
                },
                law,
            ),
        })
    }

    /// (v_max, v_flat) for these parameters.
    fn range(params: &ImpactParams, measured_v0: f64) -> (f64, Option<f64>) {
        let v_flat = flattening_speed(params);
        let want = [
            2.5 * v_flat.unwrap_or(0.0),
            1.5 * measured_v0,
            1.2 * params.v0,
        ]
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
        (nice_ceil(want).min(100.0), v_flat)
    }

    /// Whether this curve is the one `compute` would give for these inputs (v0 matters only
    /// through v_max). Costs one exact linear run.
    pub fn is_for(&self, params: &ImpactParams, law: ContactLaw, measured_v0: f64) -> bool {
        let (v_max, _) = Self::range(params, measured_v0);
        self.key
            == (
                ImpactParams {
                    v0: v_max,
                    ..*params
                },
                law,
            )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Preset;

    #[test]
    fn flattening_speed_is_where_z_m_reaches_z_p() {
        let p = Preset::embedded()[0].params();
        let v = flattening_speed(&p).unwrap();
        let at = |v0| impact(&ImpactParams { v0, ..p }, ContactLaw::Linear).unwrap();
        assert!((at(v).max_indentation - p.z_p).abs() < 1e-9 * p.z_p.max(1.0));
        assert_eq!(at(0.99 * v).permanent_indentation, 0.0);
        assert!(at(1.1 * v).permanent_indentation > 0.0);
    }

    #[test]
    fn speed_curve_reaches_past_flattening() {
        for preset in Preset::embedded() {
            let p = preset.params();
            let c = SpeedCurve::compute(&p, ContactLaw::Linear, preset.measured.v0).unwrap();
            let v_flat = c.v_flat.unwrap();
            assert!(
                c.v_max >= 2.0 * v_flat && c.v_max <= 100.0,
                "{}",
                preset.name
            );
            assert!(
                c.points.last().unwrap().cor < c.points[0].cor - 0.02,
                "{}",
                preset.name
            );
            assert!(c.is_for(&p, ContactLaw::Linear, preset.measured.v0));
            assert!(!c.is_for(&p, ContactLaw::Hertz, preset.measured.v0));
            let slower = ImpactParams {
                v0: 0.5 * preset.measured.v0,
                ..p
            };
            assert!(c.is_for(&slower, ContactLaw::Linear, preset.measured.v0));
            if c.v_max < 100.0 {
                let faster = ImpactParams { v0: c.v_max, ..p };
                assert!(!c.is_for(&faster, ContactLaw::Linear, preset.measured.v0));
            }
        }
    }
}
