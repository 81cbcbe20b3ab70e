//! `bouncelab collide`: the ball against a target of mass M moving at v_t, rigid or with a
//! surface of its own (docs/targets.md), as a text table or one JSON object.

use super::ball::{self, BallArgs};
use super::output::{self, Met, TextJson, directed, human, table};
use super::surface::SurfaceArgs;
use crate::api::{Ball, CollisionReport};
use crate::target::Target;
use clap::Args;
use std::io::Write;

#[derive(Debug, Clone, Args)]
pub struct CollideArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// The ball's speed toward the target (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// The target's mass M (kg); `inf` for an immovable one (today's wall)
    #[arg(
        long,
        value_name = "KG",
        value_parser = super::number::number,
        allow_hyphen_values = true,
        required_unless_present_any = ["target_preset", "surface", "surface_mass"],
        conflicts_with = "target_preset"
    )]
    pub target_mass: Option<f64>,
    /// Another ball as the target: both balls deform, their chains in series (with
    /// --target-stiffness: a body of its mass behind that surface); m_eff and R_eff reported
    #[arg(long, value_name = "NAME")]
    pub target_preset: Option<String>,
    /// The target's speed toward the ball (m/s; negative: receding)
    #[arg(long, value_name = "V", default_value_t = 0.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub target_speed: f64,
    /// The stiffness K_s of the target's surface (N/m) [default: the surface's, rigid]
    #[arg(long, value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true, conflicts_with = "surface_stiffness")]
    pub target_stiffness: Option<f64>,
    #[command(flatten)]
    pub surface: SurfaceArgs,
    /// The damping c_s in parallel with K_s (kg/s) [default: the surface's, 0]
    #[arg(long, value_name = "kg/s", value_parser = super::number::number, allow_hyphen_values = true, requires = "target_stiffness", conflicts_with = "surface_damping")]
    pub target_damping: Option<f64>,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

pub fn run(a: &CollideArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve(a.v0)?;
    if a.target_preset.is_some()
        && (a.surface.surface.is_some() || a.surface.surface_mass.is_some())
    {
        anyhow::bail!(
            "--target-preset is the target: --surface and --surface-mass do not apply (give \
             --surface-stiffness, --surface-damping for its surface)"
        );
    }
    let used =
        a.surface
            .resolve()?
            .with_target(a.target_mass, a.target_stiffness, a.target_damping);
    let surface = (used.mechanics.stiffness, used.mechanics.damping);
    let other = match &a.target_preset {
        Some(name) => {
            let entry = ball::select(Some(name), a.ball.choice.config.as_deref())?;
            Some(Ball::from_entry(&entry, None, None, None)?)
        }
        None => None,
    };
    let mut report = match &other {
        Some(other) => ball.collide_ball(other, a.target_speed, surface)?,
        None => ball.collide(&Target {
            mass: used.mechanics.mass,
            speed: a.target_speed,
            stiffness: surface.0,
            damping: surface.1,
        })?,
    };
    // a target's surface (a ball partner has none of its own): as every answer on it says
    if a.target_preset.is_none() {
        report.warnings.extend(used.warnings());
    }
    // a ball partner that deforms is no surface: `surface` null, the note saying what was met
    // (as `peers --pair`); behind a given surface (--target-stiffness), that surface
    let partner = report.pair.as_ref().filter(|_| report.target.is_rigid());
    let said = partner.map(|p| match a.format {
        TextJson::Json => p.no_surface_note(),
        TextJson::Text => p.met_words(),
    });
    let met = match &said {
        Some(what) => Met::NoSurface(what),
        None => Met::Surface(&used),
    };
    match a.format {
        TextJson::Json => output::json_on(out, &report, met, &ball.conditions)?,
        TextJson::Text => text(out, (&ball, other.as_ref()), &report, met)?,
    }
    Ok(())
}

/// "500 g", "∞ (immovable)".
fn mass(m: f64) -> String {
    if m.is_infinite() {
        "∞ (immovable)".into()
    } else {
        format!("{} g", human(m * 1e3, 4))
    }
}

