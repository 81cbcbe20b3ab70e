//! The ball squeezed between two plates ([`crate::analysis::statics`], docs/model.md §11):
//! the load in kilograms as the tests give it, and what the ball's record says of the answer.

use super::{Ball, BallHeader, BallRecord};
use crate::analysis::statics::{ContactDeflection, StaticDeflection, static_deflection};
use crate::drop::G;
use crate::drop::deformation::DEFORMATION_STANDARDS;
use crate::preset::{Calibration, SPEED_SLACK};
use serde::Serialize;

pub use crate::analysis::statics::ITF_RETURN_PEAK;

/// "outside calibration: load …" when `load_kg` lies outside the loads of the record's
/// static tests (to [`SPEED_SLACK`] either side); `None` inside, or when no static test
/// gives its loads.
fn outside_loads(c: &Calibration, load_kg: f64) -> Option<String> {
    let ([lo, hi], sources) = c.load_range()?;
    if load_kg >= lo * (1.0 - SPEED_SLACK) && load_kg <= hi * (1.0 + SPEED_SLACK) {
        return None;
    }
    let kg = |v: f64| crate::text::short(v, 4);
    let range = if lo == hi {
        format!("{} kg only", kg(lo))
    } else {
        format!("{}–{} kg", kg(lo), kg(hi))
    };
    Some(format!(
        "outside calibration: load {} kg, the ball was tested between plates at {range} \
         ({sources}): the static deflection extrapolates the model there",
        kg(load_kg)
    ))
}

impl Ball {
    /// The return-window warning of a static standard this answer is the test of (its load
    /// and peak) on a ball the standard is for (`DeformationStandard::return_warning`).
    fn return_window_warning(&self, s: &StaticDeflection) -> Option<String> {
        let name = self.name.as_deref()?;
        DEFORMATION_STANDARDS
            .iter()
            .filter(|d| d.balls.contains(&name) && d.is_test_of(s))
            .find_map(|d| d.return_warning(s))
    }

    /// Forward and return deflection between two plates under `load_kg` (the weight
    /// `load_kg · g` on each contact), the return read after compressing the diameter by
    /// `peak` m. `Err` names the field at fault.
    pub fn static_deflection(
        &self,
        load_kg: f64,
        peak: f64,
    ) -> Result<StaticDeflection, super::BallError> {
        let bad = |field: &'static str, value: f64, reason: String| super::BallError::Invalid {
            field,
            value,
            reason,
        };
        if !(load_kg.is_finite() && load_kg > 0.0 && load_kg <= 1e6) {
            return Err(bad(
                "load",
                load_kg,
                "must be a positive mass in kg, at most 1e6".into(),
            ));
        }
        let diameter = 2.0 * self.radius();
        if !(peak.is_finite() && peak > 0.0 && (diameter.is_nan() || peak < diameter)) {
            return Err(bad(
                "peak",
                peak,
                format!(
                    "must be a positive shortening of the diameter, below the diameter {} m",
                    crate::text::short(diameter, 4)
                ),
            ));
        }
        Ok(static_deflection(&self.params, self.law, load_kg * G, peak))
    }

    /// What the caller should know about a static answer: "outside calibration: …" when the
    /// command line changed the recorded ball, when the answer runs another set or law than
    /// the record's, or when the record holds no static test (a data set with neither speeds
    /// nor heights): the chain's stiffness was then fitted to impacts alone; and a deflection
    /// past the radius, where the model's small-deflection picture does not hold.
    pub fn static_warnings(&self, s: &StaticDeflection) -> Vec<String> {
        let mut w = Vec::new();
        if let Some(c) = &self.calibration {
            if !self.overrides.is_empty() {
                w.push(format!(
                    "outside calibration: {} changed the ball, whose record ({}) no longer \
                     applies",
                    self.overrides.join(", "),
                    c.sources()
                ));
            } else if let Some(other) = &c.other_model {
                w.push(format!(
                    "outside calibration: the record ({}) is of the preset's own parameter set \
                     and law, and this answer runs {other}",
                    c.sources()
                ));
            } else if !c.data.iter().any(|d| d.is_static()) {
                w.push(format!(
                    "outside calibration: the ball's record holds no static test (it was fitted \
                     to impacts, {}: {}): the static deflection extrapolates the model there",
                    c.range_text(),
                    c.sources()
                ));
            } else if let Some(warning) = outside_loads(c, s.force / G) {
                w.push(warning);
            }
        }
        w.extend(self.return_window_warning(s));
        let r = self.radius();
        for (what, d) in [("forward", &s.forward), ("return", &s.return_)] {
            if let Ok(d) = d
                && d.total() >= r
            {
                w.push(format!(
                    "the {what} deflection at each plate, {} m, reaches the radius {} m: the \
                     model's small-deflection picture does not hold there",
                    crate::text::short(d.total(), 4),
                    crate::text::short(r, 4)
                ));
            }
        }
        w
    }
}

/// One reading of `bouncelab static --format json`, SI: the diameter's shortening and one
/// contact's parts, or `null` and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StaticReading {
    /// The diameter's shortening, m.
    pub deflection_m: Option<f64>,
    /// One contact's indentation, m.
    pub indentation_m: Option<f64>,
    /// One contact's recoil spring, m.
    pub recoil_m: Option<f64>,
    /// Why the model gives no reading.
    pub reason: Option<String>,
}

impl StaticReading {
    fn of(r: &Result<ContactDeflection, String>) -> StaticReading {
        match r {
            Ok(d) => StaticReading {
                deflection_m: Some(d.diameter()),
                indentation_m: Some(d.indentation),
                recoil_m: Some(d.recoil),
                reason: None,
            },
            Err(why) => StaticReading {
                deflection_m: None,
                indentation_m: None,
                recoil_m: None,
                reason: Some(why.clone()),
            },
        }
    }
}

/// The return reading: after compressing the diameter by `peak_m` under `peak_force_n`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ReturnReading {
    /// The reading.
    #[serde(flatten)]
    pub reading: StaticReading,
    /// The compression of the diameter it is read after, m.
    pub peak_m: f64,
    /// The force at that compression, N (`null` without a return reading).
    pub peak_force_n: Option<f64>,
}

/// `bouncelab static --format json`: the ball between two plates under a load (the command
/// line writes it, the Python package's `static` returns it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StaticReport<'a> {
    /// Which ball.
    #[serde(flatten)]
    pub header: BallHeader<'a>,
    /// The load, kg.
    pub load_kg: f64,
    /// Its weight on each contact, N.
    pub force_n: f64,
    /// g, m/s².
    pub g: f64,
    /// The forward reading.
    pub forward: StaticReading,
    /// The return reading.
    #[serde(rename = "return")]
    pub return_: ReturnReading,
    /// [`Ball::static_warnings`].
    pub warnings: Vec<String>,
    /// The ball it ran (docs/cli.md, "The ball object").
    pub ball: BallRecord,
}

impl<'a> StaticReport<'a> {
    /// The report of `s`, the static deflection of `ball` under `load_kg`.
    pub fn new(ball: &'a Ball, load_kg: f64, s: &StaticDeflection) -> StaticReport<'a> {
        StaticReport {
            header: ball.header(),
            load_kg,
            force_n: s.force,
            g: G,
            forward: StaticReading::of(&s.forward),
            return_: ReturnReading {
                reading: StaticReading::of(&s.return_),
                peak_m: s.peak,
                peak_force_n: s.peak_force,
            },
            warnings: ball.static_warnings(s),
            ball: ball.record_json(),
        }
    }
}
