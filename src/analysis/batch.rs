//! A batch of balls in one measured-data table (docs/batch.md): an `id` column names the ball
//! of each row, the other columns are those the measured readers take (drop tests, COR
//! tables, a force–time trace, or a `trace` column naming each ball's trace file).
//! Consecutive rows with the same id are one ball tested several times; an id coming back
//! after another ball's rows is refused, naming its line.
//!
//! Each ball's rows are handed to the readers of [`crate::measured`] as a table of their own
//! (the header and the ball's rows, the id cell taken out), so a batch reads each ball's
//! data exactly as `bouncelab fit` reads a file of one ball; the errors point at the batch's
//! own line and column. The summary over the balls' verdicts is `super::batch_stats`.

use crate::measured::{self, Data, MeasuredError};
use std::collections::HashMap;

pub use super::batch_stats::{BatchStats, stats, stats_in};
/// The mean's Student interval, as the summary takes it (a ball's readings too: api::batch_reading).
pub use super::mc_interval::mean_interval;

/// Header names of the column naming each ball (compared in lower case).
pub const ID_COLUMN: &str = "id";
/// Header names of a column giving each ball's force–time trace as a file path.
pub const TRACE_COLUMNS: [&str; 3] = ["trace", "trace_file", "force_time"];

/// One ball's data as the batch gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum BallData {
    /// Rows of the table, read as `bouncelab fit` reads a file.
    Measured(Data),
    /// A trace in a file of its own: the path as written, and where the batch names it.
    TraceFile {
        /// The cell's text.
        path: String,
        /// Its line in the batch.
        line: usize,
        /// Its column in the batch.
        column: usize,
    },
}

/// One ball of a batch: its id, the batch's line its rows begin at, how many rows, its data.
#[derive(Debug, Clone, PartialEq)]
pub struct BallRows {
    /// The id cell (surrounding blanks trimmed).
    pub id: String,
    /// 1-based line of its first row.
    pub line: usize,
    /// Rows it has.
    pub rows: usize,
    /// Its data.
    pub data: BallData,
}

/// Lines that hold something (not blank, not a `#` comment), with their 1-based numbers, as
/// the measured readers skip them (src/measured/table.rs).
fn content_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('#')
        })
}

/// The separator the measured readers read off the header: tab, then `;`, then `,`.
fn separator(header: &str) -> char {
    if header.contains('\t') {
        '\t'
    } else if header.contains(';') {
        ';'
    } else {
        ','
    }
}

/// Cells of a line as written (blanks kept) with the 1-based character column each starts at.
fn raw_cells(line: &str, sep: char) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut col = 1;
    for cell in line.split(sep) {
        out.push((col, cell));
        col += cell.chars().count() + 1;
    }
    out
}

/// A line with cell `k` taken out, and (from, width): a column at or past `from` in the
/// shortened line was `width` columns further right in the batch.
fn without_cell(line: &str, sep: char, k: usize) -> (String, (usize, usize)) {
    let cells = raw_cells(line, sep);
    let kept: Vec<&str> = cells
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != k)
        .map(|(_, c)| c.1)
        .collect();
    let (start, cell) = cells[k];
    let shift = if k + 1 < cells.len() {
        (start, cell.chars().count() + 1)
    } else {
        // the last cell: what precedes it keeps its columns
        (usize::MAX, 0)
    };
    (kept.join(&sep.to_string()), shift)
}

/// The rows of one ball being gathered.
struct Group<'a> {
    id: &'a str,
    /// (batch line, the line's text) of each row.
    rows: Vec<(usize, &'a str)>,
}

