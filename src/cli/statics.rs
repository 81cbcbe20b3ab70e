//! `bouncelab static`: the ball squeezed between two rigid plates under a load, the forward
//! deflection of its diameter and, where the law has hysteresis, the return deflection after
//! a deeper compression (docs/model.md §11; the ITF's deformation tests, docs/cli.md).

use super::ball::BallArgs;
use super::output::{self, TextJson, human};
use crate::analysis::statics::{ContactDeflection, StaticDeflection};
use crate::api::{ITF_RETURN_PEAK, StaticReport};
use crate::drop::G;
use clap::Args;
use std::io::Write;

#[derive(Debug, Clone, Args)]
pub struct StaticArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// The load between the plates, kg (its weight load·g bears on each contact; the ITF
    /// tests use 8.165 kg)
    #[arg(long, value_name = "KG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub load: f64,
    /// The shortening of the diameter the ball is first compressed to before the return
    /// reading, m [default: 0.0254, the ITF return test's 1 in]
    #[arg(long, value_name = "M", default_value_t = ITF_RETURN_PEAK, value_parser = super::number::number, allow_hyphen_values = true)]
    pub peak: f64,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

pub fn run(a: &StaticArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let ball = a.ball.resolve(None)?;
    let s = ball.static_deflection(a.load, a.peak)?;
    let report = StaticReport::new(&ball, a.load, &s);
    match a.format {
        // `conditions` beside the answer's keys, as every command's JSON (docs/cli.md)
        // and `surface`: both plates are the rigid plate (docs/cli.md, "The surface object")
        TextJson::Json => output::json_on(out, &report, output::Met::RigidPlate, &ball.conditions)?,
        TextJson::Text => {
            writeln!(out, "{}", ball.label())?;
            output::ball_lines(out, &ball, output::Met::RigidPlate)?;
            text(out, a.load, &s, ball.law.name())?;
            output::warning_lines(out, &report.warnings)?;
        }
    }
    Ok(())
}

fn text(out: &mut dyn Write, load: f64, s: &StaticDeflection, law: &str) -> std::io::Result<()> {
    writeln!(
        out,
        "between two rigid plates, load {} kg (F = {} N on each contact, g = {G} m/s²), {law} law",
        super::output::given(load, 6),
        human(s.force, 4)
    )?;
    writeln!(
        out,
        "each contact: the contact element in series with the recoil spring K_r; the \
         diameter shortens by twice one contact's deflection"
    )?;
    writeln!(out)?;
    let line = |r: &Result<ContactDeflection, String>| match r {
        Ok(d) => format!(
            "{} mm (each contact: indentation {} mm + recoil spring {} mm)",
            human(d.diameter() * 1e3, 4),
            human(d.indentation * 1e3, 4),
            human(d.recoil * 1e3, 4)
        ),
        Err(why) => format!("none: {why}"),
    };
    writeln!(out, "  forward deflection  {}", line(&s.forward))?;
    writeln!(out, "  return deflection   {}", line(&s.return_))?;
    if let Some(f_m) = s.peak_force {
        writeln!(
            out,
            "  (return read on unloading from a {} mm compression of the diameter, {} N; --peak)",
            human(s.peak * 1e3, 4),
            human(f_m, 4)
        )?;
    }
    Ok(())
}
