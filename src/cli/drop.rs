//! `bouncelab drop`: a ball released from rest bounces on a rigid plate (docs/drop.md), as a
//! text table, one JSON object, or the trajectory as CSV; with `--standard`, the verdict.

use super::ball::BallArgs;
use super::intervals_text::line;
use super::output::{self, csv_row, given, human, num, table};
use crate::api::Ball;
use crate::drop::standards::{self, Reference, Standard, Test, Verdict};
use crate::drop::{
    Air, DEFAULT_BOUNCES, DEFAULT_MIN_REBOUND, DropError, DropRun, DropSetup, End, G,
};
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::io::Write;

/// Release height without a standard (m).
pub const DEFAULT_HEIGHT: f64 = 1.0;
/// Time step of the CSV trajectory within each flight (s).
pub const CSV_STEP: f64 = 1e-3;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DropFormat {
    Text,
    Json,
    Csv,
}

#[derive(Debug, Clone, Args)]
pub struct DropArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Release height H of the bottom of the ball (m) [default: the standard's, else 1]
    #[arg(long, value_name = "H", value_parser = super::number::number, allow_hyphen_values = true)]
    pub height: Option<f64>,
    /// Stop after this many bounces (1 … 1000)
    #[arg(long, value_name = "N", default_value_t = DEFAULT_BOUNCES)]
    pub bounces: usize,
    /// Stop after a rebound lower than this (m)
    #[arg(
        long,
        value_name = "H",
        default_value_t = DEFAULT_MIN_REBOUND,
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub min_rebound: f64,
    /// Fall in vacuum: no air drag
    #[arg(long, conflicts_with_all = ["drag_coefficient", "air_density"])]
    pub no_drag: bool,
    /// Drag coefficient C_d of quadratic drag ½ρC_dAv² [default: 0.47, a sphere]
    #[arg(
        long,
        value_name = "CD",
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub drag_coefficient: Option<f64>,
    /// Air density ρ (kg/m³) [default: 1.204, 20 °C at sea level]
    #[arg(
        long,
        value_name = "RHO",
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub air_density: Option<f64>,
    /// Judge the ball against a standard (`bouncelab standards` lists them)
    #[arg(long, value_name = "NAME")]
    pub standard: Option<String>,
    /// Output format (csv: the trajectory t, height, velocity)
    #[arg(long, value_enum, default_value = "text")]
    pub format: DropFormat,
}

/// A drop error for the user: bad conditions are bad input (exit 2); an impact without an
/// answer is not the user's fault (exit 1).
fn drop_error(e: DropError) -> anyhow::Error {
    match e {
        DropError::Solve(s) => s.into(),
        e => anyhow::anyhow!(e.to_string()),
    }
}

