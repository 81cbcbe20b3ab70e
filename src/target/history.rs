//! A two-body impact with its sampled history, for charts (the explorer's force–displacement
//! chart of a moving or compliant target, docs/explorer.md): the force, the ball's contact
//! indentation, the chain's compression α = x_b − x_t (the ball's displacement relative to the
//! target), the surface's deflection s and the target's own displacement from its free path.
//!
//! The history is a second run on a grid over the first one's contact time: the exact flow
//! sampled where the exact solver answered, else the integrator's dense output between its
//! steps (`numeric::solve_sampled`), so the drawn curve is the very run whose numbers are
//! reported.

use super::{Collision, Target, collide, compliant_sampled};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveError, SolveOptions, simulate};

/// Points of a history (normalized, as the compliant solvers see them): the times asked for,
/// the next one to take, and (F̄, z̄, ᾱ, s̄) at those taken.
pub(crate) struct Samples {
    times: Vec<f64>,
    next: usize,
    pub(crate) out: Vec<[f64; 4]>,
}

impl Samples {
    /// No history: the solvers' answers only.
    pub(crate) fn none() -> Samples {
        Samples::at(Vec::new())
    }

    pub(crate) fn at(times: Vec<f64>) -> Samples {
        Samples {
            times,
            next: 0,
            out: Vec::new(),
        }
    }

    /// Take every time up to `to` not yet taken, the state there given by `state`.
    pub(crate) fn take(&mut self, to: f64, mut state: impl FnMut(f64) -> [f64; 4]) {
        while let Some(&t) = self.times.get(self.next).filter(|&&t| t <= to) {
            self.out.push(state(t));
            self.next += 1;
        }
    }

    /// Forget what was taken (a run that is not the answer).
    pub(crate) fn restart(&mut self) {
        (self.next, self.out) = (0, Vec::new());
    }

    /// Take every time at once from `run` (the exact flow), replacing what was taken.
    pub(crate) fn fill(&mut self, run: impl FnOnce(&[f64]) -> Vec<[f64; 4]>) {
        if !self.times.is_empty() {
            self.out = run(&self.times);
            self.next = self.times.len();
        }
    }
}

/// A two-body impact and its history, SI units; every vector is sampled at `t`.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetHistory {
    /// The answer, as [`collide`] gives it.
    pub collision: Collision,
    /// t (s), from first contact to separation (or the horizon, without rebound).
    pub t: Vec<f64>,
    /// F(t) (N), the same on both bodies.
    pub force: Vec<f64>,
    /// The ball's contact indentation z(t) (m).
    pub indentation: Vec<f64>,
    /// The chain's compression α(t) = x_b − x_t (m): the ball's displacement relative to the
    /// target, z + y + s (docs/targets.md §2).
    pub displacement: Vec<f64>,
    /// The surface's deflection s(t) (m): 0 on a rigid target.
    pub deflection: Vec<f64>,
    /// The target's displacement from the path it would have kept without the ball,
    /// u_t = (m*/M)(v_c t − α) (m, toward where the ball pushes it; 0 for M = ∞): from
    /// M u_t'' = F and m* α'' = −F with the same start, u_t = −(m*/M)(α − v_c t).
    pub target_displacement: Vec<f64>,
}

/// [`collide`] with the history at `samples` points from first contact to its end.
pub fn history(
    params: &ImpactParams,
    law: ContactLaw,
    target: &Target,
    ball_speed: f64,
    samples: usize,
) -> Result<TargetHistory, SolveError> {
    let collision = collide(params, law, target, ball_speed, None)?;
    let reduced = ImpactParams {
        mass: collision.reduced_mass,
        v0: collision.closing_speed,
        ..*params
    };
    let mut h = if target.is_rigid() {
        let opts = SolveOptions::default().with_samples(samples);
        let r = simulate(&reduced, law, &opts)?;
        let zero = vec![0.0; r.history.t.len()];
        TargetHistory {
            collision,
            t: r.history.t,
            force: r.history.force,
            indentation: r.history.indentation,
            displacement: r.history.displacement,
            deflection: zero.clone(),
            target_displacement: zero,
        }
    } else {
        compliant_history(&reduced, law, target, collision, samples)?
    };
    h.target_displacement = displacement_off_path(
        reduced.mass / target.mass,
        reduced.v0,
        &h.t,
        &h.displacement,
    );
    Ok(h)
}

/// The target's displacement from its free path, u_t = (m*/M)(v_c t − α), at times `t` (s)
/// where the chain's compression is `alpha` (m); `ratio` = m*/M, `closing` = v_c (m/s). From
/// M u_t'' = F and m* α'' = −F, both starting at rest in the same place: u_t = −(m*/M)(α − v_c t).
pub fn displacement_off_path(ratio: f64, closing: f64, t: &[f64], alpha: &[f64]) -> Vec<f64> {
    t.iter()
        .zip(alpha)
        .map(|(&t, &a)| ratio * (closing * t - a))
        .collect()
}

/// The compliant run again, sampled on a grid over the first run's duration.
fn compliant_history(
    reduced: &ImpactParams,
    law: ContactLaw,
    target: &Target,
    collision: Collision,
    samples: usize,
) -> Result<TargetHistory, SolveError> {
    let w0 = reduced.omega0();
    let (length, force) = (reduced.v0 / w0, reduced.mass * reduced.v0 * w0);
    let first = compliant_sampled(reduced, law, target, None, &mut Samples::none())?;
    let tau_end = first.duration * w0;
    let n = samples.max(2);
    let times: Vec<f64> = (0..n)
        .map(|i| tau_end * i as f64 / (n - 1) as f64)
        .collect();
    let mut grid = Samples::at(times.clone());
    compliant_sampled(reduced, law, target, None, &mut grid)?;
    let out = grid.out;
    let col = |k: usize, scale: f64| out.iter().map(|x| x[k] * scale).collect();
    Ok(TargetHistory {
        collision,
        t: times[..out.len()].iter().map(|tau| tau / w0).collect(),
        force: col(0, force),
        indentation: col(1, length),
        displacement: col(2, length),
        deflection: col(3, length),
        target_displacement: Vec::new(),
    })
}
