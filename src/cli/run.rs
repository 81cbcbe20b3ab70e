//! `bouncelab run`: one impact, as a text table, one JSON object or CSV.

use super::ball::{self, BallArgs, BallHeader, ChosenBall};
use super::output::{self, csv_row, num, opt_num};
use crate::model::contact::ContactLaw;
use crate::solver::{EnergyBudget, ImpactResponse, Method, SolveOptions, simulate};
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::io::Write;

/// History samples by default, and at most.
const SAMPLES: usize = 400;
const MAX_SAMPLES: usize = 100_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RunFormat {
    Text,
    Json,
    Csv,
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
    pub format: RunFormat,
    /// Also print F(t), z(t), α(t), evenly sampled over the contact
    #[arg(long)]
    pub history: bool,
    /// Number of history samples
    #[arg(long, value_name = "N", default_value_t = SAMPLES, requires = "history")]
    pub samples: usize,
}

pub fn run(args: &RunArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if args.normalized && args.ball.set.any() {
        anyhow::bail!(
            "--normalized runs m = K_p = v0 = 1: --k-p, --damping, --k-r and --z-p do not apply"
        );
    }
    ball::check_overrides(&args.ball.set, args.lambda, args.zeta)?;
    let ball = if args.normalized {
        let law = args.ball.law.map_or(ContactLaw::Linear, ContactLaw::from);
        ball::normalized(
            args.lambda.unwrap_or(1.0),
            args.zeta.unwrap_or(0.1),
            args.zp_bar,
            law,
        )?
    } else {
        let mut b = args.ball.resolve(args.v0)?;
        ball::set_lambda_zeta(&mut b.ball.params, args.lambda, args.zeta)?;
        b
    };
    if args.history && !(2..=MAX_SAMPLES).contains(&args.samples) {
        anyhow::bail!(
            "invalid samples: {} (must lie in 2 … {MAX_SAMPLES})",
            args.samples
        );
    }
    let samples = if args.history { args.samples } else { 0 };
    let opts = SolveOptions::default().with_samples(samples).with_energy();
    let r = simulate(&ball.ball.params, ball.ball.law, &opts)?;
    match args.format {
        RunFormat::Json => output::json(out, &report(&ball, &r, args.history))?,
        RunFormat::Csv if args.history => history_csv(out, &r)?,
        RunFormat::Csv => summary_csv(out, &ball, &r)?,
        RunFormat::Text => super::run_text::write(out, &ball, &r, args.history)?,
    }
    Ok(())
}

#[derive(Serialize)]
struct Measured {
    v0: f64,
    cor: Option<f64>,
    max_force: Option<f64>,
    contact_time: Option<f64>,
}

#[derive(Serialize)]
struct Energy {
    #[serde(flatten)]
    budget: EnergyBudget,
    relative_residual: f64,
}

/// The JSON object of one run, SI units; `null` for infinite z_p or c and for the contact time
/// of a ball that does not rebound.
#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    method: Method,
    mass: f64,
    k_p: f64,
    k_r: f64,
    c: f64,
    z_p: f64,
    k_h: f64,
    v0: f64,
    lambda: f64,
    zeta: f64,
    zp_bar: f64,
    cor: f64,
    rebound: bool,
    max_force: f64,
    contact_time: Option<f64>,
    max_indentation: f64,
    permanent_indentation: f64,
    max_force_normalized: f64,
    contact_time_normalized: Option<f64>,
    measured: Option<Measured>,
    energy: Option<Energy>,
    #[serde(skip_serializing_if = "Option::is_none")]
    t: Option<&'a [f64]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    force: Option<&'a [f64]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    indentation: Option<&'a [f64]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    displacement: Option<&'a [f64]>,
}

fn report<'a>(b: &'a ChosenBall, r: &'a ImpactResponse, history: bool) -> Report<'a> {
    let p = &b.ball.params;
    let n = &r.normalized;
    let h = |v: &'a Vec<f64>| history.then_some(v.as_slice());
    Report {
        ball: b.header(),
        method: r.method,
        mass: p.mass,
        k_p: p.k_p,
        k_r: p.k_r,
        c: p.damping,
        z_p: p.z_p,
        k_h: p.k_h,
        v0: p.v0,
        lambda: n.lambda,
        zeta: n.zeta,
        zp_bar: n.zp_bar,
        cor: r.cor,
        rebound: r.rebound,
        max_force: r.max_force,
        contact_time: r.contact_time,
        max_indentation: r.max_indentation,
        permanent_indentation: r.permanent_indentation,
        max_force_normalized: r.max_force_normalized,
        contact_time_normalized: r.contact_time_normalized,
        measured: b.ball.measured.as_ref().map(|m| Measured {
            v0: m.v0,
            cor: m.cor,
            max_force: m.max_force,
            contact_time: m.contact_time,
        }),
        energy: r.energy.map(|budget| Energy {
            budget,
            relative_residual: budget.relative_residual(),
        }),
        t: h(&r.history.t),
        force: h(&r.history.force),
        indentation: h(&r.history.indentation),
        displacement: h(&r.history.displacement),
    }
}

/// Columns of `run --format csv` (one row).
pub const SUMMARY_COLUMNS: [&str; 28] = [
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
];

fn summary_csv(out: &mut dyn Write, b: &ChosenBall, r: &ImpactResponse) -> std::io::Result<()> {
    let p = &b.ball.params;
    let n = &r.normalized;
    let e = r.energy;
    let en = |f: fn(&EnergyBudget) -> f64| opt_num(e.as_ref().map(f));
    let method = match r.method {
        Method::Exact => "exact",
        Method::Numeric => "numeric",
    };
    csv_row(out, &SUMMARY_COLUMNS)?;
    csv_row(
        out,
        &[
            b.preset().unwrap_or_default().to_string(),
            b.origin.clone(),
            b.ball.source.clone(),
            r.law.name().into(),
            method.into(),
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
        ],
    )
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
