//! Static deflections of a ball squeezed between two plates (`fit --static`, docs/fitting.md
//! "Joint calibration"): one row a load, its mass in kg (`load_kg`) and the shortening of the
//! diameter it caused (`deflection_m`, or `deflection_mm`), optionally the reading's standard
//! deviation (`deflection_sd_m`, `deflection_sd_mm`). Read by the same table reader as the
//! COR tables (`table`: quoting, BOM, separators, line and column in every error).

use super::MeasuredError;
use super::points;
use super::table::ColumnSpec;

/// One static deflection, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticRow {
    /// The load's mass, kg (> 0); each plate's contact carries its weight.
    pub load_kg: f64,
    /// The shortening of the diameter between the plates, m (> 0).
    pub deflection: f64,
    /// The reading's standard deviation, m, where the file gives one.
    pub sd: Option<f64>,
    /// The row's line in the file.
    pub line: usize,
}

const SPECS: [ColumnSpec; 3] = [
    ColumnSpec::required("load", &[("load_kg", 1.0), ("load_g", 1e-3)]),
    ColumnSpec::required(
        "deflection",
        &[("deflection_m", 1.0), ("deflection_mm", 1e-3)],
    ),
    ColumnSpec::optional(
        "deflection standard deviation",
        &[("deflection_sd_m", 1.0), ("deflection_sd_mm", 1e-3)],
    ),
];

/// The static deflections in `text`: `load_kg` (or `load_g`), `deflection_m` (or
/// `deflection_mm`), optionally `deflection_sd_m` (`deflection_sd_mm`). Loads and deflections
/// must be positive, standard deviations positive; at most `MAX_POINTS` rows.
pub fn parse_static(text: &str) -> Result<Vec<StaticRow>, MeasuredError> {
    let p = points::read(text, &SPECS)?;
    // (each cell is named by its place: its value in SI would not read as typed)
    let rows = points::each_row(&p, |row| {
        Ok(StaticRow {
            load_kg: row.positive(0, "load must be positive")?,
            deflection: row.positive(1, "deflection must be positive")?,
            sd: row.positive_if_given(2, "deflection standard deviation must be positive")?,
            line: row.line(),
        })
    })?;
    if rows.is_empty() {
        return Err(MeasuredError::at(
            p.end_line,
            1,
            "no static deflection rows",
        ));
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deflections_are_read_in_their_units() {
        let rows =
            parse_static("# ITF\nload_kg;deflection_mm;deflection_sd_mm\n8,165;6,5;0,1\n2;1,6;\n")
                .unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].load_kg, 8.165);
        assert!((rows[0].deflection - 6.5e-3).abs() < 1e-15);
        assert!((rows[0].sd.unwrap() - 1e-4).abs() < 1e-15);
        assert_eq!((rows[1].sd, rows[1].line), (None, 4));
    }

    #[test]
    fn bad_rows_are_named_at_their_cell() {
        let e = parse_static("load_kg,deflection_m\n1,0.001\n0,0.002\n").unwrap_err();
        assert_eq!((e.line, e.column), (3, 1), "{e}");
        let e = parse_static("load_kg,deflection_m\n1,-0.001\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3), "{e}");
        let e = parse_static("load_kg,deflection_m,deflection_sd_m\n1,0.001,0\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 9), "{e}");
        assert!(parse_static("load_kg,deflection_m\n").is_err());
        assert!(parse_static("load_kg\n1\n").is_err());
    }
}
