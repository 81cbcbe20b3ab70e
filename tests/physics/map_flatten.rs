//! The flattening cells' closed form (`map::fast::flattening`, issue 30 item 2) against the
//! exact solver (`bouncelab run`'s answer for the linear law) over the flattening domain:
//! wherever it answers, e, F̄_m and τ_f agree to 1e-12 — the promise the no-flattening closed
//! form keeps (tests/physics/map_precision.rs) — and it answers over most of the domain.

use bouncelab::map::fast::{Summary, flattening, summary};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// The closed form's answer at (λ, ζ, z̄_p) and the exact solver's worst relative difference
/// over e, F̄_m and τ_f (asserted below 1e-12), or `None` where the closed form does not
/// answer.
fn against_exact(l: f64, z: f64, zp: f64) -> Option<(Summary, f64)> {
    let s = flattening(l, z, zp)?;
    let p = ImpactParams::from_normalized(l, z, zp);
    let r = simulate(&p, ContactLaw::Linear, &SolveOptions::default()).unwrap();
    let tf = r.contact_time_normalized.unwrap_or(f64::NAN);
    let d = rel(s.cor, r.cor)
        .max(rel(s.max_force, r.max_force_normalized))
        .max(rel(s.contact_time, tf));
    assert!(
        d < 1e-12,
        "λ = {l}, ζ = {z}, z̄_p = {zp}: {d:e} {s:?} vs e = {}, F̄_m = {}, τ_f = {tf}",
        r.cor,
        r.max_force_normalized
    );
    Some((s, d))
}

/// Over a log grid of the flattening domain — λ = 1e-6 … 1e4, ζ = 1e-3 … 1e3, z̄_p from 1e-4
/// of the peak to just below it — the closed form agrees with the exact solver to 1e-12
/// wherever it answers, and answers at most points where the ball flattens (2 424 of 2 844:
/// its rounding bound leaves the rest, a small e after a deep flattening, to the steps).
#[test]
fn flattening_agrees_with_the_exact_solver_over_the_domain() {
    // the benchmark's ball (benches/solver.rs, case 3) and a peak just above z̄_p
    for (l, z, zp) in [(1.3, 0.16, 0.3), (1.0, 0.1, 0.8766346203766)] {
        assert!(
            against_exact(l, z, zp).is_some(),
            "λ = {l}, ζ = {z}, z̄_p = {zp}"
        );
    }
    let (mut answered, mut flattening_cells, mut worst) = (0, 0, 0.0f64);
    for i in 0..=20 {
        for j in 0..=24 {
            let (l, z) = (
                10f64.powf(-6.0 + 0.5 * i as f64),
                10f64.powf(-3.0 + 0.25 * j as f64),
            );
            let Some(peak) = summary(l, z).map(|s| s.max_force) else {
                continue;
            };
            for f in [1e-4, 1e-2, 0.1, 0.5, 0.9, 0.999] {
                flattening_cells += 1;
                if let Some((_, d)) = against_exact(l, z, f * peak) {
                    answered += 1;
                    worst = worst.max(d);
                }
            }
        }
    }
    eprintln!("flattening vs exact: worst {worst:e}, {answered} of {flattening_cells} answered");
    assert!(
        answered * 100 >= flattening_cells * 80,
        "{answered} of {flattening_cells}"
    );
}

/// The tennis ball's cells over the explorer's plane, λ and ζ = 10^(−3 + `step` i) for i in
/// 0 ..= `steps`, where it flattens (the peak of the answer without flattening passes z̄_p):
/// (λ, ζ, z̄_p) of each, ζ running fastest.
pub(crate) fn tennis_flattening_cells(step: f64, steps: usize) -> Vec<(f64, f64, f64)> {
    let ball = bouncelab::Ball::from_preset("tennis").unwrap();
    let mut cells = Vec::new();
    for i in 0..=steps {
        for j in 0..=steps {
            let (l, z) = (
                10f64.powf(-3.0 + step * i as f64),
                10f64.powf(-3.0 + step * j as f64),
            );
            let n = ball.params.with_lambda_zeta(l, z).normalized();
            match summary(n.lambda, n.zeta) {
                Some(s) if s.max_force <= n.zp_bar => continue,
                _ => cells.push((n.lambda, n.zeta, n.zp_bar)),
            }
        }
    }
    cells
}

/// The tennis ball (which flattens over most of its map) over the explorer's whole plane,
/// λ and ζ = 1e-3 … 1e3: wherever the ball flattens, the closed form agrees with the exact
/// solver to 1e-12 and answers at nearly every cell (the map's cost is these cells).
#[test]
fn the_tennis_ball_flattens_in_closed_form() {
    let cells = tennis_flattening_cells(0.2, 30);
    let flattening_cells = cells.len();
    let answered = cells
        .iter()
        .filter(|&&(l, z, zp)| against_exact(l, z, zp).is_some())
        .count();
    eprintln!("tennis: {answered} of {flattening_cells} flattening cells answered");
    assert!(
        answered * 100 >= flattening_cells * 90,
        "{answered} of {flattening_cells}"
    );
}

/// Seeded random points over the flattening domain (λ = 1e-6 … 1e4, ζ = 1e-3 … 1e3, log-
/// uniform; z̄_p a log-uniform 1e-4 … 1 of the peak): wherever the closed form answers it is
/// the exact solver's answer to 1e-12 — among them the unloadings whose separation comes
/// from the pair's phase (`search::fall_from_turn`), which must not take a root past a reload
/// (the exact solver follows a reload: its answer would differ).
#[test]
fn random_flattening_balls_agree_with_the_exact_solver() {
    let mut seeded = crate::seeded::Seeded::new(0x2545_f491_4f6c_dd1d_u64);
    let mut next = || seeded.uniform();
    let (mut answered, mut cells, mut worst) = (0, 0, 0.0f64);
    while cells < 4000 {
        let (l, z) = (
            10f64.powf(-6.0 + 10.0 * next()),
            10f64.powf(-3.0 + 6.0 * next()),
        );
        let f = 10f64.powf(-4.0 * next());
        let Some(peak) = summary(l, z).map(|s| s.max_force) else {
            continue;
        };
        cells += 1;
        if let Some((_, d)) = against_exact(l, z, f * peak) {
            answered += 1;
            worst = worst.max(d);
        }
    }
    eprintln!("random flattening balls: worst {worst:e}, {answered} of {cells} answered");
    assert!(answered * 100 >= cells * 80, "{answered} of {cells}");
}
