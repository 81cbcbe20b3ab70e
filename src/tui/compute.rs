//! The numbers behind the charts, computed with the library (`simulate`, `cor_vs_zeta`) when
//! the state changes — never while drawing. SI units throughout. The sweeps view's COR
//! against speed is [`crate::tui::views::sweeps::speed`].

use crate::analysis::sweep::{ZetaPoint, cor_vs_zeta, log_space};
use crate::figure::explorer::TargetMotion;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{History, ImpactResponse, SolveOptions, simulate};
use crate::tui::setting::Setting;
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

/// The run of `setting`: the ball's at the wall; against a rigid target the reduced ball's at
/// the closing speed (docs/targets.md §2), with the target's displacement u_t; on a compliant
/// target the library's sampled two-body history ([`crate::target::history`]) as an impact of
/// the reduced ball, with the surface's deflection too. An impact on a compliant target
/// carries no energy budget (the readout then shows none).
pub fn pair(setting: &Setting) -> Result<(ImpactResponse, Option<TargetMotion>), String> {
    let target = setting.target;
    let p = setting.run_params();
    if target.is_rigid() {
        let run = impact(&p, setting.law)?;
        let motion = (target.mass < f64::INFINITY).then(|| TargetMotion {
            displacement: crate::target::displacement_off_path(
                p.mass / target.mass,
                p.v0,
                &run.history.t,
                &run.history.displacement,
            ),
            deflection: Vec::new(),
        });
        return Ok((run, motion));
    }
    let ball = &setting.params;
    let h = crate::target::history(ball, setting.law, &target, ball.v0, HISTORY_SAMPLES)
        .map_err(|e| e.to_string())?;
    let c = &h.collision;
    let (n, w0) = (p.normalized(), p.omega0());
    let run = ImpactResponse {
        law: setting.law,
        method: c.method,
        cor: c.cor,
        rebound: c.rebound,
        max_force: c.max_force,
        contact_time: c.contact_time,
        duration: h.t.last().copied().unwrap_or(0.0),
        max_indentation: c.max_indentation,
        permanent_indentation: c.permanent_indentation,
        // not followed by the two-body history: nothing in the explorer reads it
        element_displacement: 0.0,
        max_force_normalized: c.max_force / (p.mass * p.v0 * w0),
        element_displacement_normalized: 0.0,
        contact_time_normalized: c.contact_time.map(|t| t * w0),
        normalized: n,
        events: Vec::new(),
        energy: None,
        history: History {
            t: h.t,
            force: h.force,
            indentation: h.indentation,
            displacement: h.displacement,
        },
        steps: 0,
        stiff: false,
    };
    let motion = TargetMotion {
        displacement: if target.mass < f64::INFINITY {
            h.target_displacement
        } else {
            Vec::new()
        },
        deflection: h.deflection,
    };
    Ok((run, Some(motion)))
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
