//! `fit_oblique`: μ and K_t (and κ when the outgoing spin is measured) fitted to oblique
//! bounces, as `bouncelab fit --oblique FILE` (docs/oblique.md §9): the same reader
//! (`measured::parse_oblique`), the same library function (`Ball::fit_oblique_watched`) and
//! the same report, turned into a dict through the command line's JSON (serde_json), so the
//! keys, their order and the values are the command line's.

use crate::arguments::ball::ball_pyfunction;
use crate::{batch::read_text, floats, value_error};
use bouncelab::api::ObliqueFitReport;
use bouncelab::measured::{MeasuredError, parse_oblique};
use pyo3::prelude::*;
use std::fmt::Write;
use std::path::PathBuf;

/// The columns of the table, in the order the reader takes them.
const COLUMNS: [&str; 6] = ["v0", "angle_deg", "spin_in", "vx_out", "vy_out", "spin_out"];

/// The arrays as the CSV text the command line reads (shortest round trip of each number, an
/// empty `spin_out` cell where it is NaN: not measured).
fn table_text(cols: &[Vec<f64>]) -> String {
    let mut text = COLUMNS[..cols.len()].join(",");
    text.push('\n');
    for i in 0..cols[0].len() {
        for (k, col) in cols.iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            if !(k == 5 && col[i].is_nan()) {
                let _ = write!(text, "{:?}", col[i]);
            }
        }
        text.push('\n');
    }
    text
}

/// A reader's error about the arrays: "oblique row N, `column`: message" (row 0 the first).
fn array_error(e: MeasuredError, text: &str) -> PyErr {
    let row = e.line.saturating_sub(2);
    // the column named by where its cell starts on the line
    let line = text.lines().nth(e.line.saturating_sub(1)).unwrap_or("");
    let before = line
        .chars()
        .take(e.column.saturating_sub(1))
        .collect::<String>();
    let name = COLUMNS.get(before.matches(',').count()).unwrap_or(&"row");
    value_error(format!("oblique row {row}, {name}: {}", e.message))
}

/// The rows: from `file` (errors `FILE:LINE:COLUMN: message`, as the command line's) or from
/// the arrays (errors naming the row and the column).
fn rows(
    file: Option<PathBuf>,
    arrays: [Option<&Bound<'_, PyAny>>; 6],
) -> PyResult<(Vec<bouncelab::measured::ObliqueRow>, Option<String>)> {
    let given = arrays.iter().filter(|a| a.is_some()).count();
    if let Some(path) = file {
        if given > 0 {
            return Err(value_error(
                "give the bounces as a file or as arrays, not both".into(),
            ));
        }
        let text = read_text(&path)?;
        let shown = path.display().to_string();
        let rows = parse_oblique(&text)
            .map_err(|e| value_error(format!("{shown}:{}:{}: {}", e.line, e.column, e.message)))?;
        return Ok((rows, Some(shown)));
    }
    let mut cols = Vec::new();
    for (k, a) in arrays.iter().enumerate() {
        match a {
            Some(a) => cols.push(floats(a, COLUMNS[k])?),
            None if k == 5 => break,
            None => {
                return Err(value_error(format!(
                    "{} is missing: give a file or the arrays v0, angle_deg, spin_in, vx_out, \
                     vy_out (and spin_out)",
                    COLUMNS[k]
                )));
            }
        }
    }
    if cols[0].is_empty() {
        // not the reader's "no data rows after the header" of the text made of them
        return Err(value_error("invalid v0: no value given".into()));
    }
    if let Some(k) = cols.iter().position(|c| c.len() != cols[0].len()) {
        return Err(value_error(format!(
            "v0 and {} differ in length ({} and {})",
            COLUMNS[k],
            cols[0].len(),
            cols[k].len()
        )));
    }
    let text = table_text(&cols);
    let rows = parse_oblique(&text).map_err(|e| array_error(e, &text))?;
    Ok((rows, None))
}

ball_pyfunction! {
    /// μ and K_t (and κ with `spin_out`) fitted to oblique bounces, as `bouncelab fit --oblique
    /// FILE`: a CSV file `v0,angle_deg,spin_in,vx_out,vy_out[,spin_out]` or the same columns as
    /// arrays. Returns the command line's JSON document as a dict (`file` None for arrays).
    signature = (file=None, *, v0=None, angle_deg=None, spin_in=None, vx_out=None, vy_out=None, spin_out=None, preset="superball", law=None, params=None,);
    fn fit_oblique<'py>(
        py,
        file: Option<PathBuf>,
        v0: Option<&Bound<'py, PyAny>>,
        angle_deg: Option<&Bound<'py, PyAny>>,
        spin_in: Option<&Bound<'py, PyAny>>,
        vx_out: Option<&Bound<'py, PyAny>>,
        vy_out: Option<&Bound<'py, PyAny>>,
        spin_out: Option<&Bound<'py, PyAny>>,
        preset: &str,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyAny>>;
    ball choice = (preset, params, law);
    {
        let (rows, shown) = rows(file, [v0, angle_deg, spin_in, vx_out, vy_out, spin_out])?;
        let ball = choice.ball(None)?;
        let report: ObliqueFitReport =
            crate::interrupt::detach_watched(py, |w| ball.fit_oblique_watched(&rows, shown, w))?;
        let d = crate::answer::json(py, &report)?;
        // the ball the fit started from, as the command line's `ball`
        d.set_item("ball", &crate::answer::Record::of(&ball))?;
        // the rigid plate the fit assumed, as every answer's surface dict gives it (∞ as inf,
        // where the JSON writes null), and the conditions, as the command line's JSON
        d.set_item("surface", crate::surface::rigid_plate(py)?)?;
        d.set_item("conditions", &crate::answer::Stated::of(&ball))?;
        Ok(d)
    }
}
