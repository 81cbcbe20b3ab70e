//! A reproducible spread of balls for the tests that hold a fast path to `run`
//! (tests/rows.rs, tests/run_summary.rs).

use bouncelab::ImpactParams;

/// A reproducible spread of balls: each parameter a decade either side of the superball's.
pub fn balls(seed: u64, count: usize) -> Vec<ImpactParams> {
    let mut x = seed;
    let mut next = || {
        // xorshift64*: plain, seeded, enough to spread test points
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        (x.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut spread = |v: f64| v * 10f64.powf(2.0 * next() - 1.0);
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
