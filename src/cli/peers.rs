//! `bouncelab peers`: the field's contact models calibrated to one ball's COR, beside the
//! Christoforou–Yigit model, as text, JSON or CSV; `--export CODE` writes the parameters for
//! a DEM or multibody code (docs/peers.md).

mod case;
mod code_export;
mod pair;
mod write;

use super::ball::BallArgs;
use super::output::{self, TextJsonCsv, num};
use crate::analysis::fit::{FitError, fit_k_r};
use crate::api::Ball;
use crate::model::params::ImpactParams;
use crate::peers::PeerBall;
use crate::peers::calibrate::{self, Calibrated};
use crate::solver::{SolveOptions, simulate};
use clap::{Args, ValueEnum};
use pair::{Pair, pair_ball};
use serde::Serialize;
use std::io::Write;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ExportArg {
    Lammps,
    Liggghts,
    Chrono,
    Yade,
    Mujoco,
    Json,
}

/// Where the target COR comes from when `--cor` is not given.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TargetArg {
    /// The preset's measured COR
    Measured,
    /// The Christoforou–Yigit model's COR for the same ball at v0
    ChristoforouYigit,
    /// The Christoforou–Yigit COR-vs-speed curve (v0/4 … 4 v0), in least squares
    ChristoforouYigitCurve,
}

/// What `--target` names: where the target COR comes from, or — any other word — the preset
/// of a pair's partner, as `--pair` does (issue 33 calls it `peers --target PRESET`). The three
/// sources' names come first: a preset named like one of them is reached with `--pair`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TargetChoice {
    Source(TargetArg),
    Pair(String),
}

/// `--target`'s parser: a source's name (as clap's value enum reads it), else a preset's.
fn target_or_pair(s: &str) -> Result<TargetChoice, String> {
    match TargetArg::from_str(s, true) {
        Ok(t) => Ok(TargetChoice::Source(t)),
        Err(_) if s.trim().is_empty() => Err("a source or a preset's name is needed".into()),
        Err(_) => Ok(TargetChoice::Pair(s.to_string())),
    }
}

#[derive(Debug, Clone, Args)]
pub struct PeersArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// COR to calibrate to, in [0, 1] [default: the preset's measured COR]
    #[arg(long, value_name = "E", conflicts_with = "target",
          value_parser = super::number::number, allow_hyphen_values = true)]
    pub cor: Option<f64>,
    /// Impact speed v0 (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Target when --cor is not given: measured, christoforou-yigit, christoforou-yigit-curve;
    /// or another preset's name, the partner of a pair (as --pair PRESET, issue 33's name)
    /// [default: measured; with --export, christoforou-yigit at the bounce's normal speed]
    #[arg(long, value_name = "TARGET", value_parser = target_or_pair)]
    pub target: Option<TargetChoice>,
    /// Calibrate for the pair with another preset ball (docs/targets.md): m_eff = m1 m2/(m1 +
    /// m2), R_eff = R1 R2/(R1 + R2), v0 the closing speed; the target COR is the model's for
    /// the pair, both balls deforming (as collide --target-preset), unless --cor or another
    /// --target is given
    #[arg(long, value_name = "PRESET")]
    pub pair: Option<String>,
    /// Output format of the comparison (not with --export, whose CODE is the format; `--export
    /// json` is the JSON one)
    #[arg(long, value_enum, default_value = "text", conflicts_with = "export")]
    pub format: TextJsonCsv,
    /// Write the exactly calibrated parameters for a code instead of the comparison
    #[arg(long, value_enum, value_name = "CODE")]
    pub export: Option<ExportArg>,
    /// With --export lammps|mujoco|json: add the oblique impacts' tangential model with this
    /// Coulomb friction μ (docs/oblique.md §10)
    #[arg(long, value_name = "MU", requires = "export", value_parser = super::number::number, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// The tangential spring K_t with --friction [default: Mindlin's 2(1 − ν)/(2 − ν) K_p]
    #[arg(long, value_name = "N/m", requires = "friction", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_stiffness: Option<f64>,
    /// The tangential dashpot c_t (kg/s) with --friction, as LAMMPS's x_gamma_t = c_t/η
    /// [default: none]
    #[arg(long, value_name = "KG_PER_S", requires = "friction", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_damping: Option<f64>,
    /// With --export: the bounce is oblique, at this angle to the surface (degrees, 0 < θ ≤
    /// 90); the normal model is calibrated at the normal speed v·sinθ (v: --v0), and the
    /// snippet gives bouncelab's answer for that bounce (docs/peers.md §5)
    #[arg(long, value_name = "DEG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub angle: Option<f64>,
    /// With --angle: the incoming spin ω of that bounce, rad/s (> 0 topspin) [default: 0]
    #[arg(long, value_name = "RAD_PER_S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin: Option<f64>,
}

/// One row of the comparison (the JSON keys of issue 19, then `k_r` for the
/// Christoforou–Yigit row).
#[derive(Debug, Clone, Serialize)]
struct Row {
    model: &'static str,
    rule: &'static str,
    stiffness: f64,
    damping: f64,
    cor: f64,
    max_force: f64,
    contact_time: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    k_r: Option<f64>,
}

