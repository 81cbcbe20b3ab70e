//! Measured data read from text: force–time traces, COR-against-speed tables and drop tests
//! (docs/fitting.md). Parsing from `&str`; reading a file at the edge (a regular file, a size
//! limit, UTF-8) is `bounded`'s, its errors worded for the command line by `file` (with the
//! `tui` feature). Every error carries
//! the 1-based line and column it is about.

pub mod bounded;
mod court;
mod drop;
mod oblique;
mod points;
// reading a data file from disk: anyhow, which the `tui` and `cli` features bring
mod cor_temperature;
#[cfg(feature = "tui")]
pub mod file;
pub mod overlay;
mod pressure;
pub mod rows;
mod statics;
mod stop;
mod table;
mod trace;

pub use cor_temperature::{CorTemperatureRow, parse_cor_temperature};
pub use court::{CourtRow, parse_court};
pub use drop::{Air, DropTest, Flight, G, cor_per_rebound_height, drop_to_cor, drops_to_points};
pub use oblique::{ObliqueRow, parse_oblique};
pub use pressure::{PressureRow, parse_pressure};
pub use statics::{StaticRow, parse_static};
pub use stop::stop_on;
pub use table::{MAX_ROWS, RowTable, Source};
pub use trace::{Trace, TraceSummary};

use std::fmt;
use table::ColumnSpec;

/// What is wrong with a measured-data text, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MeasuredError {
    /// 1-based line of the text.
    pub line: usize,
    /// 1-based column (of the cell at fault, or of the line's start).
    pub column: usize,
    /// What is wrong, one line.
    pub message: String,
}

impl MeasuredError {
    /// An error at `line`:`column`.
    pub fn at(line: usize, column: usize, message: impl Into<String>) -> MeasuredError {
        MeasuredError {
            line,
            column,
            message: message.into(),
        }
    }
}

impl fmt::Display for MeasuredError {
    /// `line:column: message`; the caller puts the file name in front.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.column, self.message)
    }
}

impl std::error::Error for MeasuredError {}

/// One COR measurement, SI, with what else was measured at that speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CorPoint {
    /// Impact speed, m/s.
    pub v0: f64,
    /// Measured coefficient of restitution.
    pub cor: f64,
    /// Standard deviation of `cor` (weights the fit), if given.
    pub cor_sd: Option<f64>,
    /// Where `cor_sd` is not given, this row's COR error relative to the other rows' (1: all
    /// alike, as in a COR table): the fit divides the row's miss by it times the scale it
    /// finds from the misses, so the row weighs by its own precision while the intervals
    /// still take their size from the data. A drop test sets it from the reading of the
    /// rebound height, σ_e ∝ ∂e/∂R ([`cor_per_rebound_height`], docs/fitting.md):
    /// a COR read from a low rebound weighs less.
    pub cor_sd_relative: f64,
    /// Peak force measured at this speed, N, if given.
    pub max_force: Option<f64>,
    /// Contact time measured at this speed, s, if given.
    pub contact_time: Option<f64>,
    /// Line of the file it came from (0: the command line).
    pub line: usize,
}

impl CorPoint {
    /// A COR `cor` at `v0` (m/s) with nothing else measured, not from a file (line 0).
    pub fn new(v0: f64, cor: f64) -> CorPoint {
        CorPoint {
            v0,
            cor,
            cor_sd: None,
            cor_sd_relative: 1.0,
            max_force: None,
            contact_time: None,
            line: 0,
        }
    }
}

/// COR against impact speed.
#[derive(Debug, Clone, PartialEq)]
pub struct CorTable {
    /// The measurements, in the file's order.
    pub points: Vec<CorPoint>,
    /// The line after the last one read, for errors about the whole table.
    pub end_line: usize,
}

/// Measured data of any kind, as found in a file.
#[derive(Debug, Clone, PartialEq)]
pub enum Data {
    /// A force–time trace (columns time and force).
    Trace(Trace),
    /// A COR-against-speed table (columns v0 and cor, optionally more).
    Cor(CorTable),
    /// Drop and rebound heights.
    Drop(DropTest),
}

