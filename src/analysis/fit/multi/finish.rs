//! A multi-parameter fit's answer at its minimum: estimates with their intervals,
//! correlations, warnings and verdicts.

use super::super::Param;
use super::super::lm::{Best, Solution};
use super::super::result::{Estimate, MultiFit, MultiFitError};
use super::super::stats::{Spread, Uncertainty, uncertainty_by};
use super::super::verdict;
use super::finite;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;

/// Estimates, correlations and warnings at the minimum `sol`.
pub(in crate::analysis::fit) fn finish(
    params: ImpactParams,
    law: ContactLaw,
    free: &[Param],
    best: &Best,
    spread: Spread,
    rms_residual: f64,
    model: Vec<f64>,
) -> Result<MultiFit, MultiFitError> {
    let sol = &best.sol;
    if !finite(sol) || !rms_residual.is_finite() {
        return Err(MultiFitError::NonFinite);
    }
    let u = uncertainty_by(&sol.jacobian, &sol.residuals, spread);
    let (mut fitted, mut time_offset, mut baseline) = estimates(free, sol, &u);
    let mut names: Vec<&'static str> = fitted.iter().map(|e| e.name).collect();
    names.extend(time_offset.iter().chain(&baseline).map(|e| e.name));
    let n = names.len();
    let correlation = (0..n)
        .map(|i| (0..n).map(|j| u.correlation[(i, j)]).collect())
        .collect();
    let mut warnings = warnings(&fitted, &names, &u, sol);
    // Residuals all zero with degrees of freedom left: s² = 0 makes every standard error 0,
    // an interval that says "certain" where the data show no scatter to estimate it from.
    // SciPy's curve_fit returns that zero covariance silently; it returns inf where it cannot
    // estimate (n ≤ p), and so do we here: no standard error, no interval (null), as for an
    // exact solve (`MultiFit::exact`), with a warning. A variable the data do not see keeps
    // its infinite variance (not pinned). tests/cli/cli_fit.rs,
    // `equal_cors_leave_no_scatter_to_estimate_from`.
    let dof = sol.residuals.len().saturating_sub(names.len());
    // (with stated sds the interval needs no scatter: `Spread::Stated`)
    let stated = spread == Spread::Stated && dof > 0;
    let no_scatter = !stated && dof > 0 && sol.residuals.iter().all(|r| *r == 0.0);
    if no_scatter {
        warnings.insert(0, verdict::NO_SCATTER.into());
    }
    drop_unknown_intervals(&mut fitted, &mut time_offset, &mut baseline, no_scatter);
    let not_pinned = verdict::not_pinned(&fitted, best, names.len(), no_scatter);
    let on_bound = (0..free.len())
        .filter(|&j| verdict::on_bound(sol.x[j], best.lo[j], best.hi[j]))
        .map(|j| free[j].name())
        .collect();
    Ok(MultiFit {
        params,
        law,
        fitted,
        time_offset,
        baseline,
        names,
        correlation,
        rms_residual,
        points: sol.residuals.len(),
        iterations: sol.iterations,
        converged: sol.converged,
        condition: u.condition,
        warnings,
        model,
        identified: false,
        not_pinned,
        on_bound,
        no_scatter,
        stated_sd: stated,
        lack_of_fit: None,
    })
}

/// The free parameters' estimates at `sol`, then a trace's contact start and baseline (it
/// has them after the parameters), each with its standard error and 95 % interval from `u`.
fn estimates(
    free: &[Param],
    sol: &Solution,
    u: &Uncertainty,
) -> (Vec<Estimate>, Option<Estimate>, Option<Estimate>) {
    let k = free.len();
    let trace = sol.x.len() > k;
    let se = |j: usize| u.covariance[(j, j)].sqrt();
    let fitted: Vec<Estimate> = free
        .iter()
        .enumerate()
        .map(|(j, p)| {
            // an interval symmetric in ln p: exp(θ ± t s_θ); the standard error by the delta
            // method, s_p = p s_θ
            let (theta, s) = (sol.x[j], se(j));
            Estimate {
                name: p.name(),
                unit: p.unit(),
                value: theta.exp(),
                std_error: theta.exp() * s,
                ci95: [(theta - u.t975 * s).exp(), (theta + u.t975 * s).exp()],
            }
        })
        .collect();
    let linear = |j: usize, name, unit| Estimate {
        name,
        unit,
        value: sol.x[j],
        std_error: se(j),
        ci95: [sol.x[j] - u.t975 * se(j), sol.x[j] + u.t975 * se(j)],
    };
    if trace {
        (
            fitted,
            Some(linear(k, "time_offset", "s")),
            Some(linear(k + 1, "baseline", "N")),
        )
    } else {
        (fitted, None, None)
    }
}

/// No interval where the standard error is unknown; with `no_scatter`, every finite
/// standard error is unknown first (an infinite one, a variable the data do not see, stays).
fn drop_unknown_intervals(
    fitted: &mut [Estimate],
    time_offset: &mut Option<Estimate>,
    baseline: &mut Option<Estimate>,
    no_scatter: bool,
) {
    if no_scatter {
        let unknown = |e: &mut Estimate| {
            if e.std_error.is_finite() {
                e.std_error = f64::NAN;
            }
        };
        fitted.iter_mut().for_each(unknown);
        time_offset
            .iter_mut()
            .chain(baseline.iter_mut())
            .for_each(unknown);
    }
    for e in fitted
        .iter_mut()
        .chain(time_offset.iter_mut())
        .chain(baseline.iter_mut())
    {
        if !e.std_error.is_finite() {
            e.ci95 = [f64::NAN, f64::NAN];
        }
    }
}

fn warnings(fitted: &[Estimate], names: &[&str], u: &Uncertainty, sol: &Solution) -> Vec<String> {
    let dof = sol.residuals.len().saturating_sub(names.len());
    let hint = "fix it (leave it out of --free) or add data";
    let mut w = verdict::pinning_warnings(dof, u, names[u.weakest], hint);
    for e in fitted {
        if dof > 0 && e.std_error.is_finite() && e.ci95[1] - e.ci95[0] > e.value {
            w.push(format!(
                "the 95 % interval of {} is wider than its value: the data barely pin it",
                e.name
            ));
        }
    }
    if !sol.converged {
        w.push(verdict::not_converged(sol.iterations));
    }
    w
}
