//! `bouncelab fit` on a COR table, a force–time trace or drop tests: several parameters with
//! standard errors, 95 % intervals and correlations ([`crate::analysis::fit::fit`]); the
//! report as text or JSON, and the `--plot` and `--save` that go with every fit.

use super::{FitArgs, Loaded, Source};
use crate::analysis::fit::{FitData, MultiFit, MultiFitError, Param, fit_watched};
use crate::api::Ball;
use crate::atomic::Outputs;
use crate::cli::measured_file as files;
use crate::cli::output::TextJson;
use crate::cli::{output, outputs};
use crate::measured::{Air, CorPoint};
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};
use std::io::Write;
use std::path::Path;

/// Refuse outputs that cannot be written, before any work.
pub fn check_outputs(a: &FitArgs) -> anyhow::Result<()> {
    if let Some(p) = &a.plot {
        crate::cli::figure::check_writable(&[p.as_path()], a.force)?;
    }
    if let Some(name) = &a.save {
        super::save::check(name, a.force)?;
    }
    Ok(())
}

pub(super) fn load(a: &FitArgs, source: &Source, ball: &Ball) -> anyhow::Result<Loaded> {
    let air = a.drag_coefficient.map(|cd| Air {
        density: a.air_density,
        drag_coefficient: cd,
    });
    // the library checks the air and the reading's precision (whatever the data) and the drop
    // heights
    ball.drops_to_cor_read(&[], air, a.rebound_height_sd)?;
    let from_drops = |drops: &[(f64, f64, usize)]| drop_points(a, source, ball, air, drops);
    Ok(match source {
        // `fit::run` hands oblique bounces to `oblique`
        Source::Oblique(p) => anyhow::bail!(
            "{}: oblique bounces fit the tangential model (fit --oblique)",
            p.display()
        ),
        Source::Trace(p) => {
            let t = files::trace(p)?;
            crate::cli::budget::stop_if_interrupted()?;
            Loaded {
                end_line: t.end_line,
                trace: Some(t),
                ..no_data("force-time trace", Some(p), files::label(p), air)
            }
        }
        Source::CorTable(p) => {
            let t = files::cor_table(p)?;
            Loaded {
                points: t.points,
                end_line: t.end_line,
                ..no_data("COR table", Some(p), files::label(p), air)
            }
        }
        Source::DropFile(p) => {
            let t = files::drop_test(p)?;
            Loaded {
                points: from_drops(&t.drops)?,
                drops: t.drops.iter().map(|d| (d.0, d.1)).collect(),
                end_line: t.drops.last().map_or(1, |d| d.2 + 1),
                ..no_data("drop test", Some(p), files::label(p), air)
            }
        }
        Source::Drops(pairs) => {
            let drops: Vec<(f64, f64, usize)> = pairs.iter().map(|&(h, r)| (h, r, 0)).collect();
            Loaded {
                points: from_drops(&drops)?,
                drops: pairs.clone(),
                ..no_data("drop test", None, "drop tests".into(), air)
            }
        }
        Source::Cor(e) => {
            if !(0.0..=1.0).contains(e) {
                anyhow::bail!(
                    "invalid cor: {} (a measured COR lies in [0, 1])",
                    output::num(*e)
                );
            }
            Loaded {
                points: vec![CorPoint::new(ball.params.v0, *e)],
                ..no_data("COR", None, format!("COR {}", output::num(*e)), air)
            }
        }
    })
}

/// The data of `kind` read from `file` (`None`: given on the command line), as yet without
/// any, under the legend label `label`.
fn no_data(kind: &'static str, file: Option<&Path>, label: String, air: Option<Air>) -> Loaded {
    Loaded {
        kind,
        file: file.map(|p| p.display().to_string()),
        label,
        trace: None,
        points: vec![],
        drops: vec![],
        end_line: 0,
        air,
        joint: vec![],
    }
}

