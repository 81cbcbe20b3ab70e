//! A trace whose first sample is the contact's start (issue 52: `run --history` writes the
//! contact alone, a trace cropped to its pulse does the same): no quiet stretch before the
//! pulse tells the start t0 and the baseline b apart from the pulse's shape.
//!
//! The cost is kinked at t0 = the first sample's time t₁: with t0 after it, the first sample
//! is baseline alone (the model's F(t − t0) = 0 there) and pins b; with t0 before it, every
//! sample is inside the contact, and an earlier start with a lower baseline (and a softer
//! recoil spring) fits the visible pulse almost as well — the Jacobian's covariance differs
//! by a factor 10 to 20 in b and t0 on the two sides. A fit ending on one side takes the
//! curvature of that side alone. Measured (tests/analysis/fit_coverage.rs, the superball trace,
//! 500 seeds, v0 free): of the 288 fits ending after t₁ the Jacobian's intervals held v0 74 %
//! of the time, t0 77 %, b 74 %; of the 212 before it, 98–99 %. The residual scatter was
//! not the cause (s = 3.00 N on σ = 3 N; σ itself in place of s changed no count by more than
//! 3), nor the start (fits started at the truth ended on the same minima).
//!
//! The rule: when the fitted pulse starts within the trace's first tenth (or t0's interval
//! reaches back to t₁), the fit is done again with t0 held on the other side of t₁
//! (Levenberg–Marquardt from the first minimum, t0's bound moved to t₁). The estimate is the
//! lower of the two minima (the least-squares one; in 12 of the first 100 seeds the lower
//! one is on the second side: `lower_minimum_on_the_other_side_is_reported`), and each 95 % interval is
//! the hull of the two sides' intervals (each the Jacobian's on its side): the union of a
//! set that holds the truth 95 % of the time when t0 lies before t₁ and one that does when
//! it lies after, so a set that holds it at least 95 % of the time wherever it lies.
//!
//! A sound other side joins the hull without the profile-t test of t0 = t₁ (its cost above the lower's
//! by at most s² t₀.₉₇₅², Bates & Watts §6.1, as `super::profile`): that test assumes a smooth
//! cost, and here it is kinked at every row the start crosses (the
//! pulse opens with a ramp, F ≈ K_p v0 (t − t0)): with the truth at t₁ (the superball
//! trace), τ² passed t₀.₉₇₅² in 20 of the first 100 seeds where 5 were due, and most of
//! the t0 and baseline intervals that missed were those. A side whose fit ran a parameter
//! to its bound, left one unpinned, or cannot follow the data (the runs test of
//! `verdict::runs_test`: a trace with a quiet stretch, its start forced before the first
//! row) still joins the hull where the test keeps it (the intervals are then unknown where
//! it pinned nothing), and is left out where the test rejects it.

use super::lm::{self, Best, Solution};
use super::result::{Estimate, MultiFit, MultiFitError};
use super::stats::{t975, uncertainty};
use super::trace::TraceProblem;
use super::verdict;

/// The warning a fit whose intervals span both sides of the first sample carries.
pub const BOTH_SIDES: &str = "the contact starts at the trace's first row (no quiet stretch \
before it): the start may lie before it, and the 95 % intervals span the fits on both sides";

/// The warning a fit of a contact-only trace with the speed free carries beside
/// [`BOTH_SIDES`]: the one interval that still holds the truth less often than it says
/// (tests/analysis/fit_coverage.rs, `speed_free_trace_intervals_cover_the_truth_over_many_seeds`).
pub const K_R_SHORT: &str = "with the speed fitted and the contact starting at the first \
row, k_r's 95 % interval held the truth 92 % of the time in a trial of 500 traces: give --v0 \
where the speed was measured";

/// Widen `f`'s intervals to the hull of both sides of the first sample where the fitted start
/// lies near it (see the module's comment); `iterations` is the budget of the side's fit. Where
/// the other side's minimum is the lower, it becomes the fit (`best` and `f` at it: the
/// least-squares estimate is the lowest minimum, `lower_minimum_on_the_other_side_is_reported`),
/// and the first side's intervals join the hull; `refinish` makes the fit's report at a
/// minimum.
pub(super) fn both_sides(
    p: &TraceProblem,
    best: &mut Best,
    f: &mut MultiFit,
    iterations: usize,
    refinish: impl Fn(&Best) -> Result<MultiFit, MultiFitError>,
) -> Result<(), MultiFitError> {
    let first = p.data.time[0];
    let Some(t0) = &f.time_offset else {
        return Ok(());
    };
    // the pulse starting within the trace's first tenth, which `Trace::summary` would read
    // as quiet: no stretch before it tells t0 and b from the pulse
    let tenth = p.trace.time[p.trace.time.len() / 10];
    if !(t0.value < tenth || t0.ci95[0] <= first) {
        return Ok(());
    }
    let Some(other) = other_side(p, best, first, iterations) else {
        return Ok(());
    };
    let mut other = Best {
        sol: other,
        lo: best.lo.clone(),
        hi: best.hi.clone(),
    };
    if other.sol.cost < best.sol.cost {
        other.sol.iterations += best.sol.iterations;
        std::mem::swap(best, &mut other);
        *f = refinish(best)?;
    }
    hull_other_side(p, best, &other.sol, f);
    Ok(())
}