impl Data {
    /// What the data are, as messages name them: "force-time trace", "COR table", "drop test".
    pub fn kind(&self) -> &'static str {
        match self {
            Data::Trace(_) => "force-time trace",
            Data::Cor(_) => "COR table",
            Data::Drop(_) => "drop test",
        }
    }
}

const COR_SPECS: [ColumnSpec; 5] = [
    ColumnSpec::required(
        "impact speed",
        &[("v0", 1.0), ("v0_m_s", 1.0), ("speed", 1.0)],
    ),
    ColumnSpec::required("COR", &[("cor", 1.0), ("e", 1.0)]),
    ColumnSpec::optional("COR standard deviation", &[("cor_sd", 1.0)]),
    ColumnSpec::optional(
        "peak force",
        &[
            ("max_force_n", 1.0),
            ("max_force", 1.0),
            ("max_force_kn", 1e3),
        ],
    ),
    ColumnSpec::optional(
        "contact time",
        &[
            ("contact_time_s", 1.0),
            ("contact_time", 1.0),
            ("contact_time_ms", 1e-3),
            ("contact_time_us", 1e-6),
        ],
    ),
];

/// A measured quantity in its domain, or an error at its cell naming it: positive (else "must
/// be positive", as before) and within the physically meaningful range the model's own
/// parameters keep (`model::params::check_positive`, 1e-15 … 1e15), or below `max` where the
/// quantity has a tighter bound (a COR's standard deviation, at most 1). A value outside it is
/// the file's fault, exit 2 at its place, not a fit with no starting point
/// (tests/analysis/measured_readers.rs, `out_of_domain_numbers_are_named_at_their_cell`).
fn in_domain(
    row: &points::Cells<'_>,
    k: usize,
    name: &str,
    max: f64,
) -> Result<Option<f64>, MeasuredError> {
    use crate::model::params::{MEANINGFUL_MAX, MEANINGFUL_MIN};
    let at = |why: String| row.error(k, why);
    match row.get(k) {
        Some(v) if v <= 0.0 => Err(at(format!("{name} {v} must be positive"))),
        Some(v) if !(MEANINGFUL_MIN..=max.min(MEANINGFUL_MAX)).contains(&v) => Err(at(format!(
            "{name} {} is out of the range a measurement can have ({} … {})",
            crate::text::number(v),
            crate::text::number(MEANINGFUL_MIN),
            crate::text::number(max.min(MEANINGFUL_MAX))
        ))),
        v => Ok(v),
    }
}

/// Most rows of a COR table or drop test: each is one impact per evaluation of the fit, and
/// ten thousand measured impacts is already far beyond any series a lab takes.
pub const MAX_POINTS: usize = 10_000;

impl CorTable {
    /// Columns `v0`/`v0_m_s`/`speed`, `cor`/`e`; optional `cor_sd`, `max_force_N`,
    /// `contact_time_s` (or `_ms`, `_us`).
    pub fn parse(text: &str) -> Result<CorTable, MeasuredError> {
        CorTable::read(text.into())
    }

    /// [`CorTable::parse`] of a text or of rows already read (a batch's ball).
    pub fn read(src: Source<'_>) -> Result<CorTable, MeasuredError> {
        let p = points::read(src, &COR_SPECS)?;
        let points = points::each_row(&p, |row| {
            let cor = row.value(1);
            if !(0.0..=1.0).contains(&cor) {
                return Err(row.error(1, format!("COR {cor} must lie in [0, 1]")));
            }
            Ok(CorPoint {
                v0: in_domain(&row, 0, "impact speed", f64::MAX)?.unwrap_or(f64::NAN),
                cor,
                cor_sd: in_domain(&row, 2, "COR standard deviation", 1.0)?,
                cor_sd_relative: 1.0,
                max_force: in_domain(&row, 3, "peak force", f64::MAX)?,
                contact_time: in_domain(&row, 4, "contact time", f64::MAX)?,
                line: row.line(),
            })
        })?;
        Ok(CorTable {
            points,
            end_line: p.end_line,
        })
    }
}