/// Drop tests (drop height, rebound height, line) as COR points. A file's rows are checked
/// one at a time, so that a refused drop is named by its line; then converted together, each
/// weighed against the others (`Ball::drops_to_cor_read`).
fn drop_points(
    a: &FitArgs,
    source: &Source,
    ball: &Ball,
    air: Option<Air>,
    drops: &[(f64, f64, usize)],
) -> anyhow::Result<Vec<CorPoint>> {
    let file = match source {
        Source::DropFile(p) => p.display().to_string(),
        _ => String::new(),
    };
    for d in drops.iter().filter(|d| d.2 != 0) {
        ball.drops_to_cor(&[(d.0, d.1)], air)
            .map_err(|e| anyhow::anyhow!("{file}:{}:1: {e}", d.2))?;
    }
    let pairs: Vec<(f64, f64)> = drops.iter().map(|d| (d.0, d.1)).collect();
    let mut points = ball.drops_to_cor_read(&pairs, air, a.rebound_height_sd)?;
    for (p, d) in points.iter_mut().zip(drops) {
        p.line = d.2;
    }
    Ok(points)
}

/// A fit error for the user: where the data are at fault, the file and line.
fn fit_error(e: MultiFitError, data: &Loaded, free: &[Param]) -> anyhow::Error {
    let names: Vec<&str> = free.iter().map(|p| p.name()).collect();
    let place = data
        .file
        .as_ref()
        .map(|f| format!("{f}:{}:1: ", data.end_line))
        .unwrap_or_default();
    match e {
        MultiFitError::Params(p) => p.into(),
        e @ MultiFitError::Contradicts { .. } => match &data.file {
            Some(f) => anyhow::anyhow!("{f}: {e}"),
            None => anyhow::anyhow!("{e}"),
        },
        MultiFitError::NoPulse(m) => {
            anyhow::anyhow!("{}:{m}", data.file.clone().unwrap_or_default())
        }
        MultiFitError::TooFew { points, parameters } => anyhow::anyhow!(
            "{place}{}, fewer than the {} fitted (--free {}{})",
            crate::text::counted(points, "data point"),
            crate::text::counted(parameters, "parameter"),
            names.join(","),
            if data.trace.is_some() {
                ", with the contact start and the baseline"
            } else {
                ""
            }
        ),
        // no answer is not the input's fault: exit 1 (cli::exit_code)
        MultiFitError::NoAnswer => anyhow::Error::new(e),
        // Ctrl-C or SIGTERM: exit 130, nothing written
        MultiFitError::Interrupted => crate::cli::budget::Interrupted.into(),
        e => anyhow::anyhow!("{e}"),
    }
}

pub fn run(
    a: &FitArgs,
    source: &Source,
    free: Option<Vec<Param>>,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    check_outputs(a)?;
    let ball = a.ball.resolve(a.v0)?;
    let data = load(a, source, &ball)?;
    let mut free =
        free.unwrap_or_else(|| Param::defaults(data.trace.is_some(), data.points.len(), ball.law));
    // a trace without --v0 was not taken at the preset's speed for sure: its speed is fitted
    // too (as --free v0), and the report says so (the library's rule, Python's fit_trace's too)
    let speed_fitted = Ball::free_trace_speed(&mut free, data.trace.is_some(), a.v0.is_some());
    let input = match &data.trace {
        Some(t) => FitData::Trace(t),
        None => FitData::Cor(&data.points),
    };
    let watch = crate::cli::budget::Watcher::new("model runs");
    let mut f = fit_watched(&ball.params, ball.law, input, &free, &watch)
        .map_err(|e| fit_error(e, &data, &free))?;
    drop(watch);
    // the fitted ball where it presses deepest: the data's fastest speed (a trace's: v0)
    let speeds: Vec<f64> = match &data.trace {
        Some(_) => vec![ball.params.v0],
        None => data.points.iter().map(|p| p.v0).collect(),
    };
    fitted_warnings(&ball, &mut f, &speeds, speed_fitted);
    // the data's speed: the trace's (the ball's v0), else the first row's
    // (a fitted speed is the fit's)
    let v0 = if free.contains(&Param::V0) {
        f.params.v0
    } else {
        data.points.first().map_or(ball.params.v0, |p| p.v0)
    };
    let fitted = ImpactParams { v0, ..f.params };
    let r = simulate(&fitted, ball.law, &SolveOptions::default())?;
    let report = super::report::report(&ball, &data, &f, &fitted, &r);
    let mut text = Vec::new();
    match a.format {
        TextJson::Json => {
            // the data's fit assumed the rigid plate (docs/cli.md, "The surface object")
            output::json_on(
                &mut text,
                &report,
                output::Met::RigidPlate,
                &ball.conditions,
            )?
        }
        TextJson::Text => super::report_text::text(&mut text, &ball, &data, &f, &report)?,
    }
    if !f.identified {
        out.write_all(&text)?;
        return refuse_unanswered(a, &f);
    }
    publish(a, out, &text, (&ball, &data, &f, &fitted))
}

