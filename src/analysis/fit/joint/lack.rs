//! Each set's account in a joint fit: its residuals, the scale it was weighed by, and whether
//! the joint answer suits it. A set whose rows state their standard deviations takes χ² of
//! its residuals at its share of the degrees of freedom. A set weighed by its own scatter
//! cannot be judged by χ² (its scale is its misses'), so it is fitted alone, from the joint
//! answer, and the two compared by the extra-sum-of-squares F test,
//!
//! ```text
//! F = [(RSS_joint − RSS_alone)/q] / [RSS_alone/(n − q)],   F ~ F(q, n − q)
//! ```
//!
//! q the parameters the set sees (the rank of its Jacobian): a set the joint answer forces
//! away from its own best leaves RSS_joint ≫ RSS_alone (tests/analysis/fit_joint.rs,
//! `contradicting_sets_are_flagged`). The denominator estimates the set's noise variance; it
//! is taken no smaller than the set's resolution squared (`Part::resolution`, the floor its
//! scale may be given): a set the model made exactly has RSS_alone at float noise, and a
//! nudge of 1e-12 from another set's rounding over 1e-24 is not a contradiction
//! (`an_exact_set_beside_rounded_data_is_not_a_contradiction`). With one set alone, the runs test of its misses (20
//! or more), as the fits of one data set take.

use super::super::lm::{self, Best, Residuals};
use super::super::result::{LackOfFit, MultiFit};
use super::super::verdict;
use super::parts::Part;
use super::{JointProblem, JointSet, SetFit};
use nalgebra::DMatrix;
use statrs::distribution::{ContinuousCDF, FisherSnedecor};

/// One set of a joint problem, alone, over the joint variables.
struct Alone<'a, 'b> {
    p: &'a JointProblem<'b>,
    i: usize,
}

impl Residuals for Alone<'_, '_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.p.parts[self.i].residuals(x, self.p.k)
    }
    fn jacobian(&self, x: &[f64], r: &[f64]) -> Option<DMatrix<f64>> {
        self.p.parts[self.i].jacobian(x, r, self.p.vars, self.p.k)
    }
    fn step(&self, j: usize) -> f64 {
        self.p.step(j)
    }
    fn typical(&self, j: usize) -> f64 {
        self.p.typical(j)
    }
    fn max_step(&self, j: usize) -> f64 {
        self.p.max_step(j)
    }
    fn stopped(&self) -> bool {
        self.p.stopped()
    }
}

/// Every set's account at the joint minimum `x` (`per_set`: each set's residuals there).
pub(super) fn accounts(
    p: &JointProblem,
    sets: &[JointSet],
    per_set: &[Vec<f64>],
    x: &[f64],
    best: &Best,
    iterations: usize,
) -> Option<Vec<SetFit>> {
    let n: usize = per_set.iter().map(Vec::len).sum();
    let mut out = Vec::with_capacity(sets.len());
    for (i, (part, set)) in p.parts.iter().zip(sets).enumerate() {
        let r = &per_set[i];
        let share = (p.vars * r.len()).div_ceil(n.max(1));
        let lack = if part.stated() {
            verdict::chi2_test(r, r.len().saturating_sub(share))
        } else if sets.len() > 1 {
            let floor = part.resolution();
            f_test(&Alone { p, i }, x, r, best, iterations, floor)
        } else {
            verdict::runs_test(&in_order(part, r)).filter(|_| r.iter().any(|v| *v != 0.0))
        };
        out.push(SetFit {
            kind: set.kind,
            label: set.label.clone(),
            points: part.rows(),
            rms_residual: part.rms_raw(x, p.k)?,
            unit: match part {
                Part::Cor(_) => "COR",
                Part::Trace(_) => "N",
                Part::Static(_) => "m",
            },
            sd_stated: part.stated(),
            sd_estimated: part.scale(),
            lack_of_fit: lack,
        });
    }
    Some(out)
}