#[derive(Serialize)]
struct Report<'a> {
    mass: f64,
    v0: f64,
    target_cor: f64,
    models: &'a [Row],
    preset: Option<&'a str>,
    radius: f64,
    target_source: &'static str,
    /// What the caller should know about the ball at v0 ([`Ball::warnings`]).
    warnings: Vec<String>,
    /// With --pair only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pair: Option<Pair>,
    /// The ball calibrated to (docs/cli.md, "The ball object").
    ball: crate::api::BallRecord,
}

/// The JSON `surface_note` of `peers --pair`, whose `surface` is `null`.
const PAIR_NO_SURFACE: &str = "a pair: the ball met the other ball (`pair`), no surface; the models are calibrated to the pair's COR";

impl PeersArgs {
    /// The partner of the pair, by `--pair` or `--target PRESET`; both at once is refused.
    fn pair_name(&self) -> anyhow::Result<Option<&str>> {
        match (&self.pair, &self.target) {
            (Some(p), Some(TargetChoice::Pair(t))) if p != t => {
                anyhow::bail!("target: --target {t} and --pair {p} name two partners; give one")
            }
            (Some(p), _) | (None, Some(TargetChoice::Pair(p))) => Ok(Some(p)),
            (None, Some(TargetChoice::Source(_)) | None) => Ok(None),
        }
    }

    /// Where the target COR comes from: a pair named by `--target` takes the default, which
    /// is the measured COR for the comparison and, for an export, the model's COR at the
    /// bounce's normal speed: the export is bouncelab's model of that bounce, and the answer
    /// its snippet states is the model's (issue 52 item 8; a COR measured at 6.906 m/s gave
    /// the code e_y 0.7709 where bouncelab answers 0.7610 at 30 m/s and 16°).
    fn source(&self) -> TargetArg {
        match self.target {
            Some(TargetChoice::Source(t)) => t,
            _ if self.export.is_some() => TargetArg::ChristoforouYigit,
            _ => TargetArg::Measured,
        }
    }
}

/// The ball `peers` calibrates, and the COR it is calibrated to.
struct Peered {
    /// The ball at v0, whose bounce an export states.
    whole: Ball,
    /// The bounce an export is for ([`case::asked`]).
    bounce: (f64, f64, f64),
    /// The ball calibrated: at the bounce's normal speed, or the pair's reduced ball.
    b: Ball,
    pair: Option<Pair>,
    radius: f64,
    ball: PeerBall,
    target: f64,
    /// Where the target COR came from.
    source: &'static str,
}

pub fn run(a: &PeersArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    // clap's `requires = "export"` is not held once `--format` (which conflicts with --export)
    // is given: `--format json --friction 0.5` ignored the friction (tests/peers_flags.rs)
    if a.export.is_none() && a.friction.is_some() {
        anyhow::bail!(
            "--friction adds the tangential model to an export: give --export lammps|mujoco|json"
        );
    }
    let p = peered(a)?;
    match a.export {
        Some(code) => code_export::write(a, out, code, &p),
        None => compare(a, out, p),
    }
}

/// The ball `a` asks for and its target COR.
fn peered(a: &PeersArgs) -> anyhow::Result<Peered> {
    let whole = a.ball.resolve(a.v0)?;
    // the bounce an export is for: its normal model at the normal speed v·sinθ (docs/peers.md
    // §5, "The case asked"); head-on without --angle, at v
    let bounce = case::asked(a, whole.params.v0)?;
    let b = match a.angle {
        Some(theta) => a.ball.resolve(Some(case::normal_speed(bounce.0, theta)))?,
        None => whole.clone(),
    };
    let (b, pair) = match a.pair_name()? {
        Some(name) => pair_ball(a, b, name)?,
        None => (b, None),
    };
    let radius = b.measured.as_ref().map_or(f64::NAN, |m| m.radius);
    let ball = PeerBall::from_params(&b.params, radius);
    let (target, source) = target(a, &b, pair.as_ref())?;
    Ok(Peered {
        whole,
        bounce,
        b,
        pair,
        radius,
        ball,
        target,
        source,
    })
}

/// The peers' calibrations beside the Christoforou–Yigit model, as text, JSON or CSV.
fn compare(a: &PeersArgs, out: &mut dyn Write, p: Peered) -> anyhow::Result<()> {
    let Peered {
        b,
        pair,
        radius,
        ball,
        target,
        source,
        ..
    } = p;
    let warnings = ball_warnings(&b, pair.as_ref(), source)?;
    let mut rows: Vec<Row> = calibrate::compare(&ball, target, 0)?
        .iter()
        .map(|c| peer_row(&ball, c))
        .collect();
    rows.push(christoforou_yigit_row(&b, target)?);
    let report = Report {
        mass: ball.mass,
        v0: ball.v0,
        target_cor: target,
        models: &rows,
        preset: b.name.as_deref(),
        radius,
        target_source: source,
        warnings,
        pair,
        ball: b.record_json(),
    };
    match a.format {
        // the COR is the ball's on the rigid plate, or the pair's (docs/cli.md, "The surface
        // object")
        TextJsonCsv::Json => {
            let met = match report.pair {
                None => output::Met::RigidPlate,
                Some(_) => output::Met::NoSurface(PAIR_NO_SURFACE),
            };
            output::json_on(out, &report, met, &b.conditions)?
        }
        // the rows are the peers' calibrations, not the ball's answer: its warnings on stderr,
        // as beside `run --history`'s CSV
        TextJsonCsv::Csv => {
            write::csv(out, &rows)?;
            output::warnings_to_stderr(&report.warnings);
        }
        TextJsonCsv::Text => {
            write::text(out, &b, &ball, &report)?;
            output::warning_lines(out, &report.warnings)?;
        }
    }
    Ok(())
}

