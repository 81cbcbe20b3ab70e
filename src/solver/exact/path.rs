//! The exact run's flow read at any τ: the normal force F̄, its rate F̄' and the ball's speed
//! ᾱ', which the oblique impact's tangential motion is driven by (docs/oblique.md §2). Each
//! phase keeps its anchored propagators, so a reading costs one propagator evaluation.

use super::search::eval_anchored;
use super::{Segment, l};

/// The normal motion at one τ, normalized (docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathPoint {
    /// F̄ = F/(m v0 ω0), ≥ 0.
    pub force: f64,
    /// dF̄/dτ.
    pub rate: f64,
    /// ᾱ' = α'/v0, the speed toward the wall (1 at τ = 0, −e at separation).
    pub velocity: f64,
}

/// The flow of a solved linear-law impact over [0, τ_f], phase by phase.
pub struct NormalPath {
    segments: Vec<Segment>,
}

impl NormalPath {
    pub(super) fn new(segments: Vec<Segment>) -> NormalPath {
        NormalPath { segments }
    }

    /// τ where each phase ends (unload, reload, separation), in order: F̄' may jump there.
    pub fn boundaries(&self) -> impl Iterator<Item = f64> + '_ {
        self.segments.iter().map(|s| s.start + s.len)
    }

    /// τ_f, the end of the last phase.
    pub fn end(&self) -> f64 {
        self.segments.last().map_or(0.0, |s| s.start + s.len)
    }

    /// The normal motion at τ (clamped to [0, τ_f]); at a phase boundary, the phase that
    /// ends there.
    pub fn at(&self, tau: f64) -> PathPoint {
        let i = self
            .segments
            .partition_point(|s| s.start + s.len < tau)
            .min(self.segments.len().saturating_sub(1));
        self.at_in(i, tau)
    }

    /// The normal motion at τ read on phase `i` (τ clamped to the phase).
    pub fn at_in(&self, i: usize, tau: f64) -> PathPoint {
        let seg = &self.segments[i];
        let (w, dw) = eval_anchored(&seg.anchors, (tau - seg.start).clamp(0.0, seg.len));
        PathPoint {
            force: (seg.k * l(&w)).max(0.0),
            rate: seg.k * l(&dw),
            velocity: w[1],
        }
    }

    /// The number of phases.
    pub fn phases(&self) -> usize {
        self.segments.len()
    }

    /// Where phase `i` starts and ends (τ).
    pub fn phase(&self, i: usize) -> (f64, f64) {
        let s = &self.segments[i];
        (s.start, s.start + s.len)
    }
}
