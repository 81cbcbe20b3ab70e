//! `bouncelab sweep zeta|velocity`: the paper's Figs. 2–3 (COR, F̄_m, τ_f against ζ for
//! several λ) and Fig. 4 (COR against impact speed for one ball), as CSV or JSON.

use super::ball::{BallArgs, LawArg};
use super::csv_stated;
use super::output::{self, csv_row, num, opt_num};
use crate::analysis::sweep::{VelocityPoint, lin_space, log_space};
use crate::api::{self, Ball, BallHeader, Intervals, SurfaceUsed};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::model::params::{Field, check_positive, validate_lambda_zeta};
use clap::{Args, Subcommand, ValueEnum};
use serde::Serialize;
use std::io::Write;

/// Most points along a sweep; the rows in all (λ values × points) are held to the work limit
/// of every command, [`super::budget::LIMIT`].
pub const MAX_POINTS: usize = 100_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    Csv,
    Json,
}

#[derive(Debug, Clone, Subcommand)]
// parsed once a process: the velocity sweep's options (the ball's, its conditions) are the
// larger, and boxing them would buy nothing
#[allow(clippy::large_enum_variant)]
pub enum Sweep {
    /// COR, normalized peak force and contact time against ζ (log-spaced), one curve per λ,
    /// without flattening (Figs. 2, 3)
    #[command(allow_negative_numbers = true)]
    Zeta(ZetaArgs),
    /// COR, peak force, contact time and permanent indentation against impact speed for one
    /// ball (Fig. 4)
    #[command(allow_negative_numbers = true)]
    Velocity(VelocityArgs),
}

#[derive(Debug, Clone, Args)]
pub struct ZetaArgs {
    /// λ values, comma-separated
    #[arg(
        long,
        value_name = "L,L,...",
        value_delimiter = ',',
        default_value = "0,0.4,1",
        value_parser = super::number::number,
        allow_hyphen_values = true
    )]
    pub lambda: Vec<f64>,
    /// Smallest ζ
    #[arg(
        long,
        value_name = "Z",
        default_value_t = 0.01,
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub from: f64,
    /// Largest ζ
    #[arg(
        long,
        value_name = "Z",
        default_value_t = 100.0,
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub to: f64,
    /// Number of ζ values per λ
    #[arg(long, value_name = "N", default_value_t = 400)]
    pub points: usize,
    /// Contact law
    #[arg(long, value_enum, default_value = "linear")]
    pub law: LawArg,
    /// Output format
    #[arg(long, value_enum, default_value = "csv")]
    pub format: SweepFormat,
}

#[derive(Debug, Clone, Args)]
pub struct VelocityArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Relative stiffness λ = K_r/K_p (changes K_r, keeps m and K_p)
    #[arg(long, value_name = "L", value_parser = super::number::number, allow_hyphen_values = true)]
    pub lambda: Option<f64>,
    /// Damping factor ζ = √(m K_p)/(2c) (changes c, keeps m and K_p)
    #[arg(long, value_name = "Z", value_parser = super::number::number, allow_hyphen_values = true)]
    pub zeta: Option<f64>,
    /// The ball's impact speed v0, m/s, which sets the default range [default: the preset's]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Lowest impact speed (m/s) [default: 0.1 × the preset's v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub from: Option<f64>,
    /// Highest impact speed (m/s) [default: 3 × the preset's v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub to: Option<f64>,
    /// Number of speeds (evenly spaced)
    #[arg(long, value_name = "N", default_value_t = 60)]
    pub points: usize,
    /// Output format
    #[arg(long, value_enum, default_value = "csv")]
    pub format: SweepFormat,
}

pub fn run(sweep: &Sweep, out: &mut dyn Write) -> anyhow::Result<()> {
    match sweep {
        Sweep::Zeta(a) => zeta(a, out),
        Sweep::Velocity(a) => velocity(a, out),
    }
}

fn check_points(points: usize, curves: usize, law: ContactLaw) -> anyhow::Result<()> {
    if points == 0 {
        anyhow::bail!("invalid points: 0 (must be at least 1)");
    }
    if points > MAX_POINTS {
        anyhow::bail!("invalid points: {points} (at most {MAX_POINTS})");
    }
    // the one work limit of every command (cli::budget)
    let what = format!("{curves} λ values × {points} points");
    super::budget::check(points * curves, law, &what)
}

#[derive(Serialize)]
struct ZetaDoc<'a, T> {
    sweep: &'static str,
    law: &'static str,
    rows: &'a [T],
    /// The ball swept: the normalized ball (m = K_p = v0 = 1) at λ = ζ = 1, whose K_r and c
    /// each row moves (docs/cli.md, "The ball object"), as `map --normalized` names it.
    ball: crate::api::BallRecord,
}