/// The report, the `--plot` and the `--save` of a fit as one transaction
/// (`cli::outputs`): the files staged, the report written, then the files published; a
/// failure anywhere (a preset folder that takes no file, a full stdout) leaves none of them
/// (tests/cli/cli_outputs.rs, `fit_is_all_or_nothing`).
/// The fitted ball's warnings at the data's `speeds` (validity), then the record's of the
/// parameters held ([`Ball::held_warning`], at the fit's speed where it was fitted), and
/// first, where no `--v0` was given for a trace, that its impact speed was fitted: the one
/// and the joint fit's (src/cli/fit/joint.rs) alike.
pub(super) fn fitted_warnings(ball: &Ball, f: &mut MultiFit, speeds: &[f64], speed_fitted: bool) {
    f.warnings.extend(ball.fit_warnings(f, speeds));
    if speed_fitted {
        f.warnings.insert(0, ball.speed_fitted_warning());
    }
}

pub(super) fn publish(
    a: &FitArgs,
    out: &mut dyn Write,
    report: &[u8],
    (ball, data, f, fitted): (&Ball, &Loaded, &MultiFit, &ImpactParams),
) -> anyhow::Result<()> {
    let mut files = Outputs::new(a.force);
    let mut notes = Vec::new();
    if let Some(p) = &a.plot {
        files.text(p, &super::plot::svg(ball, data, f, fitted)?)?;
        notes.push(format!("plot: {}", p.display()));
    }
    let mut created = None;
    if let Some(name) = &a.save {
        let (path, folder) = super::save::stage(name, a, ball, data, f, fitted, &mut files)?;
        notes.push(format!("saved preset '{name}' to {}", path.display()));
        created = folder.map(|top| (top, path));
    }
    if let Err(e) = outputs::report_then_commit(out, report, files) {
        if let Some((top, path)) = &created {
            let inner = path.parent().unwrap_or(top);
            super::save::remove_created(Some(top), inner);
        }
        return Err(e);
    }
    for line in notes {
        note(a, out, &line)?;
    }
    Ok(())
}

/// A fit that did not answer (not converged, or a parameter the data do not pin) is reported
/// but neither plotted nor saved, and the command exits 1 (docs/fitting.md).
fn refuse_unanswered(a: &FitArgs, f: &crate::analysis::fit::MultiFit) -> anyhow::Result<()> {
    if f.identified {
        return Ok(());
    }
    let why = crate::analysis::fit::verdict::no_answer_reasons(f.converged, &f.not_pinned);
    let refused = match (&a.plot, &a.save) {
        (None, None) => "",
        (Some(_), None) => "; --plot not written",
        (None, Some(_)) => "; --save not written",
        (Some(_), Some(_)) => "; --plot and --save not written",
    };
    Err(MultiFitError::Unanswered(format!("{}{refused}", why.join("; "))).into())
}

/// Outputs written besides the report: on stdout after a text report, on stderr after JSON
/// (stdout stays one JSON document).
fn note(a: &FitArgs, out: &mut dyn Write, line: &str) -> anyhow::Result<()> {
    match a.format {
        TextJson::Text => writeln!(out, "{line}")?,
        TextJson::Json => eprintln!("bouncelab: {line}"),
    }
    Ok(())
}

/// The single-COR fit's report, `--plot` and `--save`, as one transaction (see `publish`).
pub fn single_extras(
    a: &FitArgs,
    ball: &Ball,
    fitted: &ImpactParams,
    cor: f64,
    out: &mut dyn Write,
    report: &[u8],
) -> anyhow::Result<()> {
    if a.plot.is_none() && a.save.is_none() {
        out.write_all(report)?;
        return Ok(());
    }
    let data = load(a, &Source::Cor(cor), ball)?;
    let mut f =
        crate::analysis::fit::fit(fitted, ball.law, FitData::Cor(&data.points), &[Param::KR])
            .map_err(|e| fit_error(e, &data, &[Param::KR]))?;
    // the saved header's warnings: the report's (`single`)
    f.warnings.extend(ball.cor_fit_warnings(fitted));
    publish(a, out, report, (ball, &data, &f, fitted))
}
