//! `bouncelab drop`: a ball released from rest bounces on a rigid plate (docs/drop.md), as a
//! text table, one JSON object, or the trajectory as CSV; with `--standard`, the verdict.

use super::ball::BallArgs;
use super::drop_json::{BounceIntervals, bounce_intervals, report};
use super::drop_leak::LeakVerdict;
use super::drop_text;
use super::intervals_text::line;
use super::output::{self, TextJsonCsv, csv_row, num};
use super::surface::SurfaceUsed;
use crate::analysis::statics::StaticDeflection;
use crate::api::Ball;
use crate::drop::conditions::PressureLoss;
use crate::drop::deformation::{self, DeformationStandard};
use crate::drop::standards::{self, Standard, Verdict};
use crate::drop::{
    Air, DEFAULT_BOUNCES, DEFAULT_MIN_REBOUND, DropBall, DropError, DropRun, DropSetup,
};
use crate::preset::Output;
use clap::Args;
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

/// The standard `--standard` names, by kind: every kind `drop` takes (src/drop/names.rs).
#[derive(Clone, Copy)]
struct Asked {
    /// The pressure-loss test: it judges the leak, and runs the ball at its conditions.
    leak: Option<&'static PressureLoss>,
    /// An impact standard (a drop or COR test).
    impact: Option<&'static Standard>,
    /// A static standard (src/drop/deformation.rs).
    statics: Option<&'static DeformationStandard>,
}

fn asked_standard(name: Option<&str>) -> anyhow::Result<Asked> {
    let leak = name.and_then(super::drop_leak::find);
    let (impact, statics) = match name.filter(|_| leak.is_none()) {
        None => (None, None),
        Some(name) => match (standards::find(name), deformation::find(name)) {
            (Ok(s), _) => (Some(s), None),
            (Err(_), Some(d)) => (None, Some(d)),
            (Err(_), None) => anyhow::bail!(crate::api::not_a_drop_standard(name)),
        },
    };
    Ok(Asked {
        leak,
        impact,
        statics,
    })
}

/// The ball dropped, with the leak test's verdict and the warning of a ball off a rebound
/// standard's conditions: the leak test and a rebound standard run the ball at their test's
/// conditions (docs/drop.md, "Conditions").
fn dropped_ball(
    a: &DropArgs,
    asked: &Asked,
) -> anyhow::Result<(Ball, Option<LeakVerdict>, Option<String>)> {
    let mut ball_args = a.ball.clone();
    if let Some(t) = asked.leak {
        ball_args.conditions = super::drop_leak::conditions(t, &a.ball.conditions)?;
    }
    let b = ball_args.resolve(None)?;
    let leak_verdict = asked
        .leak
        .zip(ball_args.conditions.half_life)
        .map(|(t, h)| super::drop_leak::judge(t, h))
        .transpose()?;
    let (b, off_conditions) = match asked.impact {
        Some(s) => b.at_standard(s, &a.ball.conditions.spec())?,
        None => (b, None),
    };
    Ok((b, leak_verdict, off_conditions))
}

/// The drop's air (none with `--no-drag`) and height (asked, else the standard's, else 1 m).
fn drop_setup(a: &DropArgs, standard: Option<&Standard>, radius: f64) -> DropSetup {
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
    DropSetup {
        height,
        air,
        bounces: a.bounces,
        min_rebound: a.min_rebound,
    }
}

/// The surface, the bounces on it and their intervals. The drop and its intervals' drops are
/// watched: a bar on a terminal, Ctrl-C or SIGTERM ends the command with exit 130 before
/// anything is printed (cli_progress_pty.rs).
fn bounces(
    b: &Ball,
    dball: &DropBall,
    setup: &DropSetup,
    surface: &super::surface::SurfaceArgs,
) -> anyhow::Result<(SurfaceUsed, DropRun, Vec<BounceIntervals>)> {
    let watch = super::budget::Watcher::new("bounces");
    let surface = surface.resolve()?;
    let run = crate::drop::drop_on_watched(dball, setup, &surface.mechanics.target(), &watch)
        .map_err(drop_error)?
        .ok_or(super::budget::Interrupted)?;
    // the intervals are the fitted parameters' on the rigid plate: none on another surface
    let bands = match surface.mechanics.is_rigid() {
        true => bounce_intervals(b, setup, &watch)?,
        false => Vec::new(),
    };
    drop(watch);
    Ok((surface, run, bands))
}

