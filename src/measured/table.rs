//! A delimited text table as measured data comes: `#` comment lines and blank lines skipped, a
//! header row naming the columns, then numbers. The separator is read off the header (tab,
//! then `;`, then `,`); with `;` a decimal comma (`0,75`) is read as a decimal point. Errors
//! carry the 1-based line and column of the cell at fault.

use super::MeasuredError;

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

/// Lowered header names of a table, or `None` when it has no header line (used to tell the
/// kinds of data apart).
pub fn header_names(text: &str) -> Option<Vec<String>> {
    let (_, line) = content_lines(text).next()?;
    let sep = separator(line);
    Some(line.split(sep).map(|c| c.trim().to_lowercase()).collect())
}

fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('#')
        })
}

fn separator(header: &str) -> char {
    if header.contains('\t') {
        '\t'
    } else if header.contains(';') {
        ';'
    } else {
        ','
    }
}

/// Cells of one line with the 1-based character column each starts at.
fn cells(line: &str, sep: char) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut col = 1;
    for cell in line.split(sep) {
        let lead = cell.chars().take_while(|c| c.is_whitespace()).count();
        out.push((col + lead, cell.trim()));
        col += cell.chars().count() + 1;
    }
    out
}

/// Read `text` against `specs`.
pub fn read(text: &str, specs: &[ColumnSpec]) -> Result<Parsed, MeasuredError> {
    let mut lines = content_lines(text);
    let Some((hline, header)) = lines.next() else {
        return Err(MeasuredError::at(1, 1, "no data: the file is empty"));
    };
    let sep = separator(header);
    let map = header_map(hline, &cells(header, sep), specs)?;
    let mut parsed = Parsed {
        columns: vec![Vec::new(); specs.len()],
        lines: Vec::new(),
        cell_columns: vec![Vec::new(); specs.len()],
        end_line: text.lines().count() + 1,
    };
    for (ln, line) in lines {
        if parsed.lines.len() == MAX_ROWS {
            return Err(MeasuredError::at(
                ln,
                1,
                format!("more than {MAX_ROWS} data rows: not one measurement"),
            ));
        }
        let row = cells(line, sep);
        if row.len() != map.len() {
            return Err(MeasuredError::at(
                ln,
                row.last().map_or(1, |c| c.0),
                format!(
                    "{} fields, but the header names {} (separator '{}')",
                    row.len(),
                    map.len(),
                    sep.escape_default()
                ),
            ));
        }
        let mut values = vec![(None, 0); specs.len()];
        for ((col, cell), slot) in row.iter().zip(&map) {
            let (k, factor) = *slot;
            values[k] = (
                cell_value(ln, *col, cell, sep, &specs[k])?.map(|v| v * factor),
                *col,
            );
        }
        for (k, (v, col)) in values.into_iter().enumerate() {
            parsed.columns[k].push(v);
            parsed.cell_columns[k].push(col);
        }
        parsed.lines.push(ln);
    }
    if parsed.lines.is_empty() {
        return Err(MeasuredError::at(
            hline + 1,
            1,
            "no data rows after the header",
        ));
    }
    Ok(parsed)
}

/// Which spec (and factor) each header cell is; every required spec present once.
fn header_map(
    line: usize,
    header: &[(usize, &str)],
    specs: &[ColumnSpec],
) -> Result<Vec<(usize, f64)>, MeasuredError> {
    if let Some((col, cell)) = header.iter().find(|(_, c)| c.parse::<f64>().is_ok()) {
        return Err(MeasuredError::at(
            line,
            *col,
            format!(
                "no header: '{cell}' is a number; the first line must name the columns ({})",
                expected(specs)
            ),
        ));
    }
    let mut map = Vec::new();
    for (col, cell) in header {
        let name = cell.to_lowercase();
        let found = specs.iter().enumerate().find_map(|(k, s)| {
            s.aliases
                .iter()
                .find(|(a, _)| *a == name)
                .map(|(_, f)| (k, *f))
        });
        let Some((k, f)) = found else {
            return Err(MeasuredError::at(
                line,
                *col,
                format!(
                    "unknown column '{}' (expected {})",
                    escape(cell),
                    expected(specs)
                ),
            ));
        };
        if map.iter().any(|&(j, _)| j == k) {
            return Err(MeasuredError::at(
                line,
                *col,
                format!(
                    "column '{}' gives {} a second time",
                    escape(cell),
                    specs[k].name
                ),
            ));
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

/// Control characters escaped so a message stays one harmless line.
fn escape(s: &str) -> String {
    s.chars()
        .take(40)
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

fn cell_value(
    line: usize,
    col: usize,
    cell: &str,
    sep: char,
    spec: &ColumnSpec,
) -> Result<Option<f64>, MeasuredError> {
    if cell.is_empty() {
        return if spec.required {
            Err(MeasuredError::at(
                line,
                col,
                format!("empty {} cell", spec.name),
            ))
        } else {
            Ok(None)
        };
    }
    let text = if sep == ';' && !cell.contains('.') {
        cell.replacen(',', ".", 1)
    } else {
        cell.to_string()
    };
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(Some(v)),
        Ok(_) => Err(MeasuredError::at(
            line,
            col,
            format!("{} '{}' is not a finite number", spec.name, escape(cell)),
        )),
        Err(_) => Err(MeasuredError::at(
            line,
            col,
            format!("{} '{}' is not a number", spec.name, escape(cell)),
        )),
    }
}
