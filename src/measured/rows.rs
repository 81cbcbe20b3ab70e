//! The rows of a delimited text as spreadsheets write it, read by the `csv` crate: RFC 4180
//! quoting (`"time_ms","force_N"`, a separator or a quote inside quotes), a UTF-8 BOM (Excel's
//! "CSV UTF-8"), LF, CRLF and CR-only (classic Mac) line ends; `#` comment lines and blank
//! lines skipped. Each cell comes with the 1-based line and column it starts at, for the
//! messages (tests/analysis/measured_readers.rs, `spreadsheet_files_are_read`).

use super::MeasuredError;
use std::borrow::Cow;

/// One cell: its text (trimmed, quotes removed) and where it starts in the file.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// The text, trimmed, quotes removed.
    pub text: String,
    /// 1-based line it starts at.
    pub line: usize,
    /// 1-based column (in characters) of its first character that is not blank.
    pub column: usize,
}

impl Cell {
    /// `message` at this cell's line and column.
    pub fn error(&self, message: impl Into<String>) -> MeasuredError {
        MeasuredError::at(self.line, self.column, message)
    }
}

/// One row: its line (where it starts) and its cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// 1-based line it starts at.
    pub line: usize,
    /// Its cells.
    pub cells: Vec<Cell>,
}

/// Bytes scanned between two looks at the stop flag (`measured::stop_on`): some milliseconds
/// on a debug build, where a whole 19 MB trace took a second a scan (issue 54 item 6).
const SCAN_CHUNK: usize = 1 << 18;

/// Whether `pred` holds for some byte index of `b`, looked for in chunks; `false` once the
/// stop flag is set (the rows' first look then stops the read).
fn any_index(b: &[u8], pred: impl Fn(usize) -> bool) -> bool {
    (0..b.len())
        .step_by(SCAN_CHUNK)
        .take_while(|_| !super::stop::stopped())
        .any(|from| (from..(from + SCAN_CHUNK).min(b.len())).any(&pred))
}

/// The line feeds in `text`, counted in chunks; fewer once the stop flag is set (the read
/// is then abandoned: `table::read_each`).
pub fn newlines(text: &str) -> usize {
    text.as_bytes()
        .chunks(SCAN_CHUNK)
        .take_while(|_| !super::stop::stopped())
        .map(|c| c.iter().filter(|&&b| b == b'\n').count())
        .sum()
}

/// The text as the csv crate is given it: a UTF-8 BOM dropped (it is no part of the first
/// column's name) and every lone CR turned into LF. csv-core ends records at CR, LF and CRLF
/// alike, but ends comment lines and counts lines at LF only; a lone CR → LF keeps every byte
/// offset, so the places below hold for every line end.
pub fn normalized(text: &str) -> Cow<'_, str> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let b = text.as_bytes();
    let lone_cr = |i: usize| b[i] == b'\r' && b.get(i + 1) != Some(&b'\n');
    if !any_index(b, lone_cr) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        out.push(if c == '\r' && chars.peek() != Some(&'\n') {
            '\n'
        } else {
            c
        });
    }
    Cow::Owned(out)
}

/// Lines of a normalized text (LF, or CRLF, ends), 1-based; the number of lines.
pub fn line_count(text: &str) -> usize {
    newlines(text) + 1 - usize::from(text.is_empty() || text.ends_with('\n'))
}

/// The separator, read off the first line that is neither blank nor a comment: tab, then `;`,
/// then `,` (quoted text left out, so `"force; N",time` is comma-separated).
pub fn separator(text: &str) -> u8 {
    let header = text
        .split('\n')
        .map(|l| l.trim())
        .find(|l| !l.is_empty() && !l.starts_with('#'))
        .unwrap_or("");
    let unquoted: String = header.split('"').step_by(2).collect();
    if unquoted.contains('\t') {
        b'\t'
    } else if unquoted.contains(';') {
        b';'
    } else {
        b','
    }
}

/// Where the reading is: a byte offset and its line and column (1-based, in characters).
struct Cursor {
    byte: usize,
    line: usize,
    column: usize,
}

impl Cursor {
    /// Move on to byte `to` (not before the cursor), counting lines and characters.
    fn advance(&mut self, text: &str, to: usize) {
        for c in text[self.byte..to].chars() {
            if c == '\n' {
                self.line += 1;
                self.column = 1;
            } else {
                self.column += 1;
            }
        }
        self.byte = to;
    }
}

