//! `bouncelab fit --cor-temperature FILE`: the Arrhenius shift of a solid ball's dashpot,
//! c(T) = c_ref exp[(E_a/R)(1/T − 1/T_ref)], fitted to CORs measured at several temperatures
//! on the preset's ball (docs/model.md §10.4, `analysis::fit::cor_temperature`), with the
//! other fits' intervals, verdict and exit codes: a report, then exit 1 when the data do not
//! follow the law.

use super::FitArgs;
use crate::analysis::fit::cor_temperature::{TemperatureFit, fit_cor_temperature};
use crate::analysis::fit::verdict::LackOfFit;
use crate::analysis::fit::{Estimate, MultiFitError};
use crate::cli::output::{self, TextJson, human, table};
use std::io::Write;
use std::path::Path;

pub fn run(a: &FitArgs, path: &Path, out: &mut dyn Write) -> anyhow::Result<()> {
    // --save writes the shift into a preset (save_shift.rs); the rest is not for this fit
    let without_save = FitArgs {
        save: None,
        ..a.clone()
    };
    if without_save.beyond_a_file_fit() {
        anyhow::bail!(
            "--cor-temperature fits the dashpot's temperature shift to CORs at temperatures \
             alone: the other data and --free, --v0, --plot, --drag-coefficient, \
             --rebound-height-sd are not for it"
        );
    }
    if let Some(name) = &a.save {
        super::save::check(name, a.force)?;
    }
    // --temperature names the reference temperature here; the ball is the preset's own
    let mut ball_args = a.ball.clone();
    let t_ref = ball_args.conditions.temperature.take();
    let ball = ball_args.resolve(None)?;
    let Some(t_ref) = t_ref.or(ball.conditions.temperature_c) else {
        anyhow::bail!(
            "invalid temperature: {}'s calibration records no temperature to refer c to: give \
             --temperature T_REF (°C)",
            ball.name.as_deref().unwrap_or("the ball")
        );
    };
    let points = crate::measured::file::cor_temperature(path)?;
    let file = path.display().to_string();
    let fit = fit_cor_temperature(&ball.params, ball.law, t_ref, &points)
        .map_err(|e| anyhow::anyhow!("{file}: {e}"))?;
    // the springs kept are the record's: its speeds against the data's, as every fit's ball
    let speeds = points.iter().map(|p| p.v0);
    let (lo, hi) = (
        speeds.clone().fold(f64::INFINITY, f64::min),
        speeds.fold(0.0, f64::max),
    );
    let warnings: Vec<String> = ball.speeds_warning(lo, hi).into_iter().collect();
    let report = Report {
        kind: "cor temperature",
        file: &file,
        points: points.len(),
        preset: ball.name.as_deref(),
        t_ref_c: fit.t_ref_c,
        c_ref: &fit.c_ref,
        activation_energy: &fit.activation,
        predicted: &fit.predicted,
        dof: fit.dof,
        lack_of_fit: fit.lack_of_fit,
        answered: fit.no_answer.is_empty(),
        no_answer: &fit.no_answer,
        warnings: &warnings,
        record: ball.record_json(),
    };
    let mut text = Vec::new();
    match a.format {
        // `ball`, `warnings` and `conditions` as every answer that runs a ball (docs/cli.md)
        // (the ball's conditions at T_ref, the temperature c_ref is the dashpot's at)
        TextJson::Json => {
            let at_ref = crate::conditions::Conditions {
                temperature_c: Some(fit.t_ref_c),
                ..ball.conditions
            };
            output::json_stated(&mut text, &report, &at_ref)?
        }
        TextJson::Text => write_text(&mut text, &report, &fit)?,
    }
    if !fit.no_answer.is_empty() {
        out.write_all(&text)?;
        let refused = if a.save.is_some() {
            "; --save not written"
        } else {
            ""
        };
        return Err(
            MultiFitError::Unanswered(format!("{}{refused}", fit.no_answer.join("; "))).into(),
        );
    }
    match &a.save {
        Some(name) => {
            super::save_shift::save_then_report(a, name, &file, &points, &fit, &text, out)
        }
        None => Ok(out.write_all(&text)?),
    }
}

/// The report, as JSON writes it (SI: kg/s, J/mol; °C).
#[derive(serde::Serialize)]
struct Report<'a> {
    kind: &'static str,
    file: &'a str,
    points: usize,
    preset: Option<&'a str>,
    /// The reference temperature, °C.
    t_ref_c: f64,
    /// c at t_ref_c, kg/s.
    c_ref: &'a Estimate,
    /// E_a, J/mol.
    activation_energy: &'a Estimate,
    /// Each point's COR by the fitted law, in the file's order.
    predicted: &'a [f64],
    dof: usize,
    lack_of_fit: Option<LackOfFit>,
    answered: bool,
    no_answer: &'a [String],
    /// What the caller should know: the data's speeds against the ball's record, whose
    /// springs the fit keeps ([`crate::Ball::speeds_warning`]); `[]` when nothing.
    warnings: &'a [String],
    /// The ball the fit starts from (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    record: crate::api::BallRecord,
}

fn write_text(out: &mut dyn Write, r: &Report, f: &TemperatureFit) -> std::io::Result<()> {
    writeln!(
        out,
        "dashpot temperature shift fitted to {} ({}) on {}: c(T) = c_ref exp[(E_a/R)(1/T − 1/T_ref)], T_ref = {} °C",
        crate::sanitize::line(r.file),
        crate::text::counted(r.points, "point"),
        r.preset.unwrap_or("the ball"),
        human(r.t_ref_c, 4)
    )?;
    writeln!(out)?;
    let ci = |e: &Estimate, scale: f64| {
        if e.ci95.iter().any(|x| x.is_nan()) {
            "no interval: no point left over".to_string()
        } else {
            format!(
                "95 %: {} – {}",
                human(e.ci95[0] / scale, 4),
                human(e.ci95[1] / scale, 4)
            )
        }
    };
    let rows = vec![
        vec![
            "c_ref".into(),
            format!("{} kg/s", human(f.c_ref.value, 4)),
            ci(&f.c_ref, 1.0),
        ],
        vec![
            "E_a".into(),
            format!("{} kJ/mol", human(f.activation.value / 1e3, 4)),
            ci(&f.activation, 1e3),
        ],
    ];
    table(out, "  ", &rows)?;
    super::report_text::write_verdict(out, r.lack_of_fit.as_ref(), r.no_answer)?;
    output::warning_lines(out, r.warnings)
}
