//! The search for a phase's events on its exact flow: a step rule from the time scales of its
//! modes (`Modes::step`), a sign change or a hidden extremum of the watched function in each
//! step (`crossing_in`), and the root found by Halley's method on the flow's derivatives.

use super::modes::Modes;
use super::{MAX_STEPS, l};
use crate::solver::propagator::Propagator;
use crate::solver::roots::{halley_bracketed_from, newton_bracketed_from};
use nalgebra::Vector3;

/// w and its first three derivatives at τ.
pub(super) struct Jet([Vector3<f64>; 4]);

fn jet(p: &Propagator, tau: f64) -> Jet {
    Jet(p.jet(tau))
}

/// An event function g(τ) watched for a crossing in one direction.
#[derive(Clone, Copy)]
pub(super) enum Watch {
    /// z̄' falling through 0.
    RateFalls,
    /// z̄ − s rising through the target.
    Rises(f64),
    /// z̄ − s falling through the target.
    Falls(f64),
}

impl Watch {
    /// (g, g', g'') from the jet.
    fn eval(self, j: &Jet) -> (f64, f64, f64) {
        let [w, aw, a2w, a3w] = &j.0;
        match self {
            Watch::RateFalls => (l(aw), l(a2w), l(a3w)),
            Watch::Rises(t) | Watch::Falls(t) => (l(w) - t, l(aw), l(a2w)),
        }
    }
    fn rising(self) -> bool {
        matches!(self, Watch::Rises(_))
    }
}

/// A crossing inside [a, b]: a sign change in the watched direction, or one hidden behind an
/// extremum (g' changes sign inside and the extremum lies across zero).
fn crossing_in(
    watch: Watch,
    f: &mut impl FnMut(f64) -> Jet,
    (ta, ga, da): (f64, f64, f64),
    (tb, gb, db): (f64, f64, f64),
) -> Option<f64> {
    let sign = if watch.rising() { 1.0 } else { -1.0 };
    let (ga, gb, da, db) = (sign * ga, sign * gb, sign * da, sign * db);
    let g = |f: &mut dyn FnMut(f64) -> Jet, t: f64| {
        let (g, d, dd) = watch.eval(&f(t));
        (sign * g, sign * d, sign * dd)
    };
    if ga < 0.0 && gb >= 0.0 {
        return Some(halley_bracketed_from(|t| g(f, t), (ta, ga), (tb, gb)));
    }
    if ga < 0.0 && gb < 0.0 && da > 0.0 && db < 0.0 {
        let rate = |t| {
            let (_, d, dd) = g(f, t);
            (d, dd)
        };
        let tm = newton_bracketed_from(rate, (ta, da), (tb, db));
        let (gm, _, _) = g(f, tm);
        if gm > 1e-14 * (ga.abs() + gb.abs()) {
            return Some(halley_bracketed_from(|t| g(f, t), (ta, ga), (tm, gm)));
        }
    }
    None
}

/// The flow of one phase as a chain of anchors: (local τ of the anchor, flow from there).
pub(super) type Anchors = Vec<(f64, Propagator)>;

pub(super) fn eval_anchored(anchors: &Anchors, tau: f64) -> (Vector3<f64>, Vector3<f64>) {
    let i = anchors
        .partition_point(|(t0, _)| *t0 <= tau)
        .saturating_sub(1);
    let (t0, p) = &anchors[i];
    p.eval(tau - t0)
}

/// Where a phase's search ended.
pub(super) struct Found {
    /// Local τ of the event, or of the point after which none can come.
    pub(super) len: f64,
    /// The index of the watch that fired.
    pub(super) hit: Option<usize>,
    /// Steps taken.
    pub(super) steps: usize,
    /// The step budget ran out before an event or the settle time: the phase is unresolved.
    pub(super) exhausted: bool,
    /// The anchors laid down on the way (all of them when kept, else none) and the last one.
    pub(super) anchors: Anchors,
    pub(super) last: (f64, Propagator),
}

/// The anchors of a search: the one in use, and the earlier ones when they are kept (for
/// sampling and the energy audit; no allocation otherwise).
struct Trail {
    keep: bool,
    current: (f64, Propagator),
    anchors: Anchors,
}

impl Trail {
    /// Restart the flow at τ from the state w there (the propagator's rounding is relative to
    /// the state at its anchor).
    fn restart(&mut self, tau: f64, w: Vector3<f64>) {
        let next = (tau, self.current.1.restart(w));
        let previous = std::mem::replace(&mut self.current, next);
        if self.keep {
            self.anchors.push(previous);
        }
    }

    /// The search ended at local τ `len`: the anchor in use joins the kept ones.
    fn found(mut self, len: f64, hit: Option<usize>, steps: usize, exhausted: bool) -> Found {
        if self.keep {
            self.anchors.push(self.current.clone());
        }
        Found {
            len,
            hit,
            steps,
            exhausted,
            anchors: self.anchors,
            last: self.current,
        }
    }
}

/// (τ, g, g') of each watch at τ.
fn values(watches: &[Watch], j: &Jet, t: f64) -> [(f64, f64, f64); 2] {
    let mut v = [(t, 0.0, 0.0); 2];
    for (slot, w) in v.iter_mut().zip(watches) {
        let (g, d, _) = w.eval(j);
        *slot = (t, g, d);
    }
    v
}

/// The first event among `watches` in a phase, or the τ at which none can come any more, with
/// the anchors laid down on the way (all of them when `keep` — for sampling and the energy
/// audit — else only the last).
pub(super) fn search(first: Propagator, modes: &Modes, watches: &[Watch], keep: bool) -> Found {
    debug_assert!(watches.len() <= 2, "a phase watches at most two events");
    let mut ta = 0.0;
    let mut va = values(watches, &jet(&first, 0.0), 0.0);
    let mut trail = Trail {
        keep,
        current: (0.0, first),
        anchors: Vec::new(),
    };
    for step in 1..=MAX_STEPS {
        let tb = ta + modes.step(ta);
        let (t0, p) = &trail.current;
        let mut f = |t: f64| jet(p, t - t0);
        let jb = f(tb);
        let vb = values(watches, &jb, tb);
        let mut best: Option<(f64, usize)> = None;
        for (i, w) in watches.iter().enumerate() {
            if let Some(t) = crossing_in(*w, &mut f, va[i], vb[i])
                && best.is_none_or(|(bt, _)| t < bt)
            {
                best = Some((t, i));
            }
        }
        if let Some((t, i)) = best {
            return trail.found(t, Some(i), step, false);
        }
        trail.restart(tb, jb.0[0]);
        if modes.settle.is_some_and(|s| tb > s) {
            return trail.found(tb, None, step, false);
        }
        ta = tb;
        va = vb;
    }
    trail.found(ta, None, MAX_STEPS, true)
}
