//! 95 % intervals of an impact's answers on a fitted preset (docs/fitting.md, "Prediction
//! intervals"). The preset's `[fit]` table holds the covariance Σ of the free parameters p;
//! an output y(p) — COR, peak force, contact time — gets the delta method's variance
//! Var y = J Σ Jᵀ, J = ∂y/∂p by central differences (step 1e-4 p, each parameter moved as the
//! fit moved it, [`crate::analysis::fit::apply`]: K_h follows K_p and z_p by Eq. 16), and the
//! interval y ± t₀.₉₇₅(dof) √Var y with the fit's degrees of freedom (Student t).

use super::{Ball, BallError};
use crate::analysis::fit::stats::t975;
use crate::analysis::fit::{MultiFit, Param, apply};
use crate::analysis::work::Watch;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::FitTable;
use crate::solver::{SolveOptions, simulate};
use serde::Serialize;

/// The 95 % intervals of one impact's answers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Intervals {
    /// COR e.
    pub cor_ci95: [f64; 2],
    /// Peak force F_m, N.
    pub max_force_ci95: [f64; 2],
    /// Contact time t_f, s (`None` without a rebound).
    pub contact_time_ci95: Option<[f64; 2]>,
}

/// Relative step of the central differences: the truncation error (∝ h²) stays below 1e-8 of
/// the derivative, the solver's rounding (1e-12 relative) below 1e-8 of it too.
const STEP: f64 = 1e-4;

/// (e, F_m, t_f) of one impact; t_f NaN without a rebound.
fn outputs(p: &ImpactParams, law: ContactLaw) -> Result<[f64; 3], BallError> {
    let r = simulate(p, law, &SolveOptions::default()).map_err(BallError::from)?;
    Ok([r.cor, r.max_force, r.contact_time.unwrap_or(f64::NAN)])
}

/// Whether `params` still hold the fit's values (no override moved a free parameter).
pub fn holds(params: &ImpactParams, fit: &FitTable) -> bool {
    fit.params()
        .iter()
        .zip(&fit.values)
        .all(|(q, &v)| (q.get(params) - v).abs() <= 1e-12 * v.abs())
}

/// The intervals of the impact of `params` under `law`, from the fit's covariance.
pub fn intervals(
    params: &ImpactParams,
    law: ContactLaw,
    fit: &FitTable,
) -> Result<Intervals, BallError> {
    let y = outputs(params, law)?;
    let b = bands(params, fit, |p| Ok(outputs(p, law)?.to_vec()))?;
    Ok(Intervals {
        cor_ci95: clip(b[0], 0.0, 1.0),
        max_force_ci95: clip(b[1], 0.0, f64::INFINITY),
        contact_time_ci95: y[2].is_finite().then_some(clip(b[2], 0.0, f64::INFINITY)),
    })
}

/// A band held to what physics allows, [lo, hi]: the delta method's y ± t√Var is symmetric
/// and knows no bounds, so three drops of a table-tennis ball gave a COR up to 1.0018 and a
/// rebound above the drop, a huge `[fit]` covariance a COR of ±7e144 and negative contact
/// times (issue 54 item 8; tests/analysis/intervals_physical.rs). A COR lies in [0, 1] (the ball
/// gives back no more than it got: docs/model.md), forces and times are not negative, a
/// rebound rises no higher than the drop. The nominal value itself is always inside.
fn clip(band: [f64; 2], lo: f64, hi: f64) -> [f64; 2] {
    [band[0].clamp(lo, hi), band[1].clamp(lo, hi)]
}

/// A watch that counts on from `before` steps (the bounces of the drops already run).
struct Counted<'a> {
    watch: &'a dyn Watch,
    before: u64,
}

impl Watch for Counted<'_> {
    fn step(&self, done: u64) -> bool {
        self.watch.step(self.before + done)
    }
}

/// The delta method on any outputs `f(p)` (module docs): one 95 % interval per output, for
/// the outputs every perturbed run has (a drop may end a bounce earlier).
pub fn bands(
    params: &ImpactParams,
    fit: &FitTable,
    f: impl Fn(&ImpactParams) -> Result<Vec<f64>, BallError>,
) -> Result<Vec<[f64; 2]>, BallError> {
    let free: Vec<Param> = fit.params();
    let y = f(params)?;
    let mut n = y.len();
    let mut jac = Vec::with_capacity(free.len());
    for q in &free {
        let v = q.get(params);
        let h = STEP * v;
        let up = f(&apply(params, &[*q], &[v + h]))?;
        let down = f(&apply(params, &[*q], &[v - h]))?;
        n = n.min(up.len()).min(down.len());
        let d: Vec<f64> = up
            .iter()
            .zip(&down)
            .map(|(u, d)| (u - d) / (2.0 * h))
            .collect();
        jac.push(d);
    }
    let t = t975(fit.dof as usize);
    Ok((0..n)
        .map(|k| {
            let var: f64 = (0..free.len())
                .flat_map(|i| (0..free.len()).map(move |j| (i, j)))
                .map(|(i, j)| jac[i][k] * fit.covariance[i][j] * jac[j][k])
                .sum();
            let half = t * var.max(0.0).sqrt();
            [y[k] - half, y[k] + half]
        })
        .collect())
}

