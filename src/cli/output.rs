//! Writers shared by the subcommands: number formatting, CSV rows, JSON documents, the
//! text-table helpers, and the `--format` choices they write by. Everything writes to a
//! `dyn Write` so a closed pipe surfaces as an `io::Error` (handled quietly in `cli::main`),
//! never a panic.

use crate::api::SurfaceUsed;
use clap::ValueEnum;
use serde::Serialize;
use std::io::{self, Write};

pub use crate::text::{csv_field, given, human, number as num};

/// `--format` of a command that writes a text report or one JSON document.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextJson {
    Text,
    Json,
}

/// `--format` of a command that writes a text report, one JSON document or CSV.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextJsonCsv {
    Text,
    Json,
    Csv,
}

/// An optional number for CSV: empty when absent (e.g. no rebound).
pub fn opt_num(x: Option<f64>) -> String {
    x.map(num).unwrap_or_default()
}

/// One CSV line from already formatted fields.
pub fn csv_row<S: AsRef<str>>(out: &mut dyn Write, fields: &[S]) -> io::Result<()> {
    let line: Vec<String> = fields.iter().map(|f| csv_field(f.as_ref())).collect();
    writeln!(out, "{}", line.join(","))
}

/// A JSON document on one line (pipe it to `jq` to read it). Non-finite numbers become `null`.
pub fn json<T: Serialize>(out: &mut dyn Write, value: &T) -> io::Result<()> {
    out.write_all(json_string(value)?.as_bytes())?;
    writeln!(out)
}

/// An answer with the conditions its ball ran at appended as its last key, `conditions`
/// (docs/cli.md, "Conditions"): every JSON answer that runs a ball states them.
#[derive(Serialize)]
struct Stated<'a, T: Serialize> {
    #[serde(flatten)]
    answer: &'a T,
    conditions: &'a crate::conditions::Conditions,
}

/// [`json`] of an answer that ran a ball at `conditions`: the answer's keys, then
/// `conditions: {temperature_c, pressure_gauge_pa, atmosphere_pa}`.
pub fn json_stated<T: Serialize>(
    out: &mut dyn Write,
    value: &T,
    conditions: &crate::conditions::Conditions,
) -> io::Result<()> {
    json(
        out,
        &Stated {
            answer: value,
            conditions,
        },
    )
}

/// An answer on a surface: the answer's keys, then `surface` (the [`SurfaceUsed`] it ran on,
/// or `null` where the ball met no surface, `surface_note` then saying what it met).
#[derive(Serialize)]
struct OnSurface<'a, T: Serialize> {
    #[serde(flatten)]
    answer: &'a T,
    surface: Option<&'a SurfaceUsed>,
    #[serde(skip_serializing_if = "Option::is_none")]
    surface_note: Option<&'a str>,
}

/// What an answer's ball met, for [`json_on`]: a surface, or none and why.
pub enum Met<'a> {
    /// The surface it ran on.
    Surface(&'a SurfaceUsed),
    /// The rigid plate ([`SurfaceUsed::rigid_plate`]): what a normal impact, a drop test, a
    /// fit to them and the static test's plates run on.
    RigidPlate,
    /// No surface: what it met instead (the JSON `surface_note`).
    NoSurface(&'a str),
}

/// [`json_stated`] of an answer with the surface its ball met (docs/cli.md, "The surface
/// object"): the answer's keys, `surface`, then `conditions`.
pub fn json_on<T: Serialize>(
    out: &mut dyn Write,
    value: &T,
    met: Met<'_>,
    conditions: &crate::conditions::Conditions,
) -> io::Result<()> {
    let plate;
    let (surface, surface_note) = match met {
        Met::Surface(s) => (Some(s), None),
        Met::RigidPlate => {
            plate = SurfaceUsed::rigid_plate();
            (Some(&plate), None)
        }
        Met::NoSurface(why) => (None, Some(why)),
    };
    let on = OnSurface {
        answer: value,
        surface,
        surface_note,
    };
    json_stated(out, &on, conditions)
}

/// `value` as one line of JSON in which every character the terminal sanitizer would rewrite
/// (DEL, C1 controls, the bidirectional overrides, the invisible format characters:
/// `crate::sanitize`) is a JSON escape
/// `\u007f` — serde_json escapes only C0 itself, and the sanitizer's visible `\u{7f}` is no
/// JSON (tests/cli/escaping.rs, `json_stays_json_whatever_a_name_holds`).
pub fn json_string<T: Serialize>(value: &T) -> io::Result<String> {
    let mut buf = Vec::new();
    let mut ser = serde_json::Serializer::with_formatter(&mut buf, Escaping);
    value.serialize(&mut ser).map_err(io::Error::from)?;
    // serde_json writes UTF-8
    String::from_utf8(buf).map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))
}

/// serde_json's compact format with hostile characters escaped.
struct Escaping;

impl serde_json::ser::Formatter for Escaping {
    fn write_string_fragment<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        let mut start = 0;
        for (i, c) in fragment.char_indices() {
            if crate::sanitize::hostile(c) {
                writer.write_all(&fragment.as_bytes()[start..i])?;
                // one \uXXXX per UTF-16 unit: a surrogate pair beyond the Basic Multilingual
                // Plane (the Cf tag characters U+E0001…)
                for unit in c.encode_utf16(&mut [0; 2]) {
                    write!(writer, "\\u{:04x}", unit)?;
                }
                start = i + c.len_utf8();
            }
        }
        writer.write_all(&fragment.as_bytes()[start..])
    }
}

