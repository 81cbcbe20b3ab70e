//! Several parameters at once: restarts, the best minimum, and its uncertainty.

mod finish;

pub(super) use finish::finish;

use super::Param;
use super::bins::Samples;
use super::checks::{check_free, check_impulse, check_scale, too_few, verify_exact};
use super::cor::CorProblem;
use super::edge;
use super::lm::{self, Best, Residuals, Solution};
use super::result::{FitData, MultiFit, MultiFitError};
use super::stats::{CONDITION_MAX, Spread, uncertainty};
use super::trace::TraceProblem;
use super::verdict::{self, judge};
use crate::analysis::work::{Unwatched, Watch, fit_iterations, fit_run_cost};
use crate::measured::{CorPoint, Trace, TraceSummary};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;

/// Fit the `free` parameters of `base` to `data` under `law`.
pub fn fit(
    base: &ImpactParams,
    law: ContactLaw,
    data: FitData,
    free: &[Param],
) -> Result<MultiFit, MultiFitError> {
    fit_watched(base, law, data, free, &Unwatched)
}

/// [`fit`], each model run reported to `watch`, which may stop it
/// ([`MultiFitError::Interrupted`]); the fit's work is checked against the work limit before
/// it starts ([`crate::analysis::work::fit_iterations`]).
pub fn fit_watched(
    base: &ImpactParams,
    law: ContactLaw,
    data: FitData,
    free: &[Param],
    watch: &dyn Watch,
) -> Result<MultiFit, MultiFitError> {
    check_free(free)?;
    base.validate().map_err(MultiFitError::Params)?;
    match data {
        FitData::Trace(trace) => fit_trace(base, law, trace, free, watch, Samples::of),
        FitData::Cor(points) => {
            if free.contains(&Param::V0) {
                return Err(MultiFitError::SpeedNotFree);
            }
            fit_cor(base, law, points, free, watch)
        }
    }
}

/// A force–time trace, compared with the model at the samples `choose` makes of it (rows or
/// bins, [`Samples::of`]).
pub(super) fn fit_trace(
    base: &ImpactParams,
    law: ContactLaw,
    trace: &Trace,
    free: &[Param],
    watch: &dyn Watch,
    choose: fn(&Trace, &TraceSummary) -> Samples,
) -> Result<MultiFit, MultiFitError> {
    let summary = trace.summary().map_err(MultiFitError::NoPulse)?;
    too_few(trace.time.len(), free.len() + 2)?;
    if !free.contains(&Param::V0) {
        check_impulse(base, trace, &summary)?;
    }
    let samples = choose(trace, &summary);
    let rows = trace.time.len();
    let bins = samples.len();
    let p = TraceProblem::new(*base, law, free.to_vec(), trace, summary, samples, watch);
    let starts = p.starts();
    let run = fit_run_cost(bins, p.history(), law);
    let what = || {
        format!(
            "a fit of {} parameters to {rows} rows ({bins} bins)",
            free.len()
        )
    };
    // (one start more: the fit on the other side of the first row, `edge::both_sides`)
    let iterations = fit_iterations(run, free.len() + 2, starts.len() + 1, law, what)?;
    // a minimum at the noise floor needs no further start
    let floor = 1.5 * summary.noise;
    let sol = best(&p, starts, |x| p.bounds(x), floor, iterations);
    if p.stopped() {
        return Err(MultiFitError::Interrupted);
    }
    let mut sol = sol.ok_or(MultiFitError::NoAnswer)?;
    let model = p.model_at_rows(&sol.sol.x).unwrap_or_default();
    let ball = p.ball(&sol.sol.x);
    let rms = rms(&sol.sol.residuals);
    let mut f = finish(ball, law, free, &sol, Spread::Residuals, rms, model)?;
    let refinish = |b: &Best| {
        let model = p.model_at_rows(&b.sol.x).unwrap_or_default();
        let at = self::rms(&b.sol.residuals);
        finish(p.ball(&b.sol.x), law, free, b, Spread::Residuals, at, model)
    };
    edge::both_sides(&p, &mut sol, &mut f, iterations, refinish)?;
    if p.stopped() {
        return Err(MultiFitError::Interrupted);
    }
    // the trace's rows, whether compared one by one or in bins
    f.points = rows;
    // the model's misses matter only above the noise's scale (a noise-free synthetic trace
    // leaves rounding's systematic residuals)
    let lack = verdict::runs_test(&sol.sol.residuals)
        .filter(|_| f.rms_residual > 1e-6 * summary.peak.abs().max(f64::MIN_POSITIVE));
    judge(&mut f, lack);
    Ok(f)
}

