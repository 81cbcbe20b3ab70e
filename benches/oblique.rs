//! Speed of one oblique impact (median recorded in BENCHMARKS.md), beside the linear normal
//! impact timed in the same run. Run: `cargo bench --bench oblique`.

use bouncelab::oblique::{Oblique, mindlin_ratio, solve, solve_law};
use bouncelab::solver::{SolveOptions, simulate};
use bouncelab::{Ball, ContactLaw, ImpactParams};
use divan::black_box;

fn main() {
    divan::main();
}

/// The tennis ball and the oblique impact: 25 m/s at 16° with 300 rad/s of topspin,
/// μ = 0.6, Mindlin's K_t.
fn tennis_oblique() -> (ImpactParams, Oblique) {
    let ball = Ball::from_preset("tennis").unwrap();
    let p = ball.params;
    let k_t = mindlin_ratio(0.5) * p.k_p;
    let o = Oblique::new(16.0, 300.0, 0.6, k_t, ball.inertia_factor(), ball.radius()).unwrap();
    (p, o)
}

/// The tennis ball at the normal speed of [`tennis_oblique`]'s impact, 25 sin 16° m/s.
fn tennis_normal() -> ImpactParams {
    let mut p = Ball::from_preset("tennis").unwrap().params;
    p.v0 = 25.0 * 16f64.to_radians().sin();
    p
}

/// One oblique impact, linear law: the tennis example, 25 m/s at 16° with 300 rad/s of
/// topspin, μ = 0.6, Mindlin's K_t (target: median ≤ 5 µs).
#[divan::bench]
fn oblique_impact(b: divan::Bencher) {
    let (p, o) = tennis_oblique();
    b.bench(|| solve(black_box(&p), 25.0, black_box(&o), 0).unwrap().v_out);
}

/// The normal impact alone at the same normal speed, summary only (as `run`, no energy audit).
#[divan::bench]
fn normal_impact(b: divan::Bencher) {
    time_normal(b, ContactLaw::Linear);
}

/// The same oblique impact on the Hertz law: the normal motion is the adaptive solver's run
/// with its flow kept (docs/oblique.md §2), read point by point (no power series there).
#[divan::bench]
fn oblique_impact_hertz(b: divan::Bencher) {
    let (p, o) = tennis_oblique();
    b.bench(|| {
        solve_law(black_box(&p), ContactLaw::Hertz, 25.0, black_box(&o), 0)
            .unwrap()
            .v_out
    });
}

/// The normal Hertz impact alone at the same normal speed, summary only.
#[divan::bench]
fn normal_impact_hertz(b: divan::Bencher) {
    time_normal(b, ContactLaw::Hertz);
}

/// The normal impact of [`tennis_normal`] under `law`, summary only.
fn time_normal(b: divan::Bencher, law: ContactLaw) {
    let (p, opts) = (tennis_normal(), SolveOptions::default());
    b.bench(|| simulate(black_box(&p), law, &opts).unwrap().cor);
}