fn surface(t: &Target) -> String {
    if t.is_rigid() {
        "rigid".into()
    } else {
        format!(
            "K_s {} N/m, c_s {} kg/s",
            human(t.stiffness, 4),
            human(t.damping, 4)
        )
    }
}

/// The text report: the ball and what it met (a ball partner by its label and conditions,
/// as the ball's own), the setup, the answer, the warnings.
fn text(
    out: &mut dyn Write,
    (ball, other): (&Ball, Option<&Ball>),
    r: &CollisionReport,
    met: Met<'_>,
) -> std::io::Result<()> {
    let what = match (other, &r.pair) {
        (Some(_), Some(p)) => {
            let o = p.named();
            // both chains in series (docs/targets.md §8)
            match r.target.is_rigid() {
                true => format!("{o} (a ball that deforms too)"),
                false => format!("{o} (a body of its mass behind the given surface)"),
            }
        }
        _ => "a target".to_string(),
    };
    writeln!(out, "{} against {what}", ball.label())?;
    output::ball_lines(out, ball, met)?;
    if let Some(o) = other {
        writeln!(out, "partner: {}", o.label())?;
        if let Some(line) = o.conditions_line() {
            writeln!(out, "partner {line}")?;
        }
    }
    writeln!(out, "  law {}, method {}", r.law, r.collision.method.name())?;
    writeln!(out)?;
    table(out, "  ", &setup_rows(r, other.is_some()))?;
    writeln!(out)?;
    table(out, "  ", &result_rows(r))?;
    output::warning_lines(out, &r.warnings)
}

fn ms(v: f64) -> String {
    format!("{} m/s", human(v, 4))
}

fn mm(x: f64) -> String {
    format!("{} mm", human(x * 1e3, 4))
}

/// The ball, the target, the pair (and the DEM pair with a target preset, `ball_partner`).
fn setup_rows(r: &CollisionReport, ball_partner: bool) -> Vec<Vec<String>> {
    let (t, c) = (&r.target, &r.collision);
    let ball = format!(
        "m {}, {} toward the target",
        mass(r.ball_mass),
        ms(r.ball_speed)
    );
    let target = format!(
        "M {}, {}, {}",
        mass(t.mass),
        directed(t.speed, "toward the ball", "away from the ball"),
        if ball_partner && t.is_rigid() {
            "deforms (its own chain, in series)".into()
        } else {
            surface(t)
        }
    );
    let pair = format!(
        "m* {}, closing speed {}",
        mass(c.reduced_mass),
        ms(c.closing_speed)
    );
    let mut rows = vec![
        vec!["ball".into(), ball],
        vec!["target".into(), target],
        vec!["pair".into(), pair],
    ];
    if let (Some(m), Some(radius)) = (r.effective_mass, r.effective_radius) {
        let line = format!("m_eff {}, R_eff {}", mass(m), mm(radius));
        rows.push(vec!["DEM pair".into(), line]);
    }
    rows
}

/// e, e_A, the speeds out, F_m, t_f, the indentations (and the surface's deflection).
fn result_rows(r: &CollisionReport) -> Vec<Vec<String>> {
    let c = &r.collision;
    let contact = c.contact_time.map_or("– (no rebound)".into(), |t| {
        format!("{} ms", human(t * 1e3, 4))
    });
    let row = |k: &str, v: String| vec![k.to_string(), v];
    let mut rows = vec![
        row("COR of the pair e", human(c.cor, 4)),
        row("apparent COR e_A", human(c.apparent_cor, 4)),
        row(
            "ball speed out",
            directed(
                c.ball_speed_out,
                "away from the target",
                "toward the target",
            ),
        ),
        row(
            "target speed out",
            directed(c.target_speed_out, "toward the ball", "away from the ball"),
        ),
        row("peak force F_m", format!("{} N", human(c.max_force, 4))),
        row("contact time t_f", contact),
        row("peak indentation z_m", mm(c.max_indentation)),
        row("permanent indentation z_f", mm(c.permanent_indentation)),
    ];
    if !r.target.is_rigid() {
        rows.push(row("peak surface deflection", mm(c.max_target_deflection)));
    }
    rows
}