/// The residuals in the order a runs test reads them: a COR table's by speed, deflections by
/// load, a trace's in time.
fn in_order(part: &Part, r: &[f64]) -> Vec<f64> {
    let key: Vec<f64> = match part {
        Part::Cor(c) if c.count() == c.points.len() => c.points.iter().map(|q| q.v0).collect(),
        Part::Static(s) => s.rows.iter().map(|q| q.load_kg).collect(),
        _ => return r.to_vec(),
    };
    let mut pairs: Vec<(f64, f64)> = key.into_iter().zip(r.iter().copied()).collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    pairs.into_iter().map(|p| p.1).collect()
}

/// The extra-sum-of-squares F test of one set fitted alone from the joint `x`, its noise
/// variance taken no smaller than `resolution`² (residuals' units).
fn f_test(
    alone: &Alone,
    x: &[f64],
    r: &[f64],
    best: &Best,
    max_iterations: usize,
    resolution: f64,
) -> Option<LackOfFit> {
    let opts = lm::Options {
        max_iterations,
        ..lm::Options::default()
    };
    let jac = alone.jacobian(x, r)?;
    let q = rank(&jac);
    let n = r.len();
    if q == 0 || n <= q {
        return None;
    }
    let own = lm::minimize(alone, x, &best.lo, &best.hi, opts)?;
    let joint: f64 = r.iter().map(|v| v * v).sum();
    let apart: f64 = own.residuals.iter().map(|v| v * v).sum::<f64>().min(joint);
    if joint == 0.0 {
        return None;
    }
    let noise = (apart / (n - q) as f64).max(resolution * resolution);
    let f = if noise > 0.0 {
        ((joint - apart) / q as f64) / noise
    } else {
        f64::INFINITY
    };
    let p = FisherSnedecor::new(q as f64, (n - q) as f64).ok()?.sf(f);
    Some(LackOfFit {
        test: "F",
        statistic: f,
        p_value: if f.is_infinite() { 0.0 } else { p },
    })
}

/// The parameters a set sees: singular values of its column-scaled Jacobian above 1e-6 of
/// the largest (a column it does not see is zero).
fn rank(jac: &DMatrix<f64>) -> usize {
    let mut scaled = jac.clone();
    for mut c in scaled.column_iter_mut() {
        let norm = c.norm();
        if norm > 0.0 {
            c /= norm;
        }
    }
    let sv = scaled.svd(false, false).singular_values;
    let top = sv.iter().copied().fold(0.0, f64::max);
    sv.iter().filter(|s| **s > 1e-6 * top && top > 0.0).count()
}

/// The joint fit's verdict from its sets': the worst set's test is the fit's `lack_of_fit`;
/// with several sets, one the joint answer does not suit means they contradict each other —
/// a warning names it, and the fit gives no answer (exit 1, nothing saved): a tight answer
/// between data that disagree would be wrong for both.
pub(super) fn verdict(f: &mut MultiFit, sets: &[SetFit]) {
    let worst = sets
        .iter()
        .filter_map(|s| s.lack_of_fit)
        .min_by(|a, b| a.p_value.total_cmp(&b.p_value));
    f.lack_of_fit = worst;
    for s in sets {
        let Some(t) = s.lack_of_fit.filter(LackOfFit::significant) else {
            continue;
        };
        let what = if sets.len() > 1 {
            "the data sets contradict each other: the joint answer does not suit"
        } else {
            "the model cannot follow"
        };
        f.warnings.push(format!(
            "{what} the {} {} ({} test {} = {}, p = {})",
            s.kind,
            s.label,
            t.test,
            match t.test {
                "runs" => "z",
                "F" => "F",
                _ => "χ²",
            },
            crate::text::sig(t.statistic, 3),
            crate::text::sig(t.p_value, 2)
        ));
        if sets.len() > 1 {
            f.identified = false;
        }
    }
}

/// Whether a joint fit found its sets in contradiction (a set's test significant).
pub fn contradicted(sets: &[SetFit]) -> bool {
    sets.len() > 1
        && sets
            .iter()
            .any(|s| s.lack_of_fit.is_some_and(|t| t.significant()))
}
