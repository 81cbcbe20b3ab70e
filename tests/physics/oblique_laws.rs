//! The oblique impact on every contact law (docs/oblique.md §2, §5): the normal motion is
//! `run`'s own solver (the adaptive one for Hertz and the elastic–plastic law, its steps kept
//! and read between them), the tangential motion the same closed forms as the linear law's.

use crate::oblique::{R, assert_peak_friction_within, assert_the_grid_agrees, setup, tennis};
use bouncelab::model::contact::ContactLaw;
use bouncelab::oblique::{self, Oblique, mindlin_ratio, reference};
use bouncelab::solver::{SolveOptions, simulate};

const LAWS: [ContactLaw; 2] = [ContactLaw::Hertz, ContactLaw::ElasticPlastic];

#[test]
fn angle_90_is_run_on_every_law() {
    let p = tennis();
    for law in ContactLaw::ALL {
        let o = setup(90.0, 0.0, 0.6, 0.7 * p.k_p, 0.61);
        let r = oblique::solve_law(&p, law, p.v0, &o, 0).unwrap();
        let run = simulate(&p, law, &SolveOptions::default().with_energy()).unwrap();
        assert!(
            (r.cor_normal - run.cor).abs() <= 1e-12,
            "{law}: {} vs {}",
            r.cor_normal,
            run.cor
        );
        assert!(
            r.vx_out.abs() <= 1e-12 && r.spin_out.abs() <= 1e-12,
            "{law}"
        );
        assert!(r.max_friction_force.abs() <= 1e-12, "{law}");
        assert_eq!(r.contact_time, run.contact_time.unwrap(), "{law}");
        assert_eq!(r.max_normal_force, run.max_force, "{law}");
    }
}

#[test]
fn no_friction_leaves_the_tangential_motion_unchanged_on_every_law() {
    let p = tennis();
    for law in LAWS {
        let o = setup(30.0, 300.0, 0.0, 0.8 * p.k_p, 0.55);
        let r = oblique::solve_law(&p, law, 25.0, &o, 0).unwrap();
        assert_eq!(r.vx_out, r.vx_in, "{law}");
        assert_eq!(r.spin_out, 300.0, "{law}");
    }
}

#[test]
fn a_stiff_spring_sliding_throughout_loses_mu_times_the_normal_impulse_on_every_law() {
    // Δv_x = −μ(1 + e)v_y: the impulse is read on the flow (its ᾱ' is ∫F̄ of the interpolant),
    // e from the solver, so the two meet to the interpolation's error
    let p = tennis();
    let (mu, kappa) = (0.1, 0.55);
    for law in LAWS {
        let o = setup(16.0, 0.0, mu, 1e6 * p.k_p, kappa);
        let r = oblique::solve_law(&p, law, 25.0, &o, 0).unwrap();
        assert!(r.slid_throughout, "{law}");
        let impulse = (1.0 + r.cor_normal) * r.vy_in;
        let dvx = r.vx_out - r.vx_in;
        let rel = (dvx + mu * impulse).abs() / (mu * impulse);
        assert!(rel < 1e-6, "{law}: Δv_x {dvx} vs {}", -mu * impulse);
        let dw = r.spin_out - r.spin_in;
        let expected = mu * impulse / (kappa * R);
        assert!((dw - expected).abs() / expected < 1e-6, "{law}: Δω {dw}");
    }
}

/// The independent integration (DOP853 at 1e-13, events at every switch) over the same flow:
/// what it checks is the tangential closed forms and switches on a normal motion that is no
/// exact flow (the flow itself is held against the exact one in src/oblique/tests.rs).
#[test]
fn the_independent_integration_agrees_on_hertz_and_elastic_plastic() {
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    let mut grid = Vec::new();
    for law in LAWS {
        for angle in [5.0, 16.0, 45.0, 85.0] {
            for spin in [-500.0, 0.0, 500.0] {
                for mu in [0.05, 0.6, 2.0] {
                    let case = format!("{law} {angle}°, {spin} rad/s, μ {mu}");
                    grid.push((case, (law, setup(angle, spin, mu, kt, 0.61))));
                }
            }
        }
    }
    let solve = |(law, o): &(ContactLaw, Oblique)| {
        let r = oblique::solve_law(&p, *law, 25.0, o, 0).unwrap();
        (r, reference::solve_law(&p, *law, 25.0, o).unwrap())
    };
    assert_the_grid_agrees(grid, solve, 20);
}

/// The oblique terms close to 1e-12 of the input beyond what the normal run's own audit
/// leaves (`run`'s energy.relative_residual, of ½ m v_y²: the adaptive solver's dashpot
/// integral holds to its tolerance, docs/numerics.md).
#[test]
fn the_energy_balance_closes_on_every_law() {
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    for law in LAWS {
        for angle in [5.0, 16.0, 45.0, 80.0] {
            for (spin, mu) in [(-400.0, 0.1), (0.0, 0.6), (300.0, 2.0)] {
                let o = setup(angle, spin, mu, kt, 0.55);
                let r = oblique::solve_law(&p, law, 25.0, &o, 0).unwrap();
                let e = r.energy;
                let input = e.translational_in + e.rotational_in;
                let normal = r.normal.energy.unwrap();
                let allowed = 1e-12 + normal.relative_residual() * normal.initial_kinetic / input;
                assert!(
                    e.residual <= allowed,
                    "{law} {angle}° {spin} {mu}: residual {:e} > {allowed:e}",
                    e.residual
                );
                assert!(e.friction_dissipation >= 0.0, "{law}");
            }
        }
    }
}

#[test]
fn the_peak_friction_force_is_the_historys_largest_on_every_law() {
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    for law in LAWS {
        for (angle, spin, mu) in [(16.0, 300.0, 0.6), (45.0, -200.0, 2.0)] {
            let o = setup(angle, spin, mu, kt, 0.55);
            let r = oblique::solve_law(&p, law, 25.0, &o, 20_001).unwrap();
            assert_peak_friction_within(&r, 1e-9, &format!("{law} {angle}°"));
        }
    }
}