/// A static standard's deflection of the ball.
type Statics = (&'static DeformationStandard, StaticDeflection);

/// The asked standard's verdict on the ball, and a static standard's deflection.
fn verdicts(
    asked: &Asked,
    dball: &DropBall,
    air: Option<Air>,
    surface: &SurfaceUsed,
) -> anyhow::Result<(Option<Verdict>, Option<Statics>)> {
    let mut verdict = asked
        .impact
        .map(|s| s.judge_on(dball, air, &surface.mechanics.target()))
        .transpose()
        .map_err(drop_error)?;
    let statics = asked.statics.map(|d| (d, d.deflection(dball, dball.law)));
    if let Some((d, s)) = &statics {
        verdict = Some(d.judge(dball).ok_or_else(|| {
            anyhow::anyhow!(
                "standard {}: the model gives no static deflection of this ball: {}",
                d.name,
                s.forward.as_ref().err().map_or("", |e| e.as_str())
            )
        })?);
    }
    Ok((verdict, statics))
}

/// Everything a drop answers, for its three formats.
struct Dropped {
    asked: Asked,
    ball: Ball,
    radius: f64,
    surface: SurfaceUsed,
    run: DropRun,
    bands: Vec<BounceIntervals>,
    verdict: Option<Verdict>,
    statics: Option<Statics>,
    leak_verdict: Option<LeakVerdict>,
    warnings: Vec<String>,
}

/// The drop `a` asks, judged against its standard, with what the caller should know.
fn dropped(a: &DropArgs) -> anyhow::Result<Dropped> {
    let asked = asked_standard(a.standard.as_deref())?;
    let (ball, leak_verdict, off_conditions) = dropped_ball(a, &asked)?;
    let dball = ball.drop_ball();
    let setup = drop_setup(a, asked.impact, dball.radius);
    let (surface, run, bands) = bounces(&ball, &dball, &setup, &a.surface)?;
    let (verdict, statics) = verdicts(&asked, &dball, setup.air, &surface)?;
    let statics_run = statics.as_ref().map(|(d, s)| (*d, s));
    let standard = asked.impact;
    let mut warnings =
        ball.judged_drop_warnings(&run, a.height.is_some(), standard, statics_run, &surface)?;
    warnings.extend(ball.drop_air_warning(setup.air));
    warnings.extend(off_conditions);
    Ok(Dropped {
        asked,
        radius: dball.radius,
        ball,
        surface,
        run,
        bands,
        verdict,
        statics,
        leak_verdict,
        warnings,
    })
}

pub fn run(a: &DropArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let d = dropped(a)?;
    match a.format {
        TextJsonCsv::Json => json(out, d)?,
        TextJsonCsv::Csv => {
            let stated = super::csv_stated::with_ball_cells(&d.ball, &d.surface);
            trajectory_csv(out, &d.run, &stated)?;
            output::warnings_to_stderr(&d.warnings);
        }
        TextJsonCsv::Text => text(out, &d)?,
    }
    Ok(())
}

/// The JSON document ([`super::drop_json::Report`]), with the ball, its surface and conditions.
fn json(out: &mut dyn Write, d: Dropped) -> anyhow::Result<()> {
    let judged_at = d.asked.impact.and_then(|s| s.release_height(d.radius));
    let mut r = report(&d.run, &d.bands, d.verdict.as_ref(), judged_at);
    if let (Some(sj), Some((t, s))) = (r.standard.as_mut(), &d.statics) {
        sj.static_test = Some(crate::api::static_test_report(t, s));
    }
    r.warnings = d.warnings;
    r.ball = Some(d.ball.record_json());
    r.uncalibrated_outputs = d.ball.uncalibrated_outputs(&Output::DROP);
    r.surface = Some(d.surface);
    r.pressure_loss = d.leak_verdict;
    output::json_stated(out, &r, &d.ball.conditions)?;
    Ok(())
}

/// The text output: the bounces, the verdicts, the warnings, the first bounce's intervals and
/// the ball's own standard when none was asked.
fn text(out: &mut dyn Write, d: &Dropped) -> anyhow::Result<()> {
    // the ball, its overrides, the surface, the conditions
    let label = output::headed(d.ball.label(), &d.ball, output::Met::Surface(&d.surface));
    let standard = d.asked.impact;
    let note = d.ball.uncalibrated_note(&Output::DROP);
    drop_text::text(out, &label, &d.run, standard.zip(d.verdict), d.radius, note)?;
    if let (Some(t), Some(v)) = (d.asked.leak, &d.leak_verdict) {
        super::drop_leak::text(out, t, v)?;
    }
    if let (Some((t, s)), Some(v)) = (&d.statics, &d.verdict) {
        drop_text::static_verdict_text(out, t, s, v)?;
    }
    output::warning_lines(out, &d.warnings)?;
    first_bounce_intervals_text(out, d)?;
    own_standard_text(out, d)?;
    Ok(())
}

/// The first bounce's 95 % intervals, on a fitted preset.
fn first_bounce_intervals_text(out: &mut dyn Write, d: &Dropped) -> std::io::Result<()> {
    let (Some(i), Some(first), Some(fit)) = (d.bands.first(), d.run.bounces.first(), &d.ball.fit)
    else {
        return Ok(());
    };
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
    )
}

/// No standard asked for: the ball's own, if it has one.
fn own_standard_text(out: &mut dyn Write, d: &Dropped) -> std::io::Result<()> {
    let b = &d.ball;
    let Asked {
        leak,
        impact,
        statics,
    } = d.asked;
    if let (None, None, None, Some(own)) = (
        impact,
        statics,
        leak,
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
    Ok(())
}

/// `drop --format csv`: the trajectory, each row ending with the ball, the surface and the
/// conditions (`stated`, [`super::csv_stated::with_ball`]).
fn trajectory_csv(out: &mut dyn Write, run: &DropRun, stated: &[String]) -> std::io::Result<()> {
    let mut head = vec!["t", "height", "velocity"];
    head.extend(super::csv_stated::with_ball());
    csv_row(out, &head)?;
    for s in run.trajectory(CSV_STEP) {
        let mut row = vec![num(s.t), num(s.height), num(s.velocity)];
        row.extend_from_slice(stated);
        csv_row(out, &row)?;
    }
    Ok(())
}
