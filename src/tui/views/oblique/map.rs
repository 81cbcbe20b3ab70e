//! The oblique view's (angle, μ) map: 90 angles (1° … 90°) by 50 frictions (0.02 … 1) of the
//! current ball at its speed and the view's spin, each cell the outgoing angle, the outgoing
//! spin and Cross's e_x. The normal impact depends on the angle alone, so each angle's 50
//! frictions share it (`oblique::solve_frictions`); the angles go to all cores (rayon). The
//! explorer computes it on `worker`'s thread; `benches/oblique_map.rs` times it.

use crate::api::ObliqueSpec;
use crate::oblique::{Oblique, ObliqueResponse, solve_frictions};
use crate::{Ball, BallError};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

/// Angles of the map: 1°, 2°, … 90°.
pub const ANGLES: usize = 90;
/// Frictions of the map: 0.02, 0.04, … 1.
pub const FRICTIONS: usize = 50;

/// The map's i-th angle (degrees).
pub fn angle_at(i: usize) -> f64 {
    (i + 1) as f64
}

/// The map's j-th friction.
pub fn friction_at(j: usize) -> f64 {
    0.02 * (j + 1) as f64
}

/// The cell nearest to (θ, μ), clamped to the grid.
pub fn cell_of(angle: f64, friction: f64) -> (usize, usize) {
    let i = (angle.round() - 1.0).clamp(0.0, (ANGLES - 1) as f64) as usize;
    let j = (friction / 0.02 - 1.0)
        .round()
        .clamp(0.0, (FRICTIONS - 1) as f64) as usize;
    (i, j)
}

/// What the map colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// The outgoing angle to the surface (°).
    AngleOut,
    /// The outgoing spin (rad/s).
    SpinOut,
    /// Cross's tangential COR e_x = −v_c,out/v_c,in.
    Ex,
}

impl Quantity {
    pub const ALL: [Quantity; 3] = [Quantity::AngleOut, Quantity::SpinOut, Quantity::Ex];

    /// Its name and unit on screen.
    pub fn label(self) -> &'static str {
        match self {
            Quantity::AngleOut => "angle out [°]",
            Quantity::SpinOut => "spin out [rad/s]",
            Quantity::Ex => "e_x",
        }
    }

    /// The next one `n` shows.
    pub fn next(self) -> Quantity {
        let k = Quantity::ALL.iter().position(|&q| q == self).unwrap_or(0);
        Quantity::ALL[(k + 1) % Quantity::ALL.len()]
    }

    /// Its value in a cell (`None`: e_x of a ball arriving rolling).
    pub fn of(self, c: &Cell) -> Option<f64> {
        match self {
            Quantity::AngleOut => Some(c.angle_out),
            Quantity::SpinOut => Some(c.spin_out),
            Quantity::Ex => c.ex,
        }
    }
}

/// One cell's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    pub angle_out: f64,
    pub spin_out: f64,
    pub ex: Option<f64>,
}

impl Cell {
    fn of(r: &ObliqueResponse) -> Cell {
        Cell {
            angle_out: r.angle_out_deg,
            spin_out: r.spin_out,
            ex: r.cor_tangential,
        }
    }
}

/// What a map is of: the ball (its parameters, law, radius, ν, κ), the spin and the K_t and
/// κ set in the view (`None`: the ball's).
#[derive(Debug, Clone, PartialEq)]
pub struct MapSpec {
    pub ball: Ball,
    pub spin: f64,
    pub tangential_stiffness: Option<f64>,
    pub inertia_factor: Option<f64>,
}

/// A computed map: `cells[i * FRICTIONS + j]` at angle i, friction j (`None`: that impact
/// has no answer, e.g. more switches than the library allows).
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueMap {
    pub spec: MapSpec,
    pub cells: Vec<Option<Cell>>,
}

impl ObliqueMap {
    pub fn at(&self, i: usize, j: usize) -> Option<&Cell> {
        self.cells.get(i * FRICTIONS + j)?.as_ref()
    }

    /// The smallest and largest value of `q` over the map.
    pub fn range(&self, q: Quantity) -> Option<(f64, f64)> {
        let vals = self.cells.iter().flatten().filter_map(|c| q.of(c));
        vals.fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
    }
}

/// The map of `spec`, all cores; `None` once `cancel` is set (checked between angles).
pub fn compute(spec: &MapSpec, cancel: &AtomicBool) -> Option<Result<ObliqueMap, String>> {
    let frictions: Vec<f64> = (0..FRICTIONS).map(friction_at).collect();
    let columns: Vec<Option<Result<Vec<Option<Cell>>, String>>> = (0..ANGLES)
        .into_par_iter()
        .map(|i| {
            if cancel.load(Ordering::Relaxed) {
                return None;
            }
            Some(column(spec, angle_at(i), &frictions))
        })
        .collect();
    let mut cells = Vec::with_capacity(ANGLES * FRICTIONS);
    for c in columns {
        match c? {
            Ok(col) => cells.extend(col),
            Err(e) => return Some(Err(e)),
        }
    }
    Some(Ok(ObliqueMap {
        spec: spec.clone(),
        cells,
    }))
}

/// One angle's cells over `frictions`; an error of the arrival itself (the ball, its normal
/// impact) is the map's.
fn column(spec: &MapSpec, angle: f64, frictions: &[f64]) -> Result<Vec<Option<Cell>>, String> {
    let ball = &spec.ball;
    let s = ObliqueSpec {
        v: None,
        angle_deg: angle,
        spin: spec.spin,
        friction: frictions[0],
        tangential_stiffness: spec.tangential_stiffness,
        inertia_factor: spec.inertia_factor,
    };
    let o = oblique_of(ball, &s).map_err(|e| e.to_string())?;
    let all = solve_frictions(&ball.params, ball.law, ball.params.v0, &o, frictions)
        .map_err(|e| BallError::from(e).to_string())?;
    Ok(all.iter().map(|r| r.as_ref().ok().map(Cell::of)).collect())
}

/// The library's `Oblique` for `ball` and `s`, with the ball's own K_t, κ and R where `s`
/// gives none, as `Ball::oblique` makes it (its checks first: a radius).
pub fn oblique_of(ball: &Ball, s: &ObliqueSpec) -> Result<Oblique, BallError> {
    // one impact through the front door checks the ball as `bouncelab oblique` does …
    ball.oblique(s, 0)?;
    // … and the quantities it ran on are the ball's (src/api/oblique.rs)
    let k_t = s
        .tangential_stiffness
        .or(ball.tangential_stiffness())
        .unwrap_or(f64::NAN);
    let kappa = s.inertia_factor.unwrap_or_else(|| ball.inertia_factor());
    Oblique::new(s.angle_deg, s.spin, s.friction, k_t, kappa, ball.radius()).map_err(Into::into)
}

/// A map handed to the worker; `update` sets `cancel` once it is stale.
pub type MapJob = crate::tui::worker::Cancellable<MapSpec>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_and_its_cells() {
        assert_eq!((angle_at(0), angle_at(ANGLES - 1)), (1.0, 90.0));
        assert!((friction_at(FRICTIONS - 1) - 1.0).abs() < 1e-15);
        assert_eq!(cell_of(16.0, 0.6), (15, 29));
        assert_eq!(cell_of(0.2, 5.0), (0, FRICTIONS - 1));
        for i in [0, 37, 89] {
            for j in [0, 13, 49] {
                assert_eq!(cell_of(angle_at(i), friction_at(j)), (i, j));
            }
        }
    }
}
