//! Every closed form of docs/model.md §5, against both solvers where they apply.

use bouncelab::solver::EventKind;
use bouncelab::{ContactLaw, ImpactParams, Method, SolveOptions, simulate, simulate_normalized};
use std::f64::consts::PI;

fn exact(lambda: f64, zeta: f64) -> bouncelab::ImpactResponse {
    simulate_normalized(lambda, zeta, ContactLaw::Linear, &SolveOptions::default()).unwrap()
}

fn numeric(lambda: f64, zeta: f64) -> bouncelab::ImpactResponse {
    let o = SolveOptions {
        rtol: 1e-12,
        ..SolveOptions::default()
    }
    .with_method(Method::Numeric);
    simulate_normalized(lambda, zeta, ContactLaw::Linear, &o).unwrap()
}

/// Maxwell (λ = 0, Eq. 28): e = exp(−πζ/√(1−ζ²)) to `tol_e`, τ_f = π/√(1−ζ²) to `tol_t`.
fn assert_maxwell(r: &bouncelab::ImpactResponse, zeta: f64, tol_e: f64, tol_t: f64) {
    let s = (1.0 - zeta * zeta).sqrt();
    let e = (-PI * zeta / s).exp();
    assert!(r.rebound, "ζ={zeta} {:?}", r.method);
    assert!(
        (r.cor - e).abs() < tol_e,
        "ζ={zeta} {:?}: e={} expected {e}",
        r.method,
        r.cor
    );
    let tf = r.contact_time_normalized.unwrap();
    assert!(
        (tf - PI / s).abs() < tol_t,
        "ζ={zeta} {:?}: τ_f={tf} expected {}",
        r.method,
        PI / s
    );
}

#[test]
fn maxwell_cor_and_contact_time() {
    for i in 0..=98 {
        let zeta = 0.01 + 0.01 * i as f64;
        assert_maxwell(&exact(0.0, zeta), zeta, 1e-9, 1e-9);
    }
}

/// Maxwell again, by the adaptive solver: its rest test (an impulse bound without a recoil
/// spring: the ball cannot leave faster than (z̄* − z̄_f)/2ζ) must not cut a real rebound, down
/// to e ≈ 7e-5 at ζ = 0.95.
#[test]
fn maxwell_by_the_adaptive_solver() {
    for i in 0..=19 {
        let zeta = 0.01 + 0.05 * i as f64;
        assert_maxwell(&numeric(0.0, zeta), zeta, 1e-8, 1e-7);
    }
}

/// λ = 0, ζ ≥ 1: the ball sinks into the dashpot; no rebound, e = 0, and a bounded run.
#[test]
fn maxwell_overdamped_has_no_rebound() {
    for zeta in [1.0, 1.0 + 1e-9, 1.5, 10.0, 1e3, 1e4] {
        for r in [exact(0.0, zeta), numeric(0.0, zeta)] {
            assert!(!r.rebound, "ζ={zeta} {:?}", r.method);
            assert_eq!(r.cor, 0.0);
            assert!(r.contact_time.is_none());
            assert!(r.duration.is_finite() && r.duration > 0.0);
        }
    }
}

/// ζ → 0: the contact spring alone, e → 1, F̄_m → 1, τ_f → π; ζ = 0 exactly is that limit.
#[test]
fn zeta_to_zero_is_a_single_spring() {
    for lambda in [0.0, 0.4, 1.0, 10.0] {
        let r = exact(lambda, 0.0);
        assert!((r.cor - 1.0).abs() < 1e-12, "λ={lambda} e={}", r.cor);
        assert!((r.max_force_normalized - 1.0).abs() < 1e-12);
        assert!((r.contact_time_normalized.unwrap() - PI).abs() < 1e-12);
        // and approached continuously
        let r = exact(lambda, 1e-6);
        assert!(
            (r.cor - 1.0).abs() < 1e-4 && (r.contact_time_normalized.unwrap() - PI).abs() < 1e-4
        );
    }
}

/// ζ → ∞, λ > 0 (Eq. 29): springs K_p and K_r in series, e → 1, τ_f → π √((1+λ)/λ).
#[test]
fn zeta_to_infinity_is_springs_in_series() {
    for lambda in [0.4, 1.0, 3.0] {
        let r = exact(lambda, 1e6);
        let tf = PI * ((1.0 + lambda) / lambda).sqrt();
        assert!((r.cor - 1.0).abs() < 1e-4, "λ={lambda} e={}", r.cor);
        assert!((r.contact_time_normalized.unwrap() - tf).abs() < 1e-4 * tf);
        // F̄_m of the series spring k = λ/(1+λ): √k
        assert!((r.max_force_normalized - (lambda / (1.0 + lambda)).sqrt()).abs() < 1e-4);
    }
}

/// The corner of the accepted range, λ = ζ = 1e6 (`LAMBDA_MAX`, `ZETA_MAX`): springs in series
/// with K_r ≫ K_p, the contact spring alone, e → 1 and τ_f → π. Found by the solver_inputs fuzz
/// target: the exact solver took the oscillation, twelve decades below the dashpot's rate, for
/// the zero mode of λ = 0 and reported no rebound after 3e-10.
#[test]
fn largest_lambda_and_zeta_still_rebound() {
    for (lambda, zeta) in [(1e6f64, 1e6), (1e6, 1e5), (1e5, 1e6)] {
        let tf = PI * ((1.0 + lambda) / lambda).sqrt();
        for r in [exact(lambda, zeta), numeric(lambda, zeta)] {
            assert!(r.rebound, "λ={lambda} ζ={zeta} {:?}", r.method);
            assert!(
                (r.cor - 1.0).abs() < 1e-4,
                "λ={lambda} ζ={zeta} e={}",
                r.cor
            );
            let t = r.contact_time_normalized.unwrap();
            assert!((t - tf).abs() < 1e-4 * tf, "λ={lambda} ζ={zeta} τ_f={t}");
        }
    }
}

