//! Drop tests: a ball dropped from `H` rebounds to `R`. Without air, v0 = √(2 g H) and
//! e = √(R/H). With quadratic drag (force ½ ρ_air C_d π r² v², written k v² with
//! κ = k/m), a fall from rest over H reaches v0² = (g/κ)(1 − e^{−2κH}) and a rise from
//! speed u reaches R = ln(1 + κu²/g)/(2κ), so u² = (g/κ)(e^{2κR} − 1) and e = u/v0
//! (docs/fitting.md; both tend to the drag-free forms as κ → 0).

use super::MeasuredError;
use super::table::{self, ColumnSpec};

/// Standard gravity (m/s²).
pub const G: f64 = 9.80665;

const SPECS: [ColumnSpec; 2] = [
    ColumnSpec {
        name: "drop height",
        aliases: &[("drop_height_m", 1.0), ("drop_height", 1.0)],
        required: true,
    },
    ColumnSpec {
        name: "rebound height",
        aliases: &[("rebound_height_m", 1.0), ("rebound_height", 1.0)],
        required: true,
    },
];

/// Drop and rebound heights (m) and the line each came from (0: the command line).
#[derive(Debug, Clone, PartialEq)]
pub struct DropTest {
    pub drops: Vec<(f64, f64, usize)>,
}

/// Quadratic air drag on the ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drag {
    /// Drag coefficient C_d (≈ 0.47 for a smooth sphere).
    pub coefficient: f64,
    /// Air density (kg/m³), 1.204 at 20 °C.
    pub air_density: f64,
    pub radius: f64,
    pub mass: f64,
}

impl Drag {
    /// κ = ½ ρ_air C_d π r² / m (1/m).
    pub fn kappa(&self) -> f64 {
        0.5 * self.air_density * self.coefficient * std::f64::consts::PI * self.radius.powi(2)
            / self.mass
    }
}

/// Impact speed and COR of one drop (see the module comment).
pub fn drop_to_cor(drop: f64, rebound: f64, drag: Option<&Drag>) -> (f64, f64) {
    let k = drag.map_or(0.0, Drag::kappa);
    if k * drop.max(rebound) < 1e-12 {
        return ((2.0 * G * drop).sqrt(), (rebound / drop).sqrt());
    }
    // −expm1(−x) and expm1(x) keep the digits when κH is small
    let v0 = (G / k * -(-2.0 * k * drop).exp_m1()).sqrt();
    let u = (G / k * (2.0 * k * rebound).exp_m1()).sqrt();
    (v0, u / v0)
}

impl DropTest {
    /// Columns `drop_height_m`, `rebound_height_m`.
    pub fn parse(text: &str) -> Result<DropTest, MeasuredError> {
        let p = table::read(text, &SPECS)?;
        super::check_points(&p)?;
        let mut drops = Vec::with_capacity(p.lines.len());
        for i in 0..p.lines.len() {
            let (h, r) = (
                p.columns[0][i].unwrap_or(0.0),
                p.columns[1][i].unwrap_or(0.0),
            );
            let at =
                |k: usize, msg: String| MeasuredError::at(p.lines[i], p.cell_columns[k][i], msg);
            if h <= 0.0 {
                return Err(at(0, format!("drop height {h} m must be positive")));
            }
            if !(0.0..=h).contains(&r) {
                return Err(at(
                    1,
                    format!("rebound height {r} m must lie in [0, the drop height {h} m]"),
                ));
            }
            drops.push((h, r, p.lines[i]));
        }
        Ok(DropTest { drops })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drag_free_and_with_drag() {
        let (v, e) = drop_to_cor(1.0, 0.64, None);
        assert!((v - (2.0 * G).sqrt()).abs() < 1e-12 && (e - 0.8).abs() < 1e-12);
        // tiny drag: the drag-free answer to first order
        let d = Drag {
            coefficient: 0.47,
            air_density: 1e-9,
            radius: 0.02,
            mass: 0.04,
        };
        let (v2, e2) = drop_to_cor(1.0, 0.64, Some(&d));
        assert!((v2 - v).abs() < 1e-9 && (e2 - e).abs() < 1e-9);
        // real air slows the fall and the rise: v0 lower, e higher than without
        let d = Drag {
            air_density: 1.204,
            ..d
        };
        let (v3, e3) = drop_to_cor(2.0, 1.28, Some(&d));
        assert!(v3 < (4.0 * G).sqrt() && e3 > 0.8, "{v3} {e3}");
        // the fall by numerical integration of d(v²)/dx = 2g − 2κ v² (midpoint rule)
        let k = d.kappa();
        let (mut w, h) = (0.0f64, 1e-4);
        for _ in 0..20_000 {
            let mid = w + 0.5 * h * (2.0 * G - 2.0 * k * w);
            w += h * (2.0 * G - 2.0 * k * mid);
        }
        assert!((w.sqrt() - v3).abs() < 1e-6, "{} vs {v3}", w.sqrt());
    }

    #[test]
    fn rebound_above_drop_is_an_error() {
        let e = DropTest::parse("drop_height_m,rebound_height_m\n1,1.2\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
    }
}
