//! Joint calibration (issue 52 item 5, docs/fitting.md "Joint calibration"): one weighted
//! least-squares fit of the shared parameters to several data sets at once — COR tables and
//! drop tests, a force–time trace, static deflections — with one covariance. Each set is
//! weighed by its own uncertainty: residuals divided by the standard deviations its rows
//! state, or, where it states none, by the RMS of its own misses, estimated by iterative
//! reweighting (fit, set each such scale to its set's RMS at the minimum, fit again from
//! there, until the scales move by under 2 %) — the maximum-likelihood weights of sets with
//! unknown variances. Each set then gets its own residuals and a test of whether the joint
//! answer suits it (`lack.rs`): data sets that contradict each other are flagged, not averaged
//! into a tight wrong answer.

mod lack;
mod parts;

pub use lack::contradicted;

use super::checks::{check_free, too_few};
use super::cor::CorProblem;
use super::lm::Residuals;
use super::multi::{best, finish};
use super::result::{LackOfFit, MultiFit, MultiFitError};
use super::stats::Spread;
use super::trace::TraceProblem;
use super::verdict::judge;
use super::{Param, bins::Samples};
use crate::analysis::work::{Watch, fit_iterations, fit_run_cost};
use crate::measured::{CorPoint, StaticRow, Trace};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use nalgebra::DMatrix;
use parts::{Part, StaticProblem, TracePart, rms};
use std::cell::Cell;

/// The data of one set.
#[derive(Debug, Clone, Copy)]
pub enum JointData<'a> {
    /// COR against speed (a COR table, or drop tests converted to one).
    Cor(&'a [CorPoint]),
    /// A force–time trace (at most one: the contact start and baseline are its own).
    Trace(&'a Trace),
    /// Static deflections between two plates.
    Static(&'a [StaticRow]),
}

/// One data set and what to call it in the report.
#[derive(Debug, Clone)]
pub struct JointSet<'a> {
    /// "drop test", "COR table", "force-time trace", "static deflection".
    pub kind: &'static str,
    /// The file, or what was typed.
    pub label: String,
    /// The rows.
    pub data: JointData<'a>,
}

/// How one set fared in the joint fit.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SetFit {
    /// The set's kind ([`JointSet::kind`]).
    pub kind: &'static str,
    /// The set's file, or what was typed.
    pub label: String,
    /// Rows of the set (a trace's rows).
    pub points: usize,
    /// RMS of model − data in the set's own unit (`unit`).
    pub rms_residual: f64,
    /// "COR", "N" or "m".
    pub unit: &'static str,
    /// Whether the set's rows stated their standard deviations (taken as known).
    pub sd_stated: bool,
    /// The standard deviation the set was weighed by, estimated from its misses (its COR's
    /// for a table, N for a trace, m for deflections); `None` where stated.
    pub sd_estimated: Option<f64>,
    /// Whether the joint answer suits this set: χ² against its stated sds, else the
    /// extra-sum-of-squares F test of the set fitted alone against the joint answer.
    pub lack_of_fit: Option<LackOfFit>,
}

/// A joint fit: the fitted ball with one covariance, and each set's account.
#[derive(Debug, Clone)]
pub struct JointFit {
    /// The fitted ball, its estimates and one covariance over every set.
    pub fit: MultiFit,
    /// Each set's account, in the order given.
    pub sets: Vec<SetFit>,
}

struct JointProblem<'a> {
    parts: Vec<Part<'a>>,
    /// Free parameters.
    k: usize,
    /// Variables: k, and the trace's start and baseline.
    vars: usize,
}