/// F(0) = 0 and contact ends at F = 0, not at z = 0: with flattening z_f > 0 at separation.
#[test]
fn force_starts_and_ends_at_zero() {
    let p = ImpactParams::from_normalized(1.3, 0.16, 0.3);
    for method in [Method::Exact, Method::Numeric] {
        let r = simulate(
            &p,
            ContactLaw::Linear,
            &SolveOptions::default()
                .with_samples(400)
                .with_method(method),
        )
        .unwrap();
        assert_eq!(r.history.force[0], 0.0);
        assert!(
            r.permanent_indentation > 0.05,
            "z_f = {}",
            r.permanent_indentation
        );
        let last = r.events.last().unwrap();
        assert_eq!(last.kind, EventKind::Separation);
        // the run stopped where the indentation reached z_f (F = 0), well before z = 0
        assert!(
            (last.z - r.permanent_indentation).abs() < 1e-9,
            "{method:?}: {} vs {}",
            last.z,
            r.permanent_indentation
        );
        assert!(r.history.force.last().unwrap().abs() < 1e-6);
        assert!(r.history.indentation.last().unwrap() > &0.05);
    }
}

/// Hertz alone (no Kelvin–Voigt motion, ζ = 0): e = 1, z_m = (15 m v0²/(16 E* √R))^{2/5},
/// F_m = K_h z_m^{3/2}, t_f = 2.94328 z_m / v0. The constant is (4/5) B(2/5, 1/2) =
/// 2.9432751843247…, which docs/model.md prints rounded to six figures: the test holds the solver
/// to the exact constant at 1e-9 and checks that it rounds to the printed one.
#[test]
fn hertz_alone() {
    // superball-like: E* = E/(1−ν²), K_h = (4/3) E* √R
    let (m, r_ball, e, nu, v0): (f64, f64, f64, f64, f64) = (0.0374, 0.02155, 2.2e6, 0.5, 3.12);
    let e_star = e / (1.0 - nu * nu);
    let k_h = 4.0 / 3.0 * e_star * r_ball.sqrt();
    let p = ImpactParams {
        mass: m,
        k_p: 5.45e4,
        damping: f64::INFINITY,
        k_r: 7.08e4,
        z_p: f64::INFINITY,
        k_h,
        v0,
    };
    let res = simulate(
        &p,
        ContactLaw::Hertz,
        &SolveOptions {
            rtol: 1e-12,
            ..Default::default()
        },
    )
    .unwrap();
    let z_m = (15.0 * m * v0 * v0 / (16.0 * e_star * r_ball.sqrt())).powf(0.4);
    assert!((res.cor - 1.0).abs() < 1e-6, "e = {}", res.cor);
    assert!((res.max_indentation - z_m).abs() < 1e-6 * z_m);
    assert!((res.max_force - k_h * z_m.powf(1.5)).abs() < 1e-6 * res.max_force);
    const HERTZ_TIME: f64 = 2.943_275_184_324_705; // (4/5) B(2/5, 1/2)
    assert!((HERTZ_TIME - 2.94328).abs() < 5e-6);
    let t_f = HERTZ_TIME * z_m / v0;
    assert!(
        (res.contact_time.unwrap() - t_f).abs() < 1e-9 * t_f,
        "{} vs {t_f}",
        res.contact_time.unwrap()
    );
}

/// e never leaves [0, 1], even where rounding (λ, ζ huge: springs in series, e → 1) or the
/// stiff integrator's tolerance would put the raw −α'(t_f)/v0 a hair above 1.
#[test]
fn cor_stays_in_the_unit_interval() {
    for (lambda, zeta) in [(1e4, 1e4), (1e6, 1e6), (1e4, 0.5), (0.0, 0.0)] {
        for law in [
            ContactLaw::Linear,
            ContactLaw::Hertz,
            ContactLaw::ElasticPlastic,
        ] {
            let p = ImpactParams::from_normalized(lambda, zeta, 1.0);
            let r = simulate(&p, law, &SolveOptions::default()).unwrap();
            assert!(
                (0.0..=1.0).contains(&r.cor),
                "λ={lambda} ζ={zeta} {law}: e = {}",
                r.cor
            );
        }
    }
}

/// A Hertz contact is soft at low speed (its stiffness grows with indentation): at v0 = 1e-12
/// m/s the contact lasts thousands of linear-spring times, and the solver must follow it to
/// the rebound rather than stop at a horizon scaled for the linear spring.
#[test]
fn slow_hertz_impact_still_rebounds() {
    let p = bouncelab::preset::Preset::embedded()[0].params();
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let r = simulate(
            &ImpactParams { v0: 1e-12, ..p },
            law,
            &SolveOptions::default(),
        )
        .unwrap();
        assert!(
            r.rebound && r.cor > 0.5,
            "{law}: e = {} rebound = {}",
            r.cor,
            r.rebound
        );
    }
}
