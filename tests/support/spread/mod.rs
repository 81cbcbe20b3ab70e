//! A reproducible spread of balls for the tests that hold a fast path to `run`
//! (tests/physics/rows.rs, tests/physics/run_summary.rs).

use crate::seeded;

use bouncelab::ImpactParams;

/// A reproducible spread of balls: each parameter a decade either side of the superball's,
/// log-uniform, from the tests' seeded generator (tests/support/seeded/mod.rs).
pub fn balls(seed: u64, count: usize) -> Vec<ImpactParams> {
    let mut rng = seeded::Seeded::new(seed);
    let mut spread = |v: f64| rng.log_uniform(v / 10.0, v * 10.0);
    (0..count)
        .map(|_| {
            let (k_p, z_p) = (spread(5.45e4), spread(2e-3));
            ImpactParams {
                mass: spread(0.0495),
                k_p,
                k_r: spread(7.08e4),
                damping: spread(10.0),
                z_p,
                k_h: ImpactParams::k_h_matching(k_p, z_p),
                v0: spread(3.12),
            }
        })
        .filter(|p| p.validate().is_ok())
        .collect()
}
