//! `bouncelab shot`: a ball launched, its flight with drag and Magnus lift, its bounces on a
//! surface by `oblique`, and where it is at the end (docs/flight.md): text, one JSON object
//! or CSV, and the side view as SVG.

use super::ball::BallArgs;
use super::oblique::BounceSurfaceArgs;
use super::output::{self, TextJsonCsv, csv_row, given, num, table};
use super::outputs::{check as check_writable, report_then_commit};
use super::shot_after::{flag_named, past_bounce};
use super::surface::SurfaceUsed;
use crate::api::{Ball, BallHeader, ShotReport, ShotSpec};
use crate::atomic::Outputs;
use crate::figure::svg;
use crate::flight::{Ends, Launch};
use clap::Args;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

/// Samples of the path drawn by --svg-out when --samples does not say.
const FIGURE_SAMPLES: usize = 400;

#[derive(Debug, Clone, Args)]
pub struct ShotArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Height of the ball's centre at launch, m (at least its radius)
    #[arg(long, value_name = "H", value_parser = super::number::number, allow_hyphen_values = true)]
    pub height: f64,
    /// Launch speed |v|, m/s
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub speed: f64,
    /// Launch angle above the horizontal, degrees (negative: downward), −90 … 90
    #[arg(long, value_name = "DEG", default_value_t = 0.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub elevation: f64,
    /// Spin ω, rad/s (> 0 topspin, which pushes a ball moving forward down)
    #[arg(long, value_name = "RAD_PER_S", default_value_t = 0.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin: f64,
    #[command(flatten)]
    pub bounce: BounceSurfaceArgs,
    /// Bounces before the shot may end on the surface (0 … 100)
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub bounces: usize,
    /// End where the ball reaches this x, m from the launch
    #[arg(long, value_name = "D", value_parser = super::number::number, allow_hyphen_values = true)]
    pub distance: Option<f64>,
    /// End at this time, s after the launch
    #[arg(long, value_name = "T", value_parser = super::number::number, allow_hyphen_values = true)]
    pub time: Option<f64>,
    /// End D m (along x) past the last of the --bounces bounces: where the ball is a metre
    /// after it bounces is --after-bounce 1
    #[arg(long, value_name = "D", conflicts_with = "distance", value_parser = super::number::number, allow_hyphen_values = true)]
    pub after_bounce: Option<f64>,
    /// Air density ρ, kg/m³ (0: vacuum)
    #[arg(long, value_name = "RHO", default_value_t = crate::drop::flight::AIR_DENSITY, value_parser = super::number::number, allow_hyphen_values = true)]
    pub air_density: f64,
    /// Fixed drag coefficient C_D [default: the ball's published C_D(Re)]
    #[arg(long, value_name = "CD", value_parser = super::number::number, allow_hyphen_values = true)]
    pub drag_coefficient: Option<f64>,
    /// Fixed lift coefficient C_L while spinning [default: the ball's published C_L(S)]
    #[arg(long, value_name = "CL", value_parser = super::number::number, allow_hyphen_values = true)]
    pub lift_coefficient: Option<f64>,
    /// Spin decay time τ, s: dω/dt = −ω/τ; 0 for none [default: the ball's published decay]
    #[arg(long, value_name = "TAU", value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin_decay: Option<f64>,
    /// A vertical net DISTANCE m from the launch, HEIGHT m high [default height: 0.914, the
    /// tennis net's at the centre]: the answer says whether the ball clears it (the flight is
    /// computed as if it were absent)
    #[arg(long, value_name = "DISTANCE[,HEIGHT]", value_parser = super::shot_net::parse, allow_hyphen_values = true)]
    pub net: Option<crate::api::Net>,
    /// Trajectory samples (t, x, y, vx, vy, spin), evenly spaced in time (2 … 100000)
    #[arg(long, value_name = "N")]
    pub samples: Option<usize>,
    /// Output format (csv: the trajectory with --samples, else one row per bounce)
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJsonCsv,
    /// Write the side view (path, surface, bounces) as SVG
    #[arg(long, value_name = "FILE")]
    pub svg_out: Option<PathBuf>,
    /// Overwrite an existing --svg-out file
    #[arg(long)]
    pub force: bool,
}

impl ShotArgs {
    /// The shot asked for, on `surface` (its μ, K_t and c_t those `oblique` runs with).
    fn spec(&self, surface: &SurfaceUsed, friction: f64) -> ShotSpec {
        ShotSpec {
            launch: Launch {
                height: self.height,
                speed: self.speed,
                elevation_deg: self.elevation,
                spin: self.spin,
            },
            ends: Ends {
                bounces: self.bounces,
                distance: self.distance,
                time: self.time,
            },
            friction,
            tangential_stiffness: surface.mechanics.tangential_stiffness,
            inertia_factor: self.bounce.tangential.inertia_factor,
            tangential_damping: surface.mechanics.tangential_damping,
            air_density: self.air_density,
            drag_coefficient: self.drag_coefficient,
            lift_coefficient: self.lift_coefficient,
            spin_decay: self.spin_decay,
            samples: self.samples.unwrap_or(0),
            surface: surface.mechanics.target(),
            net: self.net,
        }
    }
}

