//! `bouncelab mc --shot`: a shot's tolerances (docs/flight.md §7): the launch of `shot`'s
//! flags spread by `--vary speed=2%,spin=30,elevation=0.5,height=0.01` (speed relative; spin
//! rad/s, elevation degrees, height m, absolute), and the spread of where it lands and how
//! it leaves.

use super::ball::BallArgs;
use super::oblique::TangentialArgs;
use super::output::{self, given, table};
use super::surface::{SurfaceArgs, SurfaceUsed};
use crate::api::{Ball, BallError, ShotMcReport, ShotMcSpec, ShotSpec, ShotSpread};
use crate::flight::{Aero, Ends, Launch};
use clap::Args;
use std::io::Write;

/// `shot`'s flags, for `mc --shot`.
#[derive(Debug, Clone, Args)]
pub struct ShotMcArgs {
    /// Spread a shot's launch (`shot`'s flags below) instead of the ball: --vary takes speed
    /// (relative: 2% or 0.02), spin (rad/s), elevation (degrees), height (m)
    #[arg(long)]
    pub shot: bool,
    /// With --shot: the centre's height at launch, m
    #[arg(long, value_name = "H", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub height: Option<f64>,
    /// With --shot: launch speed, m/s
    #[arg(long, value_name = "V", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub speed: Option<f64>,
    /// With --shot: launch angle above the horizontal, degrees
    #[arg(long, value_name = "DEG", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub elevation: Option<f64>,
    /// With --shot: spin, rad/s (> 0 topspin)
    #[arg(long, value_name = "RAD_PER_S", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin: Option<f64>,
    /// With --shot: the surface's friction μ [default: the surface's; required when it has
    /// none]
    #[arg(long, value_name = "MU", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    #[command(flatten)]
    pub tangential: TangentialArgs,
    /// With --shot: the surface every bounce is on (`shot`'s)
    #[command(flatten)]
    pub surface: SurfaceArgs,
    /// With --shot: bounces before the shot may end on the surface
    #[arg(long, value_name = "N", requires = "shot")]
    pub bounces: Option<usize>,
    /// With --shot: end at this x, m
    #[arg(long, value_name = "D", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub distance: Option<f64>,
    /// With --shot: end at this time, s
    #[arg(long, value_name = "T", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub time: Option<f64>,
    /// With --shot: end D m past each sample's own last bounce (`shot --after-bounce`)
    #[arg(long, value_name = "D", requires = "shot", conflicts_with = "distance", value_parser = super::number::number, allow_hyphen_values = true)]
    pub after_bounce: Option<f64>,
    /// With --shot: a net DISTANCE m from the launch, HEIGHT m high [default height: 0.914];
    /// the fraction of the samples that clear it
    #[arg(long, value_name = "DISTANCE[,HEIGHT]", requires = "shot", value_parser = super::shot_net::parse, allow_hyphen_values = true)]
    pub net: Option<crate::api::Net>,
    /// With --shot: air density, kg/m³
    #[arg(long, value_name = "RHO", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub air_density: Option<f64>,
    /// With --shot: fixed C_D
    #[arg(long, value_name = "CD", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub drag_coefficient: Option<f64>,
    /// With --shot: fixed C_L
    #[arg(long, value_name = "CL", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub lift_coefficient: Option<f64>,
    /// With --shot: spin decay time τ, s (0: none)
    #[arg(long, value_name = "TAU", requires = "shot", value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin_decay: Option<f64>,
}

/// `--vary` of a shot: speed relative, the others absolute.
fn parse_vary(text: &str) -> anyhow::Result<ShotSpread> {
    let mut s = ShotSpread::default();
    for item in text.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        let (name, value) = item
            .split_once('=')
            .ok_or_else(|| anyhow::anyhow!("invalid --vary: '{item}' (NAME=SPREAD)"))?;
        let (v, percent) = match value.trim().strip_suffix('%') {
            Some(p) => (p, true),
            None => (value.trim(), false),
        };
        let x: f64 = crate::text::parse::number(v)
            .map_err(|_| anyhow::anyhow!("invalid --vary: '{item}' (SPREAD is a number)"))?;
        let x = if percent { x / 100.0 } else { x };
        match (name.trim(), percent) {
            ("speed", _) => s.speed = x,
            ("spin", false) => s.spin = x,
            ("elevation", false) => s.elevation = x,
            ("height", false) => s.height = x,
            ("spin" | "elevation" | "height", true) => anyhow::bail!(
                "invalid --vary: '{item}' (with --shot only speed takes a percentage; spin is \
                 rad/s, elevation degrees, height m)"
            ),
            (other, _) => anyhow::bail!(
                "invalid --vary: '{other}' (with --shot: speed, spin, elevation or height)"
            ),
        }
    }
    Ok(s)
}

