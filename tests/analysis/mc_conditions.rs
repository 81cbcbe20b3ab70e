//! Issue 56: `mc --vary pressure=…,temperature=…`. Each sample's ball, moved by the Monte
//! Carlo's own conditions laws (`analysis::mc::McConditions`), is the ball the one resolver
//! `Ball::at_conditions` makes at that sample's pressure or temperature: two paths, one
//! answer. And the spreads a ball cannot take are refused, naming the field.

use crate::common::bad_each;
use bouncelab::Ball;
use bouncelab::analysis::mc::{Dist, McSpec, parse_vary};
use bouncelab::api::ConditionsSpec;

/// Sample `i`'s varied value and COR, against the COR of the ball `at` makes of that value.
fn agree(preset: &str, vary: &str, at: impl Fn(f64) -> ConditionsSpec) {
    let ball = Ball::from_preset(preset).unwrap();
    let spec = McSpec::new(parse_vary(vary).unwrap(), Dist::Normal, 64, 7).unwrap();
    let mc = ball.monte_carlo(&spec).unwrap();
    let sampler = ball.sampler(&spec);
    let mut seen = Vec::new();
    for i in 0..16 {
        let x = sampler.inputs(i)[0];
        let one = ball.clone().at_conditions(&at(x)).unwrap();
        let cor = one.impact().unwrap().cor;
        let sampled = mc.samples.cor[i as usize];
        assert!(
            (sampled - cor).abs() < 1e-9,
            "{preset} {vary} sample {i} at {x}: {sampled} {cor}"
        );
        seen.push(cor);
    }
    // the spread moves the answer
    let (lo, hi) = seen
        .iter()
        .fold((1.0f64, 0.0f64), |(a, b), &c| (a.min(c), b.max(c)));
    assert!(hi - lo > 1e-4, "{preset} {vary}: {lo} … {hi}");
}

#[test]
fn each_sample_is_the_ball_at_its_own_conditions() {
    // an inflated ball's gauge pressure (at the record's 20 °C)
    agree("football", "pressure=5%", |p| ConditionsSpec {
        pressure: Some(p),
        ..ConditionsSpec::default()
    });
    // its temperature, the pressure following by the gas law (sampled in kelvin, read in °C)
    agree("football", "temperature=2%", |t| ConditionsSpec {
        temperature: Some(t),
        ..ConditionsSpec::default()
    });
    // a solid ball with a stored shift: its dashpot by Arrhenius
    agree("squash", "temperature=1%", |t| ConditionsSpec {
        temperature: Some(t),
        ..ConditionsSpec::default()
    });
}

#[test]
fn a_spread_the_ball_cannot_take_is_refused() {
    bad_each(&[
        (
            "mc --preset golf --vary pressure=5%",
            &["invalid vary", "golf is not inflated"],
        ),
        (
            "mc --preset superball --vary temperature=1%",
            &["invalid vary", "superball has no temperature model"],
        ),
        (
            "mc --preset basketball --vary temperature=1%",
            &["invalid vary", "temperature is not stated"],
        ),
    ]);
}
