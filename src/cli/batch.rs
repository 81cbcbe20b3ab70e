//! `bouncelab batch`: a batch of balls in one CSV (an `id` column and the columns the fit
//! reads), one fit and one verdict per ball against a standard, the summary with Cpk
//! (docs/batch.md). The library splits the batch ([`crate::analysis::batch`]) and judges each
//! ball ([`Ball::judge_in_batch`]); this file reads the file and the trace files it names,
//! runs the balls in parallel in steps with a progress bar and Ctrl-C, and writes.

use super::ball::BallArgs;
use super::batch_text;
use super::budget::Progress;
use super::measured_file as files;
use super::output::{self, TextJsonCsv, csv_row};
use super::outputs::{check as check_writable, report_then_commit};
use crate::analysis::batch::{BallData, split};
use crate::analysis::fit::parse_free;
use crate::api::Ball;
use crate::api::{BallOutcome, BatchReport, BatchSetup, BatchUnanswered};
use crate::atomic::Outputs;
use crate::drop::standards::{self, Standard};
use crate::figure::{Axis, histogram, svg};
use crate::measured::{Air, Data};
use clap::Args;
use rayon::prelude::*;
use std::io::Write;
use std::path::{Path, PathBuf};

#[derive(Debug, Clone, Args)]
pub struct BatchArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// The batch: CSV with an id column (consecutive rows of one id are one ball) and the
    /// columns of `fit`'s files: drop_height_m,rebound_height_m; v0,cor (…); time,force; or a
    /// trace column naming each ball's trace file (relative to the batch's folder)
    #[arg(value_name = "FILE")]
    pub file: PathBuf,
    /// The standard every ball is judged against (`bouncelab standards` lists them) [default:
    /// the preset's own]
    #[arg(long, value_name = "NAME")]
    pub standard: Option<String>,
    /// Parameters fitted per ball, comma-separated, from k_p, c, k_r, z_p, k_h [default: as
    /// `fit`, by each ball's data]
    #[arg(long, value_name = "P,P,...", value_delimiter = ',')]
    pub free: Option<Vec<String>>,
    /// Drop tests: fit and judge with quadratic air drag of this drag coefficient [default:
    /// vacuum]
    #[arg(long, value_name = "CD", value_parser = super::number::number, allow_hyphen_values = true)]
    pub drag_coefficient: Option<f64>,
    /// Drop tests: air density for the drag, kg/m³
    #[arg(long, value_name = "RHO", default_value_t = 1.204, requires = "drag_coefficient",
          value_parser = super::number::number, allow_hyphen_values = true)]
    pub air_density: f64,
    /// Drop tests: the standard deviation of a rebound height's reading, m (as `fit`'s): the
    /// verdicts' intervals and the fits take it as known [default: unknown, from the
    /// readings' scatter]
    #[arg(long, value_name = "S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub rebound_height_sd: Option<f64>,
    /// Impact speed of force–time traces (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Output format: a text report, one JSON document, or the per-ball CSV
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJsonCsv,
    /// Write the per-ball CSV (id, …, cor, verdict, margin, warnings)
    #[arg(long, value_name = "FILE")]
    pub csv_out: Option<PathBuf>,
    /// Write a histogram of the measured values with the standard's window as SVG
    #[arg(long, value_name = "FILE")]
    pub svg_out: Option<PathBuf>,
    /// Overwrite existing --csv-out and --svg-out files
    #[arg(long)]
    pub force: bool,
}

/// Balls fitted between two looks at the bar and the Ctrl-C flag.
const STEP: usize = 16;
/// Linear-law impacts a fit takes, roughly: for the bar only (its starts × iterations × data).
const FIT_COST: f64 = 2000.0;

