//! The oblique fit's answer at its minimum: estimates, 95 % intervals (the profile's, or the
//! Jacobian's past the work limit), warnings and the verdict.

use super::{ObliqueFit, Problem};
use crate::analysis::fit::lm::{self, Residuals};
use crate::analysis::fit::profile;
use crate::analysis::fit::stats::{Uncertainty, uncertainty};
use crate::analysis::fit::{Estimate, MultiFitError, verdict};
use crate::measured::ObliqueRow;

fn rms(r: impl Iterator<Item = f64>) -> f64 {
    let (sum, n) = r.fold((0.0, 0usize), |(s, n), v| (s + v * v, n + 1));
    (sum / n.max(1) as f64).sqrt()
}

/// RMS of the v_x misses (m/s) and of the spin misses (rad/s).
pub(super) fn rms_pair(pred: &[(f64, f64)], rows: &[ObliqueRow]) -> (f64, f64) {
    let vx = rms(pred.iter().zip(rows).map(|(p, q)| p.0 - q.vx_out));
    let spin = rms(pred
        .iter()
        .zip(rows)
        .filter_map(|(p, q)| q.spin_out.map(|s| p.1 - s)));
    (vx, spin)
}

/// Where a fit searched and how its intervals are made.
pub(super) struct Search<'a> {
    pub(super) lo: &'a [f64],
    pub(super) hi: &'a [f64],
    pub(super) opts: lm::Options,
    /// The intervals from the profile ([`profile::interval`]); else the Jacobian's.
    pub(super) profiled: bool,
}

/// The 95 % intervals of ln μ, ln K_t (and ln κ) at `sol`: the profile's where the work allows
/// and it answers, the Jacobian's θ ± t s_θ elsewhere (a warning in `warnings`); NaN where no
/// degree of freedom is left or the data do not pin it.
fn intervals(
    p: &Problem,
    sol: &lm::Solution,
    u: &Uncertainty,
    b: &Search,
    warnings: &mut Vec<String>,
) -> Result<Vec<[f64; 2]>, MultiFitError> {
    let dof = sol.residuals.len().saturating_sub(sol.x.len());
    if no_scatter(sol) {
        return Ok(vec![[f64::NAN; 2]; sol.x.len()]);
    }
    if !b.profiled {
        warnings.push(
            "the 95 % intervals are the Jacobian's (exp(θ ± t s_θ)): profiling them would pass \
             the work limit, and where the model bends in K_t they are too narrow"
                .into(),
        );
    }
    let mut ends = Vec::new();
    for (j, (&theta, &name)) in sol.x.iter().zip(&p.names).enumerate() {
        let s = u.covariance[(j, j)].sqrt();
        if !(s.is_finite() && dof > 0) {
            ends.push([f64::NAN; 2]);
            continue;
        }
        let wald = [theta - u.t975 * s, theta + u.t975 * s];
        let profiled = b
            .profiled
            .then(|| profile::interval(p, sol, j, &u.covariance, u.t975, [b.lo, b.hi], b.opts))
            .flatten();
        if p.stopped() {
            return Err(MultiFitError::Interrupted);
        }
        if b.profiled && profiled.is_none() {
            warnings.push(format!(
                "{name}'s profile had no answer: its 95 % interval is the Jacobian's"
            ));
        }
        ends.push(profiled.unwrap_or(wald).map(f64::exp));
    }
    Ok(ends)
}

/// Residuals all zero with degrees of freedom left: s² = 0 would make every standard error 0,
/// an interval that says "certain" where the data show no scatter to estimate it from; as the
/// other fits (`analysis::fit::multi`, tests/cli/cli_fit_reports.rs), no standard error, no
/// interval, a warning, and the values judged as an exact solve. tests/cli/cli_fit_oblique.rs,
/// `bounces_the_model_meets_exactly_leave_no_scatter`.
fn no_scatter(sol: &lm::Solution) -> bool {
    sol.residuals.len() > sol.x.len() && sol.residuals.iter().all(|r| *r == 0.0)
}

