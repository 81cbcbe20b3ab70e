//! Oblique bounces as measured (docs/oblique.md §9): one row an impact, with the columns
//! `v0,angle_deg,spin_in,vx_out,vy_out[,spin_out]` (m/s, degrees, rad/s), read by the same
//! table reader as the COR tables (`table`: quoting, BOM, separators, line and column in
//! every error).

use super::MeasuredError;
use super::points;
use super::table::ColumnSpec;

/// One measured oblique bounce, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObliqueRow {
    /// Incoming speed |v| (m/s), > 0.
    pub v0: f64,
    /// Angle of the incoming path to the surface (degrees), in (0, 90].
    pub angle_deg: f64,
    /// Incoming spin (rad/s, > 0 topspin).
    pub spin_in: f64,
    /// Outgoing tangential speed (m/s).
    pub vx_out: f64,
    /// Outgoing normal speed (m/s), away from the surface, ≥ 0.
    pub vy_out: f64,
    /// Outgoing spin (rad/s), when measured.
    pub spin_out: Option<f64>,
    /// The row's line in the file.
    pub line: usize,
}

const SPECS: [ColumnSpec; 6] = [
    ColumnSpec::required("v0", &[("v0", 1.0), ("v0_m_s", 1.0), ("speed", 1.0)]),
    ColumnSpec::required("angle_deg", &[("angle_deg", 1.0), ("angle", 1.0)]),
    ColumnSpec::required("spin_in", &[("spin_in", 1.0), ("spin_in_rad_s", 1.0)]),
    ColumnSpec::required("vx_out", &[("vx_out", 1.0), ("vx_out_m_s", 1.0)]),
    ColumnSpec::required("vy_out", &[("vy_out", 1.0), ("vy_out_m_s", 1.0)]),
    ColumnSpec::optional("spin_out", &[("spin_out", 1.0), ("spin_out_rad_s", 1.0)]),
];

/// The rows of an oblique-bounce table; `spin_out` is given on every row or on none (a fit
/// of κ needs it throughout). Errors name the cell.
pub fn parse_oblique(text: &str) -> Result<Vec<ObliqueRow>, MeasuredError> {
    let p = points::read(text, &SPECS)?;
    let spins = p.columns[5].iter().filter(|s| s.is_some()).count();
    let rows = points::each_row(&p, |row| {
        let finite = |k: usize| {
            let ok = |v: f64| v.is_finite() && v.abs() <= 1e9;
            row.checked(k, SPECS[k].name, ok, "be finite")
        };
        let v0 = finite(0)?;
        if v0 <= 0.0 {
            return Err(row.error(0, format!("v0 {v0} must be positive")));
        }
        // a speed no impact runs at is the cell's fault (exit 2 at its place), not the fit's
        // "no starting point" (exit 1; issue 54 item 9, tests/cli/field_names.rs)
        use crate::model::params::MEANINGFUL_MIN;
        if v0 < MEANINGFUL_MIN {
            return Err(row.error(
                0,
                format!(
                    "v0 {} is out of the range a measurement can have (1e-15 … 1e9)",
                    crate::text::number(v0)
                ),
            ));
        }
        let angle_deg = finite(1)?;
        if !(angle_deg > 0.0 && angle_deg <= 90.0) {
            return Err(row.error(1, format!("angle_deg {angle_deg} must lie in (0, 90]")));
        }
        if v0 * angle_deg.to_radians().sin() < MEANINGFUL_MIN {
            return Err(row.error(
                1,
                format!(
                    "angle_deg {}: the normal speed v0 sin θ falls below 1e-15 m/s",
                    crate::text::number(angle_deg)
                ),
            ));
        }
        let vy_out = finite(4)?;
        if vy_out < 0.0 {
            return Err(row.error(
                4,
                format!("vy_out {vy_out} must be ≥ 0 (away from the surface)"),
            ));
        }
        let spin_out = match row.get(5) {
            Some(_) => Some(finite(5)?),
            None if spins > 0 => {
                return Err(row.error(5, "spin_out is missing: give it on every row or on none"));
            }
            None => None,
        };
        Ok(ObliqueRow {
            v0,
            angle_deg,
            spin_in: finite(2)?,
            vx_out: finite(3)?,
            vy_out,
            spin_out,
            line: row.line(),
        })
    })?;
    if rows.is_empty() {
        return Err(MeasuredError::at(p.end_line, 1, "no data rows"));
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::parse_oblique;

    #[test]
    fn a_cell_out_of_range_is_named_at_its_place() {
        let head = "v0,angle_deg,spin_in,vx_out,vy_out,spin_out\n";
        let e = parse_oblique(&format!("{head}10,30,0,-2e9,2,0\n")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 9), "{e}");
        assert!(
            e.message.contains("vx_out -2000000000 must be finite"),
            "{e}"
        );
        let e = parse_oblique(&format!("{head}10,30,0,5,2,2e9\n")).unwrap_err();
        assert_eq!((e.line, e.column), (2, 13), "{e}");
        assert!(
            e.message.contains("spin_out 2000000000 must be finite"),
            "{e}"
        );
    }
}
