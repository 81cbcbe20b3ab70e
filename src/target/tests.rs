//! The checks of docs/targets.md §6: the wall, the reduced ball, equal balls, the lossless
//! chain and its closed forms, the rigid limit, and two solvers against each other and today's.

use super::*;
use crate::api::Ball;
use crate::model::params::Field;

pub(super) fn preset(name: &str) -> ImpactParams {
    Ball::from_preset(name).unwrap().params
}

/// The preset `name` without flattening (z_p = ∞): on the linear law, the exact flow's ball.
pub(super) fn unflattened(name: &str) -> ImpactParams {
    ImpactParams {
        z_p: f64::INFINITY,
        ..preset(name)
    }
}

pub(super) fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

const LAWS: [ContactLaw; 3] = [
    ContactLaw::Linear,
    ContactLaw::ElasticPlastic,
    ContactLaw::Hertz,
];

#[test]
fn the_wall_is_todays_run() {
    for name in ["superball", "golf", "baseball"] {
        for law in LAWS {
            for v in [1.0, 6.0] {
                let p = ImpactParams {
                    v0: v,
                    ..preset(name)
                };
                let today = simulate(&p, law, &SolveOptions::default()).unwrap();
                let c = collide(&p, law, &Target::wall(), v, None).unwrap();
                assert!(rel(c.cor, today.cor) <= 1e-12, "{name} {law} {v}");
                assert!(rel(c.max_force, today.max_force) <= 1e-12);
                assert!(rel(c.contact_time.unwrap(), today.contact_time.unwrap()) <= 1e-12);
                assert!(rel(c.ball_speed_out, today.cor * v) <= 1e-12);
                assert_eq!((c.target_speed_out, c.reduced_mass), (0.0, p.mass));
                assert_eq!(c.apparent_cor, c.cor);
            }
        }
    }
}

#[test]
fn a_rigid_target_is_the_reduced_ball_at_the_closing_speed() {
    let (m_t, v_b, v_t) = (0.5, 3.0, 2.5);
    for name in ["superball", "golf", "baseball"] {
        for law in LAWS {
            let p = preset(name);
            let target = Target {
                mass: m_t,
                speed: v_t,
                ..Target::wall()
            };
            let c = collide(&p, law, &target, v_b, None).unwrap();
            let m_star = p.mass * m_t / (p.mass + m_t);
            let reduced = ImpactParams {
                mass: m_star,
                v0: v_b + v_t,
                ..p
            };
            let r = simulate(&reduced, law, &SolveOptions::default()).unwrap();
            assert!(rel(c.reduced_mass, m_star) <= 1e-15);
            assert!(rel(c.cor, r.cor) <= 1e-12, "{name} {law}");
            assert!(rel(c.max_force, r.max_force) <= 1e-12);
            // momentum along the line (x toward the target) before and after
            let before = p.mass * v_b - m_t * v_t;
            let after = -p.mass * c.ball_speed_out - m_t * c.target_speed_out;
            let scale = p.mass * v_b + m_t * v_t;
            assert!((after - before).abs() <= 1e-12 * scale, "{name} {law}");
            // separation speed e·v_c; the energy can only have fallen
            let separation = c.ball_speed_out - c.target_speed_out;
            assert!(rel(separation, r.cor * (v_b + v_t)) <= 1e-12);
            let ke = |m: f64, v: f64| 0.5 * m * v * v;
            let (ke0, ke1) = (
                ke(p.mass, v_b) + ke(m_t, v_t),
                ke(p.mass, c.ball_speed_out) + ke(m_t, c.target_speed_out),
            );
            assert!(ke1 <= ke0 * (1.0 + 1e-12));
            // e_A and the batted-ball speed of the literature (docs/targets.md §3)
            let ratio = p.mass / m_t;
            assert!(rel(c.apparent_cor, (c.cor - ratio) / (1.0 + ratio)) <= 1e-12);
            let bbs = c.apparent_cor * v_b + (1.0 + c.apparent_cor) * v_t;
            assert!(rel(c.ball_speed_out, bbs) <= 1e-12);
        }
    }
}

