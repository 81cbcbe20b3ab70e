//! A ball at its conditions (docs/model.md §10): the one resolver from a ball and the
//! conditions a caller asks for — inflation pressure, temperature, the temperature it was
//! inflated at, the time since — to the ball's parameters. The command line's `--pressure`,
//! `--temperature`, `--inflated-at`, `--after` (every command that runs a ball), the Python
//! package's `pressure=`/`temperature=` and `mc --vary pressure=…` all come here.
//!
//! An inflated ball is a preset whose calibration record states its gauge pressure p₀; its
//! K_p follows the gauge pressure by `conditions::inflated` (K_shell + 2πR p, calibrated at
//! p₀), K_r keeps λ = K_r/K_p, and c keeps the retardation time c/K_r of the Kelvin–Voigt
//! pair (docs/model.md §10.1). The pressure at the run is the
//! inflation pressure, decayed by the leak over `after` at the inflation temperature
//! (`conditions::leak`), carried to the run's temperature by the gas law at fixed volume
//! (`conditions::gas`). At the record's pressure and temperature the ball's parameters are
//! not touched, so its answers there do not move (tests/physics/conditions.rs).

use super::{Ball, BallError};
use crate::analysis::fit::{Param, apply};
use crate::conditions::{Conditions, STANDARD_ATMOSPHERE, gas, inflated::Inflated, leak::Leak};
use crate::model::params::ImpactParams;

/// Seconds in an hour.
const HOUR: f64 = 3_600.0;

/// The conditions a caller asks for; `None` keeps the ball's record's.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ConditionsSpec {
    /// Gauge pressure the ball was inflated to, Pa (at `inflated_at`).
    pub pressure: Option<f64>,
    /// The ball's temperature at the run, °C.
    pub temperature: Option<f64>,
    /// The temperature the ball was inflated at, °C [default: the record's].
    pub inflated_at: Option<f64>,
    /// Time since inflation, s: the leak's.
    pub after: Option<f64>,
    /// The leak's half-life, s [default: the limit of the ball's own pressure-loss standard].
    pub half_life: Option<f64>,
}

impl ConditionsSpec {
    /// Whether nothing is asked.
    pub fn is_empty(&self) -> bool {
        *self == ConditionsSpec::default()
    }
}

/// A ball's pressure-loss standard, as a leak: FIFA Quality Pro's limit, 20 % of the gauge
/// pressure in 72 h (docs/model.md §10.3, docs/standards: `fifa-pressure-loss`), the largest
/// leak a ball that passes may have. The football preset's default leak (no measured rate of
/// a ball was found; the assumption is stated in the answer's warnings).
pub fn standard_leak(ball_name: &str) -> Option<(Leak, &'static str)> {
    let s = crate::drop::conditions::PRESSURE_LOSS
        .iter()
        .find(|s| s.balls.contains(&ball_name))?;
    let leak = Leak::losing(s.max_loss, s.hours * HOUR).ok()?;
    Some((leak, s.name))
}

/// The conditions of a record: its temperature and pressure as it states them, the standard
/// atmosphere.
pub fn recorded(calibration: Option<&crate::preset::Calibration>) -> Conditions {
    Conditions {
        temperature_c: calibration.and_then(|c| c.temperature),
        pressure_gauge_pa: calibration.and_then(|c| c.pressure),
        atmosphere_pa: STANDARD_ATMOSPHERE,
        leak: None,
    }
}

impl Ball {
    /// The ball's name as an error names it.
    fn called(&self) -> String {
        self.name.clone().unwrap_or_else(|| "the ball".into())
    }

    /// Whether the ball is inflated: its calibration record states a gauge pressure.
    pub fn is_inflated(&self) -> bool {
        self.calibration.as_ref().and_then(|c| c.pressure).is_some()
    }

