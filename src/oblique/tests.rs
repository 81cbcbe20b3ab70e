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

/// The adaptive solver's flow, read between its steps (`solver::numeric::NumericPath`), against
/// the linear law's exact flow: the same impact solved both ways drives the same tangential
/// motion. The normal runs agree to the adaptive solver's tolerance (rtol 1e-10); the flow
/// between steps is a cubic Hermite interpolant of F̄, good to O(h⁴): 4.4e-10 found.
#[test]
fn the_adaptive_flow_drives_the_linear_law_as_the_exact_one_does() {
    use super::{Oblique, solve_with};
    use crate::model::contact::ContactLaw;
    use crate::solver::{Method, SolveOptions};
    let ball = crate::Ball::from_preset("tennis").unwrap();
    let p = ball.params;
    let kt = mindlin_ratio(0.5) * p.k_p;
    let exact = SolveOptions::default().with_energy();
    let numeric = exact.with_method(Method::Numeric);
    let mut worst: f64 = 0.0;
    for (angle, spin, mu) in [
        (16.0, 300.0, 0.6),
        (30.0, 0.0, 0.3),
        (45.0, -200.0, 2.0),
        (70.0, 100.0, 0.1),
    ] {
        let o = Oblique::new(angle, spin, mu, kt, 0.61, 0.0335).unwrap();
        let a = solve_with(&p, ContactLaw::Linear, 25.0, &o, 0, &exact).unwrap();
        let b = solve_with(&p, ContactLaw::Linear, 25.0, &o, 0, &numeric).unwrap();
        assert_eq!(b.normal.method, Method::Numeric);
        let dv = (a.vx_out - b.vx_out).abs() / 25.0;
        let dw = 0.0335 * (a.spin_out - b.spin_out).abs() / 25.0;
        assert!(
            dv < 1e-8 && dw < 1e-8,
            "{angle}° {spin} {mu}: v_x {} vs {}, ω {} vs {}",
            a.vx_out,
            b.vx_out,
            a.spin_out,
            b.spin_out
        );
        // beyond the adaptive normal run's own audit residual (of ½ m v_y²)
        let normal = b.normal.energy.unwrap();
        let input = b.energy.translational_in + b.energy.rotational_in;
        let allowed = 1e-12 + normal.relative_residual() * normal.initial_kinetic / input;
        assert!(b.energy.residual <= allowed, "{:e}", b.energy.residual);
        worst = worst.max(dv).max(dw);
    }
    eprintln!("adaptive against exact flow: worst {worst:e}");
}

/// On the exact flow the normal losses are the normal kinetic energy lost (`energy::
/// normal_losses`), not the dashpot's quadrature: they must be what `run`'s audit books — the
/// dashpot, the contact and the recoil spring — to 1e-12 of the oblique impact's input.
#[test]
fn the_normal_losses_are_the_audited_ones() {
    use super::{Oblique, solve};
    use crate::model::contact::ContactLaw;
    use crate::model::params::ImpactParams;
    use crate::solver::{SolveOptions, simulate};
    let ball = crate::Ball::from_preset("tennis").unwrap();
    let p = ball.params;
    let kt = mindlin_ratio(0.5) * p.k_p;
    for (angle, spin, mu) in [(5.0, 0.0, 0.3), (16.0, 300.0, 0.6), (45.0, -400.0, 2.0)] {
        let o = Oblique::new(angle, spin, mu, kt, 0.61, 0.0335).unwrap();
        let r = solve(&p, 25.0, &o, 0).unwrap();
        let normal = ImpactParams { v0: r.vy_in, ..p };
        let opts = SolveOptions::default().with_energy();
        let audit = simulate(&normal, ContactLaw::Linear, &opts).unwrap();
        let b = audit.energy.unwrap();
        let input = r.energy.translational_in + r.energy.rotational_in;
        let booked = b.dashpot + b.contact + b.spring;
        let miss = (r.energy.normal_dissipation - booked).abs() / input;
        assert!(miss < 1e-12, "{angle}° {spin} {mu}: {miss:e}");
    }
}

