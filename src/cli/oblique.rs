//! `bouncelab oblique`: one oblique impact with friction and spin (docs/oblique.md), as a text
//! table, one JSON object or CSV.

use super::ball::BallArgs;
use super::output::{self, TextJsonCsv, csv_row, given, human, num, opt_num, table};
use super::run::HistoryArgs;
use super::surface::{SurfaceArgs, SurfaceUsed};
use crate::api::{BallHeader, ObliqueSpec};
use crate::oblique::ObliqueResponse;
use clap::Args;
use serde::Serialize;
use std::io::Write;

/// The tangential model's options (in [`BounceSurfaceArgs`], and `mc --shot`'s).
#[derive(Debug, Clone, Args)]
pub struct TangentialArgs {
    /// Tangential stiffness K_t, N/m [default: Mindlin's 2(1 − ν)/(2 − ν) K_p, ν the preset's]
    #[arg(long, value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_stiffness: Option<f64>,
    /// κ = I/(m R²), in (0, 1] [default: the preset's, else 0.4 (solid)]
    #[arg(long, value_name = "KAPPA", value_parser = super::number::number, allow_hyphen_values = true)]
    pub inertia_factor: Option<f64>,
    /// Tangential dashpot c_t ≥ 0, kg/s, in parallel with K_t (LAMMPS's linear_history rule)
    /// [default: none]
    #[arg(long, value_name = "KG_PER_S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_damping: Option<f64>,
}

/// What `oblique`, `shot` and `court` share: the surface a bounce is on, its μ and the
/// tangential model (`court` words --friction's help its own way, by `mut_arg`). `mc --shot`
/// declares its own, each flag optional and `requires = "shot"`, and calls [`surface_of`].
#[derive(Debug, Clone, Args)]
pub struct BounceSurfaceArgs {
    /// Coulomb friction coefficient μ ≥ 0 [default: the surface's; required when it has none]
    #[arg(long, value_name = "MU", value_parser = super::number::number, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    #[command(flatten)]
    pub tangential: TangentialArgs,
    #[command(flatten)]
    pub surface: SurfaceArgs,
}

impl BounceSurfaceArgs {
    /// The surface with the tangential flags over its own, and its μ ([`surface_of`]).
    pub fn resolve(&self) -> anyhow::Result<(SurfaceUsed, f64)> {
        surface_of(&self.surface, self.friction, &self.tangential)
    }
}

#[derive(Debug, Clone, Args)]
#[command(mut_arg("history", |a| {
    a.help("Also print t, F_n, F_t, v_c and ω, evenly sampled over the contact")
}))]
pub struct ObliqueArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Incoming speed |v|, m/s [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Angle between the incoming path and the surface, degrees (0 < angle ≤ 90)
    #[arg(long, value_name = "DEG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub angle: f64,
    /// Incoming spin ω, rad/s (> 0 topspin for a ball moving in +x)
    #[arg(long, value_name = "RAD_PER_S", default_value_t = 0.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin: f64,
    #[command(flatten)]
    pub bounce: BounceSurfaceArgs,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJsonCsv,
    #[command(flatten)]
    pub history: HistoryArgs,
}

/// `oblique --format json`: the ball, the tangential model it ran and the answer.
#[derive(Serialize)]
struct Report<'a> {
    #[serde(flatten)]
    ball: BallHeader<'a>,
    friction: f64,
    tangential_stiffness: f64,
    /// c_t, kg/s: present only when a dashpot was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    tangential_damping: Option<f64>,
    inertia_factor: f64,
    radius: f64,
    #[serde(flatten)]
    answer: &'a ObliqueResponse,
    /// [`crate::Ball::oblique_warnings`]; `[]` when nothing.
    warnings: Vec<String>,
    /// The ball it ran (docs/cli.md, "The ball object").
    #[serde(rename = "ball")]
    record: crate::api::BallRecord,
    /// The surface it ran on (docs/surfaces.md).
    surface: SurfaceUsed,
}

