//! `bouncelab drop`: a ball released from rest bounces on a rigid plate (docs/drop.md), as a
//! text table, one JSON object, or the trajectory as CSV; with `--standard`, the verdict.

use super::ball::BallArgs;
use super::drop_text;
use super::intervals_text::line;
use super::output::{self, TextJsonCsv, csv_row, num};
use crate::api::Ball;
use crate::drop::deformation;
use crate::drop::standards::{self, Verdict};
use crate::drop::{Air, DEFAULT_BOUNCES, DEFAULT_MIN_REBOUND, DropError, DropRun, DropSetup};
use clap::Args;
use serde::Serialize;
use std::io::Write;

/// Release height without a standard (m).
pub const DEFAULT_HEIGHT: f64 = 1.0;
/// Time step of the CSV trajectory within each flight (s).
pub const CSV_STEP: f64 = 1e-3;

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
    pub format: TextJsonCsv,
    #[command(flatten)]
    pub surface: super::surface::SurfaceArgs,
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
    // the pressure-loss test judges the leak, and runs the ball at its conditions
    let leak_test = a.standard.as_deref().and_then(super::drop_leak::find);
    // an impact standard (drop or COR test) or a static one (src/drop/deformation.rs)
    let (standard, static_standard) = match a.standard.as_deref().filter(|_| leak_test.is_none()) {
        None => (None, None),
        Some(name) => match (standards::find(name), deformation::find(name)) {
            (Ok(s), _) => (Some(s), None),
            (Err(_), Some(d)) => (None, Some(d)),
            // every kind of standard `drop` takes (src/drop/names.rs)
            (Err(_), None) => anyhow::bail!(crate::api::not_a_drop_standard(name)),
        },
    };
    let mut ball_args = a.ball.clone();
    if let Some(t) = leak_test {
        ball_args.conditions = super::drop_leak::conditions(t, &a.ball.conditions)?;
    }
    let b = ball_args.resolve(None)?;
    let leak_verdict = leak_test
        .zip(ball_args.conditions.half_life)
        .map(|(t, h)| super::drop_leak::judge(t, h))
        .transpose()?;
    // a rebound standard runs the ball at its test's conditions (docs/drop.md, "Conditions")
    let (b, off_conditions) = match standard {
        Some(s) => b.at_standard(s.name, &a.ball.conditions.spec())?,
        None => (b, None),
    };
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
    let surface = a.surface.resolve()?;
    let run = crate::drop::drop_on_watched(&dball, &setup, &surface.mechanics.target(), &watch)
        .map_err(drop_error)?
        .ok_or(super::budget::Interrupted)?;
    // the intervals are the fitted parameters' on the rigid plate: none on another surface
    let bands = match surface.mechanics.is_rigid() {
        true => bounce_intervals(&b, &setup, &watch)?,
        false => Vec::new(),
    };
    drop(watch);
    let mut verdict = standard
        .map(|s| s.judge_on(&dball, air, &surface.mechanics.target()))
        .transpose()
        .map_err(drop_error)?;
    let statics = static_standard.map(|d| (d, d.deflection(&dball, dball.law)));
    if let Some((d, s)) = &statics {
        verdict = Some(d.judge(&dball).ok_or_else(|| {
            anyhow::anyhow!(
                "standard {}: the model gives no static deflection of this ball: {}",
                d.name,
                s.forward.as_ref().err().map_or("", |e| e.as_str())
            )
        })?);
    }
    let statics_run = statics.as_ref().map(|(d, s)| (*d, s));
    let mut warnings = b.judged_drop_warnings(&run, a.height.is_some(), standard, statics_run)?;
    warnings.extend(standard.and_then(|s| surface.off_standard_warning(s.name, s.surface)));
    warnings.extend(b.drop_air_warning(air));
    warnings.extend(off_conditions);
    match a.format {
        TextJsonCsv::Json => {
            let judged_at = standard.and_then(|s| s.release_height(radius));
            let mut r = report(&run, &bands, verdict.as_ref(), judged_at);
            if let (Some(sj), Some((d, s))) = (r.standard.as_mut(), &statics) {
                sj.static_test = Some(crate::api::static_test_report(d, s));
            }
            r.warnings = warnings;
            r.ball = Some(b.record_json());
            r.surface = Some(surface);
            r.pressure_loss = leak_verdict.clone();
            output::json_stated(out, &r, &b.conditions)?
        }
        TextJsonCsv::Csv => {
            trajectory_csv(out, &run)?;
            output::warnings_to_stderr(&warnings);
        }
        TextJsonCsv::Text => {
            let mut label = b.label();
            if let Some(line) = b.overrides_line() {
                label.push('\n');
                label.push_str(&line);
            }
            if !surface.mechanics.is_rigid() || a.surface.surface.is_some() {
                label = format!("{label}\n{}", surface.label());
            }
            if let Some(line) = b.conditions_line() {
                label.push('\n');
                label.push_str(&line);
            }
            drop_text::text(out, &label, &run, standard.zip(verdict), radius)?;
            if let (Some(t), Some(v)) = (leak_test, &leak_verdict) {
                super::drop_leak::text(out, t, v)?;
            }
            if let (Some((d, s)), Some(v)) = (&statics, &verdict) {
                drop_text::static_verdict_text(out, d, s, v)?;
            }
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
            if let (None, None, None, Some(own)) = (
                standard,
                static_standard,
                leak_test,
                b.name.as_deref().and_then(standards::for_ball),
            ) {
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
    /// A static standard's test (src/drop/deformation.rs): only for one.
    #[serde(rename = "static", skip_serializing_if = "Option::is_none")]
    static_test: Option<crate::api::StaticTestReport>,
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
    /// The surface it bounced on (docs/surfaces.md).
    surface: Option<super::surface::SurfaceUsed>,
    /// `--standard fifa-pressure-loss`'s verdict on the ball's leak.
    #[serde(skip_serializing_if = "Option::is_none")]
    pressure_loss: Option<super::drop_leak::LeakVerdict>,
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
            static_test: None,
        }),
        warnings: Vec::new(),
        ball: None,
        surface: None,
        pressure_loss: None,
    }
}

fn trajectory_csv(out: &mut dyn Write, run: &DropRun) -> std::io::Result<()> {
    csv_row(out, &["t", "height", "velocity"])?;
    for s in run.trajectory(CSV_STEP) {
        csv_row(out, &[num(s.t), num(s.height), num(s.velocity)])?;
    }
    Ok(())
}
