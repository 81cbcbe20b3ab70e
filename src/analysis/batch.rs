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

use crate::measured::rows::{self, Row};
use crate::measured::{self, Data, MeasuredError, RowTable, Source};
use std::collections::HashMap;

pub use super::batch_stats::{BatchStats, stats, stats_in};
/// The mean's Student interval, as the summary takes it (a ball's readings too: api::batch_reading).
pub use super::mc_interval::mean_interval;

/// Header names of the column naming each ball (compared in lower case).
pub const ID_COLUMN: &str = "id";
/// Header names of a column giving each ball's force–time trace as a file path.
pub const TRACE_COLUMNS: [&str; 3] = ["trace", "trace_file", "force_time"];

/// The most balls one batch takes: the bound on a whole run (issue 54 item 9). Each ball's fit
/// is held to the work limit by itself (`analysis::work`), some 5–50 ms on one core; a batch
/// of 10⁵ balls ran for hours, holding every outcome. A batch beyond it is refused at the
/// first ball past the bound, before any fit: split the file.
pub const MAX_BALLS: usize = 10_000;

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

/// The rows of one ball being gathered: its id and its rows (the batch's, id cell kept).
struct Group {
    id: String,
    rows: Vec<Row>,
}

/// Split a batch into its balls, in the order they come, each ball's data read. The batch is
/// read by the measured readers' own rows ([`crate::measured::rows`], the `csv` crate: a BOM,
/// quoted fields and headers, LF, CRLF and CR line ends, `#` comments), and each ball's rows
/// are handed to [`measured::read_any`] as rows, so a ball's data are read as `bouncelab fit`
/// reads a file of one ball and every error names the batch's own line and column (a batch
/// once split its lines by hand: a BOM made its header `\u{feff}id` and a quoted header
/// `"id"`, neither an id column; tests/cli/cli_batch_csv.rs).
pub fn split(text: &str) -> Result<Vec<BallRows>, MeasuredError> {
    let text = rows::normalized(text);
    let sep = rows::separator(&text);
    let mut lines = rows::Rows::new(&text, sep);
    let Some(header) = lines.next().transpose()? else {
        return Err(MeasuredError::at(1, 1, "no data: the file is empty"));
    };
    let hline = header.line;
    let names: Vec<String> = header.cells.iter().map(|c| c.text.to_lowercase()).collect();
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
    let header = without_cell(&header, id_col);
    groups
        .into_iter()
        .map(|g| match trace_col {
            Some(k) => trace_ball(&g, k),
            None => table_ball(g, &header, sep, id_col),
        })
        .collect()
}

/// A row with cell `k` taken out (the others keep their places in the batch).
fn without_cell(row: &Row, k: usize) -> Row {
    let mut row = row.clone();
    row.cells.remove(k);
    row
}

/// Rows gathered by ball: consecutive rows with one id; an id seen before, after another
/// ball's rows, is an error at its line.
fn group_rows(
    lines: impl Iterator<Item = Result<Row, MeasuredError>>,
    sep: u8,
    fields: usize,
    id_col: usize,
) -> Result<Vec<Group>, MeasuredError> {
    let mut groups: Vec<Group> = Vec::new();
    let mut first_line: HashMap<String, usize> = HashMap::new();
    for row in lines {
        let row = row?;
        rows::check_width(&row, fields, sep)?;
        let cell = &row.cells[id_col];
        let (ln, col) = (cell.line, cell.column);
        let id = cell.text.clone();
        if id.is_empty() {
            return Err(MeasuredError::at(
                ln,
                col,
                "empty id: name the ball of every row",
            ));
        }
        if let Some(g) = groups.last_mut().filter(|g| g.id == id) {
            g.rows.push(row);
            continue;
        }
        if let Some(first) = first_line.get(&id) {
            return Err(MeasuredError::at(
                ln,
                col,
                format!(
                    "id '{}' again: its rows began at line {first}, and a ball's rows must be \
                     consecutive (another ball's rows came between)",
                    crate::sanitize::line(&id.chars().take(40).collect::<String>())
                ),
            ));
        }
        if groups.len() == MAX_BALLS {
            return Err(MeasuredError::at(
                ln,
                col,
                format!(
                    "ball {} of the batch: a batch takes at most {MAX_BALLS} balls (split the \
                     file into batches of at most {MAX_BALLS})",
                    MAX_BALLS + 1
                ),
            ));
        }
        first_line.insert(id.clone(), row.line);
        groups.push(Group {
            id,
            rows: vec![row],
        });
    }
    Ok(groups)
}

/// A ball whose data are a trace file: one row, the path its cell.
fn trace_ball(g: &Group, k: usize) -> Result<BallRows, MeasuredError> {
    if let Some(row) = g.rows.get(1) {
        return Err(MeasuredError::at(
            row.line,
            1,
            format!(
                "ball '{}' has a second trace: one trace file per ball",
                crate::sanitize::line(&g.id)
            ),
        ));
    }
    let cell = &g.rows[0].cells[k];
    if cell.text.is_empty() {
        return Err(MeasuredError::at(
            cell.line,
            cell.column,
            "empty trace cell: give the trace's file",
        ));
    }
    Ok(BallRows {
        id: g.id.clone(),
        line: g.rows[0].line,
        rows: 1,
        data: BallData::TraceFile {
            path: cell.text.clone(),
            line: cell.line,
            column: cell.column,
        },
    })
}

/// A ball whose rows are data: the header and its rows, without the id cells, read by
/// [`measured::read_any`] (each cell keeps its place in the batch, so its errors do).
fn table_ball(g: Group, header: &Row, sep: u8, id_col: usize) -> Result<BallRows, MeasuredError> {
    let line = g.rows[0].line;
    let count = g.rows.len();
    let end_line = g.rows[count - 1].line + 1;
    let rows: Vec<Row> = g.rows.iter().map(|r| without_cell(r, id_col)).collect();
    let data = measured::read_any(Source::Rows(RowTable {
        sep,
        header,
        rows: &rows,
        end_line,
    }))?;
    Ok(BallRows {
        id: g.id,
        line,
        rows: count,
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
        // each drop carries its line in the batch (the hand-split batch gave the lines of
        // the ball's own sub-table, 2 and 3)
        assert_eq!(d.drops, vec![(2.54, 1.40, 3), (2.54, 1.42, 4)]);
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
                // the cell's first character that is not blank, as the measured readers place
                // every cell
                column: 4
            }
        );
        let e = split("id,trace\nA,a.csv\nA,b.csv\n").unwrap_err();
        assert!(e.message.contains("second trace"), "{e}");
    }
}