/// The ball's warnings at v0, and the measured COR's when it is the target. A pair's reduced
/// ball is no ball that was measured: its warnings (one ball at the closing speed against one
/// record, `peers --pair tennis --v0 30` checked 30 m/s; a reach against R_eff) give way to
/// `collide --target-preset`'s (tests/cli/issue52_trial.rs,
/// `peers_pair_warns_as_collide_for_both_balls`).
fn ball_warnings(b: &Ball, pair: Option<&Pair>, source: &str) -> anyhow::Result<Vec<String>> {
    let mut w = match pair {
        Some(p) => p.warnings.clone(),
        None => b.warnings(&b.impact()?),
    };
    if source == "measured" {
        w.extend(b.measured_cor_warning());
        w.extend(b.measurement_withheld().map(|why| {
            format!("outside calibration: the target COR is the record's, not this ball's: {why}")
        }));
    }
    Ok(w)
}

/// The target COR and where it came from.
fn target(a: &PeersArgs, b: &Ball, pair: Option<&Pair>) -> anyhow::Result<(f64, &'static str)> {
    if let Some(e) = a.cor {
        if !(e.is_finite() && (0.0..=1.0).contains(&e)) {
            anyhow::bail!("invalid cor: {} (a COR lies in [0, 1])", num(e));
        }
        return Ok((e, "given"));
    }
    let (p, law) = (&b.params, b.law);
    // a measured COR is the ball's against a wall, not the pair's: a pair takes the model's,
    // both balls deforming (as `collide --target-preset`)
    let which = match (pair, a.source()) {
        (Some(pair), TargetArg::Measured | TargetArg::ChristoforouYigit) => {
            return Ok((pair.cor, "christoforou-yigit"));
        }
        // a ball the conditions or an override changed is not the one whose COR was measured:
        // by default the model's COR for the ball as run, an export's target
        // (a_changed_ball_is_calibrated_to_its_own_cor); `--target measured` keeps the record's
        (None, TargetArg::Measured) if a.target.is_none() && b.measurement_withheld().is_some() => {
            TargetArg::ChristoforouYigit
        }
        (_, which) => which,
    };
    match which {
        TargetArg::Measured => b
            .measured
            .as_ref()
            .and_then(|m| m.cor)
            .map(|e| (e, "measured"))
            .ok_or_else(|| {
                anyhow::anyhow!("cor: the preset has no measured COR; give --cor E or --target")
            }),
        TargetArg::ChristoforouYigit => Ok((
            calibrate::christoforou_yigit_cor(p, law, p.v0)?,
            "christoforou-yigit",
        )),
        TargetArg::ChristoforouYigitCurve => {
            let speeds: Vec<f64> = (0..9)
                .map(|i| p.v0 * 4f64.powf((i as f64 - 4.0) / 4.0))
                .collect();
            let table = calibrate::christoforou_yigit_curve(p, law, &speeds)?;
            // none of the peers' COR depends on v0: the least-squares COR is the mean
            let mean = table.iter().map(|t| t.1).sum::<f64>() / table.len() as f64;
            Ok((mean, "christoforou-yigit-curve"))
        }
    }
}

fn peer_row(ball: &PeerBall, c: &Calibrated) -> Row {
    Row {
        model: c.model.name(),
        rule: c.rule.name(),
        stiffness: ball.stiffness(c.model),
        damping: c.damping,
        cor: c.response.cor,
        max_force: c.response.max_force,
        contact_time: c.response.contact_time,
        k_r: None,
    }
}

/// The Christoforou–Yigit model of the same ball: K_r fitted to the target (rule `exact`,
/// docs/model.md §4), or, when no K_r reaches it at this ζ, the preset's own K_r (rule `preset`).
fn christoforou_yigit_row(b: &Ball, target: f64) -> anyhow::Result<Row> {
    let (p, law) = (b.params, b.law);
    let (params, rule) = match fit_k_r(&p, law, target) {
        Ok(f) => (ImpactParams { k_r: f.k_r, ..p }, "exact"),
        Err(FitError::OutOfReach { .. }) => (p, "preset"),
        Err(e) => return Err(e.into()),
    };
    let r = simulate(&params, law, &SolveOptions::default())?;
    Ok(Row {
        model: "christoforou-yigit",
        rule,
        stiffness: params.k_p,
        damping: params.damping,
        cor: r.cor,
        max_force: r.max_force,
        contact_time: r.contact_time,
        k_r: Some(params.k_r),
    })
}