pub fn run(a: &BatchArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve(a.v0)?;
    let standard = standard(a, &ball)?;
    let free = a.free.as_deref().map(parse_free).transpose()?;
    let air = a.drag_coefficient.map(|cd| Air {
        density: a.air_density,
        drag_coefficient: cd,
    });
    // the library checks the air and the reading once, whatever the data
    ball.drops_to_cor_read(&[], air, a.rebound_height_sd)?;
    let paths: Vec<&Path> = [&a.csv_out, &a.svg_out]
        .into_iter()
        .flatten()
        .map(PathBuf::as_path)
        .collect();
    check_writable(&paths, a.force)?;
    let balls = load(&a.file)?;
    let setup = BatchSetup {
        standard,
        free: free.as_deref(),
        air,
        rebound_sd: a.rebound_height_sd,
    };
    let outcomes = judge_all(&ball, &a.file, &balls, &setup)?;
    let report = BatchReport::new(&ball, standard, &outcomes);
    // both files staged, then the report, then the files published: all or none
    // (cli::outputs, as every command)
    let mut written = Outputs::new(a.force);
    let csv = || balls_csv(&outcomes, &report.warnings, &ball);
    if let Some(p) = &a.csv_out {
        written.text(p, &csv())?;
    }
    if let Some(p) = &a.svg_out {
        written.text(p, &svg::render(&histogram_figure(&a.file, &report))?)?;
    }
    let mut text_out = Vec::new();
    match a.format {
        // the balls were judged on the standard's rigid plate (docs/cli.md, "The surface object")
        TextJsonCsv::Json => output::json_on(
            &mut text_out,
            &report,
            output::Met::RigidPlate,
            &ball.conditions,
        )?,
        TextJsonCsv::Csv => text_out.extend_from_slice(csv().as_bytes()),
        TextJsonCsv::Text => batch_text::text(&mut text_out, &ball, &a.file, air, &report)?,
    }
    report_then_commit(out, &text_out, written)?;
    let s = &report.summary;
    if s.no_answer > 0 {
        return Err(BatchUnanswered {
            no_answer: s.no_answer,
            balls: s.balls,
        }
        .into());
    }
    Ok(())
}

/// `--standard`, or the preset's own.
fn standard(a: &BatchArgs, ball: &Ball) -> anyhow::Result<&'static Standard> {
    match &a.standard {
        Some(name) => standards::find(name).map_err(|e| anyhow::anyhow!(e)),
        None => ball
            .name
            .as_deref()
            .and_then(standards::for_ball)
            .ok_or_else(|| {
                anyhow::anyhow!(
                    "--standard is needed: {} has no standard of its own (bouncelab standards \
                     lists them)",
                    ball.label()
                )
            }),
    }
}

/// A ball's data as the batch file gives it: its rows, or a trace file, read only when the
/// ball's step comes ([`judge_all`]), so that a batch holds at most [`STEP`] traces at once
/// (issue 54 item 4: every trace was read first, 31 MB a ball of a 10⁶-row trace, and kept
/// to the end). A ball's outcome keeps its numbers only, never its data.
enum Source {
    Rows(Data),
    Trace {
        path: PathBuf,
        line: usize,
        column: usize,
    },
}

/// The batch's balls with their data, trace files named (relative to the batch's folder).
fn load(file: &Path) -> anyhow::Result<Vec<(String, usize, Source)>> {
    let text = files::read_text(file)?;
    let rows = split(&text).map_err(|e| files::at(file, e))?;
    let dir = file.parent().unwrap_or(Path::new(""));
    Ok(rows
        .into_iter()
        .map(|b| {
            let source = match b.data {
                BallData::Measured(d) => Source::Rows(d),
                BallData::TraceFile { path, line, column } => Source::Trace {
                    path: dir.join(&path),
                    line,
                    column,
                },
            };
            (b.id, b.line, source)
        })
        .collect())
}

/// A ball's trace file read (`None` for a ball given by its rows), an error at the batch
/// `file`'s `line:column` naming the ball.
fn read_trace(file: &Path, id: &str, source: &Source) -> anyhow::Result<Option<Data>> {
    let Source::Trace { path, line, column } = source else {
        return Ok(None);
    };
    let t = files::trace(path).map_err(|e| {
        anyhow::anyhow!("{}:{line}:{column}: trace of '{id}': {e:#}", file.display())
    })?;
    Ok(Some(Data::Trace(t)))
}

/// A ball's data: its rows, or its `trace` read at its step's start.
fn data_of<'a>(source: &'a Source, trace: &'a Option<Data>) -> &'a Data {
    match (source, trace) {
        (Source::Rows(d), _) | (Source::Trace { .. }, Some(d)) => d,
        (Source::Trace { .. }, None) => unreachable!("a step's traces are read at its start"),
    }
}

