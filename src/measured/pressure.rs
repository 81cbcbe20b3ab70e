//! Pressure readings of an inflated ball over time (docs/model.md §10.3, `fit
//! --pressure-loss`): one row a reading, a time column and a gauge-pressure column, each
//! with its unit in its name (`time_h`, `pressure_kpa`, …), and optionally the reading's
//! standard deviation; read by the same table reader as the COR tables (`table`: quoting,
//! BOM, separators, line and column in every error).

use super::MeasuredError;
use super::points;
use super::table::ColumnSpec;
use crate::conditions::pressure::PSI;

/// One pressure reading, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureRow {
    /// Time since inflation, s (≥ 0).
    pub time: f64,
    /// Gauge pressure, Pa.
    pub gauge: f64,
    /// The reading's standard deviation, Pa, where the file gives one.
    pub sd: Option<f64>,
    /// The row's line in the file.
    pub line: usize,
}

const SPECS: [ColumnSpec; 3] = [
    ColumnSpec::required(
        "time",
        &[
            ("time_s", 1.0),
            ("time_min", 60.0),
            ("time_h", 3600.0),
            ("time_d", 86_400.0),
        ],
    ),
    ColumnSpec::required(
        "gauge pressure",
        &[
            ("pressure_pa", 1.0),
            ("pressure_hpa", 100.0),
            ("pressure_mbar", 100.0),
            ("pressure_kpa", 1e3),
            ("pressure_bar", 1e5),
            ("pressure_psi", PSI),
        ],
    ),
    ColumnSpec::optional(
        "pressure standard deviation",
        &[
            ("pressure_sd_pa", 1.0),
            ("pressure_sd_hpa", 100.0),
            ("pressure_sd_mbar", 100.0),
            ("pressure_sd_kpa", 1e3),
            ("pressure_sd_bar", 1e5),
            ("pressure_sd_psi", PSI),
        ],
    ),
];

/// The readings in `text`: a time column (`time_s`, `time_min`, `time_h`, `time_d`), a gauge
/// pressure column (`pressure_pa`, `_hpa`, `_mbar`, `_kpa`, `_bar`, `_psi`) and optionally
/// `pressure_sd_…` in the same units. Times must not be negative, pressures finite, standard
/// deviations positive; at most `MAX_POINTS` rows.
pub fn parse_pressure(text: &str) -> Result<Vec<PressureRow>, MeasuredError> {
    let p = points::read(text, &SPECS)?;
    points::each_row(&p, |row| {
        let time = row.value(0);
        if time.is_nan() || time < 0.0 {
            // the cell is named by its place: its value in SI would not read as typed
            return Err(row.error(0, "time must not be negative"));
        }
        Ok(PressureRow {
            time,
            sd: row.positive_if_given(2, "pressure standard deviation must be positive")?,
            gauge: row.value(1),
            line: row.line(),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn readings_are_read_in_their_units() {
        let rows = parse_pressure(
            "# FIFA 72 h test\ntime_h,pressure_bar,pressure_sd_kpa\n0,0.8,0.5\n72,0.66,\n",
        )
        .unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].time, 0.0);
        assert_eq!(rows[0].gauge, 80_000.0);
        assert_eq!(rows[0].sd, Some(500.0));
        assert_eq!(rows[1].time, 72.0 * 3600.0);
        assert!((rows[1].gauge - 66_000.0).abs() < 1e-9);
        assert_eq!((rows[1].sd, rows[1].line), (None, 4));
        let psi = parse_pressure("time_d;pressure_psi\n1;8,5\n").unwrap();
        assert!((psi[0].gauge - 8.5 * PSI).abs() < 1e-9);
    }

    #[test]
    fn bad_readings_are_named_at_their_cell() {
        let e = parse_pressure("time_h,pressure_kpa\n-1,80\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 1), "{e}");
        assert!(e.message.contains("must not be negative"), "{e}");
        let e = parse_pressure("time_h,pressure_kpa,pressure_sd_kpa\n1,80,0\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 6), "{e}");
        let e = parse_pressure("time_h,pressure\n1,80\n").unwrap_err();
        assert!(e.message.contains("unknown column 'pressure'"), "{e}");
        let e = parse_pressure("pressure_kpa\n80\n").unwrap_err();
        assert!(e.message.contains("no time column"), "{e}");
    }
}