pub fn run(a: &DropArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let standard = a
        .standard
        .as_deref()
        .map(standards::find)
        .transpose()
        .map_err(|e| anyhow::anyhow!(e))?;
    let b = a.ball.resolve(None)?;
    let dball = b.drop_ball();
    let radius = dball.radius;
    let air = (!a.no_drag).then(|| Air {
        density: a.air_density.unwrap_or(Air::default().density),
        drag_coefficient: a
            .drag_coefficient
            .unwrap_or(Air::default().drag_coefficient),
    });
    let height = a
        .height
        .or_else(|| standard.and_then(|s| s.release_height(radius)))
        .unwrap_or(DEFAULT_HEIGHT);
    let setup = DropSetup {
        height,
        air,
        bounces: a.bounces,
        min_rebound: a.min_rebound,
    };
    // the drop and its intervals' drops watched: a bar on a terminal, Ctrl-C or SIGTERM ends
    // the command with exit 130 before anything is printed (cli_progress_pty.rs)
    let watch = super::budget::Watcher::new("bounces");
    let run = crate::drop::drop_watched(&dball, &setup, &watch)
        .map_err(drop_error)?
        .ok_or(super::budget::Interrupted)?;
    let bands = bounce_intervals(&b, &setup, &watch)?;
    drop(watch);
    let verdict = standard
        .map(|s| s.judge(&dball, air))
        .transpose()
        .map_err(drop_error)?;
    let mut warnings = b.drop_warnings(&run)?;
    // the standard's own test (its height or speed) against the record, when it is another
    // impact than the first bounce above
    if let Some(w) = standard.and_then(|s| b.standard_calibration_warning(s))
        && !warnings.contains(&w)
    {
        warnings.push(w);
    }
    warnings.extend(b.drop_air_warning(air));
    match a.format {
        DropFormat::Json => {
            let judged_at = standard.and_then(|s| s.release_height(radius));
            let mut r = report(&run, &bands, verdict.as_ref(), judged_at);
            r.warnings = warnings;
            r.ball = Some(b.record_json());
            output::json(out, &r)?
        }
        DropFormat::Csv => {
            trajectory_csv(out, &run)?;
            output::warnings_to_stderr(&warnings);
        }
        DropFormat::Text => {
            let label = match b.overrides_line() {
                Some(line) => format!("{}\n{line}", b.label()),
                None => b.label(),
            };
            text(out, &label, &run, standard.zip(verdict), radius)?;
            output::warning_lines(out, &warnings)?;
            if let (Some(i), Some(first), Some(fit)) = (bands.first(), run.bounces.first(), &b.fit)
            {
                writeln!(
                    out,
                    "\nfirst bounce, 95 % from the preset's fit (delta method, Student t, {} dof):\n  {}\n  {}",
                    fit.dof,
                    line("COR", first.cor, i.cor_ci95, 1.0, ""),
                    line(
                        "rebound height",
                        first.rebound_height,
                        i.rebound_height_ci95,
                        1e3,
                        "mm"
                    )
                )?;
            }
            // no standard asked for: name the ball's own, if it has one
            if let (None, Some(own)) = (standard, b.name.as_deref().and_then(standards::for_ball)) {
                writeln!(
                    out,
                    "\n{}'s standard is {} ({}): add --standard {}",
                    b.name.as_deref().unwrap_or_default(),
                    own.name,
                    own.title,
                    own.name
                )?;
            }
        }
    }
    Ok(())
}

#[derive(Serialize)]
struct StandardJson {
    name: &'static str,
    window: [Option<f64>; 2],
    measured: f64,
    verdict: &'static str,
    margin: f64,
    /// The release height (m, bottom of the ball) the verdict was judged at: the standard's
    /// own drop, whatever `--height` gave the bounces above (`height`); `null` for a COR
    /// test. tests/cli/cli_drop.rs.
    judged_at_height_m: Option<f64>,
}

/// One bounce's 95 % intervals on a fitted preset (docs/fitting.md, "Prediction intervals").
#[derive(Debug, Clone, Copy, Serialize)]
struct BounceIntervals {
    cor_ci95: [f64; 2],
    max_force_ci95: [f64; 2],
    contact_time_ci95: [f64; 2],
    rebound_height_ci95: [f64; 2],
}

/// A bounce, with its intervals when the ball carries a fit.
#[derive(Serialize)]
struct BounceRow<'a> {
    #[serde(flatten)]
    bounce: &'a crate::drop::Bounce,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    intervals: Option<BounceIntervals>,
}

/// A fitted preset's bounce intervals ([`Ball::drop_intervals`]); empty without a fit or when
/// an override moved it.
fn bounce_intervals(
    b: &Ball,
    setup: &DropSetup,
    watch: &super::budget::Watcher,
) -> anyhow::Result<Vec<BounceIntervals>> {
    // a watch that said stop leaves the signal flag set: any error then exits 130
    // (`cli::exit_code`)
    let Some(bands) = b.drop_intervals_watched(setup, watch).transpose()? else {
        return Ok(Vec::new());
    };
    Ok(bands
        .iter()
        .map(|c| BounceIntervals {
            cor_ci95: c[0],
            max_force_ci95: c[1],
            contact_time_ci95: c[2],
            rebound_height_ci95: c[3],
        })
        .collect())
}

/// The JSON document of the issue, SI: `standard` only with `--standard`.
#[derive(Serialize)]
struct Report<'a> {
    height: f64,
    drag: bool,
    bounces: Vec<BounceRow<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    standard: Option<StandardJson>,
    /// What the caller should know (the first, fastest impact's [`Ball::warnings`]).
    warnings: Vec<String>,
    /// The ball dropped (docs/cli.md, "The ball object").
    ball: Option<crate::api::BallRecord>,
}

