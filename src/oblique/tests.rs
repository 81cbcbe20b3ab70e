//! The closed forms of a phase (docs/oblique.md §2).

use super::tangential::{Mode, Phase};
use super::{Scaled, mindlin_ratio};
use crate::solver::exact::PathPoint;

#[test]
fn mindlins_ratio_is_two_thirds_for_rubber() {
    assert!((mindlin_ratio(0.5) - 2.0 / 3.0).abs() < 1e-15);
    assert!((mindlin_ratio(0.25) - 6.0 / 7.0).abs() < 1e-15);
    assert_eq!(mindlin_ratio(0.0), 1.0);
}

#[test]
fn a_stick_keeps_the_spring_and_kinetic_energy() {
    // k̃u²/2 + ṽ_c²/(2g) is conserved while sticking: u'' = −ω̃_t² u with ω̃_t² = k̃ g
    let s = Scaled::new(0.6, 0.7, 0.55);
    let ph = Phase {
        start: 0.3,
        end: 3.0,
        mode: Mode::Stick,
        u0: 0.2,
        vc0: -0.7,
        vel0: 0.0,
    };
    let p = PathPoint {
        force: 1.0,
        rate: 0.0,
        velocity: 0.0,
    };
    let e = |(u, vc): (f64, f64)| s.kt * u * u / 2.0 + vc * vc / (2.0 * s.g);
    let e0 = e((ph.u0, ph.vc0));
    for tau in [0.3, 0.9, 1.7, 2.9] {
        assert!((e(ph.state(&s, &p, tau)) - e0).abs() < 1e-15);
    }
    // and u' = v_c, by a central difference
    let d = 1e-6;
    let (up, _) = ph.state(&s, &p, 1.0 + d);
    let (um, _) = ph.state(&s, &p, 1.0 - d);
    let (_, vc) = ph.state(&s, &p, 1.0);
    assert!(((up - um) / (2.0 * d) - vc).abs() < 1e-8);
}
