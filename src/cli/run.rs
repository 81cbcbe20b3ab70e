//! `bouncelab run`: one impact, as a text table, one JSON object or CSV.

use super::ball::BallArgs;
use super::output::{self, TextJsonCsv, csv_row, num, opt_num};
use super::surface::{SurfaceArgs, SurfaceUsed};
use crate::api::{Ball, ImpactReport};
use crate::model::contact::ContactLaw;
use crate::solver::{EnergyBudget, ImpactResponse};
use clap::Args;
use serde::Serialize;
use std::io::Write;

/// History samples by default (at most [`crate::api::MAX_SAMPLES`]).
const SAMPLES: usize = 400;

/// `--history` and `--samples`: the contact's history, evenly sampled, beside the answer
/// (`run`; `oblique`, whose `--history` help names its own columns by `mut_arg`).
#[derive(Debug, Clone, Args)]
pub struct HistoryArgs {
    /// Also print F(t), z(t), α(t), evenly sampled over the contact
    #[arg(long)]
    pub history: bool,
    /// Number of history samples
    #[arg(long, value_name = "N", default_value_t = SAMPLES, requires = "history", value_parser = super::number::count, allow_hyphen_values = true)]
    pub samples: usize,
}

impl HistoryArgs {
    /// The samples to ask the library for: none without `--history`. The library reads 0 as
    /// "no history", so with `--history` 0 is refused as 1 is (2 … MAX_SAMPLES).
    pub fn samples(&self) -> Result<usize, crate::api::BallError> {
        match (self.history, self.samples) {
            (false, _) => Ok(0),
            (true, 0) => Err(crate::api::BallError::Samples(0)),
            (true, n) => Ok(n),
        }
    }
}

#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Normalized ball, m = K_p = v0 = 1: λ and ζ alone set the run (defaults λ = 1, ζ = 0.1)
    #[arg(long, conflicts_with_all = ["preset", "config", "params", "v0"])]
    pub normalized: bool,
    /// Impact speed v0 (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Flattening threshold z̄_p = z_p ω0/v0 of the normalized ball [default: none]
    #[arg(
        long,
        value_name = "X",
        requires = "normalized",
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub zp_bar: Option<f64>,
    /// Relative stiffness λ = K_r/K_p (on a preset: changes K_r, keeps m and K_p)
    #[arg(long, value_name = "L", value_parser = super::number::number, allow_hyphen_values = true)]
    pub lambda: Option<f64>,
    /// Damping factor ζ = √(m K_p)/(2c) (on a preset: changes c, keeps m and K_p)
    #[arg(long, value_name = "Z", value_parser = super::number::number, allow_hyphen_values = true)]
    pub zeta: Option<f64>,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJsonCsv,
    #[command(flatten)]
    pub history: HistoryArgs,
    #[command(flatten)]
    pub surface: SurfaceArgs,
}

/// `run --format json`: the impact and the surface it ran on (docs/surfaces.md).
#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    report: ImpactReport<'a>,
    surface: &'a SurfaceUsed,
}

pub fn run(args: &RunArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.normalized && args.ball.changes.set.any() {
        anyhow::bail!(
            "--normalized runs m = K_p = v0 = 1: --mass, --radius, --k-p, --damping, --k-r and \
             --z-p do not apply"
        );
    }
    if args.normalized && !args.ball.conditions.spec().is_empty() {
        anyhow::bail!(
            "--normalized runs m = K_p = v0 = 1: --pressure, --temperature, --inflated-at, \
             --after and --half-life do not apply"
        );
    }
    // --normalized takes no override (refused above) for its λ and ζ to meet
    let ball = if args.normalized {
        let law = args.ball.changes.law.map_or(ContactLaw::Linear, Into::into);
        Ball::normalized(
            args.lambda.unwrap_or(1.0),
            args.zeta.unwrap_or(0.1),
            args.zp_bar,
            law,
        )?
    } else {
        args.ball.resolve_tuned(args.v0, args.lambda, args.zeta)?
    };
    let surface = args.surface.resolve()?;
    // the library checks the number of samples (2 … MAX_SAMPLES)
    let samples = args.history.samples()?;
    let r = ball.impact_on(&surface.mechanics.target(), samples)?;
    // the preset's measurement is the rigid plate's: not this impact's on a surface that gives
    let elsewhere = (!surface.mechanics.is_rigid() && ball.measured.is_some()).then(|| {
        format!(
            "the measurement is on the rigid plate, this impact on surface {}",
            surface.name
        )
    });
    let ball = match &elsewhere {
        Some(_) => Ball {
            measured: None,
            ..ball
        },
        None => ball,
    };
    // a fitted preset's 95 % intervals (docs/fitting.md), when no override moved the fit
    let intervals = ball.intervals().transpose()?;
    match args.format {
        TextJsonCsv::Json => {
            let mut report = ImpactReport::new(&ball, &r, args.history.history);
            report.warnings = ball.warnings_on(&r, &surface);
            report.intervals = intervals;
            if elsewhere.is_some() {
                report.comparison_withheld = elsewhere;
            }
            let surface = &surface;
            output::json_stated(out, &Report { report, surface }, &ball.conditions)?
        }
        TextJsonCsv::Csv if args.history.history => {
            history_csv(out, &r)?;
            output::warnings_to_stderr(&ball.warnings_on(&r, &surface));
        }
        TextJsonCsv::Csv => summary_csv(out, &ball, &r, &surface, intervals.as_ref())?,
        TextJsonCsv::Text => {
            let history = args.history.history;
            super::run_text::write(out, &ball, &r, &surface, intervals.as_ref(), history)?;
            if let Some(why) = &elsewhere {
                writeln!(out, "  (measured values not compared: {why})")?;
            }
        }
    }
    Ok(())
}

