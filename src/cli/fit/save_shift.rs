//! `fit --cor-temperature FILE --save NAME`: the preset's ball with the fitted temperature
//! shift stored in its record (`[calibration.temperature_shift]`, docs/model.md §10.4): c the
//! fitted c_ref at the reference temperature, E_a the fitted activation energy, and the CORs'
//! file among the record's data. Staged with the fit's report and published with it
//! ([`crate::cli::outputs`]), never over an existing preset without `--force`.

use super::save::{now_utc, remove_created, stage_preset};
use crate::analysis::fit::cor_temperature::TemperatureFit;
use crate::atomic::Outputs;
use crate::cli::output::TextJson;
use crate::measured::CorTemperatureRow;
use crate::preset::{Calibration, CalibrationData, Preset, TemperatureShift};
use std::io::Write;

/// The saved preset: the base's ball and material, c = c_ref, its record the base's (if
/// any) with the temperature, the shift and the CORs' data set added; no `[fit]` table (the
/// base's is of other parameters).
fn shifted(
    base: &Preset,
    name: &str,
    file: &str,
    points: &[CorTemperatureRow],
    fit: &TemperatureFit,
) -> Preset {
    let when = now_utc();
    let speeds: Vec<f64> = points.iter().map(|p| p.v0).collect();
    let source = format!("{file} (fitted by `bouncelab fit --cor-temperature` on {when})");
    let source = crate::sanitize::line(&source).to_string();
    let data = CalibrationData {
        source: source.clone(),
        quantities: "COR against temperature: the dashpot's Arrhenius shift".into(),
        speeds: speeds.clone(),
        heights: Vec::new(),
        loads: Vec::new(),
        // CORs at several temperatures: the COR
        outputs: Some(vec![crate::preset::Output::Cor]),
    };
    let mut record = match &base.calibration {
        Some(c) => {
            let mut c = c.clone();
            c.data.push(data);
            c
        }
        None => Calibration::over(data, &speeds),
    };
    for v in speeds {
        record.speed_min = record.speed_min.min(v);
        record.speed_max = record.speed_max.max(v);
    }
    record.temperature = Some(fit.t_ref_c);
    let temperatures = points.iter().map(|p| p.temperature_c);
    let lo = temperatures.clone().fold(f64::INFINITY, f64::min);
    let hi = temperatures.fold(f64::NEG_INFINITY, f64::max);
    record.temperature_shift = Some(TemperatureShift {
        activation_energy: fit.activation.value,
        reference: fit.t_ref_c,
        source,
        span: Some([lo, hi]),
    });
    let mut p = base.clone();
    // the base's flight model kept under the new name
    p.aerodynamics = base.flight_model();
    p.name = name.into();
    p.description = format!("{} with the temperature shift fitted on {when}", base.name);
    p.adopted.damping = Some(fit.c_ref.value);
    p.fit = None;
    p.calibration = Some(record);
    p
}

/// Stage the preset `name`, then write `report` and publish both (or neither).
pub fn save_then_report(
    a: &super::FitArgs,
    name: &str,
    file: &str,
    points: &[CorTemperatureRow],
    fit: &TemperatureFit,
    report: &[u8],
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    let base = crate::cli::ball::select(
        a.ball.choice.preset.as_deref(),
        a.ball.choice.config.as_deref(),
    )?
    .preset;
    let preset = shifted(&base, name, file, points, fit);
    let header = vec![format!(
        "The preset '{}' with its dashpot's temperature shift fitted by `bouncelab fit \
         --cor-temperature` to {file}: c_ref = {} kg/s at {} °C, E_a = {} J/mol.",
        base.name,
        crate::text::short(fit.c_ref.value, 6),
        crate::text::short(fit.t_ref_c, 4),
        crate::text::short(fit.activation.value, 6)
    )];
    let mut files = Outputs::new(a.force);
    let (path, created) = stage_preset(&preset, &header, a.force, &mut files)?;
    if let Err(e) = crate::cli::outputs::report_then_commit(out, report, files) {
        if let Some(top) = &created {
            remove_created(Some(top), path.parent().unwrap_or(top));
        }
        return Err(e);
    }
    let note = format!("saved preset '{name}' to {}", path.display());
    match a.format {
        TextJson::Json => eprintln!("bouncelab: {note}"),
        TextJson::Text => writeln!(out, "{note}")?,
    }
    Ok(())
}
