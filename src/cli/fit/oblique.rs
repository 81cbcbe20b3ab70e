//! `bouncelab fit --oblique FILE`: μ and K_t (and κ when the file gives `spin_out`) fitted to
//! measured oblique bounces (docs/oblique.md §9), with the other fits' intervals, verdict and
//! exit codes: a report, then exit 1 when the data do not pin what was fitted.

use super::FitArgs;
use super::report_text::{estimate_rows, exact_words};
use crate::BallError;
use crate::analysis::fit::oblique::ObliqueFit;
use crate::analysis::fit::verdict::no_answer_reasons;
use crate::analysis::fit::{Estimate, MultiFitError};
use crate::api::{ObliqueFitReport, is_oblique_data_error as is_data_error};
use crate::cli::output::{self, TextJson, human, table};
use std::io::Write;
use std::path::Path;

pub fn run(a: &FitArgs, path: &Path, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.free.is_some() || a.save.is_some() || a.plot.is_some() || a.v0.is_some() {
        anyhow::bail!(
            "--oblique fits friction, tangential_stiffness (and inertia_factor with spin_out): \
             --free, --v0, --save and --plot are not for it"
        );
    }
    let ball = a.ball.resolve(None)?;
    let rows = crate::measured::file::oblique(path)?;
    let watch = crate::cli::budget::Watcher::new("model runs");
    let file = path.display().to_string();
    let report = ball
        .fit_oblique_damped_watched(&rows, Some(file.clone()), a.tangential_damping, &watch)
        .map_err(|e| match e {
            BallError::MultiFit(MultiFitError::Interrupted) => {
                crate::cli::budget::Interrupted.into()
            }
            e if is_data_error(&e) => anyhow::anyhow!("{file}: {e}"),
            e => anyhow::Error::new(e),
        })?;
    drop(watch);
    let f = &report.fit;
    let mut text = Vec::new();
    match a.format {
        TextJson::Json => output::json_on(
            &mut text,
            &WithBall {
                report: &report,
                ball: ball.record_json(),
            },
            // the data's fit assumed the rigid plate (docs/cli.md, "The surface object")
            output::Met::RigidPlate,
            &ball.conditions,
        )?,
        TextJson::Text => write_text(&mut text, &ball, &report, f)?,
    }
    out.write_all(&text)?;
    if !f.identified {
        let why = no_answer_reasons(f.converged, &f.not_pinned);
        return Err(MultiFitError::Unanswered(why.join("; ")).into());
    }
    Ok(())
}

fn write_text(
    out: &mut dyn Write,
    ball: &crate::Ball,
    r: &ObliqueFitReport,
    f: &ObliqueFit,
) -> std::io::Result<()> {
    writeln!(out, "{}, {} law", ball.label(), r.ball.law)?;
    // the bounces are read as the ball's on the rigid plate, as the JSON's surface says
    output::ball_lines(out, ball, output::Met::RigidPlate)?;
    writeln!(
        out,
        "fitting {} to the oblique bounces {} ({}); the normal ball held",
        r.free.join(", "),
        r.file.as_deref().unwrap_or("given"),
        crate::text::counted(f.model.len(), "row")
    )?;
    writeln!(out)?;
    // an exact solve has no error to give (`ObliqueFit::exact`), as `fit --cor-table`
    let exact = f.exact().then(|| exact_words(f.no_scatter));
    let interval = |e: &Estimate| format!("{} … {}", human(e.ci95[0], 4), human(e.ci95[1], 4));
    let rows = estimate_rows(&f.fitted, exact, interval);
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
    crate::cli::output::warning_lines(out, &f.warnings)
}

/// The oblique fit's report and the ball it started from (docs/cli.md, "The ball object").
#[derive(serde::Serialize)]
struct WithBall<'a, T: serde::Serialize> {
    #[serde(flatten)]
    report: &'a T,
    ball: crate::api::BallRecord,
}
