//! Oblique impacts on a surface that gives or moves (`surface::solve_on`, docs/oblique.md §11).

use super::{Oblique, solve_law, solve_on};
use crate::api::Ball;
use crate::model::contact::ContactLaw;
use crate::target::{Target, collide};

/// The tennis ball at the ITF court test's tangential model, μ = 0.6, at `angle`.
fn tennis(angle: f64) -> (Ball, Oblique) {
    let b = Ball::from_preset("tennis").unwrap();
    let o = Oblique::new(
        angle,
        0.0,
        0.6,
        b.tangential_stiffness().unwrap(),
        b.inertia_factor(),
        b.radius(),
    )
    .unwrap();
    (b, o)
}

/// A court that gives: K_s = K_p, c_s = 50 kg/s (a test surface, no court's data).
fn soft(b: &Ball) -> Target {
    Target {
        stiffness: b.params.k_p,
        damping: 50.0,
        ..Target::wall()
    }
}

#[test]
fn at_90_degrees_it_is_the_normal_impact_on_that_surface() {
    for law in [ContactLaw::Linear, ContactLaw::Hertz] {
        let (b, o) = tennis(90.0);
        let t = soft(&b);
        let r = solve_on(&b.params, law, 20.0, &o, &t, 0).unwrap();
        let c = collide(&b.params, law, &t, 20.0, None).unwrap();
        assert_eq!(r.cor_normal, c.cor, "{law}");
        assert!((r.v_out - c.ball_speed_out).abs() <= 1e-12 * 20.0, "{law}");
        assert_eq!(r.vx_out, 0.0);
        assert_eq!(r.spin_out, 0.0);
        assert_eq!(r.max_normal_force, c.max_force);
        // the surface took something: e below the rigid plate's
        let rigid = solve_law(&b.params, law, 20.0, &o, 0).unwrap();
        assert!(r.cor_normal < rigid.cor_normal - 0.01, "{law}");
    }
}

#[test]
fn a_rigid_immovable_surface_is_todays_answer_bit_for_bit() {
    let (b, o) = tennis(16.0);
    let on = solve_on(&b.params, b.law, 30.0, &o, &Target::wall(), 0).unwrap();
    let today = solve_law(&b.params, b.law, 30.0, &o, 0).unwrap();
    assert_eq!(on.v_out.to_bits(), today.v_out.to_bits());
    assert_eq!(on.angle_out_deg.to_bits(), today.angle_out_deg.to_bits());
    assert_eq!(on.spin_out.to_bits(), today.spin_out.to_bits());
    assert_eq!(on.cor_normal.to_bits(), today.cor_normal.to_bits());
}

/// Two independent paths: the chain's force sampled by the compliant solver and read on its
/// spline (a surface that moves, but so heavy it does not: M = 10¹² kg), against the rigid
/// plate's closed-form normal motion. Sliding (16°) and gripping (60°) bounces.
#[test]
fn a_heavy_surface_agrees_with_the_rigid_plate() {
    for angle in [16.0, 60.0] {
        let (b, o) = tennis(angle);
        let heavy = Target {
            mass: 1e12,
            ..Target::wall()
        };
        let on = solve_on(&b.params, b.law, 30.0, &o, &heavy, 0).unwrap();
        let today = solve_law(&b.params, b.law, 30.0, &o, 0).unwrap();
        let near = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs().max(1.0);
        assert!(near(on.cor_normal, today.cor_normal, 1e-9), "{angle}");
        assert!(
            near(on.v_out, today.v_out, 1e-7),
            "{angle}: {} {}",
            on.v_out,
            today.v_out
        );
        assert!(near(on.spin_out, today.spin_out, 1e-6), "{angle}");
        assert!(near(on.angle_out_deg, today.angle_out_deg, 1e-7), "{angle}");
        assert!(on.energy.residual < 1e-6, "{angle}: {}", on.energy.residual);
    }
}