/// The closed-form normal motion (`closed`) against the exact solver's flow: the normal
/// responses agree (COR, F_m, τ_m, τ_f), the motion F̄, F̄', ᾱ' agrees at every τ, and so do
/// the oblique answers. Over every preset at 25 m/s, 5–85° (flattening and not), it must
/// answer for the tennis ball: the case the speed target is set on (at 90° `NormalAt` runs
/// the exact solver, so that the answer is `run`'s to the last bit).
#[test]
fn the_closed_form_is_the_exact_flow() {
    use super::{ClosedPath, NormalMotion, Oblique, solve_with};
    use crate::model::contact::ContactLaw;
    use crate::model::params::ImpactParams;
    use crate::solver::{Method, SolveOptions, simulate_path};
    let mut answered = 0;
    for preset in crate::preset::Preset::embedded_all() {
        let ball = crate::Ball::from_preset(&preset.name).unwrap();
        for angle in [5.0, 16.0, 30.0, 60.0, 85.0] {
            let vy = 25.0 * f64::to_radians(angle).sin();
            let p = ImpactParams {
                v0: vy,
                ..ball.params
            };
            let Some((closed, path)) = ClosedPath::solve(&p) else {
                assert!(
                    preset.name != "tennis",
                    "tennis at {angle}°: no closed form"
                );
                continue;
            };
            answered += 1;
            let opts = SolveOptions::default();
            let (exact, flow) = simulate_path(&p, &opts).unwrap();
            let case = format!("{} at {angle}°", preset.name);
            let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
            assert!(rel(closed.cor, exact.cor) < 1e-13, "{case}: COR");
            assert!(rel(closed.max_force, exact.max_force) < 1e-13, "{case}");
            let (tc, te) = (closed.contact_time.unwrap(), exact.contact_time.unwrap());
            assert!(rel(tc, te) < 1e-13, "{case}: contact time");
            assert_eq!(closed.events.len(), exact.events.len(), "{case}");
            for (a, b) in closed.events.iter().zip(&exact.events) {
                assert_eq!(a.kind, b.kind, "{case}");
                assert!(rel(a.t, b.t) < 1e-12, "{case}: {:?}", a.kind);
            }
            assert!(
                rel(
                    closed.permanent_indentation + 1.0,
                    exact.permanent_indentation + 1.0
                ) < 1e-13
            );
            let tf = path.end();
            let (scale_f, scale_v) = (closed.max_force_normalized, 1.0);
            for j in 0..=40 {
                let tau = tf * f64::from(j) / 40.0;
                let (a, b) = (path.at(tau), flow.at(tau));
                assert!(
                    (a.force - b.force).abs() < 1e-13 * scale_f,
                    "{case}, τ {tau}"
                );
                assert!((a.rate - b.rate).abs() < 1e-12 * scale_f, "{case}, τ {tau}");
                assert!(
                    (a.velocity - b.velocity).abs() < 1e-13 * scale_v,
                    "{case}, τ {tau}"
                );
            }
            // the oblique answers, through the closed form and through the exact solver
            let kt = ball.tangential_stiffness().unwrap();
            for (spin, mu) in [(300.0, 0.6), (-200.0, 0.1), (0.0, 2.0)] {
                let o = Oblique::new(angle, spin, mu, kt, 0.6, ball.radius()).unwrap();
                let fast = SolveOptions::default().with_energy();
                let by_solver = fast.with_method(Method::Exact);
                let a = solve_with(&ball.params, ContactLaw::Linear, 25.0, &o, 0, &fast).unwrap();
                let b =
                    solve_with(&ball.params, ContactLaw::Linear, 25.0, &o, 0, &by_solver).unwrap();
                assert_eq!(a.normal.steps, closed.steps, "{case}: the closed form ran");
                let d = (a.vx_out - b.vx_out).abs().max((a.vy_out - b.vy_out).abs());
                let dw = ball.radius() * (a.spin_out - b.spin_out).abs();
                assert!(d < 1e-12 * 25.0 && dw < 1e-12 * 25.0, "{case} {spin} {mu}");
                assert_eq!(a.phases.len(), b.phases.len(), "{case} {spin} {mu}");
                assert!(a.energy.residual < 1e-12, "{case} {spin} {mu}");
            }
        }
    }
    eprintln!("closed form answered {answered} of 40 normal impacts");
}
