//! Oblique bounces as measured (docs/oblique.md §9): one row an impact, with the columns
//! `v0,angle_deg,spin_in,vx_out,vy_out[,spin_out]` (m/s, degrees, rad/s), read by the same
//! table reader as the COR tables (`table`: quoting, BOM, separators, line and column in
//! every error).

use super::table::{self, ColumnSpec};
use super::{MeasuredError, check_points};

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
    ColumnSpec {
        name: "v0",
        aliases: &[("v0", 1.0), ("v0_m_s", 1.0), ("speed", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "angle_deg",
        aliases: &[("angle_deg", 1.0), ("angle", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "spin_in",
        aliases: &[("spin_in", 1.0), ("spin_in_rad_s", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "vx_out",
        aliases: &[("vx_out", 1.0), ("vx_out_m_s", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "vy_out",
        aliases: &[("vy_out", 1.0), ("vy_out_m_s", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "spin_out",
        aliases: &[("spin_out", 1.0), ("spin_out_rad_s", 1.0)],
        required: false,
    },
];

/// The rows of an oblique-bounce table; `spin_out` is given on every row or on none (a fit
/// of κ needs it throughout). Errors name the cell.
pub fn parse_oblique(text: &str) -> Result<Vec<ObliqueRow>, MeasuredError> {
    let p = table::read(text, &SPECS)?;
    check_points(&p)?;
    let at =
        |k: usize, i: usize, why: String| MeasuredError::at(p.lines[i], p.cell_columns[k][i], why);
    let finite = |k: usize, i: usize| -> Result<f64, MeasuredError> {
        match p.columns[k][i] {
            Some(v) if v.is_finite() && v.abs() <= 1e9 => Ok(v),
            Some(v) => Err(at(k, i, format!("{} {v} must be finite", SPECS[k].name))),
            None => Err(at(k, i, format!("{} is missing", SPECS[k].name))),
        }
    };
    let spins = p.columns[5].iter().filter(|s| s.is_some()).count();
    let mut rows = Vec::with_capacity(p.lines.len());
    for i in 0..p.lines.len() {
        let v0 = finite(0, i)?;
        if v0 <= 0.0 {
            return Err(at(0, i, format!("v0 {v0} must be positive")));
        }
        // a speed no impact runs at is the cell's fault (exit 2 at its place), not the fit's
        // "no starting point" (exit 1; issue 54 item 9, tests/cli/field_names.rs)
        use crate::model::params::MEANINGFUL_MIN;
        if v0 < MEANINGFUL_MIN {
            return Err(at(
                0,
                i,
                format!(
                    "v0 {} is out of the range a measurement can have (1e-15 … 1e9)",
                    crate::text::number(v0)
                ),
            ));
        }
        let angle_deg = finite(1, i)?;
        if !(angle_deg > 0.0 && angle_deg <= 90.0) {
            return Err(at(
                1,
                i,
                format!("angle_deg {angle_deg} must lie in (0, 90]"),
            ));
        }
        if v0 * angle_deg.to_radians().sin() < MEANINGFUL_MIN {
            return Err(at(
                1,
                i,
                format!(
                    "angle_deg {}: the normal speed v0 sin θ falls below 1e-15 m/s",
                    crate::text::number(angle_deg)
                ),
            ));
        }
        let vy_out = finite(4, i)?;
        if vy_out < 0.0 {
            return Err(at(
                4,
                i,
                format!("vy_out {vy_out} must be ≥ 0 (away from the surface)"),
            ));
        }
        let spin_out = match p.columns[5][i] {
            Some(_) => Some(finite(5, i)?),
            None if spins > 0 => {
                return Err(at(
                    5,
                    i,
                    "spin_out is missing: give it on every row or on none".into(),
                ));
            }
            None => None,
        };
        rows.push(ObliqueRow {
            v0,
            angle_deg,
            spin_in: finite(2, i)?,
            vx_out: finite(3, i)?,
            vy_out,
            spin_out,
            line: p.lines[i],
        });
    }
    if rows.is_empty() {
        return Err(MeasuredError::at(p.end_line, 1, "no data rows"));
    }
    Ok(rows)
}
