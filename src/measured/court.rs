//! ITF court pace test bounces as measured (docs/oblique.md §6): one row a bounce, columns
//! `v_in,angle_in,v_out,angle_out` (m/s and degrees to the surface), read by the table reader
//! every measured file goes through (`table`: quoting, BOM, separators, line and column in
//! every error). Each row gives the ITF's two numbers: μ_app = (v_x,in − v_x,out)/(v_y,in +
//! v_y,out) and e = v_y,out/v_y,in.

use super::MeasuredError;
use super::points;
use super::table::ColumnSpec;

/// One measured bounce, SI (angles in degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CourtRow {
    /// Incoming speed (m/s), > 0.
    pub v_in: f64,
    /// Incoming angle to the surface (degrees), in (0, 90).
    pub angle_in: f64,
    /// Outgoing speed (m/s), > 0.
    pub v_out: f64,
    /// Outgoing angle to the surface (degrees), in (0, 90].
    pub angle_out: f64,
    /// The row's line in the file.
    pub line: usize,
}

impl CourtRow {
    /// (μ_app, e) of the bounce, the ITF's definitions.
    pub fn friction_and_cor(&self) -> (f64, f64) {
        let (a, b) = (self.angle_in.to_radians(), self.angle_out.to_radians());
        let (vx_in, vy_in) = (self.v_in * a.cos(), self.v_in * a.sin());
        let (vx_out, vy_out) = (self.v_out * b.cos(), self.v_out * b.sin());
        ((vx_in - vx_out) / (vy_in + vy_out), vy_out / vy_in)
    }
}

const SPECS: [ColumnSpec; 4] = [
    ColumnSpec::required("v_in", &[("v_in", 1.0), ("v_in_m_s", 1.0)]),
    ColumnSpec::required("angle_in", &[("angle_in", 1.0), ("angle_in_deg", 1.0)]),
    ColumnSpec::required("v_out", &[("v_out", 1.0), ("v_out_m_s", 1.0)]),
    ColumnSpec::required("angle_out", &[("angle_out", 1.0), ("angle_out_deg", 1.0)]),
];

/// The rows of a court test table. Errors name the cell.
pub fn parse_court(text: &str) -> Result<Vec<CourtRow>, MeasuredError> {
    let p = points::read(text, &SPECS)?;
    let speed = "be a positive speed (m/s, at most 1e9)";
    let rows = points::each_row(&p, |row| {
        let value = |k: usize, lo: f64, hi: f64, what: &str| {
            row.checked(k, SPECS[k].name, |v| v > lo && v <= hi, what)
        };
        let r = CourtRow {
            v_in: value(0, 1e-9, 1e9, speed)?,
            angle_in: value(1, 0.0, 89.999_999, "lie in (0, 90) degrees")?,
            v_out: value(2, 1e-9, 1e9, speed)?,
            angle_out: value(3, 0.0, 90.0, "lie in (0, 90] degrees")?,
            line: row.line(),
        };
        // a court gives back less than it gets: e = v_y,out/v_y,in below 1 (at v_out's cell,
        // the first of the rebound's two)
        let (_, e) = r.friction_and_cor();
        if e >= 1.0 {
            let up = |v: f64, deg: f64| crate::text::sig(v * deg.to_radians().sin(), 4);
            return Err(row.error(
                2,
                format!(
                    "the rebound is {} the arrival: v_out sin(angle_out) = {} m/s up against \
                     v_in sin(angle_in) = {} m/s down (e = {}); a bounce's e lies below 1",
                    if e > 1.0 { "faster than" } else { "as fast as" },
                    up(r.v_out, r.angle_out),
                    up(r.v_in, r.angle_in),
                    crate::text::sig(e, 4)
                ),
            ));
        }
        Ok(r)
    })?;
    if rows.is_empty() {
        return Err(MeasuredError::at(1, 1, "no bounces: the table has no rows"));
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::parse_court;

    #[test]
    fn a_sliding_bounce_gives_the_itf_numbers() {
        // v_x: 30 cos 16° → 20; v_y: 30 sin 16° → 6
        let (vx, vy) = (20.0_f64, 6.0_f64);
        let text = format!(
            "v_in,angle_in,v_out,angle_out\n30,16,{},{}\n",
            vx.hypot(vy),
            vy.atan2(vx).to_degrees()
        );
        let rows = parse_court(&text).unwrap();
        let (mu, e) = rows[0].friction_and_cor();
        let (vx_in, vy_in) = (
            30.0 * 16f64.to_radians().cos(),
            30.0 * 16f64.to_radians().sin(),
        );
        assert!((mu - (vx_in - vx) / (vy_in + vy)).abs() < 1e-12);
        assert!((e - vy / vy_in).abs() < 1e-12);
        // the trial's row: 40 sin 17.5° = 12.03 m/s up from 30 sin 16° = 8.269 m/s down
        let faster = "v_in,angle_in,v_out,angle_out\n30,16,20,20\n30,16,40,17.5\n";
        let bad = parse_court(faster).unwrap_err().to_string();
        assert!(
            bad.starts_with("3:7: the rebound is faster than the arrival: v_out sin(angle_out) = 12.03 m/s up against v_in sin(angle_in) = 8.269 m/s down (e = 1.455)"),
            "{bad}"
        );
        let bad = parse_court("v_in,angle_in,v_out,angle_out\n30,95,20,20\n").unwrap_err();
        assert!(
            bad.to_string().contains("angle_in 95 must lie in (0, 90)"),
            "{bad}"
        );
    }
}