fn zeta(a: &ZetaArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.lambda.is_empty() {
        anyhow::bail!("invalid lambda: no value given");
    }
    for &l in &a.lambda {
        validate_lambda_zeta(l, 0.0)?;
    }
    // ζ bounds must be positive: the range is log-spaced
    check_positive(Field::From, a.from)?;
    check_positive(Field::To, a.to)?;
    let law = ContactLaw::from(a.law);
    check_points(a.points, a.lambda.len(), law)?;
    let rows = super::budget::zeta_rows(&a.lambda, &log_space(a.from, a.to, a.points), law)?;
    match a.format {
        SweepFormat::Json => {
            // dimensionless, yet named like every answer (issue 53), as `map --normalized`
            // names its grid: the normalized ball at λ = ζ = 1 (each row moves its K_r and c),
            // on the rigid plate, at the recorded conditions (no preset: the defaults)
            let ball = crate::Ball::normalized(1.0, 1.0, None, law)?;
            output::json_on(
                out,
                &ZetaDoc {
                    sweep: "zeta",
                    law: law.name(),
                    rows: &rows,
                    ball: ball.record_json(),
                },
                output::Met::RigidPlate,
                &crate::api::recorded_conditions(None),
            )?
        }
        SweepFormat::Csv => {
            csv_row(
                out,
                &[
                    "lambda",
                    "zeta",
                    "cor",
                    "max_force_normalized",
                    "contact_time_normalized",
                ],
            )?;
            for r in &rows {
                csv_row(
                    out,
                    &[
                        num(r.lambda),
                        num(r.zeta),
                        num(r.cor),
                        num(r.max_force_normalized),
                        opt_num(r.contact_time_normalized),
                    ],
                )?;
            }
        }
    }
    Ok(())
}

#[derive(Serialize)]
struct VelocityDoc<'a, T> {
    sweep: &'static str,
    #[serde(flatten)]
    ball: BallHeader<'a>,
    lambda: f64,
    zeta: f64,
    rows: &'a [T],
    /// The ball swept (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    record: crate::api::BallRecord,
    /// The rows' outputs its record does not vouch for (`Ball::uncalibrated_outputs`).
    uncalibrated_outputs: Option<Vec<crate::preset::Output>>,
}

fn velocity(a: &VelocityArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let b = a.ball.resolve_tuned(a.v0, a.lambda, a.zeta)?;
    let v0 = b.params.v0;
    let from = a.from.unwrap_or(0.1 * v0);
    let to = a.to.unwrap_or(3.0 * v0);
    check_positive(Field::From, from)?;
    check_positive(Field::To, to)?;
    check_points(a.points, 1, b.law)?;
    let (params, law) = (&b.params, b.law);
    let rows = super::budget::velocity_rows(params, law, &lin_space(from, to, a.points))?;
    let bands = velocity_intervals(&b, &rows)?;
    let rows: Vec<VelocityRow> = rows
        .iter()
        .zip(bands.iter().map(Some).chain(std::iter::repeat(None)))
        .map(|(row, i)| VelocityRow {
            row,
            intervals: i.copied(),
            warnings: b.velocity_row_warnings(row),
        })
        .collect();
    match a.format {
        SweepFormat::Json => {
            let n = b.params.normalized();
            // the ball bounces on the rigid plate (docs/cli.md, "The surface object")
            output::json_on(
                out,
                &VelocityDoc {
                    sweep: "velocity",
                    ball: b.header(),
                    lambda: n.lambda,
                    zeta: n.zeta,
                    rows: &rows,
                    record: b.record_json(),
                    uncalibrated_outputs: b.uncalibrated_outputs(&crate::preset::Output::IMPACT),
                },
                output::Met::RigidPlate,
                &b.conditions,
            )?
        }
        SweepFormat::Csv => velocity_csv(out, &b, &rows, !bands.is_empty())?,
    }
    Ok(())
}

/// A row of `sweep velocity`, with a fitted preset's 95 % intervals (docs/fitting.md) and
/// what the caller should know about it (an indentation beyond the radius).
#[derive(Serialize)]
struct VelocityRow<'a> {
    #[serde(flatten)]
    row: &'a VelocityPoint,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    intervals: Option<Intervals>,
    warnings: Vec<String>,
}

/// The intervals at each row's speed when the ball carries a fit no override moved; empty
/// otherwise.
fn velocity_intervals(b: &Ball, rows: &[VelocityPoint]) -> anyhow::Result<Vec<Intervals>> {
    let Some(fit) = b.fit.as_ref().filter(|f| api::holds(&b.params, f)) else {
        return Ok(Vec::new());
    };
    rows.iter()
        .map(|r| {
            let p = ImpactParams {
                v0: r.v0,
                ..b.params
            };
            Ok(api::intervals(&p, b.law, fit)?)
        })
        .collect()
}

/// `sweep velocity --format csv`: a row per speed, each ending with the ball, the surface
/// and the conditions ([`csv_stated::with_ball`]).
fn velocity_csv(
    out: &mut dyn Write,
    b: &Ball,
    rows: &[VelocityRow],
    bands: bool,
) -> anyhow::Result<()> {
    let mut head = vec![
        "v0",
        "cor",
        "max_force",
        "contact_time",
        "permanent_indentation",
    ];
    if bands {
        head.extend(super::intervals_text::CSV_COLUMNS);
    }
    head.push("warnings");
    head.extend(csv_stated::with_ball());
    csv_row(out, &head)?;
    // the ball bounces on the rigid plate, as the JSON's `surface` says
    let stated = csv_stated::with_ball_cells(b, &SurfaceUsed::rigid_plate());
    for VelocityRow {
        row: r,
        intervals,
        warnings,
    } in rows
    {
        let mut cells = vec![
            num(r.v0),
            num(r.cor),
            num(r.max_force),
            opt_num(r.contact_time),
            num(r.permanent_indentation),
        ];
        if let Some(i) = intervals {
            cells.extend(super::intervals_text::csv_cells(i));
        }
        cells.push(output::warnings_cell(warnings));
        cells.extend(stated.iter().cloned());
        csv_row(out, &cells)?;
    }
    Ok(())
}
