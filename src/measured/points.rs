//! The rows of a small measured table (a COR table, a drop test, static deflections,
//! pressure readings, oblique and court bounces) as each reader checks them: read by the one
//! table reader (`table`), at most [`MAX_POINTS`] rows, and each row's cells by their spec's
//! index, every error at the cell's own line and column.

use super::table::{self, ColumnSpec, Parsed, Source};
use super::{MAX_POINTS, MeasuredError};

/// `src` read against `specs`, refused at the first row past [`MAX_POINTS`].
pub(super) fn read<'a>(
    src: impl Into<Source<'a>>,
    specs: &[ColumnSpec],
) -> Result<Parsed, MeasuredError> {
    let p = table::read(src, specs)?;
    match p.lines.get(MAX_POINTS) {
        Some(&line) => Err(MeasuredError::at(
            line,
            1,
            format!("more than {MAX_POINTS} rows: a COR table or drop test is at most that"),
        )),
        None => Ok(p),
    }
}

/// Every row of `p` made into a `T` by `each`, in the file's order; the first error stops.
pub(super) fn each_row<T>(
    p: &Parsed,
    mut each: impl FnMut(Cells<'_>) -> Result<T, MeasuredError>,
) -> Result<Vec<T>, MeasuredError> {
    let mut out = Vec::with_capacity(p.lines.len());
    for i in 0..p.lines.len() {
        out.push(each(Cells { p, i })?);
    }
    Ok(out)
}

/// One data row: its cells by spec index (SI), and errors placed at them.
#[derive(Clone, Copy)]
pub(super) struct Cells<'p> {
    p: &'p Parsed,
    i: usize,
}

impl Cells<'_> {
    /// The row's line in the file.
    pub fn line(&self) -> usize {
        self.p.lines[self.i]
    }

    /// Spec `k`'s value (`None`: column absent or cell empty).
    pub fn get(&self, k: usize) -> Option<f64> {
        self.p.columns[k][self.i]
    }

    /// Spec `k`'s value, NaN where there is none (a required column always has one).
    pub fn value(&self, k: usize) -> f64 {
        self.get(k).unwrap_or(f64::NAN)
    }

    /// `why` at spec `k`'s cell.
    pub fn error(&self, k: usize, why: impl Into<String>) -> MeasuredError {
        MeasuredError::at(self.line(), self.p.cell_columns[k][self.i], why)
    }

    /// Spec `k`'s value where it is positive; otherwise (NaN too) `why` at its cell.
    pub fn positive(&self, k: usize, why: &str) -> Result<f64, MeasuredError> {
        match self.value(k) {
            v if v > 0.0 => Ok(v),
            _ => Err(self.error(k, why)),
        }
    }

    /// Spec `k`'s value where `ok` holds of it; otherwise, at its cell, `{name} {v} must
    /// {what}`, or `{name} is missing` where the cell is empty (`name`: the spec's).
    pub fn checked(
        &self,
        k: usize,
        name: &str,
        ok: impl Fn(f64) -> bool,
        what: &str,
    ) -> Result<f64, MeasuredError> {
        match self.get(k) {
            Some(v) if ok(v) => Ok(v),
            Some(v) => Err(self.error(k, format!("{name} {v} must {what}"))),
            None => Err(self.error(k, format!("{name} is missing"))),
        }
    }

    /// Spec `k`'s value where given, which must then be positive (else `why` at its cell).
    pub fn positive_if_given(&self, k: usize, why: &str) -> Result<Option<f64>, MeasuredError> {
        match self.get(k) {
            Some(v) if v <= 0.0 => Err(self.error(k, why)),
            v => Ok(v),
        }
    }
}