/// The rows of a normalized text separated by `sep`.
pub struct Rows<'a> {
    text: &'a str,
    records: csv::Reader<&'a [u8]>,
    record: csv::StringRecord,
    /// csv-core on one record again: the raw length of each field, which `csv` does not tell
    fields: csv_core::Reader,
    scratch: Vec<u8>,
    sep: char,
    cursor: Cursor,
}

impl<'a> Rows<'a> {
    /// The rows of `text` (already [`normalized`]) separated by `sep` ([`separator`]).
    pub fn new(text: &'a str, sep: u8) -> Rows<'a> {
        let records = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .delimiter(sep)
            .comment(Some(b'#'))
            .from_reader(text.as_bytes());
        Rows {
            text,
            records,
            record: csv::StringRecord::new(),
            fields: csv_core::ReaderBuilder::new().delimiter(sep).build(),
            scratch: vec![0; 4096],
            sep: char::from(sep),
            cursor: Cursor {
                byte: 0,
                line: 1,
                column: 1,
            },
        }
    }

    /// Where the record read from `from` starts: past the line ends and `#` comment lines
    /// csv-core skips there.
    fn record_start(&self, mut from: usize) -> usize {
        let b = self.text.as_bytes();
        loop {
            match b.get(from) {
                Some(b'\r' | b'\n') => from += 1,
                Some(b'#') => {
                    from = b[from..]
                        .iter()
                        .position(|&c| c == b'\n')
                        .map_or(b.len(), |i| from + i + 1)
                }
                _ => return from,
            }
        }
    }

    /// The field offsets of a record written without quotes (most data rows), found without a
    /// second parse: each field's text stands in the file as read, followed by the separator
    /// (or the line end). `None` when a field does not (it was quoted): then [`Self::field_starts`].
    fn unquoted_starts(&self, start: usize) -> Option<(Vec<usize>, usize)> {
        let b = self.text.as_bytes();
        let (mut at, mut starts) = (start, Vec::with_capacity(self.record.len()));
        for (k, field) in self.record.iter().enumerate() {
            let end = at + field.len();
            if b.get(at..end)? != field.as_bytes() {
                return None;
            }
            starts.push(at);
            let last = k + 1 == self.record.len();
            match b.get(end) {
                Some(&c) if !last && c == self.sep as u8 => at = end + 1,
                Some(b'\r' | b'\n') | None if last => return Some((starts, end)),
                _ => return None,
            }
        }
        None
    }

    /// The byte offset each field of the record at `start` begins at, and the record's end.
    fn field_starts(&mut self, start: usize) -> (Vec<usize>, usize) {
        self.fields.reset();
        let input = &self.text.as_bytes()[start..];
        let (mut at, mut starts) = (0, vec![start]);
        loop {
            let (res, nin, _) = self.fields.read_field(&input[at..], &mut self.scratch);
            at += nin;
            match res {
                csv_core::ReadFieldResult::Field { record_end: true }
                | csv_core::ReadFieldResult::End => return (starts, start + at),
                csv_core::ReadFieldResult::Field { record_end: false } => starts.push(start + at),
                // the input is all there: an empty call ends the last field
                csv_core::ReadFieldResult::InputEmpty if at < input.len() => {}
                csv_core::ReadFieldResult::InputEmpty => {
                    if let (csv_core::ReadFieldResult::Field { .. }, ..) =
                        self.fields.read_field(&[], &mut self.scratch)
                    {
                        return (starts, start + at);
                    }
                    return (starts, input.len() + start);
                }
                csv_core::ReadFieldResult::OutputFull => {}
            }
        }
    }

    /// The next record as a row, `None` at the end.
    fn next_row(&mut self) -> Result<Option<Row>, MeasuredError> {
        let from = self.cursor.byte;
        let read = self.records.read_record(&mut self.record).map_err(|e| {
            let line = e.position().map_or(self.cursor.line, |p| p.line() as usize);
            MeasuredError::at(line, 1, format!("unreadable: {e}"))
        })?;
        if !read {
            return Ok(None);
        }
        let read_from = self.record.position().map_or(0, |p| p.byte() as usize);
        let start = self.record_start(from.max(read_from));
        let (starts, end) = match self.unquoted_starts(start) {
            Some(found) => found,
            None => self.field_starts(start),
        };
        let mut cells = Vec::with_capacity(self.record.len());
        for (k, field) in self.record.iter().enumerate() {
            let at = starts.get(k).copied().unwrap_or(start);
            let raw_end = starts.get(k + 1).copied().unwrap_or(end);
            // the cell's first character that is not blank (a quote counts), within the field
            let lead: usize = self.text[at..raw_end.max(at)]
                .chars()
                .take_while(|&c| c.is_whitespace() && !matches!(c, '\n' | '\r') && c != self.sep)
                .map(char::len_utf8)
                .sum();
            self.cursor.advance(self.text, at + lead);
            cells.push(Cell {
                text: field.trim().to_string(),
                line: self.cursor.line,
                column: self.cursor.column,
            });
        }
        let line = cells.first().map_or(self.cursor.line, |c| c.line);
        self.cursor.advance(self.text, end.max(self.cursor.byte));
        Ok(Some(Row { line, cells }))
    }
}

impl Iterator for Rows<'_> {
    type Item = Result<Row, MeasuredError>;

