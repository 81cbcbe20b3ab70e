//! Issue 54 item 2: an oblique impact's work is bounded. A tiny inertia factor or a huge K_t
//! once asked the tangential search for 10⁸–10¹⁰ grid points (3–9.9 GB, an abort, exit 134) or
//! overflowed its length (a panic, exit 101); K_t was the one parameter with no upper bound
//! (`peers --export … --tangential-stiffness 1e308` exported 1e308). Now: one line naming the
//! field, exit 2, and K_t in 1e-15 … 1e15 N/m as every positive parameter.

use crate::common;
use bouncelab::api::ObliqueSpec;
use bouncelab::{Ball, BallError};
use common::{argv, argv_with, bad};

#[test]
fn a_tiny_inertia_factor_is_refused_naming_it() {
    // the reproduction: 9.9 GB asked, abort (exit 134)
    bad(
        &argv("oblique --preset tennis --angle 16 --friction 0.6 --inertia-factor 1e-15"),
        &["invalid inertia_factor: 1e-15", "search steps"],
    );
}

#[test]
fn a_huge_tangential_stiffness_is_refused_naming_it() {
    // the reproduction: "capacity overflow", exit 101
    bad(
        &argv(
            "oblique --preset tennis --law hertz --angle 30 --friction 0.4 \
            --tangential-stiffness 1e308",
        ),
        &["invalid tangential_stiffness: 1e308", "1e-15 … 1e15"],
    );
    for k in ["1e-16", "1e16"] {
        bad(
            &argv_with(
                "oblique --preset tennis --angle 30 --friction 0.4 --tangential-stiffness {}",
                &[k],
            ),
            &["invalid tangential_stiffness", "1e-15 … 1e15"],
        );
    }
}

#[test]
fn peers_export_bounds_the_tangential_stiffness() {
    bad(
        &argv("peers --preset tennis --export json --friction 0.5 --tangential-stiffness 1e308"),
        &["invalid tangential_stiffness: 1e308"],
    );
}

fn field_of(e: BallError) -> &'static str {
    match e {
        BallError::Invalid { field, .. } => field,
        other => panic!("not a refusal naming a field: {other:?}"),
    }
}

fn spec(k_t: Option<f64>, kappa: Option<f64>) -> ObliqueSpec {
    ObliqueSpec {
        v: Some(25.0),
        angle_deg: 16.0,
        spin: 0.0,
        friction: 0.6,
        tangential_stiffness: k_t,
        inertia_factor: kappa,
    }
}

#[test]
fn inside_the_ranges_the_work_is_bounded_too() {
    // κ = 1e-14 lies inside (0, 1] and took 3 GB and 11 s; K_t = 1e15 at the range's top
    // stalled the explorer 37 s (10⁷ points for each of its 90 angles)
    let tennis = Ball::from_preset("tennis").unwrap();
    for law in ["linear", "hertz"] {
        let ball = Ball {
            law: law.parse().unwrap(),
            ..tennis.clone()
        };
        let e = ball.oblique(&spec(None, Some(1e-14)), 0).unwrap_err();
        assert_eq!(field_of(e), "inertia_factor", "{law}");
        let e = ball.oblique(&spec(Some(1e15), None), 0).unwrap_err();
        assert_eq!(field_of(e), "tangential_stiffness", "{law}");
        // a stiff but resolvable spring still answers, the grid at its bound or below
        let k_p = ball.params.k_p;
        let r = ball.oblique(&spec(Some(1e3 * k_p), None), 0).unwrap();
        assert!(
            r.vx_out.is_finite() && r.energy.residual.abs() < 1e-9,
            "{law}"
        );
    }
}
