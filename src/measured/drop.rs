//! Drop tests: a ball dropped from `H` rebounds to `R`. The impact speed is the speed after the
//! fall and the COR the ratio of the speed that rises to R to it, e = u/v0, both from
//! [`crate::drop::Flight`] (docs/drop.md): in vacuum v0 = √(2 g H) and e = √(R/H); with
//! quadratic drag (κ = ½ ρ_air C_d π r²/m) v0² = (g/κ)(1 − e^{−2κH}) and
//! u² = (g/κ)(e^{2κR} − 1) (docs/fitting.md).

use super::MeasuredError;
use super::points;
use super::table::{self, ColumnSpec};
pub use crate::drop::{Air, Flight, G};
use crate::model::params::{MEANINGFUL_MAX, MEANINGFUL_MIN};

/// The columns of a drop test (also how `parse_any` tells one).
pub(super) const SPECS: [ColumnSpec; 2] = [
    ColumnSpec::required(
        "drop height",
        &[("drop_height_m", 1.0), ("drop_height", 1.0)],
    ),
    ColumnSpec::required(
        "rebound height",
        &[("rebound_height_m", 1.0), ("rebound_height", 1.0)],
    ),
];

/// Drop and rebound heights (m) and the line each came from (0: the command line).
#[derive(Debug, Clone, PartialEq)]
pub struct DropTest {
    /// (drop height, rebound height, line) of each drop, in the file's order; the drop
    /// height positive, the rebound height in [0, drop height].
    pub drops: Vec<(f64, f64, usize)>,
}

/// Impact speed and COR of one drop (see the module comment).
pub fn drop_to_cor(drop: f64, rebound: f64, flight: &Flight) -> (f64, f64) {
    let v0 = flight.fall_speed(drop);
    (v0, flight.launch_speed_for(rebound) / v0)
}

/// How much a drop's COR moves per metre of its rebound height, ∂e/∂R (1/m), at `rebound`
/// but not below `floor` (m): e = u(R)/v0(H) (see the module comment), so ∂e/∂R =
/// (du/dR)/v0 — in vacuum 1/(2√(RH)), nine times larger from 0.2 m than from 1.8 m at the
/// same COR. A rebound height read to ±σ_R gives e an error σ_R ∂e/∂R (to first order: near
/// R = 0 the slope is infinite and the first order fails, hence the floor, which the caller
/// sets to the reading's precision or, unknown, to a hundredth of the drop).
pub fn cor_per_rebound_height(drop: f64, rebound: f64, floor: f64, flight: &Flight) -> f64 {
    flight.launch_speed_slope(rebound.max(floor)) / flight.fall_speed(drop)
}

/// Drops (drop height, rebound height, m) as COR points through `flight`, each weighed by its
/// rebound height's reading: with `rebound_sd` = σ_R (m) each COR's `cor_sd` is
/// σ_R ∂e/∂R; unknown, each `cor_sd_relative` is ∂e/∂R, scaled to an RMS of 1 over the drops
/// (the fit takes the scale from its misses). The slope is taken at a rebound of at least σ_R,
/// or unknown, a hundredth of the drop ([`cor_per_rebound_height`]). No checks: callers check
/// the heights and the drag's correction first (`Ball::drops_to_cor_read`).
pub fn drops_to_points(
    drops: &[(f64, f64)],
    flight: &Flight,
    rebound_sd: Option<f64>,
) -> Vec<super::CorPoint> {
    let mut points: Vec<super::CorPoint> = drops
        .iter()
        .map(|&(h, r)| {
            let (v0, cor) = drop_to_cor(h, r, flight);
            let slope = cor_per_rebound_height(h, r, rebound_sd.unwrap_or(0.01 * h), flight);
            let mut p = super::CorPoint::new(v0, cor);
            match rebound_sd {
                Some(sd) => p.cor_sd = Some(sd * slope),
                None => p.cor_sd_relative = slope,
            }
            p
        })
        .collect();
    if rebound_sd.is_none() {
        // scaled to an RMS of 1, so the misses the fit sees keep their size
        let n = points.len().max(1) as f64;
        let rms = (points
            .iter()
            .map(|p| p.cor_sd_relative.powi(2))
            .sum::<f64>()
            / n)
            .sqrt();
        for p in &mut points {
            p.cor_sd_relative /= rms;
        }
    }
    points
}

impl DropTest {
    /// Columns `drop_height_m`, `rebound_height_m`.
    pub fn parse(text: &str) -> Result<DropTest, MeasuredError> {
        DropTest::read(text.into())
    }

