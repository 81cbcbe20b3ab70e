//! The ball of benches/fit.rs's force–time trace, the fit's start from it and the trace's
//! noise, shared by `#[path]` (as force.rs beside it) with tests/fit_memory.rs, which reads
//! and fits a dense trace of the same ball, and with the library's unit tests (src/lib.rs:
//! the binned fit's, and src/measured/trace.rs's noise); the fit tests' ball
//! (`fit_common::truth`) is it with a finite z_p.
#![allow(dead_code)]

use bouncelab::ImpactParams;

/// The trace's ball (not a preset's): m = 50 g, v0 = 2 m/s, K_p = 8e4, c = 60, K_r = 1.2e5.
pub fn truth() -> ImpactParams {
    ImpactParams {
        mass: 0.05,
        k_p: 8e4,
        damping: 60.0,
        k_r: 1.2e5,
        z_p: 1.0,
        k_h: ImpactParams::k_h_matching(8e4, 1.0),
        v0: 2.0,
    }
}

/// The fit's start: the truth's m and v0, K_p, c and K_r far from it.
pub fn start() -> ImpactParams {
    ImpactParams {
        k_p: 2e5,
        damping: 24.0,
        k_r: 3.6e4,
        ..truth()
    }
}

/// Standard normal numbers from a fixed `seed` (Box–Muller on the top 53 bits of a 64-bit
/// linear congruential sequence): the same noise on every run and machine.
pub fn normals(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    let mut u = move || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    move || {
        let (a, b) = (u(), u());
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}
