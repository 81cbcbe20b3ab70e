//! A delimited text table as measured data comes: `#` comment lines and blank lines skipped, a
//! header row naming the columns, then numbers. The rows are the `csv` crate's ([`rows`]:
//! quoting, BOM, every line end); the separator is read off the header (tab, then `;`, then
//! `,`); with `;` a decimal comma (`0,75`) is read as a decimal point. Errors carry the 1-based
//! line and column of the cell at fault.

use super::rows::{self, Cell, Row, Rows};
use super::{MeasuredError, stop};
use crate::text::parse;
use std::borrow::Cow;

/// Most data rows read: a million samples is far more than any force plate records in one
/// impact, and bounds the memory a wrong file can take.
pub const MAX_ROWS: usize = 1_000_000;

/// A column a reader accepts: names (lower case), each with the factor to SI.
pub struct ColumnSpec {
    /// Canonical name, used in messages.
    pub name: &'static str,
    /// (accepted header name, factor to SI)
    pub aliases: &'static [(&'static str, f64)],
    /// Whether the column must be present (optional columns may also have empty cells).
    pub required: bool,
}

impl ColumnSpec {
    /// A column the file must have.
    pub const fn required(name: &'static str, aliases: &'static [(&'static str, f64)]) -> Self {
        Self {
            name,
            aliases,
            required: true,
        }
    }

    /// A column the file may leave out (or leave empty on a row).
    pub const fn optional(name: &'static str, aliases: &'static [(&'static str, f64)]) -> Self {
        Self {
            name,
            aliases,
            required: false,
        }
    }
}

/// Parsed numbers, SI, one `Vec` per spec (`None`: column absent or cell empty), and the
/// line of each row.
#[derive(Debug, Clone, PartialEq)]
pub struct Parsed {
    pub columns: Vec<Vec<Option<f64>>>,
    pub lines: Vec<usize>,
    /// Column (1-based) of each spec's cells in the text, per row: for errors found later.
    pub cell_columns: Vec<Vec<usize>>,
    /// Line after the last one read (for errors about the whole file).
    pub end_line: usize,
}

/// Where a table's rows come from: a text (a file's), or rows already read from one by
/// [`rows::Rows`] — a batch's ball, the header and that ball's rows with their id cells taken
/// out (`analysis::batch`), each cell keeping the line and column it has in the batch, so
/// both are read by one reader and every error points at the file's own place.
#[derive(Debug, Clone, Copy)]
pub enum Source<'a> {
    /// A whole table as text.
    Text(&'a str),
    /// Rows already read.
    Rows(RowTable<'a>),
}

/// A table already cut into rows ([`Source::Rows`]).
#[derive(Debug, Clone, Copy)]
pub struct RowTable<'a> {
    /// The separator the rows were read with (for the decimal comma of `;`).
    pub sep: u8,
    /// The header row.
    pub header: &'a Row,
    /// The data rows.
    pub rows: &'a [Row],
    /// The line after the last row, for errors about the whole table.
    pub end_line: usize,
}

impl<'a> From<&'a str> for Source<'a> {
    fn from(text: &'a str) -> Self {
        Source::Text(text)
    }
}

/// Lowered header names of a table, or `None` when it has no header line (used to tell the
/// kinds of data apart).
pub fn header_names<'a>(src: impl Into<Source<'a>>) -> Option<Vec<String>> {
    let lowered = |h: &Row| h.cells.iter().map(|c| c.text.to_lowercase()).collect();
    match src.into() {
        Source::Text(text) => {
            let text = rows::normalized(text);
            let header = Rows::new(&text, rows::separator(&text)).next()?.ok()?;
            Some(lowered(&header))
        }
        Source::Rows(t) => Some(lowered(t.header)),
    }
}

/// Read `text` against `specs`, every row kept ([`read_each`] for the COR tables and drop
/// tests, which are small).
pub fn read<'a>(src: impl Into<Source<'a>>, specs: &[ColumnSpec]) -> Result<Parsed, MeasuredError> {
    let mut parsed = Parsed {
        columns: vec![Vec::new(); specs.len()],
        lines: Vec::new(),
        cell_columns: vec![Vec::new(); specs.len()],
        end_line: 0,
    };
    parsed.end_line = read_each(src, specs, |line, values| {
        for (k, &(v, col)) in values.iter().enumerate() {
            parsed.columns[k].push(v);
            parsed.cell_columns[k].push(col);
        }
        parsed.lines.push(line);
        Ok(())
    })?;
    Ok(parsed)
}

/// A bound on the data rows of `text` (its line ends, at most [`MAX_ROWS`]), to reserve room
/// for them once.
pub fn rows_at_most(src: Source<'_>) -> usize {
    match src {
        Source::Text(text) => (rows::newlines(text) + 1).min(MAX_ROWS),
        Source::Rows(t) => t.rows.len().min(MAX_ROWS),
    }
}

/// Read `text` against `specs`, handing each data row to `each` as it is read — its line,
/// and per spec its value in SI (`None`: column absent or cell empty) and the column of its
/// cell — and keeping none: a million-row trace is held once, in its reader's own vectors
/// (issue 30 item 4: ≤ 100 MB; tests/fit_memory.rs counts the bytes). Returns the line
/// after the last one read (for errors about the whole file).
pub fn read_each<'a>(
    src: impl Into<Source<'a>>,
    specs: &[ColumnSpec],
    each: impl FnMut(usize, &[(Option<f64>, usize)]) -> Result<(), MeasuredError>,
) -> Result<usize, MeasuredError> {
    match src.into() {
        Source::Text(text) => {
            let text = rows::normalized(text);
            let sep = rows::separator(&text);
            let mut lines = Rows::new(&text, sep);
            let Some(header) = lines.next().transpose()? else {
                return Err(MeasuredError::at(1, 1, "no data: the file is empty"));
            };
            read_rows(sep, &header, lines, specs, each)?;
            let end = rows::line_count(&text) + 1;
            if stop::stopped() {
                return Err(MeasuredError::at(end, 1, "interrupted"));
            }
            Ok(end)
        }
        Source::Rows(t) => {
            read_rows(t.sep, t.header, t.rows.iter().cloned().map(Ok), specs, each)?;
            Ok(t.end_line)
        }
    }
}

