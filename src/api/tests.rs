//! Tests of the library's front door against the command line's checks and messages.

use super::*;
use crate::catalog::Catalog;

#[test]
fn messages_name_the_field_and_the_preset() {
    let e = Ball::from_preset("superball")
        .unwrap()
        .with_v0(-1.0)
        .unwrap_err();
    assert_eq!(e.to_string(), "invalid v0: -1 (must not be negative)");
    let e = Ball::from_preset("superball")
        .unwrap()
        .with_lambda(2e6)
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid lambda: 2000000 (above 1e6, where the recoil spring is rigid; the range is 0 or 1e-15 … 1e6)"
    );
    // a ζ in its domain whose c is not: named by the ζ given
    let e = Ball::from_preset("superball")
        .unwrap()
        .with_zeta(1e-14)
        .unwrap_err();
    assert!(
        e.to_string().starts_with("invalid zeta: 1e-14 (gives c = "),
        "{e}"
    );
    let e = Ball::normalized(1.0, 0.1, Some(0.0), ContactLaw::Linear).unwrap_err();
    assert_eq!(e.to_string(), "invalid zp_bar: 0 (must be positive)");
    let e = Ball::from_preset("superball")
        .unwrap()
        .impact_history(1)
        .unwrap_err();
    assert_eq!(e.to_string(), "invalid samples: 1 (must lie in 2 … 100000)");
    let e = sweep_zeta(&[], &[1.0], ContactLaw::Linear).unwrap_err();
    assert_eq!(e.to_string(), "invalid lambda: no value given");
}

/// The builder runs what `simulate` runs: nothing is recomputed differently.
#[test]
fn the_builder_is_simulate() {
    let b = Ball::from_preset("golf")
        .unwrap()
        .with_v0(3.0)
        .unwrap()
        .with_lambda_zeta(Some(0.7), Some(0.2))
        .unwrap();
    let mut p = Ball::from_preset("golf").unwrap().params;
    p.v0 = 3.0;
    p.k_r = 0.7 * p.k_p;
    p.damping = (p.mass * p.k_p).sqrt() / 0.4;
    assert_eq!(b.params, p);
    assert!((b.lambda() - 0.7).abs() < 1e-15 && (b.zeta() - 0.2).abs() < 1e-15);
    let direct = simulate(&p, b.law, &SolveOptions::default().with_energy()).unwrap();
    assert_eq!(b.impact().unwrap(), direct);
    let fit = b.fit_cor(direct.cor).unwrap();
    assert!((fit.lambda - 0.7).abs() < 1e-8, "{}", fit.lambda);
}

#[test]
fn overrides_are_the_callers_and_k_h_follows() {
    let entry = Catalog::embedded().get("golf").unwrap().clone();
    let set = Overrides {
        k_p: Some(2e5),
        z_p: Some(1e-3),
        ..Overrides::default()
    };
    let b = Ball::from_entry_with(&entry, None, None, None, &set).unwrap();
    assert_eq!((b.params.k_p, b.params.z_p), (2e5, 1e-3));
    // Eq. 16: K_p = 1.5 K_h √z_p
    assert!((1.5 * b.params.k_h * 1e-3_f64.sqrt() / 2e5 - 1.0).abs() < 1e-12);
    let bad = Overrides {
        damping: Some(-3.0),
        ..Overrides::default()
    };
    let e = Ball::from_entry_with(&entry, None, None, None, &bad).unwrap_err();
    assert_eq!(e.to_string(), "invalid damping: -3 (must not be negative)");
    // no override: the plain entry
    assert_eq!(
        Ball::from_entry_with(&entry, None, None, None, &Overrides::default()),
        Ball::from_entry(&entry, None, None, None)
    );
}

#[test]
fn only_an_unresolved_impact_is_no_answer() {
    use crate::solver::{SolveError, Unresolved};
    let unresolved = SolveError::Unresolved {
        reason: Unresolved::Steps,
        steps: 10,
        lambda: 0.0,
        zeta: 1.0,
    };
    assert!(BallError::Solve(unresolved.clone()).is_no_answer());
    assert!(BallError::Drop(crate::drop::DropError::Solve(unresolved)).is_no_answer());
    assert!(!BallError::Samples(1).is_no_answer());
    assert!(!BallError::NoValue("lambda").is_no_answer());
}

#[test]
fn reports_carry_the_balls_values() {
    let ball = Ball::from_preset("superball").unwrap();
    let r = ball.impact_history(10).unwrap();
    let rep = ImpactReport::new(&ball, &r, true);
    assert_eq!(rep.ball.preset, Some("superball"));
    assert_eq!(
        (rep.mass, rep.c, rep.outcome.cor),
        (0.0374, ball.params.damping, r.cor)
    );
    assert_eq!(rep.lambda, ball.params.k_r / ball.params.k_p);
    assert_eq!(rep.force.map(<[f64]>::len), Some(10));
    assert!(ImpactReport::new(&ball, &r, false).t.is_none());
    let fit = ball.fit_cor(0.75).unwrap();
    let f = FitReport::new(&ball, 0.75, &fit);
    assert_eq!(
        (f.k_r, f.preset_k_r, f.target_cor),
        (fit.k_r, 70800.0, 0.75)
    );
}

#[test]
fn sweeps_keep_the_command_lines_work_limit() {
    let zetas = vec![1.0; 500_001];
    let e = sweep_zeta(&[0.5, 1.0], &zetas, ContactLaw::Linear).unwrap_err();
    assert_eq!(
        e.to_string(),
        "too much work: 2 λ values × 500001 points is 1000002 linear-law impacts, worth 1000002 \
         against the work limit of 1000000 (an impact counts 1 with the linear law, 40 with the \
         others); ask for fewer points or values"
    );
    let ball = Ball::from_preset("golf")
        .unwrap()
        .with_law(ContactLaw::Hertz);
    let e = ball.sweep_velocity(&vec![3.0; 25_001]).unwrap_err();
    assert!(
        matches!(e, BallError::Work(ref w) if w.impacts == 25_001),
        "{e}"
    );
    assert!(
        e.to_string()
            .starts_with("too much work: 25001 speeds is 25001 hertz-law")
    );
}