/// Estimates, intervals and the verdict at the minimum.
pub(super) fn finish(
    p: &Problem,
    sol: lm::Solution,
    b: &Search,
) -> Result<ObliqueFit, MultiFitError> {
    let finite = sol
        .residuals
        .iter()
        .chain(sol.jacobian.iter())
        .all(|v| v.is_finite());
    if !finite {
        return Err(MultiFitError::NonFinite);
    }
    let u = uncertainty(&sol.jacobian, &sol.residuals);
    let vars = sol.x.len();
    let dof = sol.residuals.len().saturating_sub(vars);
    let mut warnings = Vec::new();
    let ci95 = intervals(p, &sol, &u, b, &mut warnings)?;
    let no_scatter = no_scatter(&sol);
    let fitted = estimates(p, &sol, &u, &ci95, no_scatter);
    let (on_bound, not_pinned) = unpinned(p, &sol, b, &fitted, no_scatter);
    let pred = p.predict(&sol.x).ok_or(MultiFitError::NoAnswer)?;
    let (rms_vx, rms_spin) = rms_pair(&pred, p.rows);
    let rms_vy = normal_misses(p);
    let hint = "add rows that slide and rows that grip";
    if no_scatter {
        warnings.insert(0, verdict::NO_SCATTER.into());
    }
    warnings.extend(verdict::pinning_warnings(dof, &u, p.names[u.weakest], hint));
    if !sol.converged {
        warnings.push(verdict::not_converged(sol.iterations));
    }
    warnings.extend(normal_warning(p, rms_vy));
    let identified = sol.converged && not_pinned.is_empty();
    let correlation = (0..vars)
        .map(|i| (0..vars).map(|j| u.correlation[(i, j)]).collect())
        .collect();
    Ok(ObliqueFit {
        inertia_factor: p.kappa.unwrap_or_else(|| sol.x[2].exp()),
        tangential_damping: p.damping.map(|j| sol.x[j].exp()),
        fitted,
        correlation,
        rms_vx,
        rms_spin: p.spins().then_some(rms_spin),
        rms_vy,
        model: pred,
        points: sol.residuals.len(),
        iterations: sol.iterations,
        converged: sol.converged,
        condition: u.condition,
        warnings,
        identified,
        not_pinned,
        on_bound,
        no_scatter,
    })
}

/// The fitted quantities that ran to the bound of their search, and those the data do not
/// pin (`verdict::pinned`).
fn unpinned(
    p: &Problem,
    sol: &lm::Solution,
    b: &Search,
    fitted: &[Estimate],
    no_scatter: bool,
) -> (Vec<&'static str>, Vec<&'static str>) {
    let vars = sol.x.len();
    let dof = sol.residuals.len().saturating_sub(vars);
    let on_bound: Vec<&'static str> = (0..vars)
        .filter(|&j| verdict::on_bound(sol.x[j], b.lo[j], b.hi[j]))
        .map(|j| p.names[j])
        .collect();
    // residuals all zero: judged as an exact solve, on what the data see (`verdict::pinned`)
    let judged_dof = if no_scatter { 0 } else { dof };
    let not_pinned: Vec<&'static str> = fitted
        .iter()
        .filter(|e| !verdict::pinned(e, judged_dof, on_bound.contains(&e.name)))
        .map(|e| e.name)
        .collect();
    (on_bound, not_pinned)
}

/// μ, K_t (κ, c_t) at `sol` with their standard errors (by the delta method, s_p = p s_θ)
/// and the intervals `ci95`; with `no_scatter`, no standard error.
fn estimates(
    p: &Problem,
    sol: &lm::Solution,
    u: &Uncertainty,
    ci95: &[[f64; 2]],
    no_scatter: bool,
) -> Vec<Estimate> {
    (0..sol.x.len())
        .map(|j| {
            let s = sol.x[j].exp() * u.covariance[(j, j)].sqrt();
            Estimate {
                name: p.names[j],
                unit: match p.names[j] {
                    "tangential_stiffness" => "N/m",
                    "tangential_damping" => "kg/s",
                    _ => "",
                },
                value: sol.x[j].exp(),
                // a quantity the data do not see keeps its infinite variance (not pinned)
                std_error: if no_scatter && s.is_finite() {
                    f64::NAN
                } else {
                    s
                },
                ci95: ci95[j],
            }
        })
        .collect()
}

/// RMS of the normal model's v_y,out − the data's (m/s), each row's from its normal impact.
fn normal_misses(p: &Problem) -> f64 {
    rms(p.rows.iter().zip(&p.normals).map(|(q, n)| {
        let theta = q.angle_deg.to_radians();
        let vy = if q.angle_deg == 90.0 {
            q.v0
        } else {
            q.v0 * theta.sin()
        };
        n.normal().cor * vy - q.vy_out
    }))
}

/// The warning that the normal model misses v_y,out by more than 5 % RMS (`rms_vy`): not a
/// thing μ and K_t can correct.
fn normal_warning(p: &Problem, rms_vy: f64) -> Option<String> {
    let vy_scale = rms(p.rows.iter().map(|q| q.vy_out));
    (rms_vy > 0.05 * vy_scale).then(|| {
        format!(
            "the normal model misses vy_out by {:.1} % RMS: μ and K_t cannot correct that; fit \
             the normal ball first (fit --cor-table)",
            100.0 * rms_vy / vy_scale
        )
    })
}