/// Split a batch into its balls, in the order they come, each ball's data read.
pub fn split(text: &str) -> Result<Vec<BallRows>, MeasuredError> {
    let mut lines = content_lines(text);
    let Some((hline, header)) = lines.next() else {
        return Err(MeasuredError::at(1, 1, "no data: the file is empty"));
    };
    let sep = separator(header);
    let names: Vec<String> = raw_cells(header, sep)
        .iter()
        .map(|c| c.1.trim().to_lowercase())
        .collect();
    let Some(id_col) = names.iter().position(|n| n == ID_COLUMN) else {
        return Err(MeasuredError::at(
            hline,
            1,
            "no id column: a batch names the ball of each row in a column 'id'",
        ));
    };
    if names.len() < 2 {
        return Err(MeasuredError::at(
            hline,
            1,
            "only an id column: name the data columns too (drop_height_m,rebound_height_m; \
             v0,cor; or trace)",
        ));
    }
    let trace_col = names
        .iter()
        .position(|n| TRACE_COLUMNS.contains(&n.as_str()));
    if trace_col.is_some() && names.len() != 2 {
        return Err(MeasuredError::at(
            hline,
            1,
            "a batch of trace files has two columns: id and trace",
        ));
    }
    let groups = group_rows(lines, sep, names.len(), id_col)?;
    if groups.is_empty() {
        return Err(MeasuredError::at(
            hline + 1,
            1,
            "no data rows after the header",
        ));
    }
    groups
        .into_iter()
        .map(|g| match trace_col {
            Some(k) => trace_ball(&g, sep, k),
            None => table_ball(&g, (hline, header), sep, id_col),
        })
        .collect()
}

/// Rows gathered by ball: consecutive rows with one id; an id seen before, after another
/// ball's rows, is an error at its line.
fn group_rows<'a>(
    lines: impl Iterator<Item = (usize, &'a str)>,
    sep: char,
    fields: usize,
    id_col: usize,
) -> Result<Vec<Group<'a>>, MeasuredError> {
    let mut groups: Vec<Group<'a>> = Vec::new();
    let mut first_line: HashMap<&'a str, usize> = HashMap::new();
    for (ln, line) in lines {
        let cells = raw_cells(line, sep);
        if cells.len() != fields {
            return Err(MeasuredError::at(
                ln,
                cells.last().map_or(1, |c| c.0),
                format!(
                    "{} fields, but the header names {fields} (separator '{}')",
                    cells.len(),
                    sep.escape_default()
                ),
            ));
        }
        let (col, cell) = cells[id_col];
        let id = cell.trim();
        if id.is_empty() {
            return Err(MeasuredError::at(
                ln,
                col,
                "empty id: name the ball of every row",
            ));
        }
        if let Some(g) = groups.last_mut().filter(|g| g.id == id) {
            g.rows.push((ln, line));
            continue;
        }
        if let Some(first) = first_line.get(id) {
            return Err(MeasuredError::at(
                ln,
                col,
                format!(
                    "id '{}' again: its rows began at line {first}, and a ball's rows must be \
                     consecutive (another ball's rows came between)",
                    id.chars().take(40).collect::<String>()
                ),
            ));
        }
        first_line.insert(id, ln);
        groups.push(Group {
            id,
            rows: vec![(ln, line)],
        });
    }
    Ok(groups)
}

/// A ball whose data are a trace file: one row, the path its cell.
fn trace_ball(g: &Group<'_>, sep: char, k: usize) -> Result<BallRows, MeasuredError> {
    if let Some(&(ln, _)) = g.rows.get(1) {
        return Err(MeasuredError::at(
            ln,
            1,
            format!(
                "ball '{}' has a second trace: one trace file per ball",
                g.id
            ),
        ));
    }
    let (line, text) = g.rows[0];
    let (column, cell) = raw_cells(text, sep)[k];
    let path = cell.trim();
    if path.is_empty() {
        return Err(MeasuredError::at(
            line,
            column,
            "empty trace cell: give the trace's file",
        ));
    }
    Ok(BallRows {
        id: g.id.to_string(),
        line,
        rows: 1,
        data: BallData::TraceFile {
            path: path.to_string(),
            line,
            column,
        },
    })
}

