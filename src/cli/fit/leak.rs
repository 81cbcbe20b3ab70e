//! `bouncelab fit --pressure-loss FILE`: an inflated ball's leak, p(t) = p₀ e^(−k t), fitted
//! to its pressure readings (docs/model.md §10.3, `analysis::fit::pressure_loss`), with the
//! other fits' intervals, verdict and exit codes: a report, then exit 1 when the readings do
//! not follow the law.

use super::FitArgs;
use crate::analysis::fit::pressure_loss::{LeakFit, fit_pressure_loss};
use crate::analysis::fit::verdict::LackOfFit;
use crate::analysis::fit::{Estimate, MultiFitError};
use crate::cli::output::{self, TextJson, human, table};
use std::io::Write;
use std::path::Path;

/// 72 h, s: the FIFA Quality Programme's pressure-loss test (docs/model.md §10.3).
const FIFA_TEST: f64 = 72.0 * 3600.0;

pub fn run(a: &FitArgs, path: &Path, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.beyond_a_file_fit() {
        anyhow::bail!(
            "--pressure-loss fits a leak to pressure readings alone: the other data (--cor, \
             --cor-table, --force-time, drop tests, --oblique) and --free, --v0, --save, \
             --plot, --drag-coefficient, --rebound-height-sd are not for it"
        );
    }
    if let Some(flag) = a.ball.first_given() {
        anyhow::bail!(
            "--pressure-loss fits a leak to pressure readings alone: {flag} is not for it (no \
             ball is run)"
        );
    }
    let readings = crate::measured::file::pressure(path)?;
    let file = path.display().to_string();
    let fit = fit_pressure_loss(&readings).map_err(|e| anyhow::anyhow!("{file}: {e}"))?;
    let report = LeakJson::new(&file, readings.len(), &fit);
    let mut text = Vec::new();
    match a.format {
        TextJson::Json => output::json(&mut text, &report)?,
        TextJson::Text => write_text(&mut text, &report)?,
    }
    out.write_all(&text)?;
    if !fit.no_answer.is_empty() {
        return Err(MultiFitError::Unanswered(fit.no_answer.join("; ")).into());
    }
    Ok(())
}

/// The report, as JSON writes it (SI: Pa, 1/s, s; `null` for an unbounded end).
#[derive(serde::Serialize)]
struct LeakJson<'a> {
    kind: &'static str,
    file: &'a str,
    readings: usize,
    /// p₀, Pa.
    p0: &'a Estimate,
    /// k, 1/s.
    leak_rate: &'a Estimate,
    /// t½ = ln 2/k, s; its 95 % interval from k's.
    half_life: f64,
    half_life_ci95: [f64; 2],
    /// The fraction of the gauge pressure lost in the FIFA test's 72 h at the fitted k, and at
    /// the ends of k's interval.
    lost_in_72h: f64,
    lost_in_72h_ci95: [f64; 2],
    dof: usize,
    lack_of_fit: Option<LackOfFit>,
    answered: bool,
    no_answer: &'a [String],
}

impl<'a> LeakJson<'a> {
    fn new(file: &'a str, readings: usize, f: &'a LeakFit) -> Self {
        let lost = |k: f64| -(-k * FIFA_TEST).exp_m1();
        LeakJson {
            kind: "pressure loss",
            file,
            readings,
            p0: &f.p0,
            leak_rate: &f.rate,
            half_life: f.half_life[0],
            half_life_ci95: [f.half_life[1], f.half_life[2]],
            lost_in_72h: lost(f.rate.value),
            lost_in_72h_ci95: [lost(f.rate.ci95[0]), lost(f.rate.ci95[1])],
            dof: f.dof,
            lack_of_fit: f.lack_of_fit,
            answered: f.no_answer.is_empty(),
            no_answer: &f.no_answer,
        }
    }
}

/// `lo – hi` of an interval in `unit` (∞ where unbounded; "none" without degrees of freedom).
fn interval(ci: [f64; 2], scale: f64, unit: &str) -> String {
    let end = |x: f64| {
        if x.is_infinite() {
            "∞".to_string()
        } else {
            human(x / scale, 4)
        }
    };
    if ci.iter().any(|x| x.is_nan()) {
        return "no interval: no reading left over".into();
    }
    format!("95 %: {} – {} {unit}", end(ci[0]), end(ci[1]))
}

fn write_text(out: &mut dyn Write, r: &LeakJson) -> std::io::Result<()> {
    writeln!(
        out,
        "pressure loss fitted to {} ({}): p(t) = p0 e^(-k t)",
        crate::sanitize::line(r.file),
        crate::text::counted(r.readings, "reading")
    )?;
    writeln!(out)?;
    let hour = 3600.0;
    let half_life = if r.half_life.is_infinite() {
        "∞ (no loss)".to_string()
    } else {
        format!("{} h", human(r.half_life / hour, 4))
    };
    let rows = vec![
        vec![
            "p0".into(),
            format!("{} kPa", human(r.p0.value / 1e3, 4)),
            interval(r.p0.ci95, 1e3, "kPa"),
        ],
        vec![
            "leak rate k".into(),
            format!("{} /h", human(r.leak_rate.value * hour, 4)),
            interval(r.leak_rate.ci95.map(|k| k * hour), 1.0, "/h"),
        ],
        vec![
            "half-life".into(),
            half_life,
            interval(r.half_life_ci95, hour, "h"),
        ],
        vec![
            "lost in 72 h".into(),
            format!("{} %", human(100.0 * r.lost_in_72h, 3)),
            interval(r.lost_in_72h_ci95.map(|x| 100.0 * x), 1.0, "%"),
        ],
    ];
    table(out, "  ", &rows)?;
    writeln!(
        out,
        "  (FIFA's 72 h test at 0.8 bar, 20 °C: at most 20 % lost for Quality Pro, 25 % for Quality)"
    )?;
    super::report_text::write_verdict(out, r.lack_of_fit.as_ref(), r.no_answer)
}