/// Equal balls head-on at ±v, both deforming (`collide_ball`, `target::pair`, docs/targets.md
/// §8): by symmetry the contact plane stays put and each ball bounces as off a rigid wall at v,
/// so e, F_m, t_f and z_m are the ball's own wall impact at v (1e-9, as issue 53 asks). A
/// rigid body of the ball's mass instead (`collide` on a `Target` of mass m) is still the wall
/// impact of m/2 at 2v — what `collide_ball` answered before the partner deformed (tennis at
/// ±10 m/s: e 0.7047 against the wall's 0.7219).
#[test]
fn equal_balls_head_on_are_the_wall_impact_at_v_and_a_rigid_partner_is_m_half_at_2v() {
    for name in ["superball", "golf", "tennis"] {
        let ball = Ball::from_preset(name).unwrap();
        let v = ball.params.v0;
        let r = ball.collide_ball(&ball, v, (f64::INFINITY, 0.0)).unwrap();
        let own = simulate(&ball.params, ball.law, &SolveOptions::default()).unwrap();
        let c = &r.collision;
        assert!(rel(c.cor, own.cor) <= 1e-9, "{name}: {} {}", c.cor, own.cor);
        assert!(rel(c.max_force, own.max_force) <= 1e-9, "{name}");
        assert!(rel(c.contact_time.unwrap(), own.contact_time.unwrap()) <= 1e-9);
        assert!(
            rel(c.max_indentation, own.max_indentation) <= 1e-9,
            "{name}"
        );
        // symmetric: each leaves at e·v, the other ball back the way it came
        assert!(rel(c.ball_speed_out, own.cor * v) <= 1e-9);
        assert!(rel(c.target_speed_out, -own.cor * v) <= 1e-9);
        assert!(rel(r.effective_mass.unwrap(), ball.params.mass / 2.0) <= 1e-15);
        let radius = ball.measured.as_ref().unwrap().radius;
        assert!(rel(r.effective_radius.unwrap(), radius / 2.0) <= 1e-15);
        // the rigid partner of the same mass: the wall impact of m/2 at 2v
        let rigid = Target {
            mass: ball.params.mass,
            speed: v,
            ..Target::wall()
        };
        let c = collide(&ball.params, ball.law, &rigid, v, None).unwrap();
        let half = ImpactParams {
            mass: ball.params.mass / 2.0,
            v0: 2.0 * v,
            ..ball.params
        };
        let wall = simulate(&half, ball.law, &SolveOptions::default()).unwrap();
        assert!(rel(c.cor, wall.cor) <= 1e-12, "{name}");
        assert!(rel(c.ball_speed_out, wall.cor * v) <= 1e-12);
        assert!(rel(c.target_speed_out, -wall.cor * v) <= 1e-12);
    }
}

/// The superball with its dashpot locked (c = ∞: the Kelvin–Voigt pair is rigid) and no
/// flattening, against a 0.3 kg target whose surface is a spring alone (c_s = 0): two springs
/// in series, k_e = K_p K_s/(K_p + K_s), nothing dissipates.
fn lossless() -> (ImpactParams, Target) {
    let p = ImpactParams {
        damping: f64::INFINITY,
        ..unflattened("superball")
    };
    let target = Target {
        mass: 0.3,
        speed: 1.5,
        stiffness: 2e4,
        damping: 0.0,
    };
    (p, target)
}

#[test]
fn a_lossless_chain_keeps_its_energy_and_the_closed_forms() {
    let (p, target) = lossless();
    let v_b = p.v0;
    let c = collide(&p, ContactLaw::Linear, &target, v_b, None).unwrap();
    assert_eq!(c.method, Method::Exact);
    assert!((c.cor - 1.0).abs() <= 1e-12, "{}", c.cor);
    let ke0 = 0.5 * p.mass * v_b * v_b + 0.5 * target.mass * target.speed * target.speed;
    let ke1 =
        0.5 * p.mass * c.ball_speed_out.powi(2) + 0.5 * target.mass * c.target_speed_out.powi(2);
    assert!(rel(ke1, ke0) <= 1e-12);
    // half a period of m* on k_e, and its amplitude
    let k_e = p.k_p * target.stiffness / (p.k_p + target.stiffness);
    let m_star = p.mass * target.mass / (p.mass + target.mass);
    let t_f = std::f64::consts::PI * (m_star / k_e).sqrt();
    assert!(rel(c.contact_time.unwrap(), t_f) <= 1e-12);
    let f_m = (v_b + target.speed) * (m_star * k_e).sqrt();
    assert!(rel(c.max_force, f_m) <= 1e-12);
    assert!(rel(c.max_target_deflection, f_m / target.stiffness) <= 1e-12);
    // the integrated path: the same, to its tolerance
    let n = collide(&p, ContactLaw::Linear, &target, v_b, Some(Method::Numeric)).unwrap();
    assert_eq!(n.method, Method::Numeric);
    assert!((n.cor - 1.0).abs() <= 1e-9, "{}", n.cor);
    assert!(rel(n.contact_time.unwrap(), t_f) <= 1e-9);
    assert!(rel(n.max_force, f_m) <= 1e-9);
}