/// A COR table (with peak forces and contact times where given), each model run reported to
/// `watch`.
fn fit_cor(
    base: &ImpactParams,
    law: ContactLaw,
    points: &[CorPoint],
    free: &[Param],
    watch: &dyn Watch,
) -> Result<MultiFit, MultiFitError> {
    let p = CorProblem::new(*base, law, free.to_vec(), points, watch);
    too_few(p.count(), free.len())?;
    let starts = p.starts();
    let run = fit_run_cost(points.len(), 0, law);
    let what = || {
        format!(
            "a fit of {} parameters to {} rows",
            free.len(),
            points.len()
        )
    };
    // (one start more: a table of mixed kinds is fitted again from the first minimum)
    let iterations = fit_iterations(run, free.len(), starts.len() + 1, law, what)?;
    // after the work limit: the scale check is a model run over every row
    // (tests/analysis/fit_work_limit.rs)
    check_scale(&p)?;
    // no answer, or stopped by the watch
    let none = || {
        if p.stopped() {
            MultiFitError::Interrupted
        } else {
            MultiFitError::NoAnswer
        }
    };
    let sol = best(&p, starts, |x| p.bounds(x), 0.0, iterations).ok_or_else(none)?;
    // every row's COR with its stated sd, and nothing else measured: the residuals are in
    // units of their sd (`Spread::Stated`)
    let stated = points.iter().all(|q| q.cor_sd.is_some()) && p.count() == points.len();
    let (sol, t_dof) = if p.count() > points.len() {
        refit_by_kind(&p, points, free.len(), sol, iterations).ok_or_else(none)?
    } else {
        (sol, None)
    };
    let pred = p.predict(&sol.sol.x).ok_or_else(none)?;
    let model: Vec<f64> = pred.iter().map(|q| q.0).collect();
    let misses: Vec<f64> = model.iter().zip(points).map(|(m, q)| m - q.cor).collect();
    if p.count() == free.len() {
        verify_exact(&p, &sol, &pred)?;
    }
    let ball = p.ball(&sol.sol.x);
    let spread = match t_dof {
        Some(d) => Spread::Kinds(d),
        None if stated => Spread::Stated,
        None => Spread::Residuals,
    };
    let mut f = finish(ball, law, free, &sol, spread, rms(&misses), model)?;
    let lack = cor_lack_of_fit(stated, &sol, free.len(), points, misses, f.rms_residual);
    judge(&mut f, lack);
    Ok(f)
}

/// A COR table of mixed kinds: each kind weighed by its own scatter at `sol`, then fitted
/// again from there. The new minimum (its iterations counting the first fit's too), and the
/// degrees of freedom its intervals take; `None` when there is no answer or the watch
/// stopped the fit.
fn refit_by_kind(
    p: &CorProblem,
    points: &[CorPoint],
    free: usize,
    sol: Best,
    iterations: usize,
) -> Option<(Best, Option<usize>)> {
    let mut t_dof = None;
    let kinds = p.rms_by_kind(&sol.sol.x)?;
    let counts = p.count_by_kind();
    for k in 0..3 {
        if kinds[k].is_finite() && (k > 0 || points.iter().all(|q| q.cor_sd.is_none())) {
            p.scale[k].set(kinds[k].max(1e-6));
            // the weights are estimated from the data: the intervals take the degrees of
            // freedom of the kind with the fewest points, its share of the parameters
            // taken off (measured: 37–39 of 40 intervals cover, against 35–37 with the
            // n − p of all the data; tests/analysis/fit_recovery.rs,
            // cor_force_and_contact_time_jointly)
            let share = (free * counts[k]).div_ceil(p.count());
            let dof = counts[k].saturating_sub(share).max(1);
            t_dof = Some(t_dof.map_or(dof, |d: usize| d.min(dof)));
        }
    }
    let again = best(p, vec![sol.sol.x.clone()], |x| p.bounds(x), 0.0, iterations);
    let its = sol.sol.iterations;
    let mut sol = again?;
    sol.sol.iterations += its;
    Some((sol, t_dof))
}