    /// The next row that is neither blank (spaces only) nor an indented `#` comment.
    fn next(&mut self) -> Option<Self::Item> {
        loop {
            match self.next_row() {
                Ok(Some(row)) if is_blank_or_comment(&row) => continue,
                other => return other.transpose(),
            }
        }
    }
}

/// A row with as many cells as the header names (`fields`), or an error at its last cell
/// naming both counts and the separator `sep` the rows were read with.
pub fn check_width(row: &Row, fields: usize, sep: u8) -> Result<(), MeasuredError> {
    if row.cells.len() == fields {
        return Ok(());
    }
    let last = row.cells.last();
    Err(MeasuredError::at(
        last.map_or(row.line, |c| c.line),
        last.map_or(1, |c| c.column),
        format!(
            "{} fields, but the header names {fields} (separator '{}')",
            row.cells.len(),
            char::from(sep).escape_default()
        ),
    ))
}

fn is_blank_or_comment(row: &Row) -> bool {
    match row.cells.as_slice() {
        [only] if only.text.is_empty() => true,
        [first, ..] => first.text.starts_with('#'),
        [] => true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(text: &str) -> Vec<Vec<(String, usize, usize)>> {
        let text = normalized(text);
        Rows::new(&text, separator(&text))
            .map(|r| {
                r.unwrap()
                    .cells
                    .into_iter()
                    .map(|c| (c.text, c.line, c.column))
                    .collect()
            })
            .collect()
    }

    fn cell(t: &str, line: usize, column: usize) -> (String, usize, usize) {
        (t.to_string(), line, column)
    }

    #[test]
    fn line_ends_quotes_and_places() {
        let want = vec![
            vec![cell("t", 2, 1), cell("F", 2, 3)],
            vec![cell("0", 4, 1), cell("1.5", 4, 5)],
        ];
        for nl in ["\n", "\r\n", "\r"] {
            let text = format!("# rig{nl}t,F{nl}{nl}0,  1.5{nl}");
            assert_eq!(rows(&text), want, "{nl:?}");
        }
        assert_eq!(
            rows("\u{feff}\"t\",\"F, N\"\n 0 ,\"2\"\n"),
            vec![
                vec![cell("t", 1, 1), cell("F, N", 1, 5)],
                vec![cell("0", 2, 2), cell("2", 2, 5)],
            ]
        );
        // a quoted line break: the next cell is placed on the line after it
        assert_eq!(
            rows("\"a\nb\",c\n")[0],
            vec![cell("a\nb", 1, 1), cell("c", 2, 4)]
        );
        assert_eq!(rows("  # indented\n \nx\n"), vec![vec![cell("x", 3, 1)]]);
    }

    #[test]
    fn separators_and_line_counts() {
        assert_eq!(separator("# a;b\nt\tF\n"), b'\t');
        assert_eq!(separator("t;F\n"), b';');
        assert_eq!(separator("\"F; N\",t\n"), b',');
        assert_eq!(line_count(""), 0);
        assert_eq!(line_count("a\nb"), 2);
        assert_eq!(line_count("a\r\nb\r\n"), 2);
        assert_eq!(normalized("a\rb\r\nc\r").as_ref(), "a\nb\r\nc\n");
    }
}
