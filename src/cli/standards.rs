//! `bouncelab standards`: the governing bodies' ball tests and their windows (docs/drop.md,
//! "Standards", cites each source).

use super::output::{self, TextJson, given, table};
use crate::drop::conditions::{self, PRESSURE_LOSS};
use crate::drop::deformation::DEFORMATION_STANDARDS;
use crate::drop::standards::{STANDARDS, Standard, Test};
use crate::oblique::court::{CourtTest, ITF_COURT_PACE};
use crate::target::bat::{BAT_STANDARDS, BatTest};
use clap::Args;
use std::io::Write;

#[derive(Debug, Clone, Args)]
pub struct StandardsArgs {
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

pub fn run(a: &StandardsArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    match a.format {
        // the ball standards with their conditions, the bat standards, the court pace, the
        // pressure-loss tests, the static standards: one list (`test.kind` tells them apart);
        // through a `Value`, so that the keys are serde_json's order, as they always were
        TextJson::Json => output::json(out, &serde_json::to_value(crate::api::standards())?)?,
        TextJson::Text => text(out)?,
    }
    Ok(())
}

/// "drop 2.54 m (bottom) → rebound (bottom)" or "COR at 26.82 m/s".
fn test_cell(s: &Standard) -> String {
    match s.test {
        Test::Drop {
            height,
            drop_ref,
            rebound_ref,
        } => format!(
            "drop {} m ({}) → rebound ({})",
            given(height, 4),
            drop_ref.name(),
            rebound_ref.name()
        ),
        Test::Cor { speed } => format!("COR at {} m/s", given(speed, 4)),
    }
}

/// "1.35 … 1.47 m", "≤ 0.47".
pub fn window_cell(s: &Standard) -> String {
    let unit = match s.test {
        Test::Drop { .. } => " m",
        Test::Cor { .. } => "",
    };
    match s.window {
        [Some(lo), Some(hi)] => format!("{} … {}{unit}", given(lo, 4), given(hi, 4)),
        [None, Some(hi)] => format!("≤ {}{unit}", given(hi, 4)),
        [Some(lo), None] => format!("≥ {}{unit}", given(lo, 4)),
        [None, None] => "–".into(),
    }
}

fn text(out: &mut dyn Write) -> std::io::Result<()> {
    table(out, "", &table_rows())?;
    // below the table, whose columns stay as they were (the names are longer)
    pressure_loss_lines(out)?;
    writeln!(out)?;
    sources_text(out)?;
    writeln!(out)?;
    conditions_text(out)?;
    writeln!(out)?;
    writeln!(
        out,
        "heights are of the bottom or the top of the ball as each body reads them; \
         `bouncelab drop --standard NAME` judges a ball, `bouncelab bat` a bat, \
         `bouncelab court` a surface"
    )
}

/// The table's rows: a standard each, of a ball's impact, a bat, a court and a static test.
fn table_rows() -> Vec<Vec<String>> {
    let mut rows = vec![
        ["name", "test", "window", "ball", "title"]
            .map(String::from)
            .to_vec(),
    ];
    for s in &STANDARDS {
        rows.push(vec![
            s.name.into(),
            test_cell(s),
            window_cell(s),
            s.balls.join(", "),
            s.title.into(),
        ]);
    }
    for s in &BAT_STANDARDS {
        let BatTest::Bbcor { speed } = s.test;
        let hi = s.window[1].map_or("–".into(), |h| format!("≤ {}", given(h, 4)));
        rows.push(vec![
            s.name.into(),
            format!("bat BBCOR at {} m/s", given(speed, 4)),
            hi,
            s.balls.join(", "),
            s.title.into(),
        ]);
    }
    let court = &ITF_COURT_PACE;
    let CourtTest::CourtPace { speed, angle_deg } = court.test;
    rows.push(vec![
        court.name.into(),
        format!(
            "court pace at {} m/s, {}°",
            given(speed, 4),
            given(angle_deg, 4)
        ),
        "categories 1–5".into(),
        court.balls.join(", "),
        court.title.into(),
    ]);
    for s in &DEFORMATION_STANDARDS {
        let mm = |x: Option<f64>| x.map_or("–".into(), |x| given(x * 1e3, 4));
        rows.push(vec![
            s.name.into(),
            format!("static {} kg, two plates", given(s.test.load_kg, 4)),
            format!("{} … {} mm", mm(s.window[0]), mm(s.window[1])),
            s.balls.join(", "),
            s.title.into(),
        ]);
    }
    rows
}

/// The pressure-loss tests, a line each.
fn pressure_loss_lines(out: &mut dyn Write) -> std::io::Result<()> {
    for p in &PRESSURE_LOSS {
        writeln!(
            out,
            "{}: inflated to {} kPa, {} h at {} °C, loss ≤ {} % ({}): {}",
            p.name,
            given(p.pressure / 1e3, 4),
            given(p.hours, 4),
            given(p.temperature, 4),
            given(100.0 * p.max_loss, 4),
            p.balls.join(", "),
            p.title
        )?;
    }
    Ok(())
}

/// Every standard's source, and what of it could not be confirmed.
fn sources_text(out: &mut dyn Write) -> std::io::Result<()> {
    let court = &ITF_COURT_PACE;
    writeln!(out, "sources, and what could not be confirmed:")?;
    let sources = STANDARDS.iter().map(|s| (s.name, s.source, s.unconfirmed));
    let bats = BAT_STANDARDS
        .iter()
        .map(|s| (s.name, s.source, s.unconfirmed));
    let courts = std::iter::once((court.name, court.source, court.unconfirmed));
    let leaks = PRESSURE_LOSS.iter().map(|p| (p.name, p.source, None));
    let statics = DEFORMATION_STANDARDS
        .iter()
        .map(|s| (s.name, s.source, s.unconfirmed));
    for (name, source, unconfirmed) in sources
        .chain(bats)
        .chain(courts)
        .chain(leaks)
        .chain(statics)
    {
        writeln!(out, "  {name}: {source}")?;
        if let Some(u) = unconfirmed {
            writeln!(out, "    not confirmed: {u}")?;
        }
    }
    Ok(())
}

/// The conditions each test runs the ball at, with their source.
fn conditions_text(out: &mut dyn Write) -> std::io::Result<()> {
    writeln!(
        out,
        "test conditions (`drop --standard NAME` runs the ball at them; a ball at others is \
         warned):"
    )?;
    let names = STANDARDS.iter().map(|s| s.name);
    for name in names.chain(PRESSURE_LOSS.iter().map(|p| p.name)) {
        let c = conditions::of(name);
        writeln!(out, "  {name}: {}", crate::api::test_words(&c))?;
        writeln!(out, "    {}", c.source)?;
    }
    Ok(())
}
