//! The sampled history of a two-body impact (`history`): the run whose numbers `collide`
//! reports, the exact flow and the integrator's dense output agreeing point by point, and the
//! target's displacement leaving at the speed the impulse gives it.

use super::history::Samples;
use super::tests::{preset, rel, unflattened};
use super::*;

/// A rigid target's history is today's history of the reduced ball at the closing speed; the
/// target's displacement leaves at the speed change J/M the impulse gives it.
#[test]
fn a_rigid_targets_history_is_the_reduced_balls() {
    let p = preset("baseball");
    let bat = Target {
        mass: 0.8,
        speed: 30.0,
        ..Target::wall()
    };
    let h = history(&p, ContactLaw::Linear, &bat, 40.0, 400).unwrap();
    let c = &h.collision;
    let reduced = ImpactParams {
        mass: c.reduced_mass,
        v0: c.closing_speed,
        ..p
    };
    let opts = SolveOptions::default().with_samples(400);
    let r = simulate(&reduced, ContactLaw::Linear, &opts).unwrap();
    assert_eq!((&h.t, &h.force), (&r.history.t, &r.history.force));
    assert_eq!(h.displacement, r.history.displacement);
    assert!(h.deflection.iter().all(|&s| s == 0.0));
    // the slope of u_t over the last step: (m*/M)(v_c − α') → J/M = m*(1 + e)v_c/M
    let n = h.t.len();
    let slope =
        (h.target_displacement[n - 1] - h.target_displacement[n - 2]) / (h.t[n - 1] - h.t[n - 2]);
    let kick = c.reduced_mass * (1.0 + c.cor) * c.closing_speed / bat.mass;
    assert!(rel(slope, kick) <= 2e-2, "{slope} {kick}");
    assert_eq!(h.target_displacement[0], 0.0);
    // a wall does not move
    let wall = history(&p, ContactLaw::Linear, &Target::wall(), 40.0, 50).unwrap();
    assert!(wall.target_displacement.iter().all(|&u| u == 0.0));
}

/// On a compliant surface (linear law, no flattening) the exact flow's samples and the
/// integrator's dense output agree point by point, and the history reaches the reported peaks
/// and ends where the force returns to zero.
#[test]
fn the_exact_and_the_integrated_histories_agree() {
    let p = unflattened("golf");
    let target = Target {
        mass: 0.6,
        speed: 2.0,
        stiffness: 2.0 * p.k_p,
        damping: 0.5 * (p.mass * p.k_p).sqrt(),
    };
    let h = history(&p, ContactLaw::Linear, &target, p.v0, 300).unwrap();
    let c = &h.collision;
    assert_eq!(c.method, Method::Exact);
    assert_eq!(h.t.len(), 300);
    let f_m = h.force.iter().copied().fold(0.0, f64::max);
    assert!(f_m <= c.max_force && rel(f_m, c.max_force) <= 1e-3);
    let s_m = h.deflection.iter().copied().fold(0.0, f64::max);
    assert!(s_m <= c.max_target_deflection * (1.0 + 1e-12));
    assert!(rel(s_m, c.max_target_deflection) <= 1e-3);
    assert!(h.force.last().unwrap().abs() <= 1e-9 * c.max_force);
    assert!(rel(*h.t.last().unwrap(), c.contact_time.unwrap()) <= 1e-12);
    // the integrator's dense output at the same times
    let reduced = ImpactParams {
        mass: c.reduced_mass,
        v0: c.closing_speed,
        ..p
    };
    let w0 = reduced.omega0();
    let times: Vec<f64> = h.t.iter().map(|t| t * w0).collect();
    let mut grid = Samples::at(times);
    let method = Some(Method::Numeric);
    compliant_sampled(&reduced, ContactLaw::Linear, &target, method, &mut grid).unwrap();
    let (length, force) = (reduced.v0 / w0, reduced.mass * reduced.v0 * w0);
    // the integrator's end of contact may fall a rounding before the exact one's: its last
    // point then is not taken
    assert!(grid.out.len() >= 299, "{}", grid.out.len());
    // the dense output (DOP853's 7th-order interpolant at 1e-12 per step) is good to some
    // 1e-8 of the scale, the answers at the events to 1e-9; a chart needs 1e-3
    let tol = 1e-7;
    for (i, x) in grid.out.iter().enumerate() {
        assert!(
            (x[0] * force - h.force[i]).abs() <= tol * c.max_force,
            "F at {i}"
        );
        let a = h.displacement[i];
        assert!((x[2] * length - a).abs() <= tol * length, "α at {i}");
        assert!(
            (x[3] * length - h.deflection[i]).abs() <= tol * length,
            "s at {i}"
        );
    }
}

/// On the nonlinear laws (the integrator's history) α = z + y + s holds with y ≥ 0 the ball's
/// element, the surface deflects, and the history ends at the reported contact time.
#[test]
fn a_compliant_history_on_every_law_ends_at_the_contact_time() {
    let p = preset("tennis");
    let target = Target {
        mass: 0.3,
        speed: 5.0,
        stiffness: 4e4,
        damping: 5.0,
    };
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let h = history(&p, law, &target, 20.0, 200).unwrap();
        let c = &h.collision;
        assert_eq!(h.t.len(), 200, "{law}");
        assert!(rel(*h.t.last().unwrap(), c.contact_time.unwrap()) <= 1e-12);
        let f_m = h.force.iter().copied().fold(0.0, f64::max);
        assert!(
            rel(f_m, c.max_force) <= 1e-3,
            "{law}: {f_m} {}",
            c.max_force
        );
        assert!(h.deflection.iter().any(|&s| s > 0.0));
        let last = *h.target_displacement.last().unwrap();
        assert!(last > 0.0, "{law}: the target is pushed back");
    }
}