impl JointProblem<'_> {
    fn trace(&self) -> Option<&TracePart<'_>> {
        self.parts.iter().find_map(|p| match p {
            Part::Trace(t) => Some(t),
            _ => None,
        })
    }

    fn count(&self) -> usize {
        self.parts.iter().map(Part::count).sum()
    }

    fn bounds(&self, x0: &[f64]) -> (Vec<f64>, Vec<f64>) {
        match self.trace() {
            Some(t) => t.p.bounds(x0),
            None => {
                let w = 5.0 * std::f64::consts::LN_10;
                (
                    x0.iter().map(|v| v - w).collect(),
                    x0.iter().map(|v| v + w).collect(),
                )
            }
        }
    }

    /// Every set's starts, each completed with the trace's start and baseline, and the ball.
    fn starts(&self, base: &ImpactParams, free: &[Param]) -> Vec<Vec<f64>> {
        let nuisance: Vec<f64> = self
            .trace()
            .map(|t| vec![t.p.summary.t_start, t.p.summary.baseline])
            .unwrap_or_default();
        let logs: Vec<f64> = free.iter().map(|p| p.get(base).ln()).collect();
        let mut out: Vec<Vec<f64>> = Vec::new();
        let mut add = |mut x: Vec<f64>| {
            x.truncate(self.k);
            x.extend(&nuisance);
            out.push(x);
        };
        for p in &self.parts {
            match p {
                Part::Cor(c) => c.starts().into_iter().for_each(&mut add),
                Part::Trace(t) => t.p.starts().into_iter().for_each(&mut add),
                Part::Static(_) => {}
            }
        }
        for f in [1.0f64, 3.0, 1.0 / 3.0] {
            add(logs.iter().map(|v| v + f.ln()).collect());
        }
        out
    }

    /// Each set's residuals at `x`, in order.
    fn by_set(&self, x: &[f64]) -> Option<Vec<Vec<f64>>> {
        self.parts.iter().map(|p| p.residuals(x, self.k)).collect()
    }
}

impl Residuals for JointProblem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        Some(self.by_set(x)?.concat())
    }

    fn jacobian(&self, x: &[f64], r: &[f64]) -> Option<DMatrix<f64>> {
        let mut jac = DMatrix::zeros(r.len(), self.vars);
        let mut row = 0;
        for p in &self.parts {
            let n = p.count();
            let block = p.jacobian(x, &r[row..row + n], self.vars, self.k)?;
            jac.rows_mut(row, n).copy_from(&block);
            row += n;
        }
        Some(jac)
    }

    fn step(&self, j: usize) -> f64 {
        // (the COR tables' and the static sets' step in the logarithms: `CorProblem`'s)
        self.trace().map_or(1e-5, |t| t.p.step(j))
    }

    fn typical(&self, j: usize) -> f64 {
        self.trace().map_or(1.0, |t| t.p.typical(j))
    }

    fn max_step(&self, j: usize) -> f64 {
        self.trace().map_or(1.0, |t| t.p.max_step(j))
    }

    fn stopped(&self) -> bool {
        self.parts.iter().any(Part::stopped)
    }
}

/// Rounds of reweighting at most; they stop once no set's scale moves by 2 %.
const REWEIGHT_ROUNDS: usize = 6;