/// Rows read between two looks at the stop flag (`measured::stop_on`): some milliseconds of
/// parsing on a release build, well under a second on a debug one.
const ROWS_PER_LOOK: usize = 4096;

/// The data rows after `header`, each handed to `each` ([`read_each`]).
fn read_rows(
    sep: u8,
    header: &Row,
    lines: impl Iterator<Item = Result<Row, MeasuredError>>,
    specs: &[ColumnSpec],
    mut each: impl FnMut(usize, &[(Option<f64>, usize)]) -> Result<(), MeasuredError>,
) -> Result<(), MeasuredError> {
    let map = header_map(header, specs)?;
    let mut values = vec![(None, 0); specs.len()];
    let mut count = 0;
    for row in lines {
        let row = row?;
        if count % ROWS_PER_LOOK == 0 && stop::stopped() {
            return Err(MeasuredError::at(row.line, 1, "interrupted"));
        }
        if count == MAX_ROWS {
            return Err(MeasuredError::at(
                row.line,
                1,
                format!("more than {MAX_ROWS} data rows: not one measurement"),
            ));
        }
        rows::check_width(&row, map.len(), sep)?;
        values.fill((None, 0));
        for (cell, slot) in row.cells.iter().zip(&map) {
            let (k, factor) = *slot;
            values[k] = (
                cell_value(cell, sep, &specs[k])?.map(|v| v * factor),
                cell.column,
            );
        }
        each(row.line, &values)?;
        count += 1;
    }
    if count == 0 {
        return Err(MeasuredError::at(
            header.line + 1,
            1,
            "no data rows after the header",
        ));
    }
    Ok(())
}

/// Which spec (and factor) each header cell is; every required spec present once.
fn header_map(header: &Row, specs: &[ColumnSpec]) -> Result<Vec<(usize, f64)>, MeasuredError> {
    let line = header.line;
    if let Some(cell) = header.cells.iter().find(|c| c.text.parse::<f64>().is_ok()) {
        return Err(cell.error(format!(
            "no header: '{}' is a number; the first line must name the columns ({})",
            escape(&cell.text),
            expected(specs)
        )));
    }
    let mut map = Vec::new();
    for cell in &header.cells {
        let name = cell.text.to_lowercase();
        let found = specs.iter().enumerate().find_map(|(k, s)| {
            s.aliases
                .iter()
                .find(|(a, _)| *a == name)
                .map(|(_, f)| (k, *f))
        });
        let Some((k, f)) = found else {
            return Err(cell.error(format!(
                "unknown column '{}' (expected {})",
                escape(&cell.text),
                expected(specs)
            )));
        };
        if map.iter().any(|&(j, _)| j == k) {
            return Err(cell.error(format!(
                "column '{}' gives {} a second time",
                escape(&cell.text),
                specs[k].name
            )));
        }
        map.push((k, f));
    }
    if let Some(missing) = specs
        .iter()
        .enumerate()
        .find(|(k, s)| s.required && !map.iter().any(|&(j, _)| j == *k))
    {
        let names: Vec<&str> = missing.1.aliases.iter().map(|a| a.0).collect();
        return Err(MeasuredError::at(
            line,
            1,
            format!(
                "no {} column (name one {})",
                missing.1.name,
                names.join(", ")
            ),
        ));
    }
    Ok(map)
}

fn expected(specs: &[ColumnSpec]) -> String {
    specs
        .iter()
        .map(|s| s.aliases.iter().map(|a| a.0).collect::<Vec<_>>().join("/"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Hostile characters escaped visibly (`crate::sanitize::line`), at most 40 characters, so a
/// message stays one harmless line.
fn escape(s: &str) -> String {
    let cut: String = s.chars().take(40).collect();
    crate::sanitize::line(&cut).into_owned()
}

/// A cell's number in the unit of its column: read by the command line's own reader
/// (`text::parse::read`, so `1e-400` is refused here as there), finite; empty only in an
/// optional column.
fn cell_value(cell: &Cell, sep: u8, spec: &ColumnSpec) -> Result<Option<f64>, MeasuredError> {
    if cell.text.is_empty() {
        return if spec.required {
            Err(cell.error(format!("empty {} cell", spec.name)))
        } else {
            Ok(None)
        };
    }
    // a decimal comma (0,75) where `;` separates the cells
    let text = if sep == b';' && !cell.text.contains('.') {
        Cow::Owned(cell.text.replacen(',', ".", 1))
    } else {
        Cow::Borrowed(cell.text.as_str())
    };
    let shown = escape(&cell.text);
    match parse::read(&text) {
        Ok(v) if v.is_finite() => Ok(Some(v)),
        Ok(_) => Err(cell.error(format!("{} '{shown}' is not a finite number", spec.name))),
        Err(why) => Err(cell.error(format!("{} {}", spec.name, parse::refusal(&shown, why)))),
    }
}
