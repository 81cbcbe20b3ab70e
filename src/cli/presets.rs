//! `bouncelab presets`: every preset the program knows, where it comes from, and the λ, ζ it
//! runs at.

use super::ball::{PresetChoice, load_catalog};
use super::output::{self, TextJson, human, table};
use crate::api::PresetRow;
use crate::catalog;
use clap::Args;
use std::io::Write;

#[derive(Debug, Clone, Args)]
#[command(mut_arg("config", |a| a.help("Also list the preset in this file")))]
#[command(mut_arg("preset", |a| a.hide(true)))]
pub struct PresetsArgs {
    /// `--config`: also list the preset in this file (`--preset` does not apply)
    #[command(flatten)]
    pub choice: PresetChoice,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

pub fn run(a: &PresetsArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let cat = load_catalog(a.choice.config.as_deref())?;
    let rows: Vec<PresetRow> = cat.entries().iter().map(PresetRow::of).collect();
    match a.format {
        TextJson::Json => output::json(out, &rows)?,
        TextJson::Text => {
            let mut t = vec![
                [
                    "name",
                    "λ",
                    "ζ",
                    "law",
                    "parameters",
                    "origin",
                    "description",
                ]
                .map(String::from)
                .to_vec(),
            ];
            for r in &rows {
                t.push(vec![
                    r.name.clone(),
                    human(r.lambda, 3),
                    human(r.zeta, 3),
                    r.law.into(),
                    r.parameters.into(),
                    r.origin.clone(),
                    r.description.clone(),
                ]);
            }
            table(out, "", &t)?;
            writeln!(out)?;
            calibration_lines(out, &rows)?;
            match catalog::user_presets_dir() {
                Some(d) => writeln!(out, "user presets are read from {}/*.toml", d.display())?,
                None => writeln!(
                    out,
                    "user presets: neither XDG_CONFIG_HOME nor HOME is set, so none are read"
                )?,
            }
        }
    }
    Ok(())
}

/// Each preset's calibration record, after the table: the speeds it holds over, the
/// conditions and every data set it was fitted to.
fn calibration_lines(out: &mut dyn Write, rows: &[PresetRow]) -> std::io::Result<()> {
    writeln!(
        out,
        "calibration (the impact speeds each ball's parameters hold over):"
    )?;
    for r in rows {
        let Some(c) = &r.calibration else {
            writeln!(out, "  {}: no [calibration] record", r.name)?;
            continue;
        };
        let mut at = c.range_text();
        if let Some(t) = c.temperature {
            at.push_str(&format!(", {} °C", crate::text::short(t, 4)));
        }
        if let Some(p) = c.pressure {
            at.push_str(&format!(", {} kPa gauge", crate::text::short(p / 1e3, 4)));
        }
        writeln!(out, "  {}: {at}", r.name)?;
        for d in &c.data {
            writeln!(out, "    {}: {}", d.source, d.quantities)?;
        }
    }
    writeln!(out)
}
