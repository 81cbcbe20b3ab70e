//! The heat map's raster: which map cell each half character shows, its colour (viridis, the
//! SVG heat map's colour map) or shade (without colour), and the marks drawn over it (the
//! iso-COR line, the feasible region's outline, the presets, the cursor). Pure functions of
//! the map; `crate::tui::views::map::widget` draws them.

use crate::figure::colormap::viridis;
use crate::map::{Map, Quantity, Targets, contour_lines};
use ratatui::style::Color;

/// The shades without colour, low to high.
pub const RAMP: [&str; 5] = [" ", "░", "▒", "▓", "█"];
/// A cell with no value (no answer; no contact time without a rebound).
pub const NAN_COLOR: (u8, u8, u8) = (110, 110, 110);
/// Its mark without colour.
pub const NAN_SHADE: &str = "·";
/// The iso-COR line through the current point.
pub const ISO: &str = "•";
/// The feasible region's edge.
pub const OUTLINE: &str = "+";
/// The cursor (the current ball).
pub const CURSOR: &str = "╋";

/// The map's cells as the screen samples them: `rows` (λ, bottom to top) × `cols` (ζ, left to
/// right) of the grid, a cell not evaluated yet taken from the coarse lattice around it.
pub struct Raster<'a> {
    pub map: &'a Map,
    /// The quantity's values (in the unit shown), row-major, NaN where none.
    pub values: Vec<f64>,
    /// Which cells meet the targets (all of them without targets).
    pub feasible: Vec<bool>,
}

impl<'a> Raster<'a> {
    pub fn new(map: &'a Map, q: Quantity, scale: f64, targets: Option<&Targets>) -> Raster<'a> {
        let (n, m) = (map.lambdas.len(), map.zetas.len());
        let mut values = Vec::with_capacity(n * m);
        let mut feasible = Vec::with_capacity(n * m);
        for i in 0..n {
            for j in 0..m {
                let c = map.nearest(i, j);
                values.push(c.map_or(f64::NAN, |c| c.get(q) * scale));
                feasible.push(match (c, targets) {
                    (Some(c), Some(t)) => t.holds(&c),
                    (None, Some(_)) => false,
                    (_, None) => true,
                });
            }
        }
        Raster {
            map,
            values,
            feasible,
        }
    }

    pub fn rows(&self) -> usize {
        self.map.lambdas.len()
    }
    pub fn cols(&self) -> usize {
        self.map.zetas.len()
    }
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.values[i * self.cols() + j]
    }

    /// The cells on the edge of the feasible region: feasible, with an infeasible neighbour.
    pub fn outline(&self) -> Vec<(usize, usize)> {
        let (n, m) = (self.rows(), self.cols());
        let ok = |i: usize, j: usize| self.feasible[i * m + j];
        let mut out = Vec::new();
        for i in 0..n {
            for j in 0..m {
                let edge = (i > 0 && !ok(i - 1, j))
                    || (i + 1 < n && !ok(i + 1, j))
                    || (j > 0 && !ok(i, j - 1))
                    || (j + 1 < m && !ok(i, j + 1));
                if ok(i, j) && edge {
                    out.push((i, j));
                }
            }
        }
        out
    }

    /// The cells the iso-COR line at `level` passes through (marching squares over the COR
    /// of the cells as drawn, the same algorithm as the SVG's iso-lines).
    pub fn iso_cor(&self, level: f64) -> Vec<(usize, usize)> {
        let (n, m) = (self.rows(), self.cols());
        let cor: Vec<f64> = (0..n * m)
            .map(|k| self.map.nearest(k / m, k % m).map_or(f64::NAN, |c| c.cor))
            .collect();
        let mut out = Vec::new();
        for line in contour_lines(&cor, n, m, level) {
            for w in line.index.windows(2) {
                let ((a, b), (c, d)) = (w[0], w[1]);
                let steps = ((c - a).abs().max((d - b).abs()) * 2.0).ceil().max(1.0) as usize;
                for s in 0..=steps {
                    let t = s as f64 / steps as f64;
                    let (i, j) = ((a + t * (c - a)).round(), (b + t * (d - b)).round());
                    out.push((i as usize, j as usize));
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// Screen sampling: `cells` map cells over `slots` screen slots (one each when equal).
pub fn cell_of_slot(slot: usize, slots: usize, cells: usize) -> usize {
    (slot * cells / slots.max(1)).min(cells.saturating_sub(1))
}

/// The slot a cell falls in (the inverse of [`cell_of_slot`] when they are equal).
pub fn slot_of_cell(cell: usize, cells: usize, slots: usize) -> usize {
    (((2 * cell + 1) * slots) / (2 * cells.max(1))).min(slots.saturating_sub(1))
}

/// The colour of `v` on the bar from `lo` to `hi`.
pub fn colour(v: f64, lo: f64, hi: f64) -> (u8, u8, u8) {
    if v.is_nan() {
        return NAN_COLOR;
    }
    viridis((v - lo) / (hi - lo))
}

/// The shade of `v` without colour.
pub fn shade(v: f64, lo: f64, hi: f64) -> &'static str {
    if v.is_nan() {
        return NAN_SHADE;
    }
    let t = ((v - lo) / (hi - lo)).clamp(0.0, 1.0);
    let k = (t * RAMP.len() as f64).floor() as usize;
    RAMP[k.min(RAMP.len() - 1)]
}

/// A cell outside the feasible region, darkened: the region itself stands out.
pub fn dimmed((r, g, b): (u8, u8, u8)) -> (u8, u8, u8) {
    let f = |c: u8| (f64::from(c) * 0.4).round() as u8;
    (f(r), f(g), f(b))
}

pub fn rgb((r, g, b): (u8, u8, u8)) -> Color {
    Color::Rgb(r, g, b)
}

/// Black or white, whichever reads on `bg`.
pub fn contrast((r, g, b): (u8, u8, u8)) -> Color {
    let luma = 0.2126 * f64::from(r) + 0.7152 * f64::from(g) + 0.0722 * f64::from(b);
    if luma > 130.0 {
        Color::Black
    } else {
        Color::White
    }
}
