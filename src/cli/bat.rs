//! `bouncelab bat`: a bat of effective mass M_eff at the impact point — the batted-ball speed
//! of a game impact, and the NCAA BBCOR test (136 mph onto the bat at rest) with its verdict
//! against ≤ 0.50 (docs/targets.md §5).

use super::ball::BallArgs;
use super::output::{self, TextJson, directed, human, num, table};
use crate::model::params::Field;
use crate::target::Target;
use crate::target::bat::{BAT_STANDARDS, BatRun, MPH_136};
use clap::Args;
use serde::Serialize;
use std::io::Write;

/// The preset `bat` runs when none is given: the ball of the standard it judges
/// (`ncaa-bbcor`'s, docs/targets.md §5).
const BAT_BALL: &str = BAT_STANDARDS[0].balls[0];

#[derive(Debug, Clone, Args)]
pub struct BatArgs {
    /// The ball [default: baseball-mlb, the ball of the BBCOR test]
    #[command(flatten)]
    pub ball: BallArgs,
    /// The bat's effective mass at the impact point M_eff (kg)
    #[arg(long, value_name = "KG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub bat_mass: f64,
    /// The pitched ball's speed toward the bat (m/s)
    #[arg(long, value_name = "V", default_value_t = 40.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub ball_speed: f64,
    /// The bat's speed at the impact point toward the ball (m/s)
    #[arg(long, value_name = "V", default_value_t = 30.0, value_parser = super::number::number, allow_hyphen_values = true)]
    pub bat_speed: f64,
    /// The stiffness K_s of the barrel at the impact point (N/m) [default: rigid]
    #[arg(long, value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub bat_stiffness: Option<f64>,
    /// The damping c_s in parallel with K_s (kg/s) [default: 0]
    #[arg(long, value_name = "kg/s", value_parser = super::number::number, allow_hyphen_values = true, requires = "bat_stiffness")]
    pub bat_damping: Option<f64>,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

/// `bat --format json`: what was asked, then the run's fields at the top level.
#[derive(Serialize)]
struct BatJson<'a> {
    ball: Option<&'a str>,
    bat_mass: f64,
    ball_speed: f64,
    bat_speed: f64,
    standard: &'static str,
    #[serde(flatten)]
    run: &'a BatRun,
    /// [`crate::Ball::bat_warnings`]; `[]` when nothing.
    warnings: Vec<String>,
    /// The ball as every JSON answer names it (docs/cli.md, "The ball object"): `ball` is
    /// already the preset's name, a string, and stays one.
    ball_record: crate::api::BallRecord,
}

pub fn run(a: &BatArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve_for_standard(BAT_BALL)?;
    check(a)?;
    let surface = (
        a.bat_stiffness.unwrap_or(f64::INFINITY),
        a.bat_damping.unwrap_or(0.0),
    );
    let r = ball.bat(a.bat_mass, (a.ball_speed, a.bat_speed), surface)?;
    let bat = crate::api::SurfaceUsed::bat(a.bat_mass, a.bat_stiffness, a.bat_damping);
    match a.format {
        TextJson::Json => output::json_on(
            out,
            &BatJson {
                ball: ball.name.as_deref(),
                bat_mass: a.bat_mass,
                ball_speed: a.ball_speed,
                bat_speed: a.bat_speed,
                standard: BAT_STANDARDS[0].name,
                run: &r,
                warnings: ball.bat_warnings(&r),
                ball_record: ball.record_json(),
            },
            // what the ball met: the bat (docs/cli.md, "The surface object")
            output::Met::Surface(&bat),
            &ball.conditions,
        )?,
        TextJson::Text => {
            let first = format!(
                "{} against a bat of effective mass {} kg at the impact point",
                ball.label(),
                human(a.bat_mass, 4)
            );
            // what the ball met: the bat, as the JSON's surface object
            let met = output::Met::Surface(&bat);
            text(out, &output::headed(first, &ball, met), a, &r)?;
            output::warning_lines(out, &ball.bat_warnings(&r))?;
        }
    }
    Ok(())
}