/// Columns of `run --format csv` (one row), before the surface's and the conditions'
/// (`csv_stated::columns`) and a fitted preset's 95 % intervals
/// (`intervals_text::CSV_COLUMNS`).
pub const SUMMARY_COLUMNS: [&str; 29] = [
    "preset",
    "origin",
    "parameters",
    "law",
    "method",
    "mass",
    "k_p",
    "k_r",
    "c",
    "z_p",
    "k_h",
    "v0",
    "lambda",
    "zeta",
    "zp_bar",
    "cor",
    "rebound",
    "max_force",
    "contact_time",
    "max_indentation",
    "permanent_indentation",
    "max_force_normalized",
    "contact_time_normalized",
    "energy_initial",
    "energy_final",
    "energy_dashpot",
    "energy_contact",
    "energy_spring",
    "warnings",
];

/// The one row of `run --format csv`: the ball, the answer, its warnings, the surface and
/// conditions it ran on and at, and on a fitted preset the intervals (text and JSON have them).
fn summary_csv(
    out: &mut dyn Write,
    b: &Ball,
    r: &ImpactResponse,
    surface: &SurfaceUsed,
    intervals: Option<&crate::api::Intervals>,
) -> std::io::Result<()> {
    let mut head = SUMMARY_COLUMNS.to_vec();
    head.extend(super::csv_stated::columns());
    let mut cells = summary_cells(b, r, surface);
    cells.extend(super::csv_stated::cells(surface, &b.conditions));
    if let Some(i) = intervals {
        head.extend(super::intervals_text::CSV_COLUMNS);
        cells.extend(super::intervals_text::csv_cells(i));
    }
    csv_row(out, &head)?;
    csv_row(out, &cells)
}

/// The cells of [`SUMMARY_COLUMNS`].
fn summary_cells(b: &Ball, r: &ImpactResponse, surface: &SurfaceUsed) -> Vec<String> {
    let p = &b.params;
    let n = &r.normalized;
    let e = r.energy;
    let en = |f: fn(&EnergyBudget) -> f64| opt_num(e.as_ref().map(f));
    vec![
        b.name.clone().unwrap_or_default(),
        b.origin.clone(),
        b.source.into(),
        r.law.name().into(),
        r.method.name().into(),
        num(p.mass),
        num(p.k_p),
        num(p.k_r),
        num(p.damping),
        num(p.z_p),
        num(p.k_h),
        num(p.v0),
        num(n.lambda),
        num(n.zeta),
        num(n.zp_bar),
        num(r.cor),
        r.rebound.to_string(),
        num(r.max_force),
        opt_num(r.contact_time),
        num(r.max_indentation),
        num(r.permanent_indentation),
        num(r.max_force_normalized),
        opt_num(r.contact_time_normalized),
        en(|e| e.initial_kinetic),
        en(|e| e.final_kinetic),
        en(|e| e.dashpot),
        en(|e| e.contact),
        en(|e| e.spring),
        output::warnings_cell(&b.warnings_on(r, surface)),
    ]
}

fn history_csv(out: &mut dyn Write, r: &ImpactResponse) -> std::io::Result<()> {
    csv_row(out, &["t", "force", "indentation", "displacement"])?;
    let h = &r.history;
    for i in 0..h.t.len() {
        let row = [h.t[i], h.force[i], h.indentation[i], h.displacement[i]].map(num);
        csv_row(out, &row)?;
    }
    Ok(())
}