    /// The ball at the conditions `spec` asks for: K_p (and K_r, λ kept; K_h following) at the
    /// gauge pressure the run has, and [`Ball::conditions`] stating them. Refused, naming the
    /// field: a pressure or a leak for a ball that is not inflated, a half-life without a time
    /// to leak over, a temperature for a ball with no temperature model, a temperature where
    /// the record states none to start from (or an inflation temperature without the run's),
    /// `--k-p` beside a pressure, and a ball left flat, named by the flag whose step flattened
    /// it (`Ball::blame`).
    pub fn at_conditions(mut self, spec: &ConditionsSpec) -> Result<Ball, BallError> {
        if spec.is_empty() {
            return Ok(self);
        }
        let Some(p0) = self.calibration.as_ref().and_then(|c| c.pressure) else {
            return self.solid_at(spec);
        };
        self.check_inflated(spec, p0)?;
        let t_record = self.calibration.as_ref().and_then(|c| c.temperature);
        let t0 = spec.inflated_at.or(t_record);
        let t = spec.temperature.or(t_record);
        let atm = self.conditions.atmosphere_pa;
        let inflated = spec.pressure.unwrap_or(p0);
        let (leaked, leak) = match spec.after {
            Some(after) => {
                let (l, assumed) = self.leak(spec)?;
                let p = l.gauge_after(inflated, after).map_err(from)?;
                // a leak that lost nothing (no time since inflation) moved nothing: the
                // record's own conditions, as `--after 0` is
                (
                    p,
                    (p != inflated).then_some((after, l.half_life(), assumed)),
                )
            }
            None => (inflated, None),
        };
        let (t0, t) = match (t0, t) {
            (Some(t0), Some(t)) => (t0, t),
            // the temperature given is the one at fault: `run --preset tennis --temperature
            // 30` said "invalid inflated-at: 30" (issue 52's trial; tests/cli/issue52_trial.rs)
            (None, Some(t)) => {
                let why = format!(
                    "{}'s calibration records no temperature the ball was inflated at: give \
                     --inflated-at too, the temperature at which it was inflated",
                    self.called()
                );
                return Err(invalid("temperature", t, why));
            }
            _ => {
                let params = self.pressure_params(p0, leaked);
                self.params = params.map_err(|e| self.blame(e, spec, p0, None))?;
                self.conditions.pressure_gauge_pa = Some(leaked);
                self.conditions.leak = leak;
                return Ok(self);
            }
        };
        let p = gas::gauge_at(leaked, t0, t, atm).map_err(from)?;
        let params = self.pressure_params(p0, p);
        self.params = params.map_err(|e| self.blame(e, spec, p0, Some(t0)))?;
        self.conditions = Conditions {
            temperature_c: Some(t),
            pressure_gauge_pa: Some(p),
            atmosphere_pa: atm,
            leak,
        };
        Ok(self)
    }

    /// What an inflated ball refuses before its pressure is worked: a half-life without a
    /// time, `--k-p` beside a pressure, an inflation temperature without the run's where the
    /// record states none (docs/cli.md: such a ball needs both; `--inflated-at 30` alone ran
    /// the tennis ball as if at 30 °C).
    fn check_inflated(&self, spec: &ConditionsSpec, p0: f64) -> Result<(), BallError> {
        if let (Some(h), None) = (spec.half_life, spec.after) {
            return Err(invalid(
                "half-life",
                h,
                "a leak's half-life needs the time it leaks over: give --after (a pressure-loss \
                 standard gives its own)"
                    .into(),
            ));
        }
        if self.overrides.iter().any(|o| o == "k_p") {
            return Err(invalid(
                "pressure",
                spec.pressure.unwrap_or(p0),
                "--k-p sets K_p too, which the pressure sets: give one of them".into(),
            ));
        }
        let t_record = self.calibration.as_ref().and_then(|c| c.temperature);
        if let (None, Some(t0), None) = (t_record, spec.inflated_at, spec.temperature) {
            let why = format!(
                "{}'s calibration records no temperature: give --temperature too, the \
                 ball's temperature at the run (the gas law carries it from the one it was \
                 inflated at)",
                self.called()
            );
            return Err(invalid("inflated-at", t0, why));
        }
        Ok(())
    }

    /// K_p at gauge pressure `p` from its value at the record's `p0`, as a ratio so that at
    /// `p0` nothing moves (the football's K_p is the membrane term rounded to the newton).
    /// K_r keeps λ = K_r/K_p and c keeps the Kelvin–Voigt pair's retardation time c/K_r, so
    /// both move by the same ratio (docs/model.md §10.1: ζ = √(m K_p)/(2c) ∝ 1/√K_p, and a
    /// softer ball loses more, as inflated balls do). The ball's parameters there, checked.
    pub(super) fn pressure_params(&self, p0: f64, p: f64) -> Result<ImpactParams, BallError> {
        let radius = self.radius();
        let model = Inflated::calibrated(radius, self.params.k_p, p0).map_err(from)?;
        let ratio = model.k_p(p).map_err(from)? / model.k_p(p0).map_err(from)?;
        if ratio == 1.0 {
            return Ok(self.params);
        }
        let k = &self.params;
        let moved = [k.k_p * ratio, k.damping * ratio, k.k_r * ratio];
        let params = apply(&self.params, &[Param::KP, Param::C, Param::KR], &moved);
        params.validate()?;
        Ok(params)
    }

    /// The leak over `--after`: the half-life given, or the limit of the ball's own
    /// pressure-loss standard (named, as the assumption it is).
    pub(super) fn leak(
        &self,
        spec: &ConditionsSpec,
    ) -> Result<(Leak, Option<&'static str>), BallError> {
        if let Some(h) = spec.half_life {
            return Ok((Leak::from_half_life(h).map_err(from)?, None));
        }
        let name = self.name.as_deref().unwrap_or("");
        standard_leak(name)
            .map(|(l, s)| (l, Some(s)))
            .ok_or_else(|| {
                invalid(
                    "after",
                    spec.after.unwrap_or(0.0),
                    format!(
                        "no leak rate is known for {}: give --half-life (fit one with fit \
                     --pressure-loss)",
                        self.called()
                    ),
                )
            })
    }

