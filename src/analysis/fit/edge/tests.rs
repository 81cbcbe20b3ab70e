//! The fit of a contact-only trace reports the lower of the minima on the two sides of its
//! first row.

use super::*;
use crate::analysis::fit::bins::Samples;
use crate::analysis::fit::lm::Residuals;
use crate::analysis::fit::multi::best;
use crate::analysis::fit::{FitData, Param, fit};
use crate::analysis::work::{Unwatched, fit_iterations, fit_run_cost};
use crate::measured::Trace;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};
use chacha20::ChaCha8Rng;
use chacha20::rand_core::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

/// The superball (presets/superball.toml) at speed `v0`.
fn superball(v0: f64) -> ImpactParams {
    let ball = crate::Ball::from_preset("superball").unwrap();
    assert_eq!(ball.law, ContactLaw::Linear);
    ImpactParams { v0, ..ball.params }
}

/// tests/analysis/fit_coverage.rs's `superball_trace` at `seed`: the contact alone at
/// 6.24 m/s, 400 rows, Gaussian noise of 3 N (ChaCha8 seeded as the tests' `Seeded`).
fn superball_trace(seed: u64) -> Trace {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let opts = SolveOptions::default().with_samples(400);
    let r = simulate(&superball(6.24), ContactLaw::Linear, &opts).unwrap();
    let mut text = String::from("t,force\n");
    for (t, f) in r.history.t.iter().zip(&r.history.force) {
        let noise: f64 = StandardNormal.sample(&mut rng);
        text.push_str(&format!("{t},{}\n", f + 3.0 * noise));
    }
    Trace::parse(&text).unwrap()
}

/// Seed 5200 + 71 of the coverage test: the first fit ends after the first row (t0 6.9 µs),
/// and the fit with t0 held before it finds a lower minimum (by 1.8 s²). The old code kept
/// the first (higher) one as the estimate and only widened the intervals to the other's.
#[test]
fn lower_minimum_on_the_other_side_is_reported() {
    let tr = superball_trace(5271);
    let free = [Param::KP, Param::C, Param::KR, Param::V0];
    let start = superball(3.12);
    let law = ContactLaw::Linear;
    let f = fit(&start, law, FitData::Trace(&tr), &free).unwrap();
    assert!(
        f.warnings.iter().any(|w| w == BOTH_SIDES),
        "{:?}",
        f.warnings
    );
    // the fit's two minima, found as `multi::fit_trace` and `both_sides` find them
    let summary = tr.summary().unwrap();
    let data = Samples::of(&tr, &summary);
    let bins = data.len();
    let p = TraceProblem::new(start, law, free.to_vec(), &tr, summary, data, &Unwatched);
    let starts = p.starts();
    let run = fit_run_cost(bins, p.history(), law);
    let iterations =
        fit_iterations(run, free.len() + 2, starts.len() + 1, law, String::new).unwrap();
    let floor = 1.5 * summary.noise;
    let first = best(&p, starts, |x| p.bounds(x), floor, iterations).unwrap();
    let other = other_side(&p, &first, p.data.time[0], iterations).unwrap();
    assert!(
        other.cost < first.sol.cost,
        "{} {}",
        other.cost,
        first.sol.cost
    );
    // the reported fit is the lower one
    let (t0, b) = (f.time_offset.unwrap().value, f.baseline.unwrap().value);
    let x: Vec<f64> = f
        .fitted
        .iter()
        .map(|e| e.value.ln())
        .chain([t0, b])
        .collect();
    let reported = 0.5 * p.residuals(&x).unwrap().iter().map(|r| r * r).sum::<f64>();
    assert!(
        (reported - other.cost).abs() <= 1e-9 * other.cost,
        "reported {reported}, the lower minimum {} (t0 {t0:e} against {:e}), the first {}",
        other.cost,
        other.x[free.len()],
        first.sol.cost
    );
}