/// `shot --format json`: the ball, the surface and the answer, then (additive, as
/// `oblique`'s) the ball object and the surface object; `conditions` last (`json_stated`).
#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    radius: f64,
    friction: f64,
    #[serde(flatten)]
    answer: &'a ShotReport,
    /// The ball it ran (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    record: crate::api::BallRecord,
    /// The surface it bounced on (docs/surfaces.md): `--surface` (the rigid plate when not
    /// given) with the shot's μ and tangential flags over its own.
    surface: &'a SurfaceUsed,
}

pub fn run(a: &ShotArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.samples == Some(0) {
        return Err(crate::api::BallError::Samples(0).into());
    }
    let ball = a.ball.resolve(None)?;
    let (surface, friction) = a.bounce.resolve()?;
    let mut spec = a.spec(&surface, friction);
    if let Some(d) = a.after_bounce {
        spec.ends.distance = Some(past_bounce(&ball, &spec, d)?);
    }
    let paths: Vec<&std::path::Path> = a.svg_out.iter().map(PathBuf::as_path).collect();
    check_writable(&paths, a.force)?;
    let mut shot = ball.shot(&spec).map_err(flag_named)?;
    shot.warn_of(&surface);
    let mut files = Outputs::new(a.force);
    if let Some(p) = &a.svg_out {
        let drawn = if shot.trajectory.is_empty() {
            ball.shot(&ShotSpec {
                samples: FIGURE_SAMPLES,
                ..spec
            })?
        } else {
            shot.clone()
        };
        let mut fig =
            crate::figure::shot::side_view(&drawn, ball.radius(), title(&spec), ball.label());
        // what moved from the preset, its record and the plate (its bounces' speeds are the
        // text's and JSON's warnings, each bounce's own)
        fig.push_notes(&ball.moved_notes(Some(&surface), None));
        if let Some(n) = &drawn.net {
            super::shot_net::draw(&mut fig, n);
        }
        files.text(p, &svg::render(&fig)?)?;
    }
    let mut report = Vec::new();
    match a.format {
        TextJsonCsv::Json => output::json_stated(
            &mut report,
            &Report {
                ball: ball.header(),
                radius: ball.radius(),
                friction,
                answer: &shot,
                record: ball.record_json(),
                surface: &surface,
            },
            &ball.conditions,
        )?,
        TextJsonCsv::Csv if !shot.trajectory.is_empty() => trajectory_csv(&mut report, &shot)?,
        TextJsonCsv::Csv => bounces_csv(&mut report, &shot)?,
        TextJsonCsv::Text => text(&mut report, (&ball, &surface), &spec, &shot, a.after_bounce)?,
    }
    report_then_commit(out, &report, files)?;
    if a.format == TextJsonCsv::Csv {
        csv_warnings(&shot);
    }
    Ok(())
}

/// The warnings a shot's CSV has no cell for, on stderr as a time series' (`run --history`),
/// as the text says them ([`ShotReport::warnings`]) where the rows are the trajectory's
/// samples, not the bounces (whose `warnings` column holds them); else the net's, which
/// belongs to no row.
fn csv_warnings(s: &ShotReport) {
    if !s.trajectory.is_empty() {
        output::warnings_to_stderr(&s.warnings());
    } else if let Some(n) = &s.net {
        output::warnings_to_stderr(&n.warnings);
    }
}

/// A CSV header: `columns`, then the net's with `--net`.
fn csv_header(out: &mut dyn Write, columns: &[&str], s: &ShotReport) -> std::io::Result<()> {
    let mut names = columns.to_vec();
    if s.net.is_some() {
        names.extend(super::shot_net::COLUMNS);
    }
    csv_row(out, &names)
}

/// A CSV row: `cells`, then the net's with `--net` (the shot's, on every row).
fn csv_cells(out: &mut dyn Write, mut cells: Vec<String>, s: &ShotReport) -> std::io::Result<()> {
    if let Some(n) = &s.net {
        cells.extend(super::shot_net::cells(n));
    }
    csv_row(out, &cells)
}

fn title(s: &ShotSpec) -> String {
    let l = s.launch;
    format!(
        "shot from {} m at {} m/s, {}°, {} rad/s; μ = {}",
        given(l.height, 4),
        given(l.speed, 4),
        given(l.elevation_deg, 4),
        given(l.spin, 4),
        given(s.friction, 4)
    )
}