#[test]
fn a_stiffening_target_tends_to_the_rigid_one() {
    // flattening (z_p = 4 mm, at 6 m/s) on the integrated path; the exact one without it, with
    // a damped surface (a stiff one the explicit integrator could not carry)
    let cases = [
        (ContactLaw::Linear, 4e-3, 0.0),
        (ContactLaw::ElasticPlastic, 4e-3, 0.0),
        (ContactLaw::Linear, f64::INFINITY, 5.0),
    ];
    for (law, z_p, damping) in cases {
        let p = ImpactParams {
            v0: 6.0,
            z_p,
            ..preset("superball")
        };
        let rigid = Target {
            mass: 0.4,
            ..Target::wall()
        };
        let e_rigid = collide(&p, law, &rigid, 6.0, None).unwrap().cor;
        let gap = |k: f64| {
            let t = Target {
                stiffness: k * p.k_p,
                damping,
                ..rigid
            };
            (collide(&p, law, &t, 6.0, None).unwrap().cor - e_rigid).abs()
        };
        let gaps = [gap(1e1), gap(1e3), gap(1e5)];
        assert!(gaps[0] > 1e-3, "{law}: a soft surface changes e ({gaps:?})");
        assert!(
            gaps[1] < gaps[0] / 30.0 && gaps[2] < gaps[1] / 30.0,
            "{law}: {gaps:?}"
        );
        assert!(gaps[2] < 1e-5, "{law}: {gaps:?}");
    }
}

/// With the ball's dashpot locked the chain is contact – (c_s ∥ K_s): today's ball with the
/// surface's pair as its own Kelvin–Voigt pair. Every law, through the integrated path (and
/// the exact one where it applies), against today's solvers.
#[test]
fn a_locked_ball_on_a_damped_surface_is_todays_ball_with_the_surfaces_pair() {
    let (m_t, v_t) = (0.25, 1.0);
    for name in ["superball", "golf"] {
        for law in LAWS {
            for v_b in [2.0, 8.0] {
                let p = ImpactParams {
                    damping: f64::INFINITY,
                    ..preset(name)
                };
                let target = Target {
                    mass: m_t,
                    speed: v_t,
                    stiffness: 0.8 * p.k_p,
                    damping: 0.5 * (p.mass * p.k_p).sqrt(),
                };
                let m_star = p.mass * m_t / (p.mass + m_t);
                let today = ImpactParams {
                    mass: m_star,
                    damping: target.damping,
                    k_r: target.stiffness,
                    v0: v_b + v_t,
                    ..p
                };
                let r = simulate(&today, law, &SolveOptions::default()).unwrap();
                for method in [None, Some(Method::Numeric)] {
                    let c = collide(&p, law, &target, v_b, method).unwrap();
                    let what = format!("{name} {law} {v_b} {method:?} {:?}", c.method);
                    assert!((c.cor - r.cor).abs() <= 1e-8, "{what}: {} {}", c.cor, r.cor);
                    assert!(rel(c.max_force, r.max_force) <= 1e-8, "{what}");
                    let t = r.contact_time.unwrap();
                    assert!(rel(c.contact_time.unwrap(), t) <= 1e-8, "{what}");
                    assert!(rel(c.max_indentation, r.max_indentation) <= 1e-8, "{what}");
                }
            }
        }
    }
}

/// A surface without damping on the linear law without flattening is a spring in series with
/// the contact: today's ball with K_p' = K_p K_s/(K_p + K_s).
#[test]
fn an_undamped_surface_is_a_softer_contact() {
    for name in ["superball", "golf", "baseball"] {
        let p = unflattened(name);
        let target = Target {
            mass: 0.3,
            speed: 0.5,
            stiffness: 1.5 * p.k_p,
            damping: 0.0,
        };
        let k_p = p.k_p * target.stiffness / (p.k_p + target.stiffness);
        let today = ImpactParams {
            mass: p.mass * 0.3 / (p.mass + 0.3),
            k_p,
            v0: p.v0 + 0.5,
            ..p
        };
        let r = simulate(&today, ContactLaw::Linear, &SolveOptions::default()).unwrap();
        for method in [None, Some(Method::Numeric)] {
            let c = collide(&p, ContactLaw::Linear, &target, p.v0, method).unwrap();
            assert!((c.cor - r.cor).abs() <= 1e-9, "{name} {method:?}");
            assert!(rel(c.max_force, r.max_force) <= 1e-9, "{name} {method:?}");
            let t = r.contact_time.unwrap();
            assert!(rel(c.contact_time.unwrap(), t) <= 1e-9, "{name} {method:?}");
        }
    }
}