/// Fit the `free` parameters of `base` to every set in `sets` at once.
pub fn fit_joint(
    base: &ImpactParams,
    law: ContactLaw,
    sets: &[JointSet],
    free: &[Param],
    watch: &dyn Watch,
) -> Result<JointFit, MultiFitError> {
    check_free(free)?;
    base.validate().map_err(MultiFitError::Params)?;
    let p = problem(base, law, sets, free, watch)?;
    if free.contains(&Param::V0) && p.trace().is_none() {
        return Err(MultiFitError::SpeedNotFree);
    }
    too_few(p.count(), p.vars)?;
    let starts = p.starts(base, free);
    let rows: usize = p.parts.iter().map(Part::count).sum();
    let run = fit_run_cost(rows, p.trace().map_or(0, |t| t.p.history()), law);
    let what = || format!("a joint fit of {} parameters to {rows} data", free.len());
    let iterations = fit_iterations(run, p.vars, starts.len() + REWEIGHT_ROUNDS, law, what)?;
    let none = || {
        if p.stopped() {
            MultiFitError::Interrupted
        } else {
            MultiFitError::NoAnswer
        }
    };
    // first weights: each set's own misses at the most promising start
    let first = starts
        .iter()
        .find(|x| p.by_set(x).is_some())
        .ok_or_else(none)?;
    for part in &p.parts {
        part.rescale(first, p.k);
    }
    let bounds = |x: &[f64]| p.bounds(x);
    let mut sol = best(&p, starts, bounds, 0.0, iterations).ok_or_else(none)?;
    for _ in 0..REWEIGHT_ROUNDS {
        let mut change: f64 = 0.0;
        for part in &p.parts {
            change = change.max(part.rescale(&sol.sol.x, p.k).ok_or_else(none)?);
        }
        let its = sol.sol.iterations;
        sol = best(&p, vec![sol.sol.x.clone()], bounds, 0.0, iterations).ok_or_else(none)?;
        sol.sol.iterations += its;
        if change < 0.02 {
            break;
        }
    }
    let x = sol.sol.x.clone();
    let per_set = p.by_set(&x).ok_or_else(none)?;
    let n = p.count();
    // the sets whose scale was estimated: the intervals take the degrees of freedom of the
    // one with the fewest rows, its share of the parameters off (as a COR table of mixed
    // kinds does, `multi::fit_cor`)
    let share = |m: usize| (p.vars * m).div_ceil(n.max(1));
    let estimated: Vec<usize> = p
        .parts
        .iter()
        .filter(|q| !q.stated())
        .map(|q| q.count().saturating_sub(share(q.count())).max(1))
        .collect();
    let spread = match estimated.iter().min() {
        Some(&d) => Spread::Kinds(d),
        None => Spread::Stated,
    };
    let ball = p.parts.iter().find_map(|q| match q {
        Part::Trace(t) => Some(t.p.ball(&x)),
        _ => None,
    });
    let values: Vec<f64> = x[..p.k].iter().map(|v| v.exp()).collect();
    let ball = ball.unwrap_or_else(|| super::apply(base, free, &values));
    let overall = rms(&sol.sol.residuals);
    let mut f = finish(ball, law, free, &sol, spread, overall, vec![])?;
    f.stated_sd = matches!(spread, Spread::Stated);
    let accounts = lack::accounts(&p, sets, &per_set, &x, &sol, iterations);
    let sets = accounts.ok_or_else(none)?;
    judge(&mut f, None);
    lack::verdict(&mut f, &sets);
    Ok(JointFit { fit: f, sets })
}

fn problem<'a>(
    base: &ImpactParams,
    law: ContactLaw,
    sets: &'a [JointSet],
    free: &[Param],
    watch: &'a dyn Watch,
) -> Result<JointProblem<'a>, MultiFitError> {
    let mut parts = Vec::new();
    let mut traces = 0;
    for s in sets {
        parts.push(match s.data {
            JointData::Cor(points) => {
                Part::Cor(CorProblem::new(*base, law, free.to_vec(), points, watch))
            }
            JointData::Static(rows) => Part::Static(StaticProblem {
                base: *base,
                law,
                free: free.to_vec(),
                rows,
                scale: Cell::new(1.0),
            }),
            JointData::Trace(trace) => {
                traces += 1;
                let summary = trace.summary().map_err(MultiFitError::NoPulse)?;
                let samples = Samples::of(trace, &summary);
                let tp =
                    TraceProblem::new(*base, law, free.to_vec(), trace, summary, samples, watch);
                Part::Trace(TracePart {
                    p: tp,
                    scale: Cell::new(1.0),
                })
            }
        });
    }
    if traces > 1 {
        return Err(MultiFitError::OutOfReach(
            "a joint fit takes one force-time trace".into(),
        ));
    }
    let k = free.len();
    Ok(JointProblem {
        parts,
        k,
        vars: k + 2 * traces,
    })
}
