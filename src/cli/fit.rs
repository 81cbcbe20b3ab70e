//! `bouncelab fit`: the recoil spring K_r (and λ) that makes the model's COR equal a measured
//! one, at the ball's ζ, z_p and v0 (MODEL.md §4).

use super::ball::{BallArgs, BallHeader};
use super::output::{self, given, human, table};
use crate::analysis::fit::fit_k_r;
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::io::Write;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FitFormat {
    Text,
    Json,
}

#[derive(Debug, Clone, Args)]
pub struct FitArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Measured coefficient of restitution to match, in [0, 1]
    #[arg(long, value_name = "E", value_parser = super::number::number, allow_hyphen_values = true)]
    pub cor: f64,
    /// Impact speed v0 (m/s) the COR was measured at [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: FitFormat,
}

#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    v0: f64,
    target_cor: f64,
    k_r: f64,
    lambda: f64,
    zeta: f64,
    cor: f64,
    k_p: f64,
    preset_k_r: f64,
    preset_lambda: f64,
}

pub fn run(a: &FitArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let b = a.ball.resolve(a.v0)?;
    let f = fit_k_r(&b.ball.params, b.ball.law, a.cor)?;
    let p = &b.ball.params;
    let r = Report {
        ball: b.header(),
        v0: p.v0,
        target_cor: a.cor,
        k_r: f.k_r,
        lambda: f.lambda,
        zeta: f.zeta,
        cor: f.cor,
        k_p: p.k_p,
        preset_k_r: p.k_r,
        preset_lambda: p.k_r / p.k_p,
    };
    match a.format {
        FitFormat::Json => output::json(out, &r)?,
        FitFormat::Text => {
            writeln!(out, "{}, {} law", b.label(), r.ball.law)?;
            writeln!(
                out,
                "fitting K_r at v0 = {} m/s, holding m, K_p, c (ζ = {}) and z_p",
                given(r.v0, 6),
                human(r.zeta, 4)
            )?;
            writeln!(out)?;
            let rows = vec![
                vec!["target COR".into(), given(r.target_cor, 6)],
                vec!["fitted K_r".into(), format!("{} N/m", human(r.k_r, 5))],
                vec!["fitted λ = K_r/K_p".into(), human(r.lambda, 5)],
                vec!["model COR at the fit".into(), human(r.cor, 6)],
                vec![
                    "preset's K_r".into(),
                    format!(
                        "{} N/m (λ = {})",
                        human(r.preset_k_r, 5),
                        human(r.preset_lambda, 5)
                    ),
                ],
            ];
            table(out, "  ", &rows)?;
        }
    }
    Ok(())
}