/// Columns a cell takes on a terminal: combining marks (the bar of z̄) take none.
fn width(s: &str) -> usize {
    s.chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count()
}

/// A signed difference with a relative one: "+1.2 ms (+4.0 %)"; without a unit (a COR),
/// four decimals.
pub fn difference(model: f64, measured: f64, scale: f64, unit: &str) -> String {
    let d = (model - measured) * scale;
    let shown = if unit.is_empty() {
        format!("{d:+.4}")
    } else {
        signed(d)
    };
    let rel = if measured != 0.0 {
        format!(" ({:+.1} %)", 100.0 * (model - measured) / measured)
    } else {
        String::new()
    };
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    format!("{shown}{unit}{rel}")
}

fn signed(x: f64) -> String {
    let s = human(x, 3);
    if x >= 0.0 { format!("+{s}") } else { s }
}

/// A speed along the line of centres as its size and the way it goes: `positive` names the
/// way of a positive value (the JSON's sign, docs/targets.md §3), `negative` the other, so
/// that no signed speed sits beside words that say the opposite
/// (tests/cli/cli_targets.rs, `collide_text_says_the_way_each_speed_goes`).
pub fn directed(v: f64, positive: &str, negative: &str) -> String {
    let way = if v < 0.0 { negative } else { positive };
    format!("{} m/s {way}", human(v.abs(), 4))
}

/// A residual (a fraction of an energy) to two digits, `1.5e-16`; an exact zero as `0`, not
/// Rust's `0.0e0` (`run --lambda 0 --zeta 1`, tests/cli/cli_odd_inputs.rs).
pub fn residual(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

/// The text header's surface line, every text answer's (docs/cli.md, "The surface object"):
/// "surface steel-plate (rigid, immovable)", the surface's label
/// ([`SurfaceUsed::label`]), the default plate's included; where the ball met no surface,
/// "surface none: " and what it met (tests/cli/cli_surface_header.rs).
pub fn surface_line(met: &Met<'_>) -> String {
    match met {
        Met::Surface(s) => s.label(),
        Met::RigidPlate => SurfaceUsed::rigid_plate().label(),
        Met::NoSurface(what) => format!("surface none: {what}"),
    }
}

/// The lines under a text report's first that say how its ball differs from its preset and
/// what it met: the overrides ([`crate::api::Ball::overrides_line`]), then the surface
/// ([`surface_line`], always), then the conditions ([`crate::api::Ball::conditions_line`]).
/// A header as one string: `first`, then the [`ball_lines`] (`drop`'s and `bat`'s, which
/// print their heading inside their report).
pub fn headed(first: String, ball: &crate::api::Ball, met: Met<'_>) -> String {
    let mut lines = Vec::new();
    // writing to memory does not fail
    let _ = ball_lines(&mut lines, ball, met);
    let lines = String::from_utf8_lossy(&lines);
    format!("{first}\n{}", lines.trim_end_matches('\n'))
}

pub fn ball_lines(out: &mut dyn Write, ball: &crate::api::Ball, met: Met<'_>) -> io::Result<()> {
    if let Some(line) = ball.overrides_line() {
        writeln!(out, "{line}")?;
    }
    writeln!(out, "{}", surface_line(&met))?;
    if let Some(line) = ball.conditions_line() {
        writeln!(out, "{line}")?;
    }
    Ok(())
}

/// An answer's warnings after its text, a `warning:` line each (docs/guarantees.md,
/// "Warnings travel with the answer").
pub fn warning_lines<S: AsRef<str>>(out: &mut dyn Write, warnings: &[S]) -> io::Result<()> {
    for w in warnings {
        writeln!(out, "warning: {}", w.as_ref())?;
    }
    Ok(())
}

/// An answer's warnings where its output has no place for them (a time series as CSV): on
/// stderr, a `bouncelab: warning:` line each, its control characters shown as text.
pub fn warnings_to_stderr<S: AsRef<str>>(warnings: &[S]) {
    for w in warnings {
        let line = format!("bouncelab: warning: {}", w.as_ref());
        let _ = writeln!(io::stderr(), "{}", crate::sanitize::line(&line));
    }
}

/// An answer's warnings as one CSV cell, `; ` between them (empty when none).
pub fn warnings_cell(warnings: &[String]) -> String {
    warnings.join("; ")
}

/// Rows of cells as a left-aligned table with two spaces between columns.
pub fn table(out: &mut dyn Write, indent: &str, rows: &[Vec<String>]) -> io::Result<()> {
    let cols = rows.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..cols)
        .map(|c| {
            rows.iter()
                .filter_map(|r| r.get(c))
                .map(|s| width(s))
                .max()
                .unwrap_or(0)
        })
        .collect();
    for r in rows {
        let mut line = String::from(indent);
        for (c, cell) in r.iter().enumerate() {
            line.push_str(cell);
            if c + 1 < r.len() {
                let pad = widths[c] - width(cell) + 2;
                line.extend(std::iter::repeat_n(' ', pad));
            }
        }
        writeln!(out, "{}", line.trim_end())?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differences() {
        assert_eq!(
            difference(3.05e-3, 3.0e-3, 1e3, "ms"),
            "+0.0500 ms (+1.7 %)"
        );
        assert_eq!(difference(0.7506, 0.75, 1.0, ""), "+0.0006 (+0.1 %)");
    }
}
