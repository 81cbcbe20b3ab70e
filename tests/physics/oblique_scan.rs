//! The oblique impact against its independent integration (`oblique::reference`, DOP853 with
//! events at every stick/slip switch) at seeded random settings of every input — speed, angle,
//! spin, friction, tangential stiffness and inertia factor — and at the settings where a scan
//! found them apart (issue 31's check: agreement to 1e-8 of the incoming speed).

use bouncelab::oblique::{self, Oblique, reference};
use bouncelab::{Ball, ImpactParams};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn tennis() -> (ImpactParams, f64) {
    let b = Ball::from_preset("tennis").unwrap();
    let r = b.radius();
    (b.params, r)
}

/// |Δv_x|/v and R|Δω|/v between the two, or the panic message naming the setting.
fn apart(p: &ImpactParams, r: f64, v0: f64, o: &Oblique) -> f64 {
    let fast = oblique::solve(p, v0, o, 0).unwrap();
    let (vx, w, _) = reference::solve(p, v0, o).unwrap();
    ((vx - fast.vx_out).abs() / v0).max(r * (w - fast.spin_out).abs() / v0)
}

#[test]
fn the_scans_outliers_agree_with_the_reference() {
    let (p, r) = tennis();
    // (v0, angle, spin, μ, K_t): settings a scan of 162 081 impacts found hard — the second
    // sticks for 1e-3 ω0⁻¹ only at first contact (K̃|ṽ_c| 0.59994 against μF̄'(0) = 0.6)
    for (v0, angle, spin, mu, kt) in [
        (29.0, 65.0, -200.0, 0.45, 15753.3634),
        (21.0, 25.0, 250.0, 0.6, 12346.59806321861),
        (25.0, 45.0, -200.0, 0.6, 11127.93390903778),
    ] {
        let o = Oblique::new(angle, spin, mu, kt, 0.6105, r).unwrap();
        let d = apart(&p, r, v0, &o);
        assert!(
            d < 1e-8,
            "{v0} m/s {angle}° {spin} rad/s μ {mu} K_t {kt}: apart by {d:e}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 300,
        rng_seed: RngSeed::Fixed(31),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn seeded_random_settings_agree_with_the_reference(
        v0 in 5.0..35.0f64,
        angle in 5.0..85.0f64,
        spin in -500.0..500.0f64,
        mu in 0.05..2.0f64,
        kt_ratio in 0.2..2.0f64,
        kappa in 0.4..0.7f64,
    ) {
        let (p, r) = tennis();
        let o = Oblique::new(angle, spin, mu, kt_ratio * p.k_p, kappa, r).unwrap();
        let d = apart(&p, r, v0, &o);
        prop_assert!(d < 1e-8, "apart by {:e}", d);
    }
}
