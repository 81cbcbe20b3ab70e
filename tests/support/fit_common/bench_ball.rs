//! The ball of benches/fit.rs's force–time trace and the fit's start from it, shared with
//! tests/fit_memory.rs, which reads and fits a dense trace of the same ball (both by
//! `#[path]`, as force.rs beside it).

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
