//! A Monte Carlo's temperature spread says where it takes the ball that the conditions'
//! model does not vouch for, as `run` says it of one temperature (docs/model.md §10,
//! docs/cli.md "Conditions"): the squash ball's shift beyond its fitted span, and past the
//! COR's turn that `run` refuses; an inflated ball's gas moved by the gas law alone.

use crate::common;

use common::{argv, bl, outside_calibration};
use statrs::distribution::{ContinuousCDF, Normal};

use crate::conditions_squash::json_calibrated;

/// The squash ball's shift was fitted over 36.11–45 °C (presets/squash.toml `span`).
const SPAN: [f64; 2] = [36.11, 45.0];

/// `mc … --format json`'s one warning that speaks of the temperature spread.
fn spread_warning(line: &str) -> Option<String> {
    let v = json_calibrated(&argv(line));
    let w = outside_calibration(&v);
    let spread: Vec<&str> = w
        .into_iter()
        .filter(|w| w.contains("temperature spread"))
        .collect();
    assert!(spread.len() <= 1, "{line}: {spread:?}");
    spread.first().map(|w| w.to_string())
}

/// The share (0–1) the warning gives after `after` ("… about P % of the samples"), checked
/// against `p` to the three significant figures it is written to.
fn share_after(w: &str, after: &str, p: f64) {
    let tail = w
        .split(after)
        .nth(1)
        .unwrap_or_else(|| panic!("no {after:?} in {w}"));
    let said: f64 = tail
        .trim_start_matches("about ")
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|e| panic!("{e}: {w}"));
    let ulp = 10f64.powf((100.0 * p).log10().floor() - 2.0);
    assert!(
        (said - 100.0 * p).abs() <= 0.5 * ulp,
        "{said} % against {}: {w}",
        100.0 * p
    );
}

/// The defect: `mc --preset squash --temperature 40 --vary temperature=10%` drew a normal
/// temperature of sd 31.3 K about 40 °C — most samples beyond the shift's span, one in eight
/// colder than the COR's turn at 4.3621 °C, which `run` refuses — and said nothing of either.
/// Now the share beyond the span and the share past the turn are the normal's own (Φ worked
/// here), and the turn is `run`'s refusal bound. Fails on the old code (no such warning).
#[test]
fn a_temperature_spread_says_its_share_beyond_the_shift() {
    let w = spread_warning(
        "mc --preset squash --temperature 40 --vary temperature=10% --samples 2000 \
         --format json",
    )
    .expect("a warning of the spread");
    // the turn, as `run` refuses below it
    let refused = bl(&argv("run --preset squash --temperature -50"));
    assert_eq!(refused.code, 2);
    let bound = refused.stderr.split("refused below ").nth(1).unwrap();
    let turn: f64 = bound.split(' ').next().unwrap().parse().unwrap();
    let phi = |t: f64| Normal::standard().cdf((t - 40.0) / (0.1 * (40.0 + 273.15)));
    let outside = phi(SPAN[0]) + 1.0 - phi(SPAN[1]);
    let past = phi(turn);
    share_after(&w, "takes ", outside);
    assert!(
        w.contains("outside the temperature shift's fitted span 36.11–45 °C"),
        "{w}"
    );
    share_after(&w, "extrapolated; ", past);
    assert!(w.contains(&format!("colder than {turn} °C")), "{w}");
}

/// A uniform spread of 10 % about 40 °C reaches down to 8.7 °C only: beyond the span, never
/// past the turn, and the warning says the first alone; a spread inside the span says nothing.
#[test]
fn a_spread_that_stays_clear_of_the_turn_says_only_the_span() {
    let w = spread_warning(
        "mc --preset squash --temperature 40 --vary temperature=10% --dist uniform \
         --samples 500 --format json",
    )
    .expect("a warning of the spread");
    // uniform on 40 ± 31.315 °C: the span's 8.89 K of its 62.63 K, the rest beyond
    let outside = 1.0 - (SPAN[1] - SPAN[0]) / (2.0 * 0.1 * 313.15);
    share_after(&w, "takes ", outside);
    assert!(!w.contains("COR minimum"), "{w}");
    let inside = spread_warning(
        "mc --preset squash --temperature 40 --vary temperature=0.1% --dist uniform \
         --samples 500 --format json",
    );
    assert_eq!(inside, None);
}

/// An inflated ball's temperature spread moves its gas by the gas law alone, the rubber taken
/// at the record's temperature: said once, by the spread at the record's temperature and by
/// the ball's own warning away from it (not twice).
#[test]
fn an_inflated_balls_spread_says_the_gas_law_alone_once() {
    let said = |line: &str| {
        let v = json_calibrated(&argv(line));
        outside_calibration(&v)
            .iter()
            .filter(|w| w.contains("by the gas law alone"))
            .count()
    };
    let at_record = "mc --preset football --vary temperature=1% --samples 50 --format json";
    assert_eq!(said(at_record), 1);
    let warm = "mc --preset football --temperature 30 --vary temperature=1% --samples 50 \
                --format json";
    assert_eq!(said(warm), 1);
    assert_eq!(
        spread_warning(at_record).map(|w| w.contains("record's 20 °C")),
        Some(true)
    );
}
