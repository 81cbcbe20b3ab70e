//! The conditions the form (`m`) sets (issue 56): the inflation pressure p and the ball's
//! temperature T, as `--pressure` and `--temperature` take them, resolved by the library's one
//! resolver ([`Ball::at_conditions`], docs/model.md §10) on the ball the `y` line's options
//! make, so that the line's `bouncelab …` runs to the screen's numbers.
//!
//! An inflated ball's K_p follows its gauge pressure (K_shell + 2πR p, calibrated at the
//! record's p₀), K_r and c by the same factor (λ and the retardation time kept); at the
//! record's pressure and temperature nothing moves. A typed K_p beside a pressure is refused,
//! as `run --k-p … --pressure …` refuses it. A solid ball takes no pressure, and a temperature
//! only where the library has a temperature model for it (the library's refusal says why).

use super::Field;
use crate::api::{Ball, ConditionsSpec, recorded_conditions};
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::tui::setting::Setting;

/// The ball `preset` with `params` and radius `radius` at the conditions `spec`, by
/// [`Ball::at_conditions`]: its parameters, or the library's refusal naming the field.
pub fn conditioned(
    preset: &Preset,
    params: ImpactParams,
    radius: f64,
    spec: &ConditionsSpec,
) -> Result<ImpactParams, String> {
    if spec.is_empty() {
        return Ok(params);
    }
    ball_of(preset, params, radius)
        .at_conditions(spec)
        .map(|b| b.params)
        .map_err(|e| e.to_string())
}

/// The library's ball of `preset` with `params` and radius `radius`, at its record's
/// conditions.
fn ball_of(preset: &Preset, params: ImpactParams, radius: f64) -> Ball {
    let mut measured = preset.measured.clone();
    measured.radius = radius;
    Ball {
        name: Some(preset.name.clone()),
        origin: "explorer".into(),
        source: "adopted",
        params,
        law: preset.law,
        measured: Some(measured),
        description: String::new(),
        fit: None,
        poisson_ratio: Some(preset.material.poisson),
        calibration: preset.calibration.clone(),
        overrides: Vec::new(),
        conditions: recorded_conditions(preset.calibration.as_ref()),
        flight_model: preset.flight_model(),
    }
}

/// The library's ball of `s`: the preset's at the setting's conditions, as `run --pressure …
/// --temperature …` makes it ([`Ball::at_conditions`]; at the record's where it cannot), with
/// the setting's parameters and law, what those change from that ball its overrides. A typed
/// pressure is so a condition, not a change of K_p, K_r, c: the ball's calibration warning
/// and withheld comparison are `run`'s for the `y` line.
pub fn library_ball(preset: &Preset, s: &Setting) -> Ball {
    let own = ball_of(preset, preset.params(), s.radius);
    let at = own.clone().at_conditions(&s.conditions).unwrap_or(own);
    Ball {
        overrides: crate::api::changed_params(&at.params, &s.params),
        params: s.params,
        law: s.law,
        ..at
    }
}

/// Whether `preset` is an inflated ball: its calibration records a gauge pressure.
pub fn inflated(preset: &Preset) -> bool {
    preset
        .calibration
        .as_ref()
        .and_then(|c| c.pressure)
        .is_some()
}

/// `s` with the pressure (Pa) or temperature (°C) typed in `field` (or why not): the
/// conditions set, and the parameters of the ball the `y` line makes at them (`base`, given
/// a setting: `crate::tui::command::conditioned_base`). K_r and c each move by the factor the
/// conditions move the ball's own, so a λ or ζ the user set moves as the ball's does.
pub fn set(
    field: Field,
    value: f64,
    s: &Setting,
    preset: &Preset,
    base: &dyn Fn(&Setting) -> Result<ImpactParams, String>,
) -> Result<Setting, String> {
    let mut next = s.clone();
    match field {
        Field::Pressure => next.conditions.pressure = Some(value),
        _ => next.conditions.temperature = Some(value),
    }
    // back at the record's value: no option, as a fresh ball has none
    let rec = s.record;
    if next.conditions.pressure == rec.pressure {
        next.conditions.pressure = None;
    }
    if next.conditions.temperature == rec.temperature {
        next.conditions.temperature = None;
    }
    let was = base(s)?;
    if inflated(preset) && s.params.k_p != was.k_p {
        return Err(format!(
            "K_p was typed, and the pressure sets K_p too (as `run` refuses --k-p beside \
             --pressure): {} kept; `r` resets the ball",
            field.symbol()
        ));
    }
    let now = base(&next)?;
    let moved = |v: f64, old: f64, new: f64| if v == old { new } else { v * (new / old) };
    let p = &s.params;
    next.params = ImpactParams {
        v0: p.v0,
        k_r: moved(p.k_r, was.k_r, now.k_r),
        damping: moved(p.damping, was.damping, now.damping),
        ..now
    };
    next.params.validate().map_err(|e| super::refusal(&e))?;
    super::closing(&next)?;
    Ok(next)
}

/// Why K_p (or E, which sets it) cannot be typed: an inflated ball away from its record's
/// conditions takes its K_p from them, as `run` refuses `--k-p` beside `--pressure`.
pub fn k_p_refused(s: &Setting) -> Option<String> {
    let away = s.conditions.pressure.is_some() || s.conditions.temperature.is_some();
    (away && s.record.pressure.is_some()).then(|| {
        "the pressure and temperature set this inflated ball's K_p (as `run` refuses --k-p \
         beside --pressure): type p instead"
            .into()
    })
}

/// The readout's line of the conditions the form set (issue 56: every answer states its
/// conditions): " conditions 5.000 °C, gauge 69.93 kPa", the gauge pressure at the run's
/// temperature (the form's p is the inflation pressure); `None` at the record's, where the
/// preset's own numbers hold.
pub fn stated(preset: &Preset, s: &Setting) -> Option<String> {
    if s.conditions.is_empty() {
        return None;
    }
    let at = ball_of(preset, preset.params(), s.radius)
        .at_conditions(&s.conditions)
        .ok()?
        .conditions;
    let value = crate::tui::format::value;
    let mut parts = Vec::new();
    if let Some(t) = at.temperature_c {
        parts.push(format!("{} °C", value(t)));
    }
    if let Some(p) = at.pressure_gauge_pa {
        parts.push(format!("gauge {} kPa", value(p / 1e3)));
    }
    Some(format!(" conditions {}", parts.join(", ")))
}
