//! Issue 54 item 10: the elastic–plastic map's stiff corner. The tennis ball's map
//! (`bouncelab map --preset tennis --law elastic-plastic --lambda 0.01:100 --zeta 0.01:100`)
//! spent 5.3 of its 5.8 s in the quarter λ, ζ ∈ [1, 100]: impacts past yield whose unloading
//! is too stiff for the Taylor steps' usual few, each left to the adaptive solver
//! (BENCHMARKS.md). Those cells are now answered by the fast summary (`solver::table::summary`,
//! which the map, the Monte Carlo and Python's `impacts` take) through the Taylor steps given
//! the steps their stiffness needs (`taylor::stiff_summary`). Two independent paths: each such
//! answer is held to the implicit steps of `solver::stiff` (extrapolated linearly implicit
//! Euler at 1e-12) to 1e-9 in e, F̄_m, τ_f and z̄_m (z̄_f to 1e-9 of z̄_m) — what
//! docs/numerics.md promises of the fast paths — and to the adaptive solver at rtol 1e-13 to
//! its own precision where it ran stiff, 1e-6 (docs/numerics.md; it is the loosest of the three:
//! 6e-7 from both at golf, 60 m/s, λ = 36, ζ = 65), 1e-9 elsewhere.

use bouncelab::solver::taylor::Summary;
use bouncelab::solver::{stiff, table};
use bouncelab::{Ball, ContactLaw, ImpactParams, SolveOptions, simulate};

/// `n` values from `lo` to `hi`, evenly spaced in the logarithm.
fn log_axis(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The largest relative gap in e, F̄_m, τ_f, z̄_m (z̄_f against z̄_m) between two summaries.
fn apart(a: &Summary, b: &Summary) -> f64 {
    let rel = |x: f64, y: f64| (x - y).abs() / y.abs();
    [
        rel(a.cor, b.cor),
        rel(a.max_force, b.max_force),
        rel(a.contact_time, b.contact_time),
        rel(a.max_indentation, b.max_indentation),
        (a.permanent_indentation - b.permanent_indentation).abs() / b.max_indentation,
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

/// The gaps of the fast summary of `p` to the implicit steps and to the adaptive solver at
/// rtol 1e-13 (and whether that run was stiff), or `None` where the fast summary does not
/// answer.
fn gaps(p: &ImpactParams, law: ContactLaw) -> Option<(f64, f64, bool)> {
    let n = p.normalized();
    let fast = table::summary(&n, law)?;
    let implicit = stiff::summary(&n, law).expect("the implicit steps answer");
    let tight = SolveOptions {
        rtol: 1e-13,
        ..SolveOptions::default()
    };
    let r = simulate(p, law, &tight).unwrap();
    assert!(
        r.rebound,
        "{p:?}: the solver says no rebound, the fast path {fast:?}"
    );
    let length = p.v0 / p.omega0();
    let solver = Summary {
        cor: r.cor,
        max_force: r.max_force_normalized,
        contact_time: r.contact_time_normalized.unwrap(),
        max_indentation: r.max_indentation / length,
        permanent_indentation: r.permanent_indentation / length,
        ..fast
    };
    Some((apart(&fast, &implicit), apart(&fast, &solver), r.stiff))
}

/// The bound against the adaptive solver: its own precision, 1e-6 where it ran stiff.
fn solver_bound(stiff: bool) -> f64 {
    if stiff { 1e-6 } else { 1e-9 }
}

#[test]
fn the_stiff_corner_of_the_elastic_plastic_map_is_answered_to_the_solvers_precision() {
    let tennis = Ball::from_preset("tennis").unwrap().params;
    let law = ContactLaw::ElasticPlastic;
    let (mut worst, mut worst_solver, mut cells) = (0.0f64, 0.0f64, 0);
    let mut missed = Vec::new();
    for &lambda in &log_axis(1.0, 100.0, 6) {
        for &zeta in &log_axis(1.0, 100.0, 6) {
            let p = tennis.with_lambda_zeta(lambda, zeta);
            cells += 1;
            match gaps(&p, law) {
                Some((d, s, stiff)) => {
                    assert!(
                        d <= 1e-9,
                        "λ = {lambda}, ζ = {zeta}: {d:e} from the implicit steps"
                    );
                    let bound = solver_bound(stiff);
                    assert!(
                        s <= bound,
                        "λ = {lambda}, ζ = {zeta}: {s:e} from rtol 1e-13"
                    );
                    worst = worst.max(d);
                    worst_solver = worst_solver.max(s);
                }
                None => missed.push((lambda, zeta)),
            }
        }
    }
    eprintln!(
        "{cells} cells of the stiff corner: widest gap {worst:e} to the implicit steps, \
         {worst_solver:e} to the adaptive solver"
    );
    // on the old code every one of them went to the adaptive solver
    assert!(
        missed.is_empty(),
        "not answered by the fast summary: {missed:?}"
    );
}

#[test]
fn stiff_impacts_past_yield_agree_at_other_balls_and_speeds() {
    // the golf ball, the superball and the tennis ball past yield, weak dashpots against
    // stiff springs
    let law = ContactLaw::ElasticPlastic;
    let (mut worst, mut worst_solver, mut answered) = (0.0f64, 0.0f64, 0);
    for (name, v0) in [("golf", 60.0), ("superball", 9.4), ("tennis", 40.0)] {
        let ball = Ball::from_preset(name).unwrap().params;
        for &lambda in &log_axis(0.5, 300.0, 4) {
            for &zeta in &log_axis(3.0, 300.0, 4) {
                let p = ImpactParams {
                    v0,
                    ..ball.with_lambda_zeta(lambda, zeta)
                };
                if let Some((d, s, stiff)) = gaps(&p, law) {
                    let at = format!("{name} at {v0} m/s, λ = {lambda}, ζ = {zeta}");
                    assert!(d <= 1e-9, "{at}: {d:e} from the implicit steps");
                    assert!(s <= solver_bound(stiff), "{at}: {s:e} from rtol 1e-13");
                    worst = worst.max(d);
                    worst_solver = worst_solver.max(s);
                    answered += 1;
                }
            }
        }
    }
    eprintln!(
        "{answered} impacts answered by the fast summary: widest gap {worst:e} to the implicit \
         steps, {worst_solver:e} to the adaptive solver"
    );
    assert!(answered >= 30, "{answered} answered");
}