    /// A solid ball: no pressure, no leak; a temperature only at the record's own.
    fn solid_at(self, spec: &ConditionsSpec) -> Result<Ball, BallError> {
        let solid = |field, value| {
            let why = format!(
                "{} is not inflated: its calibration records no inflation pressure",
                self.called()
            );
            Err(invalid(field, value, why))
        };
        if let Some(p) = spec.pressure {
            return solid("pressure", p);
        }
        if let Some(t) = spec.inflated_at {
            return solid("inflated-at", t);
        }
        if let Some(a) = spec.after {
            return solid("after", a);
        }
        if let Some(h) = spec.half_life {
            return solid("half-life", h);
        }
        let t = spec.temperature.unwrap_or(f64::NAN);
        crate::conditions::kelvin("temperature", t).map_err(from)?;
        let shift = self.temperature_shift().cloned();
        if shift.is_some() && self.overrides.iter().any(|o| o == "c") {
            // checked before the record's own temperature returns: a c given beside any
            // temperature is two settings of c, at the record's too (docs/cli.md)
            let why = "--damping sets c too, which the temperature shifts: give one of them";
            return Err(invalid("temperature", t, why.into()));
        }
        if self.conditions.temperature_c == Some(t) {
            return Ok(self);
        }
        if let Some(shift) = shift {
            return self.shifted(&shift, t);
        }
        Err(invalid(
            "temperature",
            t,
            format!(
                "{} has no temperature model (docs/model.md §10.4): its parameters hold at \
                 its record's temperature{}",
                self.called(),
                match self.conditions.temperature_c {
                    Some(r) => format!(", {} °C", crate::text::short(r, 4)),
                    None => ", which the record does not state".into(),
                }
            ),
        ))
    }
}

pub(super) fn invalid(field: &'static str, value: f64, reason: String) -> BallError {
    BallError::Invalid {
        field,
        value,
        reason,
    }
}

/// A condition out of its domain as the ball's error, its message kept.
pub(super) fn from(e: crate::conditions::ConditionsError) -> BallError {
    use crate::conditions::ConditionsError as E;
    match e {
        E::Temperature { field, value } => invalid(field, value, "must be above −273.15 °C".into()),
        E::Pressure { field, value, why } | E::Time { field, value, why } => {
            invalid(field, value, why.into())
        }
    }
}

impl Ball {
    /// The run's conditions for a Monte Carlo that spreads them (`mc --vary pressure=…,
    /// temperature=…`; `analysis::mc::McConditions`): `None` when `spec` varies neither.
    /// Refused, naming the field, where the ball cannot take the spread: a pressure for a
    /// ball that is not inflated, a temperature for a solid ball without a stored shift or a
    /// ball whose temperature is not stated (give `--temperature`).
    pub fn mc_conditions(
        &self,
        spec: &crate::analysis::mc::McSpec,
    ) -> Result<Option<crate::analysis::mc::McConditions>, BallError> {
        use crate::analysis::mc::Varied;
        let varies = |w| spec.vary.iter().find(|s| s.what == w).map(|s| s.spread);
        let (pressure, temperature) = (varies(Varied::Pressure), varies(Varied::Temperature));
        if pressure.is_none() && temperature.is_none() {
            return Ok(None);
        }
        let c = &self.conditions;
        let inflated = match c.pressure_gauge_pa {
            Some(p) => {
                let model =
                    Inflated::calibrated(self.radius(), self.params.k_p, p).map_err(from)?;
                let membrane = crate::conditions::inflated::membrane_stiffness(self.radius(), 1.0);
                Some((p, model.shell, membrane))
            }
            None => None,
        };
        if let (Some(s), None) = (pressure, inflated) {
            let why = format!(
                "pressure: {} is not inflated: its calibration records no inflation pressure",
                self.called()
            );
            return Err(invalid("vary", s, why));
        }
        let activation = self.temperature_shift().map(|s| s.activation_energy);
        if let Some(s) = temperature {
            let why = if inflated.is_none() && activation.is_none() {
                Some(format!(
                    "temperature: {} has no temperature model (docs/model.md §10.4)",
                    self.called()
                ))
            } else if c.temperature_c.is_none() {
                Some(format!(
                    "temperature: {}'s temperature is not stated: give --temperature",
                    self.called()
                ))
            } else {
                None
            };
            if let Some(why) = why {
                return Err(invalid("vary", s, why));
            }
        }
        Ok(Some(crate::analysis::mc::McConditions {
            temperature_c: c.temperature_c.unwrap_or(f64::NAN),
            inflated,
            atmosphere_pa: c.atmosphere_pa,
            activation,
        }))
    }
}