/// Columns of `shot --format csv` without --samples (one row per bounce).
pub const BOUNCE_COLUMNS: [&str; 12] = [
    "t",
    "x",
    "v_in",
    "angle_in",
    "spin_in",
    "v_out",
    "angle_out",
    "spin_out",
    "cor_normal",
    "contact_time",
    "slid_throughout",
    "warnings",
];

/// Columns of `shot --format csv --samples N`.
pub const TRAJECTORY_COLUMNS: [&str; 6] = ["t", "x", "y", "vx", "vy", "spin"];

fn bounces_csv(out: &mut dyn Write, s: &ShotReport) -> std::io::Result<()> {
    csv_header(out, &BOUNCE_COLUMNS, s)?;
    for b in &s.bounces {
        let mut row: Vec<String> = [
            b.t,
            b.x,
            b.v_in,
            b.angle_in,
            b.spin_in,
            b.v_out,
            b.angle_out,
            b.spin_out,
            b.cor_normal,
            b.contact_time,
        ]
        .map(num)
        .to_vec();
        row.push(b.slid_throughout.to_string());
        row.push(output::warnings_cell(&b.warnings));
        csv_cells(out, row, s)?;
    }
    Ok(())
}

fn trajectory_csv(out: &mut dyn Write, s: &ShotReport) -> std::io::Result<()> {
    csv_header(out, &TRAJECTORY_COLUMNS, s)?;
    for p in &s.trajectory {
        csv_cells(
            out,
            [p.t, p.x, p.y, p.vx, p.vy, p.spin].map(num).to_vec(),
            s,
        )?;
    }
    Ok(())
}

/// The header's lines after its first, `shot`'s and `mc --shot`'s: the ball's overrides
/// (when any), the surface, the conditions (when stated) and the air.
pub(super) fn ran_lines(
    out: &mut dyn Write,
    ball: &Ball,
    surface: &SurfaceUsed,
    aero: &crate::flight::Aero,
) -> std::io::Result<()> {
    output::ball_lines(out, ball, output::Met::Surface(surface))?;
    writeln!(
        out,
        "air: ρ = {} kg/m³; {}",
        given(aero.air_density, 4),
        aero.source
    )
}

fn text(
    out: &mut dyn Write,
    (ball, surface): (&Ball, &SurfaceUsed),
    spec: &ShotSpec,
    s: &ShotReport,
    after_bounce: Option<f64>,
) -> std::io::Result<()> {
    writeln!(out, "{}: {}", ball.label(), title(spec))?;
    ran_lines(out, ball, surface, &s.aero)?;
    writeln!(out)?;
    let mut rows = vec![
        [
            "bounce",
            "t (s)",
            "x (m)",
            "v in",
            "angle in (°)",
            "spin in",
            "v out",
            "angle out (°)",
            "spin out",
            "slid",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for (k, b) in s.bounces.iter().enumerate() {
        rows.push(vec![
            (k + 1).to_string(),
            given(b.t, 4),
            given(b.x, 5),
            given(b.v_in, 5),
            given(b.angle_in, 4),
            given(b.spin_in, 4),
            given(b.v_out, 5),
            given(b.angle_out, 4),
            given(b.spin_out, 4),
            if b.slid_throughout {
                "throughout"
            } else {
                "then gripped"
            }
            .into(),
        ]);
    }
    if !s.bounces.is_empty() {
        table(out, "", &rows)?;
        writeln!(out, "(speeds m/s, spins rad/s, > 0 topspin)")?;
        writeln!(out)?;
    }
    if let Some(n) = &s.net {
        writeln!(out, "{}", super::shot_net::line(n))?;
    }
    let e = s.end.state;
    let why = match (s.end.reason, after_bounce) {
        (crate::flight::EndReason::Landing, _) => "lands".into(),
        // the distance --after-bounce stood for, past the last bounce (`past_bounce` refused a
        // shot that passes it before)
        (crate::flight::EndReason::Distance, Some(d)) => {
            format!("{} m past bounce {}", given(d, 6), s.bounces.len())
        }
        (crate::flight::EndReason::Distance, None) => "reaches the distance".into(),
        (crate::flight::EndReason::Time, _) => "reaches the time".into(),
    };
    writeln!(
        out,
        "end ({why}): t = {} s, x = {} m, height {} m, speed {} m/s (v_x {}, v_y {}), spin {} rad/s",
        given(e.t, 4),
        given(e.x, 5),
        given(e.y, 4),
        given(s.end.speed, 4),
        given(e.vx, 4),
        given(e.vy, 4),
        given(e.spin, 4)
    )?;
    output::warning_lines(out, &s.warnings())
}
