//! Writers shared by the subcommands: number formatting, CSV rows, JSON documents, and the
//! text-table helpers. Everything writes to a `dyn Write` so a closed pipe surfaces as an
//! `io::Error` (handled quietly in `cli::main`), never a panic.

use serde::Serialize;
use std::io::{self, Write};

pub use crate::model::params::display_number as num;

/// An optional number for CSV: empty when absent (e.g. no rebound).
pub fn opt_num(x: Option<f64>) -> String {
    x.map(num).unwrap_or_default()
}

/// One CSV field (RFC 4180): quoted when it holds a comma, quote or line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// One CSV line from already formatted fields.
pub fn csv_row<S: AsRef<str>>(out: &mut dyn Write, fields: &[S]) -> io::Result<()> {
    let line: Vec<String> = fields.iter().map(|f| csv_field(f.as_ref())).collect();
    writeln!(out, "{}", line.join(","))
}

/// A JSON document on one line (pipe it to `jq` to read it). Non-finite numbers become `null`.
pub fn json<T: Serialize>(out: &mut dyn Write, value: &T) -> io::Result<()> {
    serde_json::to_writer(&mut *out, value).map_err(io::Error::from)?;
    writeln!(out)
}

/// A human-readable number with `sig` significant digits, exponent form when very large or
/// small: 0.7502, 121.3, 5.45e4 → "54500", 1.2e-7.
pub fn human(x: f64, sig: usize) -> String {
    if !x.is_finite() {
        return num(x);
    }
    if x == 0.0 {
        return "0".into();
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-3..6).contains(&mag) {
        return format!("{:.*e}", sig.saturating_sub(1), x);
    }
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    format!("{x:.decimals$}")
}

/// As [`human`], without trailing zeros: for values the user gave (3.12 m/s, not 3.120).
pub fn given(x: f64, sig: usize) -> String {
    let s = human(x, sig);
    let (mantissa, exp) = match s.split_once('e') {
        Some((m, e)) => (m.to_string(), format!("e{e}")),
        None => (s.clone(), String::new()),
    };
    if !mantissa.contains('.') {
        return s;
    }
    let m = mantissa.trim_end_matches('0').trim_end_matches('.');
    format!("{m}{exp}")
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
    fn numbers() {
        assert_eq!(num(0.75), "0.75");
        assert_eq!(num(1e300), "1e300");
        assert_eq!(num(1.5e-7), "1.5e-7");
        assert_eq!(num(f64::INFINITY), "inf");
        assert_eq!(num(f64::NAN), "NaN");
        assert_eq!(num(-2.0), "-2");
        assert_eq!(human(0.750_123, 3), "0.750");
        assert_eq!(human(121.34, 4), "121.3");
        assert_eq!(human(54500.0, 3), "54500");
        assert_eq!(human(1.2e7, 3), "1.20e7");
        assert_eq!(
            difference(3.05e-3, 3.0e-3, 1e3, "ms"),
            "+0.0500 ms (+1.7 %)"
        );
        assert_eq!(difference(0.7506, 0.75, 1.0, ""), "+0.0006 (+0.1 %)");
        assert_eq!(given(3.120, 4), "3.12");
        assert_eq!(given(3e-3 * 1e3, 4), "3");
        assert_eq!(given(1.05e6, 4), "1.05e6");
        assert_eq!(given(54500.0, 4), "54500");
    }

    #[test]
    fn csv_quoting() {
        assert_eq!(csv_field("plain"), "plain");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    }
}
