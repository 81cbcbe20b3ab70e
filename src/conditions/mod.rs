//! The conditions a ball is used at: its inflation pressure, the temperature, and the time
//! since it was inflated (docs/model.md §10). Plain physics, no I/O:
//!
//! - [`pressure`]: a pressure typed with its unit (`0.8bar`, `8psi`, `55kPa`, Pa bare);
//! - [`gas`]: the gas law at fixed volume, the gauge pressure a ball inflated at one
//!   temperature has at another;
//! - [`inflated`]: the contact stiffness of an inflated ball from its gauge pressure (the
//!   pressure acting on the flat, the shell's own stiffness), calibrated at the preset's
//!   nominal pressure so that the preset's answers there do not move;
//! - [`leak`]: the gauge pressure's decay by permeation through the bladder, and its rate
//!   fitted from pressure readings.

pub mod duration;
pub mod gas;
pub mod inflated;
pub mod leak;
pub mod pressure;

/// A quantity as users type it, a number and an optional unit from `units` (lower case; of
/// two that end alike the longer first), matched case-insensitively at its end, with or
/// without a space between: (the number, the unit's size, the text as messages show it).
/// A number the command line's own reader refuses (`text::parse::read`) is refused naming
/// `field`; the caller checks the quantity's own domain. [`pressure::parse`] and
/// [`duration::parse`] read by it.
fn with_unit<'t>(
    field: &str,
    text: &'t str,
    units: &[(&str, f64)],
) -> Result<(f64, f64, std::borrow::Cow<'t, str>), String> {
    let t = text.trim();
    let lower = t.to_ascii_lowercase();
    let (number, scale) = units
        .iter()
        .find(|(unit, _)| lower.ends_with(unit))
        .map(|(unit, scale)| (&t[..t.len() - unit.len()], *scale))
        .unwrap_or((t, 1.0));
    let shown = crate::sanitize::line(t);
    match crate::text::parse::read(number) {
        Ok(x) => Ok((x, scale, shown)),
        Err(why) => Err(format!(
            "invalid {field}: {}",
            crate::text::parse::refusal(&shown, why)
        )),
    }
}

/// The standard atmosphere, Pa (ISO 2533; the pressure a gauge reading is relative to unless
/// the user gives another).
pub const STANDARD_ATMOSPHERE: f64 = 101_325.0;

/// 0 °C in kelvin (the kelvin's definition, SI Brochure 9th ed.).
pub const ZERO_CELSIUS: f64 = 273.15;

/// The conditions an answer was computed at, as every answer states them: the temperature,
/// the gauge pressure at that temperature (`None` for a solid ball) and the atmosphere the
/// gauge reads against.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Conditions {
    /// The ball's temperature, °C; `None` where neither the ball's calibration record nor
    /// the caller states one (the answer is the record's, at a temperature nobody wrote down).
    pub temperature_c: Option<f64>,
    /// Gauge pressure inside the ball at `temperature_c`, Pa; `None` for a solid ball.
    pub pressure_gauge_pa: Option<f64>,
    /// The atmosphere's pressure, Pa.
    pub atmosphere_pa: f64,
    /// The time since inflation the pressure was decayed over, s, and the leak's half-life,
    /// s, with the standard whose limit was assumed as the leak (`None`: the caller's own
    /// half-life); for the answer's warnings, not its JSON.
    #[serde(skip)]
    pub leak: Option<(f64, f64, Option<&'static str>)>,
}

/// A condition out of its domain, naming the field as the command line's flags do.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ConditionsError {
    /// A temperature at or below absolute zero, or not finite.
    #[error("invalid {field}: {value} °C (must be above absolute zero, −273.15 °C)")]
    Temperature {
        /// The flag or field (`temperature`, `inflated-at`).
        field: &'static str,
        /// What was given.
        value: f64,
    },
    /// A pressure that is not finite, or an absolute pressure that is not positive.
    #[error("invalid {field}: {value} Pa ({why})")]
    Pressure {
        /// The flag or field (`pressure`, `atmosphere`).
        field: &'static str,
        /// What was given, Pa.
        value: f64,
        /// Why it was refused.
        why: &'static str,
    },
    /// A time or rate that is negative or not finite.
    #[error("invalid {field}: {value} ({why})")]
    Time {
        /// The flag or field (`after`, `half-life`).
        field: &'static str,
        /// What was given, s.
        value: f64,
        /// Why it was refused.
        why: &'static str,
    },
}

/// `t` °C in kelvin, refused at or below absolute zero (`field` names it).
pub fn kelvin(field: &'static str, t: f64) -> Result<f64, ConditionsError> {
    let k = t + ZERO_CELSIUS;
    if !t.is_finite() || k <= 0.0 {
        return Err(ConditionsError::Temperature { field, value: t });
    }
    Ok(k)
}

/// The atmosphere `p_atm`, Pa, checked: finite and positive.
pub fn atmosphere(p_atm: f64) -> Result<f64, ConditionsError> {
    if !p_atm.is_finite() || p_atm <= 0.0 {
        return Err(ConditionsError::Pressure {
            field: "atmosphere",
            value: p_atm,
            why: "must be a positive absolute pressure",
        });
    }
    Ok(p_atm)
}
