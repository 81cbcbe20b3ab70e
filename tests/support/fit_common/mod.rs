//! Measured data made by the solver from known parameters, with noise and a time offset the
//! fit is not told: what the recovery tests fit back.
#![allow(dead_code)]

mod bench_ball;
mod force;
pub mod oblique;

pub use force::force_at;

use bouncelab::analysis::fit::Estimate;
use bouncelab::measured::{CorPoint, Trace};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

use crate::seeded;

/// The tests' seeded generator (tests/support/seeded/mod.rs): every test run draws the same noise.
pub type Rng = seeded::Seeded;

/// The estimate's 95 % interval holds `truth`.
pub fn covers(e: &Estimate, truth: f64) -> bool {
    e.ci95[0] <= truth && truth <= e.ci95[1]
}

/// A ball no preset has, benches/fit.rs's with z_p = 1 mm: m = 50 g, v0 = 2 m/s,
/// K_p = 8e4 N/m, K_r = 1.2e5 N/m (λ = 1.5), c = 60 kg/s (ζ ≈ 0.53), and the contact flattens
/// from about 1.6 m/s, where F_m = K_p z_p.
pub fn truth() -> ImpactParams {
    let bench = bench_ball::truth();
    ImpactParams {
        z_p: 1e-3,
        k_h: ImpactParams::k_h_matching(bench.k_p, 1e-3),
        ..bench
    }
}

/// The truth's ball as the fit is given it: m, v0 and z_p known, the rest far off.
pub fn guess(t: &ImpactParams) -> ImpactParams {
    ImpactParams {
        k_p: t.k_p * 2.5,
        damping: t.damping * 0.4,
        k_r: t.k_r * 0.3,
        ..*t
    }
}

/// A recorder's trace: `grid` = (n, dt), n samples dt apart from t = −1.7 ms, the contact starting at
/// `offset` (s), Gaussian noise of `sd` newtons on a `baseline`.
pub fn trace(
    p: &ImpactParams,
    law: ContactLaw,
    offset: f64,
    sd: f64,
    baseline: f64,
    grid: (usize, f64),
    rng: &mut Rng,
) -> Trace {
    let (n, dt) = grid;
    let r = simulate(p, law, &SolveOptions::default().with_samples(4_001)).unwrap();
    let h = &r.history;
    let tf = *h.t.last().unwrap();
    let mut text = String::from("# synthetic\ntime_ms;force_N\n");
    for i in 0..n {
        let t = -1.7e-3 + i as f64 * dt;
        let f = force_at(h, tf, t - offset);
        text.push_str(&format!(
            "{};{}\n",
            t * 1e3,
            f + baseline + sd * rng.normal()
        ));
    }
    Trace::parse(&text).unwrap()
}

/// COR at each speed, with Gaussian noise of `sd`.
pub fn cor_table(
    p: &ImpactParams,
    law: ContactLaw,
    speeds: &[f64],
    sd: f64,
    rng: &mut Rng,
) -> Vec<CorPoint> {
    speeds
        .iter()
        .map(|&v0| {
            let e = simulate(&ImpactParams { v0, ..*p }, law, &SolveOptions::default())
                .unwrap()
                .cor;
            CorPoint {
                v0,
                cor: (e + sd * rng.normal()).clamp(0.0, 1.0),
                cor_sd: None,
                cor_sd_relative: 1.0,
                max_force: None,
                contact_time: None,
                line: 0,
            }
        })
        .collect()
}
