//! `bouncelab fit --oblique FILE`: μ and K_t (and κ when the file gives `spin_out`) fitted to
//! measured oblique bounces (docs/oblique.md §9), with the other fits' intervals, verdict and
//! exit codes: a report, then exit 1 when the data do not pin what was fitted.

use super::{FitArgs, FitFormat};
use crate::analysis::fit::MultiFitError;
use crate::analysis::fit::oblique::{ObliqueFit, ObliqueStart, fit_oblique};
use crate::analysis::fit::verdict::no_answer_reasons;
use crate::api::{BallHeader, SOLID_INERTIA_FACTOR};
use crate::cli::output::{self, human, table};
use crate::oblique::mindlin_ratio;
use serde::Serialize;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::Path;

/// `fit --oblique --format json`.
#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    data: &'static str,
    file: String,
    free: Vec<&'static str>,
    friction: f64,
    tangential_stiffness: f64,
    inertia_factor: f64,
    radius: f64,
    /// RMS misses: v_x,out (m/s), ω_out (rad/s, null without spins), v_y,out (m/s, the normal
    /// model's, not fitted).
    rms_vx: f64,
    rms_spin: Option<f64>,
    rms_vy: f64,
    points: usize,
    converged: bool,
    iterations: usize,
    condition_number: f64,
    fitted: BTreeMap<&'static str, &'a crate::analysis::fit::Estimate>,
    correlation: BTreeMap<&'static str, BTreeMap<&'static str, f64>>,
    warnings: &'a [String],
    identified: bool,
    not_pinned: &'a [&'static str],
    on_bound: &'a [&'static str],
}

pub fn run(a: &FitArgs, path: &Path, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.free.is_some() || a.save.is_some() || a.plot.is_some() || a.v0.is_some() {
        anyhow::bail!(
            "--oblique fits friction, tangential_stiffness (and inertia_factor with spin_out): \
             --free, --v0, --save and --plot are not for it"
        );
    }
    let ball = a.ball.resolve(None)?;
    let rows = crate::measured::file::oblique(path)?;
    let radius = Some(ball.radius()).filter(|r| r.is_finite());
    let radius = radius
        .ok_or_else(|| anyhow::anyhow!("invalid radius: the ball is no preset and carries none"))?;
    let k_t = ball
        .tangential_stiffness()
        .unwrap_or(mindlin_ratio(0.5) * ball.params.k_p);
    let kappa = ball
        .measured
        .as_ref()
        .and_then(|m| m.inertia_factor)
        .unwrap_or(SOLID_INERTIA_FACTOR);
    let start = ObliqueStart {
        params: ball.params,
        law: ball.law,
        radius,
        friction: None,
        tangential_stiffness: k_t,
        inertia_factor: kappa,
    };
    let watch = crate::cli::budget::Watcher::new("model runs");
    let file = path.display().to_string();
    let f = fit_oblique(&start, &rows, &watch).map_err(|e| match e {
        MultiFitError::Interrupted => crate::cli::budget::Interrupted.into(),
        MultiFitError::NoAnswer => anyhow::Error::new(e),
        e => anyhow::anyhow!("{file}: {e}"),
    })?;
    drop(watch);
    let report = Report {
        ball: ball.header(),
        data: "oblique bounces",
        file,
        free: f.fitted.iter().map(|e| e.name).collect(),
        friction: f.fitted[0].value,
        tangential_stiffness: f.fitted[1].value,
        inertia_factor: f.inertia_factor,
        radius,
        rms_vx: f.rms_vx,
        rms_spin: f.rms_spin,
        rms_vy: f.rms_vy,
        points: f.points,
        converged: f.converged,
        iterations: f.iterations,
        condition_number: f.condition,
        fitted: f.fitted.iter().map(|e| (e.name, e)).collect(),
        correlation: correlation(&f),
        warnings: &f.warnings,
        identified: f.identified,
        not_pinned: &f.not_pinned,
        on_bound: &f.on_bound,
    };
    let mut text = Vec::new();
    match a.format {
        FitFormat::Json => output::json(&mut text, &report)?,
        FitFormat::Text => write_text(&mut text, &ball.label(), &report, &f)?,
    }
    out.write_all(&text)?;
    if !f.identified {
        let why = no_answer_reasons(f.converged, &f.not_pinned);
        return Err(MultiFitError::Unanswered(why.join("; ")).into());
    }
    Ok(())
}

fn correlation(f: &ObliqueFit) -> BTreeMap<&'static str, BTreeMap<&'static str, f64>> {
    f.fitted
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let row = f.fitted.iter().enumerate();
            (
                a.name,
                row.map(|(j, b)| (b.name, f.correlation[i][j])).collect(),
            )
        })
        .collect()
}

fn write_text(out: &mut dyn Write, label: &str, r: &Report, f: &ObliqueFit) -> std::io::Result<()> {
    writeln!(out, "{label}, {} law", r.ball.law)?;
    writeln!(
        out,
        "fitting {} to the oblique bounces {} ({} rows); the normal ball held",
        r.free.join(", "),
        r.file,
        f.model.len()
    )?;
    writeln!(out)?;
    let mut rows = vec![vec![
        String::new(),
        "value".into(),
        "std. error".into(),
        "95 % interval".into(),
        "unit".into(),
    ]];
    for e in &f.fitted {
        rows.push(vec![
            e.name.into(),
            human(e.value, 5),
            human(e.std_error, 3),
            format!("{} … {}", human(e.ci95[0], 4), human(e.ci95[1], 4)),
            e.unit.into(),
        ]);
    }
    table(out, "  ", &rows)?;
    writeln!(out)?;
    let mut rest = vec![vec![
        "rms residual v_x".into(),
        format!("{} m/s", human(f.rms_vx, 4)),
    ]];
    if let Some(s) = f.rms_spin {
        rest.push(vec![
            "rms residual ω".into(),
            format!("{} rad/s", human(s, 4)),
        ]);
    }
    rest.push(vec![
        "normal model's v_y miss".into(),
        format!("{} m/s rms (not fitted)", human(f.rms_vy, 4)),
    ]);
    let conv = if f.converged {
        "converged"
    } else {
        "not converged"
    };
    rest.push(vec![
        "iterations".into(),
        format!("{}, {conv}", f.iterations),
    ]);
    let answered = if f.identified {
        "yes".to_string()
    } else {
        format!(
            "no: {}",
            no_answer_reasons(f.converged, &f.not_pinned).join("; ")
        )
    };
    rest.push(vec!["answered".into(), answered]);
    table(out, "  ", &rest)?;
    for w in &f.warnings {
        writeln!(out, "warning: {w}")?;
    }
    Ok(())
}
