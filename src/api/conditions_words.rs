//! A ball's conditions in words (docs/cli.md "Conditions"): the text header's line, and the
//! ball's conditions against its record's for the `outside calibration:` warning and the
//! withheld comparison ([`Ball::conditions_moved`]).

use super::Ball;
use super::conditions::recorded;
use crate::conditions::Conditions;

/// Seconds in an hour.
const HOUR: f64 = 3_600.0;

impl Ball {
    /// The text header's line of conditions: "conditions: 20 °C, gauge 80 kPa (0.8 bar,
    /// 11.6 psi), atmosphere 101.3 kPa"; `None` for a ball whose record states neither a
    /// temperature nor a pressure and that was given none (the JSON's `conditions` says so
    /// with its nulls).
    pub fn conditions_line(&self) -> Option<String> {
        let c = &self.conditions;
        if c.temperature_c.is_none() && c.pressure_gauge_pa.is_none() {
            return None;
        }
        let short = crate::text::short;
        let t = c
            .temperature_c
            .map_or("temperature not recorded".into(), |t| {
                format!("{} °C", short(t, 4))
            });
        let p = c.pressure_gauge_pa.map_or("solid ball".into(), |p| {
            format!(
                "gauge {} kPa ({} bar, {} psi)",
                short(p / 1e3, 4),
                short(p / 1e5, 3),
                short(p / crate::conditions::pressure::PSI, 4)
            )
        });
        let atm = short(c.atmosphere_pa / 1e3, 4);
        Some(format!("conditions: {t}, {p}, atmosphere {atm} kPa"))
    }
}

/// "20 °C, 0.8 bar": a record's or a run's conditions in words, for the warnings.
pub(super) fn words(c: &Conditions) -> String {
    let short = crate::text::short;
    let t = c
        .temperature_c
        .map_or("an unrecorded temperature".into(), |t| {
            format!("{} °C", short(t, 4))
        });
    match c.pressure_gauge_pa {
        Some(p) => format!("{t}, {} kPa gauge", short(p / 1e3, 4)),
        None => t,
    }
}

/// Whether `run` is at `record`'s conditions to the precision a record states them: 4
/// significant digits of the gauge pressure (0.05 %: the basketball's record says 55 160 Pa
/// for 8 psi, 55 158.06 Pa; a user typing `--pressure 8psi` is at it) and 0.01 K; a
/// leak is always a change. Tested by tests/physics/conditions_squash.rs,
/// `a_ball_at_its_record_s_pressure_typed_in_other_units_is_not_warned`.
fn at_record(run: &Conditions, record: &Conditions) -> bool {
    let near = |a: Option<f64>, b: Option<f64>, tol: f64| match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() <= tol * b.abs().max(1.0),
        (None, None) => true,
        _ => false,
    };
    run.leak.is_none()
        && run.atmosphere_pa == record.atmosphere_pa
        && near(run.pressure_gauge_pa, record.pressure_gauge_pa, 5e-4)
        && match (run.temperature_c, record.temperature_c) {
            (Some(a), Some(b)) => (a - b).abs() <= 0.01,
            (a, b) => a.is_none() && b.is_none(),
        }
}

impl Ball {
    /// The ball's conditions against its record's, in words, when they differ: "the ball at
    /// 5 °C, 75.54 kPa gauge; its record at 20 °C, 80 kPa gauge"; `None` at the record's
    /// own (or without a record).
    pub fn conditions_moved(&self) -> Option<String> {
        let record = recorded(Some(self.calibration.as_ref()?));
        (!at_record(&self.conditions, &record)).then(|| {
            let leak = self
                .conditions
                .leak
                .map_or(String::new(), |(t, half, assumed)| {
                    let h = crate::text::short;
                    let whose = match assumed {
                        Some(s) => format!(
                            "no measured leak rate: the limit of {s} assumed, half-life {} h",
                            h(half / HOUR, 4)
                        ),
                        None => format!("half-life {} h", h(half / HOUR, 4)),
                    };
                    format!(", {} h after inflation ({whose})", h(t / HOUR, 4))
                });
            format!(
                "the ball at {}{leak}; its record at {}",
                words(&self.conditions),
                words(&record)
            )
        })
    }
}
