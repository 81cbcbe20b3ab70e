//! A ball at a standard's test conditions (docs/drop.md, "Conditions"): `drop --standard NAME`
//! runs the ball at the temperature and pressure the standard's rule states, and a ball run
//! at others says so in its warnings.

use super::{Ball, BallError, ConditionsSpec};
use crate::conditions::Conditions;
use crate::drop::conditions::{TestConditions, of};
use crate::drop::standards::Standard;
use crate::text::short;

/// Relative slack on a pressure window's ends: the presets' pressures are rounded to 10 Pa
/// (the basketball's 8 psi is 55 160 Pa, 8 psi being 55 158.06 Pa).
const PRESSURE_SLACK: f64 = 1e-3;

/// Whether `c` lies within the test's stated conditions; `None` where the test states
/// nothing the ball's conditions can be compared with.
fn within(t: &TestConditions, c: &Conditions) -> Option<bool> {
    let temperature = match (t.temperature_c, c.temperature_c) {
        (Some([nominal, tol]), Some(x)) => Some((x - nominal).abs() <= tol),
        _ => None,
    };
    let pressure = match (t.pressure_gauge_pa, c.pressure_gauge_pa) {
        (Some([lo, hi]), Some(p)) => {
            Some(p >= lo * (1.0 - PRESSURE_SLACK) && p <= hi * (1.0 + PRESSURE_SLACK))
        }
        _ => None,
    };
    match (temperature, pressure) {
        (None, None) => None,
        (a, b) => Some(a.unwrap_or(true) && b.unwrap_or(true)),
    }
}

/// "20 ± 2 °C, 80 kPa gauge": a test's stated conditions in words; "23 °C" where no
/// tolerance is stated (a tolerance of 0: `wsf-23` printed "23 ± 0 °C", issue 52's trial).
pub fn test_words(t: &TestConditions) -> String {
    let temperature = t.temperature_c.map(|[n, tol]| {
        if tol == 0.0 {
            format!("{} °C", short(n, 4))
        } else {
            format!("{} ± {} °C", short(n, 4), short(tol, 3))
        }
    });
    let pressure = t.pressure_gauge_pa.map(|[lo, hi]| {
        if lo == hi {
            format!("{} kPa gauge", short(lo / 1e3, 4))
        } else {
            format!("{}–{} kPa gauge", short(lo / 1e3, 4), short(hi / 1e3, 4))
        }
    });
    match (temperature, pressure) {
        (Some(t), Some(p)) => format!("{t}, {p}"),
        (Some(t), None) => format!("{t}, no pressure stated"),
        (None, Some(p)) => format!("no temperature stated, {p}"),
        (None, None) => "no temperature or pressure stated".into(),
    }
}

impl Ball {
    /// The ball for the standard `s`'s test: when the caller asked no conditions and one of
    /// the standard's balls ([`Ball::is_named_among`]) is off the test's (an inflated ball's
    /// pressure outside its window, or its temperature off the test's), the ball at the
    /// test's own — inflated to the middle of the window at the test's temperature; a solid
    /// ball with a stored temperature shift at the test's temperature. Another sport's ball
    /// keeps its own conditions (a tennis ball is not inflated to FIBA's 8 psi): its warning
    /// is [`Ball::standard_ball_warning`]'s. With a warning when one of the standard's balls
    /// is off the test's conditions (the caller's choice, or what the ball cannot change).
    pub fn at_standard(
        self,
        s: &Standard,
        asked: &ConditionsSpec,
    ) -> Result<(Ball, Option<String>), BallError> {
        let name = s.name;
        let test = of(name);
        let mut ball = self;
        if !ball.is_named_among(s.balls) {
            return Ok((ball, None));
        }
        if asked.is_empty() && within(&test, &ball.conditions) == Some(false) {
            let at = test.temperature_c.map(|[n, _]| n);
            let spec = if ball.is_inflated() {
                ConditionsSpec {
                    pressure: test.pressure_gauge_pa.map(|[lo, hi]| (lo + hi) / 2.0),
                    temperature: at,
                    inflated_at: at,
                    ..ConditionsSpec::default()
                }
            } else if ball.temperature_shift().is_some() {
                // a solid ball with a stored shift: at the test's temperature (the squash
                // ball at WSF's 23 °C, docs/model.md §10.4)
                ConditionsSpec {
                    temperature: at,
                    ..ConditionsSpec::default()
                }
            } else {
                ConditionsSpec::default()
            };
            if !spec.is_empty() {
                ball = ball.at_conditions(&spec)?;
            }
        }
        let warning = (within(&test, &ball.conditions) == Some(false)).then(|| {
            format!(
                "off the test's conditions: {name} tests at {}; this ball is at {} — the \
                 verdict is of this ball, not of the test's",
                test_words(&test),
                super::conditions_words::words(&ball.conditions)
            )
        });
        Ok((ball, warning))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_tolerance_stated_prints_none() {
        let words = |name| test_words(&crate::drop::conditions::of(name));
        assert_eq!(words("wsf-23"), "23 °C, no pressure stated");
        assert_eq!(words("fifa-quality-pro"), "20 ± 2 °C, 80 kPa gauge");
    }

    fn at(t: Option<f64>, p: Option<f64>) -> Conditions {
        Conditions {
            temperature_c: t,
            pressure_gauge_pa: p,
            atmosphere_pa: 101_325.0,
            leak: None,
        }
    }

    #[test]
    fn within_the_tests_conditions() {
        let fiba = of("fiba");
        assert_eq!(within(&fiba, &at(None, Some(55_160.0))), Some(true));
        assert_eq!(within(&fiba, &at(None, Some(40_000.0))), Some(false));
        let itf = of("itf");
        assert_eq!(within(&itf, &at(None, None)), None);
        assert_eq!(within(&itf, &at(Some(21.5), None)), Some(true));
        assert_eq!(within(&itf, &at(Some(5.0), None)), Some(false));
        assert_eq!(within(&of("mlb"), &at(Some(5.0), None)), None);
    }

    #[test]
    fn a_ball_off_the_test_is_brought_to_it_unless_the_caller_asked() {
        let fifa_pro = crate::drop::standards::find("fifa-quality-pro").unwrap();
        let cold = Ball::from_preset("football")
            .unwrap()
            .at_conditions(&ConditionsSpec {
                temperature: Some(5.0),
                ..ConditionsSpec::default()
            })
            .unwrap();
        // asked: kept, and warned
        let asked = ConditionsSpec {
            temperature: Some(5.0),
            ..ConditionsSpec::default()
        };
        let (b, w) = cold.clone().at_standard(fifa_pro, &asked).unwrap();
        assert_eq!(b.conditions.temperature_c, Some(5.0));
        assert!(
            w.unwrap()
                .contains("fifa-quality-pro tests at 20 ± 2 °C, 80 kPa gauge")
        );
        // at the record: unchanged, no warning
        let own = Ball::from_preset("football").unwrap();
        let (b, w) = own
            .clone()
            .at_standard(fifa_pro, &ConditionsSpec::default())
            .unwrap();
        assert_eq!((b, w), (own, None));
    }
}
