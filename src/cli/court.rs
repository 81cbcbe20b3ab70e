//! `bouncelab court`: the ITF Court Pace Rating of a surface (ITF CS 01/02) from the oblique
//! impact of the ball at 30 m/s and 16° without spin (docs/oblique.md §6).

use super::ball::BallArgs;
use super::oblique::TangentialArgs;
use super::output::{self, given, human, table};
use crate::api::{BallHeader, CourtPace};
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::io::Write;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CourtFormat {
    Text,
    Json,
}

#[derive(Debug, Clone, Args)]
pub struct CourtArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// The surface's Coulomb friction coefficient μ ≥ 0
    #[arg(long, value_name = "MU", value_parser = super::number::number, allow_hyphen_values = true)]
    pub friction: f64,
    #[command(flatten)]
    pub tangential: TangentialArgs,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: CourtFormat,
}

#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    standard: &'static str,
    friction: f64,
    /// c_t, kg/s: present only when a dashpot was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    tangential_damping: Option<f64>,
    #[serde(flatten)]
    pace: &'a CourtPace,
    /// The ball fired (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    ball_record: crate::api::BallRecord,
}

pub fn run(a: &CourtArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    super::ball::check_overrides(&a.ball.set, None, None)?;
    let ball = a.ball.resolve(None)?;
    let pace = ball.court_pace_damped(
        a.friction,
        a.tangential.tangential_stiffness,
        a.tangential.inertia_factor,
        a.tangential.tangential_damping,
    )?;
    match a.format {
        CourtFormat::Json => output::json(
            out,
            &Report {
                ball: ball.header(),
                standard: "itf-court-pace",
                friction: a.friction,
                tangential_damping: a.tangential.tangential_damping,
                pace: &pace,
                ball_record: ball.record_json(),
            },
        )?,
        CourtFormat::Text => {
            writeln!(
                out,
                "{}: ITF court pace (CS 01/02: 30 m/s at 16°, no spin), μ = {}",
                ball.label(),
                given(a.friction, 6)
            )?;
            if let Some(line) = ball.overrides_line() {
                writeln!(out, "{line}")?;
            }
            let row = |k: &str, v: String| vec![k.to_string(), v];
            let rows = vec![
                row("court pace rating", human(pace.cpr, 4)),
                row(
                    "category",
                    format!("{} ({})", pace.category, pace.category_name),
                ),
                row("apparent friction", human(pace.apparent_friction, 5)),
                row("normal COR e_y", human(pace.cor_normal, 5)),
                row("outgoing speed (m/s)", human(pace.v_out, 5)),
                row("outgoing angle (°)", human(pace.angle_out_deg, 5)),
                row("outgoing spin (rad/s)", human(pace.spin_out, 5)),
            ];
            table(out, "", &rows)?;
            writeln!(out)?;
            writeln!(
                out,
                "CPR = 100(1 − μ_app) + 150(0.81 − e_y); categories 1 slow ≤ 29, 2 medium-slow \
                 30–34, 3 medium 35–39, 4 medium-fast 40–44, 5 fast ≥ 45"
            )?;
            output::warning_lines(out, &pace.warnings)?;
        }
    }
    Ok(())
}