fn required(x: Option<f64>, flag: &str) -> anyhow::Result<f64> {
    x.ok_or_else(|| anyhow::anyhow!("mc --shot needs {flag}"))
}

/// What `mc` gives `mc --shot`: its own flags' values, and those that do not go with it.
pub struct Mc<'a> {
    /// The ball.
    pub ball: &'a BallArgs,
    /// `--vary`.
    pub vary: &'a str,
    /// `--dist uniform`.
    pub uniform: bool,
    /// `--samples`.
    pub samples: usize,
    /// `--seed`.
    pub seed: u64,
    /// `--format json`.
    pub json: bool,
    /// (given, flag) of the flags refused with `--shot`.
    pub refused: &'a [(bool, &'static str)],
}

pub fn run(s: &ShotMcArgs, a: &Mc<'_>, out: &mut dyn Write) -> anyhow::Result<()> {
    if let Some((_, flag)) = a.refused.iter().find(|(given, _)| *given) {
        anyhow::bail!("{flag} does not go with --shot");
    }
    let uniform = a.uniform;
    let ball = a.ball.resolve(None)?;
    if s.surface.surface.is_none() {
        required(s.friction, "--friction")?;
    }
    let (surface, friction) = super::oblique::surface_of(&s.surface, s.friction, &s.tangential)?;
    let shot = ShotSpec {
        launch: Launch {
            height: required(s.height, "--height")?,
            speed: required(s.speed, "--speed")?,
            elevation_deg: s.elevation.unwrap_or(0.0),
            spin: s.spin.unwrap_or(0.0),
        },
        ends: Ends {
            bounces: s.bounces.unwrap_or(1),
            distance: s.distance,
            time: s.time,
        },
        friction,
        tangential_stiffness: surface.mechanics.tangential_stiffness,
        inertia_factor: s.tangential.inertia_factor,
        tangential_damping: surface.mechanics.tangential_damping,
        air_density: s.air_density.unwrap_or(crate::drop::flight::AIR_DENSITY),
        drag_coefficient: s.drag_coefficient,
        lift_coefficient: s.lift_coefficient,
        spin_decay: s.spin_decay,
        samples: 0,
        surface: surface.mechanics.target(),
        net: s.net,
    };
    if let Some(d) = s.after_bounce {
        // the nominal's refusal, named by the flag as `shot`'s
        super::shot_after::past_bounce(&ball, &shot, d)?;
    }
    let spec = ShotMcSpec {
        shot,
        spread: parse_vary(a.vary)?,
        uniform,
        samples: a.samples,
        seed: a.seed,
        after_bounce: s.after_bounce,
    };
    // the bar on stderr and the Ctrl-C check between blocks (src/cli/budget.rs); a shot
    // (some 17 µs, BENCHMARKS.md) counts as one impact for when the bar shows
    let progress = super::budget::Progress::new(spec.samples as u64, 1.0, "shots");
    let mut shown = 0usize;
    let mut stopped = None;
    let r = ball
        .shot_mc_watched(&spec, &mut |done| {
            progress.advance((done - shown) as u64);
            shown = done;
            match progress.check() {
                Ok(()) => true,
                Err(e) => {
                    stopped = Some(e);
                    false
                }
            }
        })
        .map_err(|e: BallError| anyhow::anyhow!("{e}"))?;
    let Some(mut r) = r else {
        return Err(stopped.unwrap_or_else(|| super::budget::Interrupted.into()));
    };
    // the surface's, as `shot`'s bounces carry it (`SurfaceUsed::warnings`)
    r.warnings.extend(surface.warnings());
    progress.finish();
    let ran = Ran {
        ball: &ball,
        surface: &surface,
        aero: ball.aero(&spec.shot),
    };
    if a.json {
        output::json_stated(out, &json(&ran, &r), &ball.conditions)?
    } else {
        text(out, &ran, &r)?
    }
    Ok(())
}