fn report<'a>(
    run: &'a DropRun,
    bands: &[BounceIntervals],
    v: Option<&Verdict>,
    judged_at: Option<f64>,
) -> Report<'a> {
    let bands = bands
        .iter()
        .copied()
        .map(Some)
        .chain(std::iter::repeat(None));
    Report {
        height: run.setup.height,
        drag: run.drag(),
        bounces: run
            .bounces
            .iter()
            .zip(bands)
            .map(|(bounce, intervals)| BounceRow { bounce, intervals })
            .collect(),
        standard: v.map(|v| StandardJson {
            name: v.name,
            window: v.window,
            measured: v.measured,
            verdict: if v.pass { "pass" } else { "fail" },
            margin: v.margin,
            judged_at_height_m: judged_at,
        }),
        warnings: Vec::new(),
        ball: None,
    }
}

fn trajectory_csv(out: &mut dyn Write, run: &DropRun) -> std::io::Result<()> {
    csv_row(out, &["t", "height", "velocity"])?;
    for s in run.trajectory(CSV_STEP) {
        csv_row(out, &[num(s.t), num(s.height), num(s.velocity)])?;
    }
    Ok(())
}

fn text(
    out: &mut dyn Write,
    label: &str,
    run: &DropRun,
    judged: Option<(&Standard, Verdict)>,
    radius: f64,
) -> std::io::Result<()> {
    writeln!(out, "{label}")?;
    writeln!(
        out,
        "released from rest at {} m (bottom of the ball), g = {G} m/s², {}",
        given(run.setup.height, 6),
        run.drag_model()
    )?;
    writeln!(out)?;
    let mut rows = vec![
        [
            "#",
            "t_start s",
            "v_in m/s",
            "v_out m/s",
            "COR",
            "rebound m",
            "contact ms",
            "peak force N",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for (i, b) in run.bounces.iter().enumerate() {
        rows.push(vec![
            (i + 1).to_string(),
            human(b.t_start, 4),
            human(b.v_in, 4),
            human(b.v_out, 4),
            format!("{:.4}", b.cor),
            human(b.rebound_height, 4),
            human(b.contact_time * 1e3, 4),
            human(b.max_force, 4),
        ]);
    }
    table(out, "  ", &rows)?;
    writeln!(out)?;
    let why = match run.end {
        End::Count => format!("after {} bounces (--bounces)", run.bounces.len()),
        End::MinRebound => format!(
            "a rebound below {} m (--min-rebound)",
            given(run.setup.min_rebound, 4)
        ),
        End::NoRebound => "the ball stayed on the plate (e = 0)".into(),
    };
    writeln!(out, "ended: {why}")?;
    if let Some((s, v)) = judged {
        writeln!(out)?;
        verdict_text(out, s, &v, radius)?;
        if s.release_height(radius)
            .is_some_and(|h| h != run.setup.height)
        {
            writeln!(
                out,
                "  (judged on the standard's own drop, not on the {} m above)",
                given(run.setup.height, 6)
            )?;
        }
    }
    Ok(())
}

/// "standard itf (…): window 1.35 … 1.47 m, measured 1.410 m → pass, margin +0.060 m".
fn verdict_text(
    out: &mut dyn Write,
    s: &Standard,
    v: &Verdict,
    radius: f64,
) -> std::io::Result<()> {
    let (unit, conditions) = match s.test {
        Test::Drop {
            height,
            drop_ref,
            rebound_ref,
        } => (
            " m",
            format!(
                "drop from {} m to the {} of the ball, rebound read at the {}{}",
                given(height, 4),
                drop_ref.name(),
                rebound_ref.name(),
                match rebound_ref {
                    Reference::Top => format!(" (+{} m, the diameter)", given(2.0 * radius, 4)),
                    Reference::Bottom => String::new(),
                }
            ),
        ),
        Test::Cor { speed } => ("", format!("COR at {} m/s", given(speed, 4))),
    };
    writeln!(out, "standard {}: {}", s.name, s.title)?;
    writeln!(out, "  {conditions}, {}", s.surface)?;
    writeln!(
        out,
        "  window {}, predicted {}{unit}: {}, margin {}{}{unit}",
        super::standards::window_cell(s),
        human(v.measured, 4),
        if v.pass { "PASS" } else { "FAIL" },
        if v.margin >= 0.0 { "+" } else { "" },
        human(v.margin, 3),
    )
}