/// Every ball, in parallel in steps of [`STEP`], with the bar and the Ctrl-C check between
/// steps (a ball's outcome depends on its data alone, so the steps change no answer); a
/// step's trace files are read at its start and dropped at its end.
fn judge_all(
    ball: &Ball,
    file: &Path,
    balls: &[(String, usize, Source)],
    setup: &BatchSetup<'_>,
) -> anyhow::Result<Vec<BallOutcome>> {
    let progress = Progress::new(balls.len() as u64, FIT_COST, "balls");
    let mut all = Vec::with_capacity(balls.len());
    for step in balls.chunks(STEP) {
        progress.check()?;
        let traces = step
            .par_iter()
            .map(|(id, _, source)| read_trace(file, id, source))
            .collect::<anyhow::Result<Vec<_>>>()?;
        all.par_extend(step.par_iter().zip(traces.par_iter()).map(
            |((id, line, source), trace)| {
                ball.judge_in_batch(id, *line, data_of(source, trace), setup)
            },
        ));
        progress.advance(step.len() as u64);
    }
    progress.finish();
    Ok(all)
}

/// `id, line, data, points, free, k_p, c, k_r, z_p, identified, cor, measured, verdict,
/// margin, error, warnings, measured_ci95_lo, measured_ci95_hi, verdict_from, readings,
/// model_measured, fit_error`, then on every row the lot's: `lot_warnings` (the JSON's
/// top-level `warnings`, which belong to no ball: `lot` its warnings) and the ball the fits
/// start from, the rigid plate they were judged on and its conditions
/// ([`super::csv_stated::with_ball`]) (SI; empty where a ball has no value; lists joined by
/// `; `; columns added later come last).
fn balls_csv(balls: &[BallOutcome], lot: &[String], ball: &Ball) -> String {
    let stated = super::csv_stated::with_ball_cells(ball, &crate::api::SurfaceUsed::rigid_plate());
    let mut header = vec![
        "id",
        "line",
        "data",
        "points",
        "free",
        "k_p",
        "c",
        "k_r",
        "z_p",
        "identified",
        "cor",
        "measured",
        "verdict",
        "margin",
        "error",
        "warnings",
        "measured_ci95_lo",
        "measured_ci95_hi",
        "verdict_from",
        "readings",
        "model_measured",
        "fit_error",
        "lot_warnings",
    ];
    header.extend(super::csv_stated::with_ball());
    let mut buf = Vec::new();
    let mut rows = || -> std::io::Result<()> {
        csv_row(&mut buf, &header)?;
        for b in balls {
            let mut row = vec![
                b.id.clone(),
                b.line.to_string(),
                b.data.to_string(),
                b.points.to_string(),
                b.free.join(" "),
                output::opt_num(b.k_p),
                output::opt_num(b.c),
                output::opt_num(b.k_r),
                output::opt_num(b.z_p),
                b.identified.to_string(),
                output::opt_num(b.cor),
                output::opt_num(b.measured),
                b.verdict.unwrap_or_default().to_string(),
                output::opt_num(b.margin),
                b.error.clone().unwrap_or_default(),
                b.warnings.join("; "),
                output::opt_num(b.measured_ci95.map(|ci| ci[0])),
                output::opt_num(b.measured_ci95.map(|ci| ci[1])),
                b.verdict_from.unwrap_or_default().to_string(),
                b.readings.to_string(),
                output::opt_num(b.model_measured),
                b.fit_error.clone().unwrap_or_default(),
                output::warnings_cell(lot),
            ];
            row.extend(stated.iter().cloned());
            csv_row(&mut buf, &row)?;
        }
        Ok(())
    };
    rows().expect("writing to memory");
    String::from_utf8(buf).expect("CSV of UTF-8 text")
}

/// The histogram of the measured values with the window's bounds marked.
fn histogram_figure(file: &Path, r: &BatchReport<'_>) -> crate::figure::Figure {
    let values: Vec<f64> = r.balls.iter().filter_map(|b| b.measured).collect();
    let (quantity, unit) = (r.standard.quantity, r.standard.unit);
    let [lo, hi] = r.standard.window;
    let marks: Vec<(&str, &str, f64)> = [("window low", "lo", lo), ("window high", "hi", hi)]
        .into_iter()
        .filter_map(|(l, id, x)| x.map(|x| (l, id, x)))
        .collect();
    let label = match unit {
        "" => quantity.replace('_', " "),
        u => format!("{} ({u})", quantity.replace('_', " ")),
    };
    // about √n bins, as a quality chart draws a batch
    let bins = ((values.len() as f64).sqrt().ceil() as usize).clamp(5, 40);
    histogram::figure(
        &format!(
            "{} of the batch {}",
            quantity.replace('_', " "),
            files::label(file)
        ),
        &format!(
            "{}, standard {}: {}",
            crate::text::counted(values.len(), "ball"),
            r.standard.name,
            r.standard.title
        ),
        Axis::linear(&label, quantity, 1.0),
        &values,
        bins,
        &marks,
    )
}
