//! `bouncelab court`: the ITF Court Pace Rating of a surface (ITF CS 01/02) from the oblique
//! impact of the ball at 30 m/s and 16° without spin (docs/oblique.md §6).

use super::ball::BallArgs;
use super::oblique::BounceSurfaceArgs;
use super::output::{self, TextJson, given, human, table};
use super::surface::SurfaceUsed;
use crate::api::{BallHeader, CourtCalibration, CourtPace};
use crate::oblique::court::ITF_COURT_PACE;
use clap::Args;
use serde::Serialize;
use std::io::Write;

#[derive(Debug, Clone, Args)]
#[command(mut_arg("friction", |a| {
    a.help(
        "The surface's Coulomb friction coefficient μ ≥ 0 [default: the surface's; required \
         when it has none]",
    )
}))]
pub struct CourtArgs {
    /// The ball [default: tennis, the ball of the ITF court pace test]
    #[command(flatten)]
    pub ball: BallArgs,
    /// `oblique`'s --friction (its help names the court's surface: the `mut_arg` above), the
    /// tangential flags and --surface*
    #[command(flatten)]
    pub bounce: BounceSurfaceArgs,
    /// Calibrate the court to this measured vertical COR e at the ITF test: c_s solved, K_s
    /// held (--surface-stiffness, else the ball's K_p: an assumption); with --friction, the
    /// measured (μ, e) pair
    #[arg(long, value_name = "E", value_parser = super::number::number, allow_hyphen_values = true, conflicts_with = "surface_damping")]
    pub surface_cor: Option<f64>,
    /// Calibrate the court to measured ITF test bounces (CSV: v_in, angle_in, v_out,
    /// angle_out in m/s and degrees): their mean μ_app and e, as --friction and --surface-cor
    #[arg(long, value_name = "FILE", conflicts_with_all = ["surface_cor", "friction", "surface_damping"])]
    pub fit: Option<std::path::PathBuf>,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
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
    /// The court it ran on (docs/surfaces.md).
    surface: &'a SurfaceUsed,
    /// The calibration to a measured e, when asked (`--surface-cor`, `--fit`).
    #[serde(skip_serializing_if = "Option::is_none")]
    calibration: Option<&'a CourtCalibration>,
    /// The measured bounces' numbers, with `--fit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    measured: Option<&'a Measured>,
    /// What μ_app and e were computed on.
    computed_on: String,
    /// The ball fired (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    ball_record: crate::api::BallRecord,
}

/// `court --fit FILE`: the measured bounces' means and the ITF's rating of them.
type Measured = crate::api::CourtMeasured;

/// The measured means of `--fit FILE`.
fn measured(path: &std::path::Path) -> anyhow::Result<Measured> {
    let rows = super::measured_file::court(path)?;
    Ok(crate::api::court_measured(
        super::measured_file::label(path),
        &rows,
    ))
}

pub fn run(a: &CourtArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve_for_standard(ITF_COURT_PACE.balls[0])?;
    let measured = a.fit.as_deref().map(measured).transpose()?;
    let friction = measured
        .as_ref()
        .map(|m| m.apparent_friction)
        .or(a.bounce.friction);
    let (mut surface, friction) =
        super::oblique::surface_of(&a.bounce.surface, friction, &a.bounce.tangential)?;
    let target_cor = measured.as_ref().map(|m| m.cor_normal).or(a.surface_cor);
    let calibration = match target_cor {
        Some(e) => {
            let c = ball.calibrate_court(
                e,
                a.bounce.surface.surface_stiffness,
                surface.mechanics.mass,
            )?;
            let how = match a.fit.as_deref() {
                Some(p) => format!("court --fit {}", p.display()),
                None => "court --surface-cor".to_string(),
            };
            surface.calibrated(&c, &how);
            Some(c)
        }
        None => None,
    };
    let (pace, computed_on) =
        ball.court_pace_on_surface(friction, a.bounce.tangential.inertia_factor, &surface)?;
    match a.format {
        TextJson::Json => output::json_stated(
            out,
            &Report {
                ball: ball.header(),
                standard: ITF_COURT_PACE.name,
                friction,
                tangential_damping: surface.mechanics.tangential_damping,
                pace: &pace,
                surface: &surface,
                calibration: calibration.as_ref(),
                measured: measured.as_ref(),
                computed_on,
                ball_record: ball.record_json(),
            },
            &ball.conditions,
        )?,
        TextJson::Text => text(
            out,
            &ball,
            &pace,
            (friction, &surface),
            &report_of(&measured, &calibration),
        )?,
    }
    Ok(())
}

/// What `court --fit` and `--surface-cor` add to the text: the measured and the calibration.
fn report_of<'a>(
    m: &'a Option<Measured>,
    c: &'a Option<CourtCalibration>,
) -> (Option<&'a Measured>, Option<&'a CourtCalibration>) {
    (m.as_ref(), c.as_ref())
}

/// `court`'s text: the header and the surface, the rating's table, the formula, the measured
/// bounces and the calibration, the warnings.
fn text(
    out: &mut dyn Write,
    ball: &crate::api::Ball,
    pace: &CourtPace,
    (friction, surface): (f64, &SurfaceUsed),
    (measured, calibration): &(Option<&Measured>, Option<&CourtCalibration>),
) -> std::io::Result<()> {
    writeln!(
        out,
        "{}: ITF court pace (CS 01/02: 30 m/s at 16°, no spin), μ = {}",
        ball.label(),
        given(friction, 6)
    )?;
    output::ball_lines(out, ball, output::Met::Surface(surface))?;
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
    if let Some(m) = &measured {
        writeln!(
            out,
            "measured ({}, {}): μ_app {}, e {}, CPR {}",
            m.file,
            crate::text::counted(m.bounces, "bounce"),
            human(m.apparent_friction, 5),
            human(m.cor_normal, 5),
            human(m.cpr, 4)
        )?;
    }
    if let Some(c) = &calibration {
        writeln!(
            out,
            "calibrated to e = {}: K_s {} N/m, c_s {} kg/s (e reachable {}–{}); {}",
            given(c.surface_cor, 6),
            human(c.stiffness, 5),
            human(c.damping, 6),
            human(c.reachable[0], 4),
            human(c.reachable[1], 4),
            c.assumption
        )?;
    }
    output::warning_lines(out, &pace.warnings)
}