/// A ball whose rows are data: the header and its rows, without the id column, read by
/// [`measured::parse_any`]; an error's line and column put back where the batch has them.
fn table_ball(
    g: &Group<'_>,
    (hline, header): (usize, &str),
    sep: char,
    id_col: usize,
) -> Result<BallRows, MeasuredError> {
    let mut text = String::new();
    // batch line and column shift of each line of `text`
    let mut origin = Vec::with_capacity(g.rows.len() + 1);
    for &(ln, line) in std::iter::once(&(hline, header)).chain(&g.rows) {
        let (short, shift) = without_cell(line, sep, id_col);
        text.push_str(&short);
        text.push('\n');
        origin.push((ln, shift));
    }
    let data = measured::parse_any(&text).map_err(|e| {
        let (line, (from, width)) = origin
            .get(e.line.saturating_sub(1))
            .copied()
            // past the last row: the line after the ball's rows
            .unwrap_or((g.rows[g.rows.len() - 1].0 + 1, (usize::MAX, 0)));
        let column = if e.column >= from {
            e.column + width
        } else {
            e.column
        };
        MeasuredError::at(line, column, e.message)
    })?;
    Ok(BallRows {
        id: g.id.to_string(),
        line: g.rows[0].0,
        rows: g.rows.len(),
        data: BallData::Measured(data),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn consecutive_rows_are_one_ball() {
        let b = split(
            "# lot 7\nid,drop_height_m,rebound_height_m\nA,2.54,1.40\nA,2.54,1.42\n\nB,2.54,1.30\n",
        )
        .unwrap();
        assert_eq!(b.len(), 2);
        assert_eq!((b[0].id.as_str(), b[0].line, b[0].rows), ("A", 3, 2));
        assert_eq!((b[1].id.as_str(), b[1].line, b[1].rows), ("B", 6, 1));
        let BallData::Measured(Data::Drop(d)) = &b[0].data else {
            panic!("{:?}", b[0].data)
        };
        assert_eq!(d.drops, vec![(2.54, 1.40, 2), (2.54, 1.42, 3)]);
    }

    /// The id column anywhere: the other cells keep their columns in errors.
    #[test]
    fn errors_point_at_the_batch_line_and_column() {
        let e = split("v0,id,cor\n1,A,0.5\n1,B,x\n").unwrap_err();
        assert_eq!((e.line, e.column), (3, 5), "{e}");
        assert!(e.message.contains("'x' is not a number"), "{e}");
        let e = split("id;v0;cor\nA;1;0,5\nlong-name;2;1,5\n").unwrap_err();
        assert_eq!((e.line, e.column), (3, 13), "{e}");
        let e = split("v0,cor,id\n1,2,A\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3), "{e}");
    }

    #[test]
    fn an_id_coming_back_is_refused_at_its_line() {
        let e = split("id,v0,cor\nA,1,0.5\nB,1,0.6\nA,2,0.4\n").unwrap_err();
        assert_eq!((e.line, e.column), (4, 1), "{e}");
        assert!(e.message.contains("line 2"), "{e}");
        let e = split("id,v0,cor\nA,1,0.5\n ,1,0.6\n").unwrap_err();
        assert!(e.message.contains("empty id"), "{e}");
        let e = split("v0,cor\n1,0.5\n").unwrap_err();
        assert!(e.message.contains("no id column"), "{e}");
        let e = split("id,v0,cor\nA,1\n").unwrap_err();
        assert_eq!(e.line, 2, "{e}");
    }

    #[test]
    fn trace_files_one_per_ball() {
        let b = split("id,trace\nA, a.csv\nB,b.csv\n").unwrap();
        assert_eq!(
            b[0].data,
            BallData::TraceFile {
                path: "a.csv".into(),
                line: 2,
                column: 3
            }
        );
        let e = split("id,trace\nA,a.csv\nA,b.csv\n").unwrap_err();
        assert!(e.message.contains("second trace"), "{e}");
    }
}