/// Read measured data of whichever kind the header names: the kind that knows the most of its
/// column names (drop tests, then traces, first on a tie), a COR table when none knows any.
/// `time_ms,forse_N` is so a trace whose reader blames `forse_N`, not a COR table that blames
/// `time_ms` (tests/analysis/measured_readers.rs, `the_misspelt_column_is_blamed`).
pub fn parse_any(text: &str) -> Result<Data, MeasuredError> {
    read_any(text.into())
}

/// [`parse_any`] of a text or of rows already read (a batch's ball: `analysis::batch`).
pub fn read_any(src: Source<'_>) -> Result<Data, MeasuredError> {
    let names = table::header_names(src).unwrap_or_default();
    let known = |specs: &[ColumnSpec]| {
        names
            .iter()
            .filter(|n| {
                specs
                    .iter()
                    .any(|s| s.aliases.iter().any(|a| a.0 == n.as_str()))
            })
            .count()
    };
    let (drops, trace, cor) = (known(&drop::SPECS), known(&trace::SPECS), known(&COR_SPECS));
    if drops > 0 && drops >= trace && drops >= cor {
        DropTest::read(src).map(Data::Drop)
    } else if trace > 0 && trace >= cor {
        Trace::read(src).map(Data::Trace)
    } else {
        CorTable::read(src).map(Data::Cor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cor_table_reads_units_weights_and_decimal_commas() {
        let t = CorTable::parse(
            "# air cannon\nv0;cor;cor_sd;contact_time_ms\n1,5;0,8;0,01;3,1\n3;0,7;;\n",
        )
        .unwrap();
        assert_eq!(t.points.len(), 2);
        assert_eq!(t.points[0].v0, 1.5);
        assert_eq!(t.points[0].cor_sd, Some(0.01));
        assert!((t.points[0].contact_time.unwrap() - 3.1e-3).abs() < 1e-15);
        assert_eq!(t.points[1].cor_sd, None);
        assert_eq!(t.points[1].line, 4);
    }

    #[test]
    fn cor_table_errors_point_at_the_cell() {
        let e = CorTable::parse("v0,cor\n1,0.5\n2,abc\n").unwrap_err();
        assert_eq!((e.line, e.column), (3, 3), "{e}");
        assert!(e.message.contains("'abc' is not a number"), "{e}");
        let e = CorTable::parse("v0,cor\n1,NaN\n").unwrap_err();
        assert!(e.message.contains("not a finite number"), "{e}");
        let e = CorTable::parse("v0,cor,colour\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, 8), "{e}");
        assert!(e.message.contains("unknown column 'colour'"), "{e}");
        let e = CorTable::parse("1,0.5\n2,0.4\n").unwrap_err();
        assert!(e.message.starts_with("no header"), "{e}");
        let e = CorTable::parse("v0,cor\n1,1.2\n").unwrap_err();
        assert!(e.message.contains("[0, 1]"), "{e}");
        let e = CorTable::parse("speed\n1\n").unwrap_err();
        assert!(e.message.contains("no COR column"), "{e}");
        let e = CorTable::parse("v0,cor\n").unwrap_err();
        assert!(e.message.contains("no data rows"), "{e}");
    }

    #[test]
    fn kinds_are_told_apart_by_header() {
        assert!(matches!(
            parse_any("t,F\n0,0\n1e-3,5\n"),
            Ok(Data::Trace(_))
        ));
        assert!(matches!(parse_any("v0,e\n1,0.5\n"), Ok(Data::Cor(_))));
        assert!(matches!(
            parse_any("drop_height_m,rebound_height_m\n1,0.5\n"),
            Ok(Data::Drop(_))
        ));
    }
}