/// The surface of a bounce (`oblique`, `shot`, `court`, `mc --shot`): `--surface*` with the
/// tangential flags over the surface's own; μ must come from one of them.
pub fn surface_of(
    surface: &SurfaceArgs,
    friction: Option<f64>,
    tangential: &TangentialArgs,
) -> anyhow::Result<(SurfaceUsed, f64)> {
    let used = surface.resolve()?.with_tangential([
        friction,
        tangential.tangential_stiffness,
        tangential.tangential_damping,
    ]);
    let Some(mu) = used.mechanics.friction else {
        anyhow::bail!(
            "invalid friction: the surface {} gives no μ (docs/surfaces.md): give --friction",
            used.name
        );
    };
    Ok((used, mu))
}

pub fn run(a: &ObliqueArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve(a.v0)?;
    let (surface, friction) = a.bounce.resolve()?;
    let spec = ObliqueSpec {
        v: a.v0,
        angle_deg: a.angle,
        spin: a.spin,
        friction,
        tangential_stiffness: surface.mechanics.tangential_stiffness,
        inertia_factor: a.bounce.tangential.inertia_factor,
    };
    let samples = a.history.samples()?;
    let damping = surface.mechanics.tangential_damping;
    let r = ball.oblique_on(&spec, damping, samples, &surface.mechanics.target())?;
    let k_t = surface
        .mechanics
        .tangential_stiffness
        .or(ball.tangential_stiffness())
        .unwrap_or(f64::NAN);
    let kappa = a
        .bounce
        .tangential
        .inertia_factor
        .unwrap_or_else(|| ball.inertia_factor());
    let radius = ball.radius();
    let warnings = ball.oblique_warnings_on(&r, &surface);
    match a.format {
        TextJsonCsv::Json => {
            let report = Report {
                ball: ball.header(),
                friction,
                tangential_stiffness: k_t,
                tangential_damping: damping,
                inertia_factor: kappa,
                radius,
                answer: &r,
                warnings,
                record: ball.record_json(),
                surface,
            };
            output::json_stated(out, &report, &ball.conditions)?
        }
        TextJsonCsv::Csv if a.history.history => {
            history_csv(out, &r)?;
            output::warnings_to_stderr(&warnings);
        }
        TextJsonCsv::Csv => {
            let stated = super::csv_stated::with_ball_cells(&ball, &surface);
            summary_csv(out, &r, &warnings, &stated)?
        }
        TextJsonCsv::Text => {
            // the law is named when it is not the linear one (the header `run` prints too)
            let law = match ball.law {
                crate::model::contact::ContactLaw::Linear => String::new(),
                law => format!(", {law} law"),
            };
            let dashpot =
                damping.map_or(String::new(), |c| format!(", c_t = {} kg/s", given(c, 4)));
            writeln!(
                out,
                "{}{law}: μ = {}, K_t = {} N/m{dashpot}, κ = {}, R = {} mm",
                ball.label(),
                given(friction, 6),
                human(k_t, 4),
                given(kappa, 4),
                given(radius * 1e3, 4)
            )?;
            output::ball_lines(out, &ball, output::Met::Surface(&surface))?;
            text(out, &r)?;
            output::warning_lines(out, &warnings)?
        }
    }
    Ok(())
}

/// Columns of `oblique --format csv` (one row).
pub const SUMMARY_COLUMNS: [&str; 19] = [
    "v_in",
    "angle_in_deg",
    "spin_in",
    "vx_in",
    "vy_in",
    "v_out",
    "angle_out_deg",
    "spin_out",
    "vx_out",
    "vy_out",
    "cor_normal",
    "cor_tangential",
    "apparent_friction",
    "slid_throughout",
    "grip_time",
    "contact_time",
    "max_normal_force",
    "max_friction_force",
    "warnings",
];

