//! `bouncelab map`: COR, peak force and contact time over a (λ, ζ) grid, with targets, as
//! CSV, JSON or an SVG heat map (docs/map.md). The library does the work ([`crate::map`]);
//! this file reads the options, checks the work limit and writes.

use super::ball::{BallArgs, LawArg, Overrides, PresetChanges, PresetChoice, Size};
use super::output::num;

use crate::map::csv::{csv, header};
use crate::map::{Axis, Map, MapSpec, Param, Quantity, Scale, Targets};
use crate::model::contact::ContactLaw;
use clap::{Args, ValueEnum};
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MapFormat {
    Csv,
    Json,
    Svg,
}

#[derive(Debug, Clone, Args)]
pub struct MapArgs {
    #[command(flatten)]
    pub choice: PresetChoice,
    /// Normalized ball, m = K_p = v0 = 1 (F̄_m and τ_f in the outputs)
    #[arg(long, conflicts_with_all = ["preset", "config", "v0"])]
    pub normalized: bool,
    /// Flattening threshold z̄_p = z_p ω0/v0 of the normalized ball [default: none]
    #[arg(long, value_name = "Z", requires = "normalized",
          value_parser = super::number::number, allow_hyphen_values = true)]
    pub zp_bar: Option<f64>,
    /// Contact law [default: the preset's; linear for the normalized ball]
    #[arg(long, value_enum)]
    pub law: Option<LawArg>,
    /// Impact speed v0 (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    #[command(flatten)]
    pub size: Size,
    /// `--pressure`, `--temperature`, `--inflated-at`, `--after`, `--half-life`.
    #[command(flatten)]
    pub conditions: super::conditions::ConditionsArgs,
    /// λ = K_r/K_p values: FROM:TO:N (log-spaced unless --linear-axes)
    #[arg(long, value_name = "FROM:TO:N", allow_hyphen_values = true)]
    pub lambda: String,
    /// ζ = √(m K_p)/(2c) values: FROM:TO:N (log-spaced unless --linear-axes)
    #[arg(long, value_name = "FROM:TO:N", allow_hyphen_values = true)]
    pub zeta: String,
    /// Space both axes evenly instead of in log10
    #[arg(long)]
    pub linear_axes: bool,
    /// Targets, comma-separated: cor>=E, max_force<=F, contact_time>=T (N and s; F̄_m and τ_f
    /// on the normalized ball); adds the `feasible` column
    #[arg(long = "where", value_name = "CONSTRAINTS")]
    pub targets: Option<String>,
    /// Output format
    #[arg(long, value_enum, default_value = "csv")]
    pub format: MapFormat,
    /// Write to FILE (atomically) instead of stdout; an existing file is refused unless --force
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Overwrite an existing --out file
    #[arg(long, requires = "out")]
    pub force: bool,
}

/// The ball a map runs on, with its name for the outputs.
pub struct MapBall {
    pub spec: MapSpec,
    /// The preset's name; `None` for the normalized ball.
    pub preset: Option<String>,
    /// The preset's own (λ, ζ), marked on the picture.
    pub own: Option<(f64, f64)>,
    pub v0: f64,
    /// The preset's radius, m (NaN for the normalized ball): the map's warnings.
    pub radius: f64,
    /// The grid against the ball's calibration record, said once for the grid: its speed,
    /// and its cells' other λ and ζ ([`crate::Ball::map_calibration_warnings`]; empty
    /// without a record).
    pub calibration: Vec<String>,
    /// The JSON `ball` object: the ball the grid starts from (the cells move its K_r and c).
    pub record: crate::api::BallRecord,
    /// The conditions the ball is at (the JSON `conditions`).
    pub conditions: crate::conditions::Conditions,
    /// What moved from the preset and its record, for the picture's subtitle
    /// ([`crate::Ball::moved_notes`]: overrides, conditions, its speed); empty for the
    /// normalized ball.
    pub notes: Vec<String>,
}