/// Where both apply (linear law, no flattening), the exact flow and the integrator agree with
/// every element in play: the ball's pair and a damped surface.
#[test]
fn the_exact_and_the_integrated_compliant_solvers_agree() {
    for name in ["superball", "golf", "baseball"] {
        for (ks, cs) in [(0.3, 0.2), (2.0, 1.0), (10.0, 0.05), (0.5, 0.0)] {
            let p = unflattened(name);
            let target = Target {
                mass: 0.6,
                speed: 2.0,
                stiffness: ks * p.k_p,
                damping: cs * (p.mass * p.k_p).sqrt(),
            };
            let e = collide(&p, ContactLaw::Linear, &target, p.v0, None).unwrap();
            let n = collide(&p, ContactLaw::Linear, &target, p.v0, Some(Method::Numeric));
            let n = n.unwrap();
            assert_eq!((e.method, n.method), (Method::Exact, Method::Numeric));
            let what = format!("{name} K_s {ks} c_s {cs}");
            assert!((e.cor - n.cor).abs() <= 1e-9, "{what}: {} {}", e.cor, n.cor);
            assert!(rel(e.max_force, n.max_force) <= 1e-9, "{what}");
            let t = e.contact_time.unwrap();
            assert!(rel(n.contact_time.unwrap(), t) <= 1e-9, "{what}");
            let (sn, se) = (n.max_target_deflection, e.max_target_deflection);
            assert!(rel(sn, se) <= 1e-9, "{what}: {sn} {se}");
            assert!(e.cor > 0.0 && e.cor < 1.0, "{what}");
        }
    }
}

#[test]
fn bad_targets_are_named() {
    let p = preset("golf");
    let field = |t: Target, v: f64| match collide(&p, ContactLaw::Linear, &t, v, None) {
        Err(SolveError::Param(e)) => e.field,
        other => panic!("{t:?}: {other:?}"),
    };
    let w = Target::wall();
    for m in [0.0, -1.0, f64::NAN, f64::NEG_INFINITY] {
        assert_eq!(field(Target { mass: m, ..w }, 1.0), Field::TargetMass);
    }
    for k in [0.0, -5.0, f64::NAN] {
        assert_eq!(
            field(Target { stiffness: k, ..w }, 1.0),
            Field::TargetStiffness
        );
    }
    for c in [-1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(field(Target { damping: c, ..w }, 1.0), Field::TargetDamping);
    }
    assert_eq!(
        field(
            Target {
                speed: f64::NAN,
                ..w
            },
            1.0
        ),
        Field::TargetSpeed
    );
    // speeds that never close: the target recedes as fast as the ball comes
    let away = Target { speed: -2.0, ..w };
    assert_eq!(field(away, 2.0), Field::TargetSpeed);
    assert_eq!(field(away, 1.0), Field::TargetSpeed);
    assert!(collide(&p, ContactLaw::Linear, &away, 2.5, None).is_ok());
    let e = Target { mass: 0.0, ..w }
        .validate()
        .unwrap_err()
        .to_string();
    assert_eq!(e, "invalid target_mass: 0 (must be positive)");
}

#[test]
fn the_bat_test_is_the_pair_cor_at_136_mph_on_the_bat_at_rest() {
    let p = preset("baseball");
    let run = bat::run(
        &p,
        ContactLaw::Linear,
        0.8,
        (40.0, 30.0),
        (f64::INFINITY, 0.0),
    )
    .unwrap();
    assert!((bat::MPH_136 - 60.79744).abs() < 1e-12);
    let at_rest = Target {
        mass: 0.8,
        ..Target::wall()
    };
    let test = collide(&p, ContactLaw::Linear, &at_rest, 60.79744, None).unwrap();
    assert_eq!(run.bbcor, test.cor);
    let e_a = run.apparent_cor;
    assert!(rel(run.bbs, e_a * 40.0 + (1.0 + e_a) * 30.0) <= 1e-12);
    assert_eq!(run.pass, run.bbcor <= 0.5);
    assert_eq!(run.verdict, if run.pass { "PASS" } else { "FAIL" });
}

/// Maxwell's ball (λ = 0) past ζ = 1 sinks into its dashpot on any target: no rebound, said by
/// both compliant solvers after a bounded time, as today's solver says it at the wall.
#[test]
fn a_ball_that_stays_is_no_rebound_on_a_compliant_target_too() {
    let p = Ball::normalized(0.0, 2.0, None, ContactLaw::Linear)
        .unwrap()
        .params;
    let target = Target {
        mass: 3.0,
        speed: 0.0,
        stiffness: 2.0,
        damping: 0.0,
    };
    for method in [None, Some(Method::Numeric)] {
        let c = collide(&p, ContactLaw::Linear, &target, 1.0, method).unwrap();
        assert!(!c.rebound && c.cor == 0.0, "{method:?}: {c:?}");
        assert_eq!(c.contact_time, None);
        // no rebound: the two move on together at the centre of mass's speed, m v/(m + M)
        // toward the target (each speed out is counted the other way round)
        assert!((c.ball_speed_out - c.target_speed_out).abs() < 1e-15);
        assert!(
            (c.ball_speed_out + 1.0 / 4.0).abs() < 1e-12,
            "{}",
            c.ball_speed_out
        );
    }
}