/// Each of `f`'s intervals the hull of its own and `other`'s (the Jacobian's at the other
/// side's minimum; see the module's comment for when `other` is left out).
fn hull_other_side(p: &TraceProblem, best: &Best, other: &Solution, f: &mut MultiFit) {
    let k = p.k();
    let n = best.sol.residuals.len();
    let dof = n.saturating_sub(k + 2);
    if dof == 0 {
        return;
    }
    let s2 = 2.0 * best.sol.cost / dof as f64;
    let t = t975(dof);
    // τ² of t0 = t₁ (≥ 0: `best` is the lower minimum)
    let tau2 = 2.0 * (other.cost - best.sol.cost) / s2;
    let u = uncertainty(&other.jacobian, &other.residuals);
    let se = |j: usize| u.covariance[(j, j)].sqrt();
    // beyond reach, the other side still joins the hull (the union argument of the module's
    // comment) where its fit pinned everything and follows the data (no lack of fit by the
    // runs test: a trace with a quiet stretch, its start forced before the first row, does
    // not); a side that does not is left out there (within reach, it makes the intervals
    // unknown)
    let usable = (0..k + 2).all(|j| se(j).is_finite())
        && (0..k).all(|j| !verdict::on_bound(other.x[j], best.lo[j], best.hi[j]))
        && verdict::runs_test(&other.residuals).is_none_or(|l| !l.significant());
    if tau2 > t * t && !usable {
        return;
    }
    let hull = |e: &mut Estimate, [a, b]: [f64; 2]| {
        e.ci95 = if a.is_finite() && b.is_finite() {
            [e.ci95[0].min(a), e.ci95[1].max(b)]
        } else {
            [f64::NAN, f64::NAN]
        };
    };
    for (j, e) in f.fitted.iter_mut().enumerate() {
        let (theta, s) = (other.x[j], se(j));
        hull(e, [(theta - u.t975 * s).exp(), (theta + u.t975 * s).exp()]);
    }
    for (j, e) in [(k, f.time_offset.as_mut()), (k + 1, f.baseline.as_mut())] {
        if let Some(e) = e {
            let (x, s) = (other.x[j], se(j));
            hull(e, [x - u.t975 * s, x + u.t975 * s]);
        }
    }
    f.not_pinned = verdict::not_pinned(&f.fitted, best, f.names.len(), f.no_scatter);
    f.warnings.push(BOTH_SIDES.into());
    if p.free.contains(&super::Param::V0) && p.free.contains(&super::Param::KR) {
        f.warnings.push(K_R_SHORT.into());
    }
}

/// The minimum with t0 on the other side of `first` from `best`'s, searched from `best`'s
/// variables (t0 moved just across `first`).
pub(super) fn other_side(
    p: &TraceProblem,
    best: &Best,
    first: f64,
    iterations: usize,
) -> Option<Solution> {
    let k = p.k();
    let (mut lo, mut hi, mut x) = (best.lo.clone(), best.hi.clone(), best.sol.x.clone());
    // a thousandth of the samples' spacing across: the first sample inside the contact (or
    // not) without moving the pulse by anything the data resolve
    let spacing = p.data.time.get(1).map_or(0.0, |t| t - first);
    let across = 1e-3 * spacing.max(1e-9 * (p.summary.t_end - p.summary.t_start));
    if x[k] > first {
        hi[k] = first - across;
        x[k] = hi[k];
    } else {
        lo[k] = first + across;
        x[k] = lo[k];
    }
    if lo[k] > hi[k] {
        return None;
    }
    let opts = lm::Options {
        max_iterations: iterations,
        ..lm::Options::default()
    };
    let s = lm::minimize(p, &x, &lo, &hi, opts)?;
    let finite = s
        .residuals
        .iter()
        .chain(s.jacobian.iter())
        .all(|v| v.is_finite());
    finite.then_some(s)
}

#[cfg(test)]
mod tests;