/// The map's ball and axes from the options, each checked (exit 2 naming the flag).
pub fn spec(a: &MapArgs) -> anyhow::Result<MapBall> {
    let scale = if a.linear_axes {
        Scale::Linear
    } else {
        Scale::Log
    };
    let lambda = Axis::parse(Param::Lambda, &a.lambda, scale)?;
    let zeta = Axis::parse(Param::Zeta, &a.zeta, scale)?;
    if a.normalized {
        if a.size.mass.is_some() || a.size.radius.is_some() {
            anyhow::bail!("--normalized runs m = K_p = v0 = 1: --mass and --radius do not apply");
        }
        if !a.conditions.spec().is_empty() {
            anyhow::bail!(
                "--normalized runs m = K_p = v0 = 1: --pressure, --temperature, --inflated-at, \
                 --after and --half-life do not apply"
            );
        }
        let law = a.law.map_or(ContactLaw::Linear, ContactLaw::from);
        let spec = MapSpec::normalized(a.zp_bar, law, lambda, zeta)?
            .with_fast(true)
            .with_fast_laws(true);
        return Ok(MapBall {
            spec,
            preset: None,
            own: None,
            v0: 1.0,
            radius: f64::NAN,
            calibration: Vec::new(),
            record: crate::Ball::normalized(1.0, 1.0, a.zp_bar, law)?.record_json(),
            conditions: crate::api::recorded_conditions(None),
            notes: Vec::new(),
        });
    }
    let args = BallArgs {
        choice: a.choice.clone(),
        changes: PresetChanges {
            law: a.law,
            set: Overrides {
                size: a.size.clone(),
                ..Overrides::default()
            },
            ..PresetChanges::default()
        },
        conditions: a.conditions,
    };
    let b = args.resolve(a.v0)?;
    let spec = MapSpec::dimensional(b.params, b.law, lambda, zeta)?
        .with_fast(true)
        .with_fast_laws(true);
    let n = b.params.normalized();
    Ok(MapBall {
        spec,
        preset: b.name.clone(),
        own: Some((n.lambda, n.zeta)),
        v0: b.params.v0,
        radius: b.radius(),
        calibration: b.map_calibration_warnings(),
        record: b.record_json(),
        notes: b.moved_notes(None, Some((b.params.v0, b.params.v0))),
        conditions: b.conditions,
    })
}

pub fn run(a: &MapArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = spec(a)?;
    let targets = match &a.targets {
        Some(t) => Some(Targets::parse(t)?),
        None => None,
    };
    let s = &ball.spec;
    let what = format!("{} λ values × {} ζ values", s.lambda.n, s.zeta.n);
    super::budget::check(s.cells(), s.law, &what)?;
    // the target before the grid: the one check of every command (cli::outputs)
    if let Some(path) = &a.out {
        super::outputs::check(&[path.as_path()], a.force)?;
    }
    let map = super::budget::map(ball.spec.clone())?;
    let unmet = targets
        .as_ref()
        .and_then(|t| crate::map::unmet_warning(&map, t));
    // the cells read against the radius once, for the warning and the picture's note
    let reach = crate::api::map_reach(&map, ball.radius);
    let warnings: Vec<String> = crate::api::map_indentation_warning(&map, ball.radius)
        .into_iter()
        .chain(reach.as_ref().and_then(crate::api::MapReach::warning))
        .chain(unmet)
        .chain(ball.calibration.clone())
        .collect();
    let text = match a.format {
        MapFormat::Csv => csv(&map, targets.as_ref()),
        MapFormat::Json => json(&map, &ball, targets.as_ref(), &warnings)?,
        MapFormat::Svg => {
            let view = crate::figure::svg_map::View {
                quantity: Quantity::Cor,
                targets: targets.as_ref(),
                own: ball.own,
                title_ball: match &ball.preset {
                    Some(p) => format!("{p} at v0 = {} m/s", num(ball.v0)),
                    None => "normalized ball (m = K_p = v0 = 1)".into(),
                },
                radius_note: reach.as_ref().and_then(crate::api::MapReach::note),
                notes: ball.notes.clone(),
            };
            crate::figure::svg_map::render(&map, &view)?
        }
    };
    // JSON carries them; CSV rows have no place for them, the picture only for its short
    // note (radius_note): stderr
    if a.format != MapFormat::Json {
        super::output::warnings_to_stderr(&warnings);
    }
    match &a.out {
        Some(path) => super::figure::write_file(path, &text, a.force),
        None => Ok(out.write_all(text.as_bytes())?),
    }
}