    /// [`DropTest::parse`] of a text or of rows already read (a batch's ball).
    pub fn read(src: table::Source<'_>) -> Result<DropTest, MeasuredError> {
        let p = points::read(src, &SPECS)?;
        let drops = points::each_row(&p, |row| {
            let (h, r) = (row.get(0).unwrap_or(0.0), row.get(1).unwrap_or(0.0));
            if h <= 0.0 {
                return Err(row.error(0, format!("drop height {h} m must be positive")));
            }
            // heights in the range a measurement can have, as every measured quantity
            // (`super::in_domain`): 1e-310 m is no drop, 1e300 m no rebound
            if !(MEANINGFUL_MIN..=MEANINGFUL_MAX).contains(&h) {
                return Err(row.error(0, out_of_range("drop height", h)));
            }
            if r > 0.0 && r < MEANINGFUL_MIN {
                return Err(row.error(1, out_of_range("rebound height", r)));
            }
            if !(0.0..=h).contains(&r) {
                return Err(row.error(
                    1,
                    format!("rebound height {r} m must lie in [0, the drop height {h} m]"),
                ));
            }
            Ok((h, r, row.line()))
        })?;
        Ok(DropTest { drops })
    }
}

fn out_of_range(name: &str, v: f64) -> String {
    format!(
        "{name} {} m is out of the range a measurement can have ({} … {} m)",
        crate::text::number(v),
        crate::text::number(MEANINGFUL_MIN),
        crate::text::number(MEANINGFUL_MAX)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drag_free_and_with_drag() {
        let (v, e) = drop_to_cor(1.0, 0.64, &Flight::vacuum());
        assert!((v - (2.0 * G).sqrt()).abs() < 1e-12 && (e - 0.8).abs() < 1e-12);
        // real air slows the fall and the rise: v0 lower, e higher than without
        let air = Flight::new(0.04, 0.02, Some(Air::default()));
        let (v3, e3) = drop_to_cor(2.0, 1.28, &air);
        assert!(v3 < (4.0 * G).sqrt() && e3 > 0.8, "{v3} {e3}");
        // the fall by numerical integration of d(v²)/dx = 2g − 2κ v² (midpoint rule)
        let k = air.drag_per_mass;
        let (mut w, h) = (0.0f64, 1e-4);
        for _ in 0..20_000 {
            let mid = w + 0.5 * h * (2.0 * G - 2.0 * k * w);
            w += h * (2.0 * G - 2.0 * k * mid);
        }
        assert!((w.sqrt() - v3).abs() < 1e-6, "{} vs {v3}", w.sqrt());
    }

    /// ∂e/∂R against a central difference of [`drop_to_cor`], in vacuum (where it is
    /// 1/(2√(RH))) and through real air; the floor holds near R = 0.
    #[test]
    fn cor_slope_is_the_derivative_of_drop_to_cor() {
        let air = Flight::new(0.057, 0.033, Some(Air::default()));
        for flight in [Flight::vacuum(), air] {
            for (h, r) in [(0.2, 0.1), (1.8, 0.9), (2.54, 1.4), (1.0, 0.05)] {
                let d = 1e-6;
                let e = |r: f64| drop_to_cor(h, r, &flight).1;
                let numeric = (e(r + d) - e(r - d)) / (2.0 * d);
                let slope = cor_per_rebound_height(h, r, 0.0, &flight);
                assert!(
                    (slope / numeric - 1.0).abs() < 1e-7,
                    "{h} {r}: {slope} {numeric}"
                );
            }
        }
        let vacuum = Flight::vacuum();
        let s = cor_per_rebound_height(1.8, 0.9, 0.0, &vacuum);
        assert!((s - 1.0 / (2.0 * (0.9f64 * 1.8).sqrt())).abs() < 1e-12);
        // from 0.2 m the same COR's error is nine times larger than from 1.8 m (module doc)
        let low = cor_per_rebound_height(0.2, 0.1, 0.0, &vacuum);
        assert!((low / s - 9.0).abs() < 1e-9, "{}", low / s);
        // no rebound: the slope at the floor, finite
        let at_floor = cor_per_rebound_height(1.0, 0.0, 0.01, &vacuum);
        assert_eq!(at_floor, cor_per_rebound_height(1.0, 0.01, 0.0, &vacuum));
    }

    #[test]
    fn rebound_above_drop_is_an_error() {
        let e = DropTest::parse("drop_height_m,rebound_height_m\n1,1.2\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
    }
}