/// What the shots ran with, named in the answer as `shot` names it (issue 52 item 3, issue
/// 53): the ball, the surface, the air; the conditions follow (`json_stated`).
struct Ran<'a> {
    ball: &'a Ball,
    surface: &'a SurfaceUsed,
    aero: Aero,
}

/// The JSON answer: `mc --shot`'s keys, then (additive) `aero`, `warnings`, the ball and the
/// surface objects; `conditions` last.
fn json(ran: &Ran<'_>, r: &ShotMcReport) -> serde_json::Value {
    let ball = ran.ball;
    let stats: serde_json::Map<String, serde_json::Value> = (r.stats.iter())
        .chain(&r.end_stats)
        .map(|(k, s)| (k.to_string(), serde_json::to_value(s).unwrap_or_default()))
        .collect();
    let mut j = serde_json::json!({
        "preset": ball.name,
        "shot": true,
        "samples": r.samples,
        "seed": r.seed,
        "dist": r.dist,
        "vary": r.vary,
        "failed": r.failed,
        "stats": stats,
        "aero": ran.aero,
        "warnings": r.warnings,
        "ball": ball.record_json(),
        "surface": ran.surface,
    });
    if let Some(map) = j.as_object_mut() {
        if let Some(net) = &r.net {
            map.insert("net".into(), serde_json::to_value(net).unwrap_or_default());
        }
        if let Some(d) = r.after_bounce {
            map.insert("after_bounce".into(), d.into());
        }
    }
    j
}

fn text(out: &mut dyn Write, ran: &Ran<'_>, r: &ShotMcReport) -> std::io::Result<()> {
    let v = r.vary;
    writeln!(
        out,
        "{}: {} shots, seed {}, {} spread: speed {} %, spin {} rad/s, elevation {}°, height {} m",
        ran.ball.label(),
        r.samples,
        r.seed,
        r.dist,
        given(v.speed * 100.0, 4),
        given(v.spin, 4),
        given(v.elevation, 4),
        given(v.height, 4)
    )?;
    super::shot::ran_lines(out, ran.ball, ran.surface, &ran.aero)?;
    if let Some(d) = r.after_bounce {
        writeln!(out, "end: {} m past each shot's own bounce", given(d, 6))?;
    }
    let mut rows = vec![
        ["", "mean", "sd", "2.5 %", "median", "97.5 %"]
            .map(String::from)
            .to_vec(),
    ];
    let names = [
        "landing x (m)",
        "landing t (s)",
        "v out (m/s)",
        "angle out (°)",
        "spin out (rad/s)",
        "end x (m)",
        "end height (m)",
        "end t (s)",
    ];
    for ((_, s), name) in r.stats.iter().chain(&r.end_stats).zip(names) {
        rows.push(vec![
            name.to_string(),
            given(s.mean, 5),
            given(s.sd, 3),
            given(s.q025, 5),
            given(s.q50, 5),
            given(s.q975, 5),
        ]);
    }
    table(out, "", &rows)?;
    if let Some(n) = &r.net {
        writeln!(out, "{}", net_line(n, r.samples - r.failed))?;
    }
    if r.failed > 0 {
        writeln!(
            out,
            "{} samples drawn out of the shot's domain left out",
            r.failed
        )?;
    }
    output::warning_lines(out, &r.warnings)?;
    Ok(())
}

/// The net's line: how many samples clear it, and the clearance's spread.
fn net_line(n: &crate::api::NetMc, answered: usize) -> String {
    let head = format!(
        "net at x = {} m, {} m high: {} % clear it ({} of {answered})",
        given(n.x, 6),
        given(n.height, 4),
        given(100.0 * n.fraction, 3),
        n.cleared
    );
    match &n.clearance {
        Some(c) => format!(
            "{head}; clearance mean {} m, sd {} m, 2.5 % {} m, 97.5 % {} m",
            given(c.mean, 3),
            given(c.sd, 3),
            given(c.q025, 3),
            given(c.q975, 3)
        ),
        None => format!("{head}; none reaches it"),
    }
}
