//! `Ball::closed_form_summary` (Python's `run` on the linear law, docs/python.md) against
//! `Ball::impact` (`bouncelab run`): where the closed forms answer, every field of the summary
//! is the exact solver's to 1e-12 (the method, the rebound and the normalized numbers exactly),
//! over the presets at their own and at other speeds, and over random balls flattening or not.

use crate::spread;
use bouncelab::api::ImpactSummary;
use bouncelab::catalog::Catalog;

use bouncelab::{Ball, ContactLaw};
use spread::balls;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1e-300)
}

fn close_opt(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => close(a, b),
        _ => false,
    }
}

/// The summary of `ball` when the closed forms answer (then checked field by field against
/// the exact solver's answer); whether they answered and the ball flattened.
fn check(ball: &Ball) -> Option<bool> {
    let s: ImpactSummary = ball.closed_form_summary()?;
    let r = ball
        .impact()
        .expect("the exact solver answers where the closed form does");
    let full = ImpactSummary::from(&r);
    let what = format!("{:?}\n fast {s:?}\n full {full:?}", ball.params);
    assert_eq!(s.method, full.method, "{what}");
    assert_eq!(s.normalized, full.normalized, "{what}");
    let (s, full) = (s.outcome, full.outcome);
    assert_eq!(s.rebound, full.rebound, "{what}");
    for (a, b) in [
        (s.cor, full.cor),
        (s.max_force, full.max_force),
        (s.max_indentation, full.max_indentation),
        (s.max_force_normalized, full.max_force_normalized),
    ] {
        assert!(close(a, b), "{what}");
    }
    assert!(close_opt(s.contact_time, full.contact_time), "{what}");
    assert!(
        close_opt(s.contact_time_normalized, full.contact_time_normalized),
        "{what}"
    );
    // z_f = z_m − z̄_p√(2 z_m/z̄_p − 1) (Eqs. 18–19) loses digits where z_m is just past z̄_p:
    // its error is z_m's over the slope 1 − 1/√(2 z_m/z̄_p − 1)
    let flattened = full.permanent_indentation > 0.0;
    if flattened {
        let zp = ball.params.z_p;
        let slope = 1.0 - 1.0 / (2.0 * full.max_indentation / zp - 1.0).sqrt();
        let tol = 1e-12 * full.max_indentation / slope.max(1e-300);
        let dz = (s.permanent_indentation - full.permanent_indentation).abs();
        assert!(dz <= tol.max(1e-12 * full.permanent_indentation), "{what}");
    } else {
        assert_eq!(s.permanent_indentation, 0.0, "{what}");
    }
    Some(flattened)
}

#[test]
fn the_summary_is_the_exact_solvers_over_random_balls() {
    let (mut plain, mut flattened, mut left) = (0, 0, 0);
    for p in balls(0x9e37_79b9_7f4a_7c15, 2000) {
        let ball = Ball::from_params(p, ContactLaw::Linear).unwrap();
        match check(&ball) {
            Some(true) => flattened += 1,
            Some(false) => plain += 1,
            None => left += 1,
        }
    }
    eprintln!("{plain} plain, {flattened} flattened, {left} left to the exact solver");
    // both closed forms taken, and most balls answered by one
    assert!(
        plain > 200 && flattened > 200 && left < plain + flattened,
        "{plain} plain, {flattened} flattened, {left} left to the exact solver"
    );
}

#[test]
fn the_summary_is_the_exact_solvers_on_every_preset() {
    let catalog = Catalog::embedded();
    let mut answered = 0;
    for e in catalog.entries() {
        let ball = Ball::from_entry(e, None, Some(ContactLaw::Linear), None).unwrap();
        let v0 = ball.params.v0;
        for v in [v0, 0.3 * v0, 3.0 * v0] {
            let b = ball.clone().with_v0(v).unwrap();
            answered += usize::from(check(&b).is_some());
        }
    }
    assert!(answered >= 20, "{answered} of 24");
}

#[test]
fn other_laws_and_no_rebound_are_left_to_the_solvers() {
    let golf = Ball::from_preset("golf").unwrap();
    assert!(golf.closed_form_summary().is_some());
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        assert_eq!(golf.clone().with_law(law).closed_form_summary(), None);
    }
    // Maxwell's ball at ζ ≥ 1 stays at the wall: the exact solver says so
    let maxwell = Ball::normalized(0.0, 2.0, None, ContactLaw::Linear).unwrap();
    assert_eq!(maxwell.closed_form_summary(), None);
    assert!(!maxwell.impact().unwrap().rebound);
}