/// A fit's uncertainty as a `[fit]` table (docs/fitting.md, "Prediction intervals"): what
/// `fit --save` writes into the preset, and what a batch's ball carries to its test.
/// cov_ij = r_ij s_i s_j of the free parameters' correlations and standard errors,
/// dof = n − p; `None` when no degree of freedom is left, a standard error is not finite, or
/// v0 was fitted.
pub fn fit_table(f: &MultiFit) -> Option<FitTable> {
    let dof = f.points.checked_sub(f.names.len()).filter(|&d| d > 0)?;
    // a fitted v0 is the trace's speed, not the ball's: its covariance is no preset's
    if f.fitted
        .iter()
        .any(|e| e.name == crate::analysis::fit::Param::V0.name())
    {
        return None;
    }
    let se: Vec<f64> = f.fitted.iter().map(|e| e.std_error).collect();
    if se.iter().any(|s| !s.is_finite()) {
        return None;
    }
    let k = se.len();
    // r_ij s_i s_j, symmetric to the last bit
    let cov =
        |i: usize, j: usize| 0.5 * (f.correlation[i][j] + f.correlation[j][i]) * (se[i] * se[j]);
    let covariance = (0..k)
        .map(|i| (0..k).map(|j| cov(i, j)).collect())
        .collect();
    Some(FitTable {
        free: f.fitted.iter().map(|e| e.name.to_string()).collect(),
        values: f.fitted.iter().map(|e| e.value).collect(),
        covariance,
        dof: u32::try_from(dof).ok()?,
        residual_sd: f.rms_residual * (f.points as f64 / dof as f64).sqrt(),
    })
}

impl Ball {
    /// The 95 % intervals of this ball's impact, when it carries a fit (a preset saved by
    /// `fit --save`, on its adopted set and law) whose free parameters no override moved;
    /// `None` otherwise.
    pub fn intervals(&self) -> Option<Result<Intervals, BallError>> {
        let fit = self.fit.as_ref()?;
        holds(&self.params, fit).then(|| intervals(&self.params, self.law, fit))
    }

    /// The 95 % intervals of every bounce of a drop, (e, F_m, t_f, rebound height) each, by
    /// the delta method over the whole drop (each perturbed ball dropped again, so a later
    /// bounce's interval carries the earlier ones'), for the bounces every run shares; `None`
    /// as for [`Ball::intervals`].
    pub fn drop_intervals(
        &self,
        setup: &crate::drop::DropSetup,
    ) -> Option<Result<Vec<[[f64; 2]; 4]>, BallError>> {
        self.drop_intervals_watched(setup, &crate::analysis::work::Unwatched)
    }

    /// [`Ball::drop_intervals`], each bounce of each of its drops reported to `watch` (the
    /// count runs on over the drops), which may stop it ([`BallError::Interrupted`]): the
    /// command line's and Python's Ctrl-C.
    pub fn drop_intervals_watched(
        &self,
        setup: &crate::drop::DropSetup,
        watch: &dyn Watch,
    ) -> Option<Result<Vec<[[f64; 2]; 4]>, BallError>> {
        let fit = self.fit.as_ref()?;
        if !holds(&self.params, fit) {
            return None;
        }
        let dball = self.drop_ball();
        let before = std::cell::Cell::new(0u64);
        let outputs = |p: &ImpactParams| -> Result<Vec<f64>, BallError> {
            let ball = crate::drop::DropBall {
                params: *p,
                ..dball
            };
            let counted = Counted {
                watch,
                before: before.get(),
            };
            let run =
                crate::drop::drop_watched(&ball, setup, &counted)?.ok_or(BallError::Interrupted)?;
            before.set(before.get() + run.bounces.len() as u64);
            let per =
                |x: &crate::drop::Bounce| [x.cor, x.max_force, x.contact_time, x.rebound_height];
            Ok(run.bounces.iter().flat_map(per).collect())
        };
        let (inf, top) = (f64::INFINITY, setup.height);
        Some(bands(&self.params, fit, outputs).map(|b| {
            b.chunks_exact(4)
                .map(|c| {
                    [
                        clip(c[0], 0.0, 1.0),
                        clip(c[1], 0.0, inf),
                        clip(c[2], 0.0, inf),
                        clip(c[3], 0.0, top),
                    ]
                })
                .collect()
        }))
    }
}