#[derive(Serialize)]
struct Doc<'a> {
    map: &'static str,
    preset: Option<&'a str>,
    law: &'static str,
    normalized: bool,
    v0: f64,
    lambda: &'a Axis,
    zeta: &'a Axis,
    #[serde(rename = "where")]
    targets: Option<String>,
    columns: Vec<&'a str>,
    /// One array per cell, in the order of `columns` (null where a value does not exist).
    rows: Vec<Vec<serde_json::Value>>,
    /// The iso-lines of each COR target, as [λ, ζ] polylines.
    iso_cor: Vec<IsoLine>,
    /// The boundary of the feasible region, as [λ, ζ] polylines.
    feasible_outline: Vec<Vec<(f64, f64)>>,
    /// What the caller should know ([`crate::api::map_indentation_warning`],
    /// [`crate::api::map_displacement_warning`], [`crate::map::unmet_warning`]); `[]` when
    /// nothing.
    warnings: &'a [String],
    /// The ball the grid starts from (docs/cli.md, "The ball object").
    ball: &'a crate::api::BallRecord,
    /// The surface every cell's ball bounces on: the rigid plate, the model's own (docs/cli.md,
    /// "The surface object").
    surface: crate::api::SurfaceUsed,
    /// The conditions it is at (docs/cli.md, "Conditions").
    conditions: &'a crate::conditions::Conditions,
}

#[derive(Serialize)]
struct IsoLine {
    level: f64,
    lines: Vec<Vec<(f64, f64)>>,
}

fn json(
    map: &Map,
    ball: &MapBall,
    targets: Option<&Targets>,
    warnings: &[String],
) -> anyhow::Result<String> {
    let head = header(map.spec.normalized, targets.is_some());
    let v = |x: f64| {
        if x.is_finite() {
            serde_json::Value::from(x)
        } else {
            serde_json::Value::Null
        }
    };
    let rows = map
        .cells()
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let (i, j) = (k / map.zetas.len(), k % map.zetas.len());
            let c = c.unwrap_or(crate::map::Cell::UNRESOLVED);
            let mut row = vec![v(map.lambdas[i]), v(map.zetas[j]), v(c.cor), v(c.max_force)];
            row.push(c.contact_time.map_or(serde_json::Value::Null, v));
            if let Some(t) = targets {
                row.push(t.holds(&c).into());
            }
            row
        })
        .collect();
    let cor_levels = targets.map_or(Vec::new(), |t| {
        t.0.iter()
            .filter(|k| k.quantity == Quantity::Cor)
            .map(|k| k.value)
            .collect()
    });
    let iso_cor = cor_levels
        .into_iter()
        .map(|level| IsoLine {
            level,
            lines: map
                .contours(Quantity::Cor, level)
                .into_iter()
                .map(|c| c.points)
                .collect(),
        })
        .collect();
    let feasible_outline = targets.map_or(Vec::new(), |t| {
        map.feasible_outline(t)
            .into_iter()
            .map(|c| c.points)
            .collect()
    });
    let doc = Doc {
        map: "lambda-zeta",
        preset: ball.preset.as_deref(),
        law: map.spec.law.name(),
        normalized: map.spec.normalized,
        v0: ball.v0,
        lambda: &map.spec.lambda,
        zeta: &map.spec.zeta,
        targets: targets.map(ToString::to_string),
        columns: head.trim_end().split(',').collect(),
        rows,
        iso_cor,
        feasible_outline,
        warnings,
        ball: &ball.record,
        surface: crate::api::SurfaceUsed::rigid_plate(),
        conditions: &ball.conditions,
    };
    let mut s = super::output::json_string(&doc)?;
    s.push('\n');
    Ok(s)
}
