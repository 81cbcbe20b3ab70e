//! The normal motion an oblique impact's tangential motion is driven by (docs/oblique.md §2): a
//! trait over the linear law's exact flow, the closed form (`closed`) and any law's adaptive
//! run, read at any τ, on the search's grid and, bracket by bracket, with F̄''.

use super::closed;
use crate::solver::Flow;
use crate::solver::exact::{LocalFlow, NormalPath, PathPoint};

/// The normal motion an oblique impact is driven by: the linear law's exact flow, or any
/// law's adaptive run read between its steps (`solver::Flow`).
pub trait NormalMotion {
    /// F̄, F̄' and ᾱ' at τ.
    fn at(&self, tau: f64) -> PathPoint;
    /// τ_f.
    fn end(&self) -> f64;
    /// Where F̄' may jump (phase ends), in order.
    fn kinks(&self) -> Vec<f64>;
    /// The motion at τ_j = j h for j = 0, 1, … while j h < τ_f, then at τ_f: the tangential
    /// search's grid (`tangential::Grid`). Read point by point unless the flow knows better.
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        grid_by_points(self, h)
    }
    /// The motion on [a, b] read with F̄'' for Newton's steps, when the flow has a cheaper
    /// reading there or a closed form (`None`: read `at`).
    fn local(&self, _a: f64, _b: f64) -> Option<Local<'_>> {
        None
    }
}

/// The normal motion on a bracket of the switches' search, read with F̄'': the exact flow's
/// power series from the bracket's start, or the closed form itself.
// a temporary on the stack, one a bracket: boxing the series would allocate for each
#[allow(clippy::large_enum_variant)]
pub enum Local<'a> {
    /// [`NormalPath::local`]'s series.
    Series(LocalFlow),
    /// The closed form (`closed`), turned from the bracket's start.
    Closed(closed::Near<'a>),
}

impl Local<'_> {
    /// The normal motion at τ.
    pub fn at(&self, tau: f64) -> PathPoint {
        self.at_with_curvature(tau).0
    }

    /// The normal motion at τ and F̄'' there.
    pub fn at_with_curvature(&self, tau: f64) -> (PathPoint, f64) {
        match self {
            Local::Series(l) => l.at_with_curvature(tau),
            Local::Closed(c) => c.with_curvature(tau),
        }
    }
}

/// [`NormalMotion::grid`] read point by point.
fn grid_by_points<M: NormalMotion + ?Sized>(m: &M, h: f64) -> Vec<PathPoint> {
    let tf = m.end();
    let n = (tf / h).ceil().max(1.0) as usize;
    (0..=n)
        .map(|j| m.at(if j == n { tf } else { j as f64 * h }))
        .collect()
}

impl NormalMotion for NormalPath {
    fn at(&self, tau: f64) -> PathPoint {
        NormalPath::at(self, tau)
    }
    fn end(&self) -> f64 {
        NormalPath::end(self)
    }
    fn kinks(&self) -> Vec<f64> {
        self.boundaries().collect()
    }
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        NormalPath::grid(self, h)
    }
    fn local(&self, a: f64, b: f64) -> Option<Local<'_>> {
        NormalPath::local(self, a, b).map(Local::Series)
    }
}

impl NormalMotion for Flow {
    fn at(&self, tau: f64) -> PathPoint {
        Flow::at(self, tau)
    }
    fn end(&self) -> f64 {
        Flow::end(self)
    }
    fn kinks(&self) -> Vec<f64> {
        self.boundaries()
    }
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        match self {
            Flow::Exact(p) => p.grid(h),
            Flow::Numeric(_) => grid_by_points(self, h),
        }
    }
    fn local(&self, a: f64, b: f64) -> Option<Local<'_>> {
        match self {
            Flow::Exact(p) => p.local(a, b).map(Local::Series),
            Flow::Numeric(_) => None,
        }
    }
}
