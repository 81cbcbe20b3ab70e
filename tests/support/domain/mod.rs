//! The property tests' domain as proptest strategies: λ ∈ [0, 1e4], ζ ∈ [1e-4, 1e4],
//! v0 ∈ (0, 200] m/s, and a ball of random mass, stiffness and flattening at random λ, ζ
//! (tests/physics/properties.rs; tests/physics/taylor.rs holds the Taylor steps to the solvers
//! over the same balls).
#![allow(dead_code)]

use bouncelab::ImpactParams;
use proptest::prelude::*;

/// log-uniform in [lo, hi]
pub fn log_range(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..=hi.ln()).prop_map(f64::exp)
}

/// λ over [0, 1e4]: the edges themselves, log-uniform over the decades from 1e-6, again over
/// (1e-11, 1e-6) (a recoil spring so soft that it releases the ball over ~1/(2ζλ) ω0⁻¹, where
/// the exact solver's propagator had to be split into its fast and slow modes) and over
/// (1e-15, 1e-11) (softer still: the nonlinear laws' creeps end there below the integrators'
/// tolerance, in closed form, see `solver::numeric::creep`), and uniform (which mostly lands in
/// the top decade, where K_r is nearly rigid).
pub fn lambda() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        1 => Just(1e4),
        6 => log_range(1e-6, 1e4),
        2 => log_range(1e-11, 1e-6),
        1 => log_range(1e-15, 1e-11),
        2 => 0.0..=1e4,
    ]
}

/// ζ over [1e-4, 1e4], log-uniform, with the edges and critical damping (ζ = 1 at λ = 0).
pub fn zeta() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(1e-4),
        1 => Just(1e4),
        1 => Just(1.0),
        8 => log_range(1e-4, 1e4),
    ]
}

/// v0 over (0, 200] m/s, log-uniform from 1 mm/s.
pub fn v0() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(200.0), 9 => log_range(1e-3, 200.0)]
}

/// A ball of random mass, contact stiffness, flattening and speed, at random λ, ζ.
pub fn ball() -> impl Strategy<Value = ImpactParams> {
    (
        lambda(),
        zeta(),
        v0(),
        log_range(1e-3, 10.0),
        log_range(1e2, 1e8),
        // flattening from a hundredth of a micron to a decimetre, or none at all
        prop_oneof![1 => Just(f64::INFINITY), 5 => log_range(1e-8, 1e-1)],
        // K_h around the Eq. 16 match, off by up to a decade either way
        log_range(0.1, 10.0),
    )
        .prop_map(|(lambda, zeta, v0, mass, k_p, z_p, k_h_factor)| {
            let k_h_at = if z_p.is_finite() { z_p } else { 1e-3 };
            ImpactParams {
                mass,
                k_p,
                damping: 1.0,
                k_r: 0.0,
                z_p,
                k_h: ImpactParams::k_h_matching(k_p, k_h_at) * k_h_factor,
                v0,
            }
            .with_lambda_zeta(lambda, zeta)
        })
}
