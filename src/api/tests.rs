//! Tests of the library's front door against the command line's checks and messages.

use super::*;

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
        "invalid lambda: 2000000 (above 1e6, where the recoil spring is rigid)"
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
