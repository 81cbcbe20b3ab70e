//! The checks of a fit's data and answer that can refuse it (docs/fitting.md, "Did the fit
//! answer?"): a trace's impulse against the setup, measured values beyond the search's
//! reach, an exact solve that misses, the free set itself.

use super::cor::CorProblem;
use super::lm::Best;
use super::result::MultiFitError;
use super::{Param, fit_k_r, verdict};
use crate::measured::Trace;
use crate::model::params::ImpactParams;
use crate::text::sig;

/// A trace whose impulse needs e outside [0, 1] at the given speed cannot come from this
/// ball: refused, with the speeds it allows (three standard errors of the impulse's noise
/// are given to it).
pub(super) fn check_impulse(
    base: &ImpactParams,
    trace: &Trace,
    s: &crate::measured::TraceSummary,
) -> Result<(), MultiFitError> {
    let n = trace.time.len();
    let dt = (trace.time[n - 1] - trace.time[0]) / (n - 1).max(1) as f64;
    let (e, sd) = verdict::implied_cor(s, base.mass, base.v0, dt);
    if !(e.is_finite() && sd.is_finite()) {
        return Err(MultiFitError::NonFinite);
    }
    if e < -3.0 * sd || e > 1.0 + 3.0 * sd {
        let m = base.mass;
        return Err(MultiFitError::Contradicts {
            implied: e,
            v0: base.v0,
            impulse: s.impulse,
            allowed: [s.impulse / (2.0 * m), s.impulse / m],
        });
    }
    Ok(())
}

/// Peak forces and contact times more than [`verdict::SCALE_MAX`] from the starting ball's,
/// either way, lie beyond what the search (±5 decades in each parameter) can bring the model
/// to: refused, naming the row, rather than fitted to the other kinds while these are
/// outvoted.
pub(super) fn check_scale(p: &CorProblem) -> Result<(), MultiFitError> {
    let x0: Vec<f64> = p.free.iter().map(|q| q.get(&p.base).ln()).collect();
    let Some(pred) = p.predict(&x0) else {
        return Ok(());
    };
    for (q, (_, f, t)) in p.points.iter().zip(&pred) {
        let kinds = [
            ("peak force", "N", q.max_force, Some(*f)),
            ("contact time", "s", q.contact_time, *t),
        ];
        for (what, unit, measured, model) in kinds {
            let (Some(m), Some(model)) = (measured, model) else {
                continue;
            };
            let ratio = m / model;
            if !(1.0 / verdict::SCALE_MAX..=verdict::SCALE_MAX).contains(&ratio) {
                let row = if q.line > 0 {
                    format!("line {}: ", q.line)
                } else {
                    String::new()
                };
                return Err(MultiFitError::OutOfReach(format!(
                    "{row}the {what} measured at v0 = {} m/s, {} {unit}, is {}× the model's {} \
                     {unit}: beyond a factor {} either way, out of the fit's reach",
                    sig(q.v0, 4),
                    sig(m, 4),
                    sig(ratio, 3),
                    sig(model, 4),
                    verdict::SCALE_MAX
                )));
            }
        }
    }
    Ok(())
}

/// An exact solve (as many data as parameters) must reproduce every datum to
/// [`verdict::EXACT_MISS`] with no parameter on its bound; otherwise the data are out of the
/// model's reach. One COR with K_r free says how far the model reaches ([`fit_k_r`]'s range).
pub(super) fn verify_exact(
    p: &CorProblem,
    sol: &Best,
    pred: &[(f64, f64, Option<f64>)],
) -> Result<(), MultiFitError> {
    let rel = |m: f64, d: f64| (m - d).abs() <= verdict::EXACT_MISS * d.abs().max(1e-300);
    let hit = p.points.iter().zip(pred).all(|(q, (e, f, t))| {
        rel(*e, q.cor)
            && q.max_force.is_none_or(|m| rel(*f, m))
            && q.contact_time.is_none_or(|m| t.is_some_and(|t| rel(t, m)))
    });
    let pressed: Vec<&str> = (0..p.free.len())
        .filter(|&j| verdict::on_bound(sol.sol.x[j], sol.lo[j], sol.hi[j]))
        .map(|j| p.free[j].name())
        .collect();
    if hit && pressed.is_empty() {
        return Ok(());
    }
    if let ([q], [Param::KR]) = (p.points, p.free.as_slice()) {
        let at = ImpactParams { v0: q.v0, ..p.base };
        if let Err(e @ super::FitError::OutOfReach { .. }) = fit_k_r(&at, p.law, q.cor) {
            return Err(MultiFitError::OutOfReach(format!(
                "{e} at v0 = {} m/s",
                crate::text::sig(q.v0, 4)
            )));
        }
    }
    let closest: Vec<String> = p
        .points
        .iter()
        .zip(pred)
        .map(|(q, (e, _, _))| format!("COR {} for {}", sig(*e, 4), sig(q.cor, 4)))
        .collect();
    Err(MultiFitError::OutOfReach(format!(
        "out of reach: the model comes no closer than {}{}",
        closest.join(", "),
        if pressed.is_empty() {
            String::new()
        } else {
            format!(" ({} on the bound of the search)", pressed.join(", "))
        }
    )))
}

pub(super) fn check_free(free: &[Param]) -> Result<(), MultiFitError> {
    if free.is_empty() {
        return Err(MultiFitError::NoFree);
    }
    for (i, p) in free.iter().enumerate() {
        if free[..i].contains(p) {
            return Err(MultiFitError::Repeated(*p));
        }
    }
    if free.contains(&Param::KP) && free.contains(&Param::KH) {
        return Err(MultiFitError::Tied);
    }
    Ok(())
}

pub(super) fn too_few(points: usize, parameters: usize) -> Result<(), MultiFitError> {
    if points < parameters {
        return Err(MultiFitError::TooFew { points, parameters });
    }
    Ok(())
}