/// The bat's values checked as `Target::validate` and `collide` check them, the error naming
/// the flag the user gave (`bat_mass`, not the library's `target_mass`): the library's bat is
/// a target, the command line's is a bat (tests/cli/cli_targets.rs, `bat_errors_name_its_flags`).
fn check(a: &BatArgs) -> anyhow::Result<()> {
    let bat = Target {
        mass: a.bat_mass,
        speed: a.bat_speed,
        stiffness: a.bat_stiffness.unwrap_or(f64::INFINITY),
        damping: a.bat_damping.unwrap_or(0.0),
    };
    if let Err(e) = bat.validate() {
        let name = match e.field {
            Field::TargetMass => "bat_mass",
            Field::TargetSpeed => "bat_speed",
            Field::TargetStiffness => "bat_stiffness",
            _ => "bat_damping",
        };
        anyhow::bail!("invalid {name}: {} ({})", num(e.value), e.reason);
    }
    if !a.ball_speed.is_finite() || a.ball_speed.abs() > 1e15 {
        let reason = "must be finite, within ±1e15 m/s";
        anyhow::bail!("invalid ball_speed: {} ({reason})", num(a.ball_speed));
    }
    if a.ball_speed + a.bat_speed <= 0.0 {
        // the one that moves away from the other is at fault (both: the ball)
        let (name, v) = if a.ball_speed < 0.0 || a.bat_speed >= 0.0 {
            ("ball_speed", a.ball_speed)
        } else {
            ("bat_speed", a.bat_speed)
        };
        let reason = "the ball and the bat never meet: ball_speed + bat_speed must be positive";
        anyhow::bail!("invalid {name}: {} ({reason})", num(v));
    }
    Ok(())
}

fn text(out: &mut dyn Write, head: &str, a: &BatArgs, r: &BatRun) -> std::io::Result<()> {
    writeln!(out, "{head}")?;
    writeln!(out)?;
    let ms = |v: f64| format!("{} m/s", human(v, 4));
    if a.ball_speed >= 0.0 && a.bat_speed >= 0.0 {
        let (ball, bat) = (ms(a.ball_speed), ms(a.bat_speed));
        writeln!(out, "game: ball at {ball}, bat at {bat}, toward each other")?;
    } else {
        let ball = directed(a.ball_speed, "toward the bat", "away from the bat");
        let bat = directed(a.bat_speed, "toward the ball", "away from the ball");
        writeln!(out, "game: ball at {ball}, bat at {bat}")?;
    }
    let g = &r.game;
    let rows = vec![
        vec!["batted-ball speed BBS".into(), ms(r.bbs)],
        vec!["apparent COR e_A".into(), human(r.apparent_cor, 4)],
        vec!["COR of the pair e".into(), human(g.cor, 4)],
        vec![
            "peak force F_m".into(),
            format!("{} N", human(g.max_force, 4)),
        ],
    ];
    table(out, "  ", &rows)?;
    writeln!(out)?;
    writeln!(
        out,
        "NCAA BBCOR: ball at {} (136 mph) onto the bat at rest",
        ms(MPH_136)
    )?;
    let rows = vec![
        vec!["BBCOR (the pair's e)".into(), human(r.bbcor, 4)],
        vec!["apparent COR e_A".into(), human(r.test.apparent_cor, 4)],
        vec![
            "verdict".into(),
            // the limit as a limit: "FAIL (BBCOR ≤ 0.50)" read as if the condition held
            format!(
                "{} (BBCOR {} {} the limit {})",
                r.verdict,
                human(r.bbcor, 4),
                if r.pass { "within" } else { "over" },
                human(r.limit, 2)
            ),
        ],
    ];
    table(out, "  ", &rows)
}