/// The one row of `oblique --format csv`: [`SUMMARY_COLUMNS`], then the ball, the surface
/// and the conditions (`stated`, [`super::csv_stated::with_ball`]).
fn summary_csv(
    out: &mut dyn Write,
    r: &ObliqueResponse,
    warnings: &[String],
    stated: &[String],
) -> std::io::Result<()> {
    let mut head = SUMMARY_COLUMNS.to_vec();
    head.extend(super::csv_stated::with_ball());
    csv_row(out, &head)?;
    let mut row: Vec<String> = [
        r.v_in,
        r.angle_in_deg,
        r.spin_in,
        r.vx_in,
        r.vy_in,
        r.v_out,
        r.angle_out_deg,
        r.spin_out,
        r.vx_out,
        r.vy_out,
        r.cor_normal,
    ]
    .map(num)
    .to_vec();
    row.push(opt_num(r.cor_tangential));
    row.push(num(r.apparent_friction));
    row.push(r.slid_throughout.to_string());
    for x in [
        r.grip_time,
        r.contact_time,
        r.max_normal_force,
        r.max_friction_force,
    ] {
        row.push(num(x));
    }
    row.push(output::warnings_cell(warnings));
    row.extend_from_slice(stated);
    csv_row(out, &row)
}

fn history_csv(out: &mut dyn Write, r: &ObliqueResponse) -> std::io::Result<()> {
    csv_row(
        out,
        &[
            "t",
            "normal_force",
            "friction_force",
            "slip_velocity",
            "spin",
        ],
    )?;
    if let Some(h) = &r.history {
        for i in 0..h.t.len() {
            let row = [
                h.t[i],
                h.normal_force[i],
                h.friction_force[i],
                h.slip_velocity[i],
                h.spin[i],
            ]
            .map(num);
            csv_row(out, &row)?;
        }
    }
    Ok(())
}

fn text(out: &mut dyn Write, r: &ObliqueResponse) -> std::io::Result<()> {
    let row = |name: &str, a: String, b: String| vec![name.to_string(), a, b];
    let rows = vec![
        row("", "in".into(), "out".into()),
        row("speed (m/s)", human(r.v_in, 5), human(r.v_out, 5)),
        row(
            "angle to the surface (°)",
            human(r.angle_in_deg, 5),
            human(r.angle_out_deg, 5),
        ),
        row("spin (rad/s)", human(r.spin_in, 5), human(r.spin_out, 5)),
        row("v_x (m/s)", human(r.vx_in, 5), human(r.vx_out, 5)),
        row("v_y (m/s)", human(r.vy_in, 5), human(r.vy_out, 5)),
    ];
    table(out, "", &rows)?;
    writeln!(out)?;
    let cor_t = r
        .cor_tangential
        .map_or("– (arrives rolling)".into(), |e| human(e, 5));
    let grip = if r.slid_throughout {
        "slid throughout".to_string()
    } else {
        format!("gripped {} ms", human(r.grip_time * 1e3, 4))
    };
    let e = &r.energy;
    let lines = vec![
        row("normal COR e_y", human(r.cor_normal, 6), String::new()),
        row("tangential COR e_x", cor_t, String::new()),
        row(
            "apparent friction",
            human(r.apparent_friction, 5),
            String::new(),
        ),
        row(
            "contact",
            format!("{} ms", human(r.contact_time * 1e3, 5)),
            grip,
        ),
        row(
            "peak forces",
            format!("F_n {} N", human(r.max_normal_force, 5)),
            format!("|F_t| {} N", human(r.max_friction_force, 5)),
        ),
        row(
            "energy lost (J)",
            format!("normal {}", human(e.normal_dissipation, 4)),
            format!("friction {}", human(e.friction_dissipation, 4)),
        ),
        row(
            "energy balance",
            format!("residual {}", output::residual(e.residual)),
            String::new(),
        ),
    ];
    table(out, "", &lines)?;
    if let Some(d) = e.tangential_damping {
        writeln!(
            out,
            "tangential dashpot  {} J lost while gripping",
            human(d, 4)
        )?;
    }
    if let Some(h) = &r.history {
        writeln!(out)?;
        let mut rows = vec![
            ["t (ms)", "F_n (N)", "F_t (N)", "v_c (m/s)", "ω (rad/s)"]
                .map(String::from)
                .to_vec(),
        ];
        let n = h.t.len();
        let step = n.div_ceil(40).max(1);
        for i in (0..n).step_by(step) {
            rows.push(vec![
                human(h.t[i] * 1e3, 4),
                human(h.normal_force[i], 4),
                human(h.friction_force[i], 4),
                human(h.slip_velocity[i], 4),
                human(h.spin[i], 5),
            ]);
        }
        table(out, "", &rows)?;
    }
    Ok(())
}