/// χ² when every row carries its standard deviation (and nothing else was measured,
/// `stated`), else the runs test of the COR `misses` in the data's order of speed (none
/// where the model meets the data: RMS ≤ 1e-9).
fn cor_lack_of_fit(
    stated: bool,
    sol: &Best,
    free: usize,
    points: &[CorPoint],
    misses: Vec<f64>,
    rms_residual: f64,
) -> Option<verdict::LackOfFit> {
    let dof = sol.sol.residuals.len().saturating_sub(free);
    if stated {
        verdict::chi2_test(&sol.sol.residuals, dof)
    } else {
        let mut by_speed: Vec<(f64, f64)> = points.iter().map(|q| q.v0).zip(misses).collect();
        by_speed.sort_by(|a, b| a.0.total_cmp(&b.0));
        let r: Vec<f64> = by_speed.iter().map(|m| m.1).collect();
        verdict::runs_test(&r).filter(|_| rms_residual > 1e-9)
    }
}

/// s² = Σr²/(n − p) at a minimum.
fn variance(s: &Solution) -> f64 {
    2.0 * s.cost / s.residuals.len().saturating_sub(s.x.len()).max(1) as f64
}

fn rms(r: &[f64]) -> f64 {
    (r.iter().map(|v| v * v).sum::<f64>() / r.len().max(1) as f64).sqrt()
}

/// Whether a solution's residuals and Jacobian are finite numbers (the SVD of the uncertainty
/// is undefined otherwise).
fn finite(s: &Solution) -> bool {
    s.residuals.iter().all(|r| r.is_finite()) && s.jacobian.iter().all(|j| j.is_finite())
}

/// The lowest minimum over `starts`; stops early once the RMS residual is at `floor`, or when
/// two starts have converged to the same lowest cost (to 1e-9) where the data pin every
/// parameter: the restarts are there to escape a local minimum, and two ways into the same
/// one make another unlikely. (A flat region, where a parameter has no effect, is not such a
/// minimum: two starts in it would agree and stop the search too early.) Each start takes at
/// most `max_iterations` ([`crate::analysis::work::fit_iterations`]).
pub(super) fn best<P: Residuals>(
    p: &P,
    starts: Vec<Vec<f64>>,
    bounds: impl Fn(&[f64]) -> (Vec<f64>, Vec<f64>),
    floor: f64,
    max_iterations: usize,
) -> Option<Best> {
    let opts = lm::Options {
        max_iterations,
        ..lm::Options::default()
    };
    // the most promising start first: one evaluation each
    let mut starts: Vec<(f64, Vec<f64>)> = starts
        .into_iter()
        .filter_map(|x0| Some((p.residuals(&x0).map(|r| rms(&r))?, x0)))
        .collect();
    starts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best: Option<Best> = None;
    let mut iterations = 0;
    for (_, x0) in starts {
        if p.stopped() {
            return None;
        }
        let (lo, hi) = bounds(&x0);
        let Some(s) = lm::minimize(p, &x0, &lo, &hi, opts) else {
            continue;
        };
        iterations += s.iterations;
        let same = best.as_ref().map(|b| &b.sol).is_some_and(|b| {
            b.converged
                && (s.cost - b.cost).abs() <= (1e-9 * b.cost).max(1e-3 * variance(b))
                && finite(&s)
                && uncertainty(&s.jacobian, &s.residuals).condition < CONDITION_MAX
        });
        let done = s.converged && (rms(&s.residuals) <= floor || same);
        let done = done && s.residuals.iter().all(|r| r.is_finite());
        if best.as_ref().is_none_or(|b| s.cost < b.sol.cost) {
            best = Some(Best { sol: s, lo, hi });
        }
        if done {
            break;
        }
    }
    best.map(|mut b| {
        b.sol.iterations = iterations;
        b
    })
}
