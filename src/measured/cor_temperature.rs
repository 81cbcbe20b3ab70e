//! CORs measured at several temperatures (docs/model.md §10.4, `fit --cor-temperature`): one
//! row a measurement, columns `temperature_c`, `v0` (m/s), `cor` and optionally `cor_sd`;
//! read by the same table reader as the COR tables (`table`: quoting, BOM, separators, line
//! and column in every error).

use super::MeasuredError;
use super::points;
use super::table::ColumnSpec;

/// One COR at a temperature, SI (°C for the temperature, as typed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CorTemperatureRow {
    /// The ball's temperature, °C.
    pub temperature_c: f64,
    /// Impact speed, m/s.
    pub v0: f64,
    /// The measured COR.
    pub cor: f64,
    /// Its standard deviation, where the file gives one.
    pub sd: Option<f64>,
    /// The row's line in the file.
    pub line: usize,
}

const SPECS: [ColumnSpec; 4] = [
    ColumnSpec::required("temperature", &[("temperature_c", 1.0)]),
    ColumnSpec::required("impact speed", &[("v0", 1.0), ("v0_m_s", 1.0)]),
    ColumnSpec::required("COR", &[("cor", 1.0)]),
    ColumnSpec::optional("COR standard deviation", &[("cor_sd", 1.0)]),
];

/// The rows of `text`: `temperature_c,v0,cor[,cor_sd]`. Temperatures above −273.15 °C, speeds
/// positive, CORs in [0, 1], deviations positive; at most `MAX_POINTS` rows.
pub fn parse_cor_temperature(text: &str) -> Result<Vec<CorTemperatureRow>, MeasuredError> {
    let p = points::read(text, &SPECS)?;
    points::each_row(&p, |row| {
        let t = row.value(0);
        if t.is_nan() || t <= -crate::conditions::ZERO_CELSIUS {
            return Err(row.error(0, "temperature must lie above −273.15 °C"));
        }
        let v0 = row.positive(1, "v0 must be positive")?;
        let cor = row.value(2);
        if !(0.0..=1.0).contains(&cor) {
            return Err(row.error(2, "cor must lie in [0, 1]"));
        }
        Ok(CorTemperatureRow {
            temperature_c: t,
            v0,
            cor,
            sd: row.positive_if_given(3, "cor_sd must be positive")?,
            line: row.line(),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_read_and_bad_cells_named() {
        let rows = parse_cor_temperature("temperature_c,v0,cor,cor_sd\n23,3,0.5,0.01\n45,3,0.6,\n")
            .unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(
            (rows[0].temperature_c, rows[0].v0, rows[0].cor),
            (23.0, 3.0, 0.5)
        );
        assert_eq!(
            (rows[0].sd, rows[1].sd, rows[1].line),
            (Some(0.01), None, 3)
        );
        let e = parse_cor_temperature("temperature_c,v0,cor\n23,3,1.5\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 6), "{e}");
        let e = parse_cor_temperature("temperature_c,v0,cor\n-300,3,0.5\n").unwrap_err();
        assert!(e.message.contains("above −273.15"), "{e}");
        let e = parse_cor_temperature("v0,cor\n3,0.5\n").unwrap_err();
        assert!(e.message.contains("temperature"), "{e}");
    }
}
