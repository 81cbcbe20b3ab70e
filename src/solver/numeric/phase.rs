//! One phase of the adaptive solver: what it watches for (the events, with the direction of
//! their crossing, as SciPy's `solve_ivp` events), the watcher that finds them on the dense
//! output, and the integration of the phase down the integrator cascade to its first
//! confirmed event.

use super::integrator::{CASCADE, Integrator, STIFF_ENTRY, solve_with};
use super::{ATOL_FACTOR, EVENT_SLACK, Impact, STIFF, X};
use crate::solver::each_step::{EachStep, EndState};
use crate::solver::roots::brent;

/// What a phase watches for, with the direction of the crossing.
#[derive(Clone, Copy, Debug)]
pub(super) enum Watch {
    /// z̄' falls through 0: unload.
    RateFalls,
    /// z̄ rises through z̄_p: the elastic–plastic law turns linear (a kink the steps must meet).
    Yields(f64),
    /// z̄ falls to z̄_f: F = 0, separation.
    Separates(f64),
    /// z̄ rises back to z̄_m: reload.
    Reloads(f64),
}

impl Watch {
    pub(super) fn g(self, imp: &Impact, x: &X) -> f64 {
        let z = x[0];
        match self {
            Watch::RateFalls => x[1] - imp.force_and_rate(x).1,
            Watch::Yields(t) | Watch::Separates(t) | Watch::Reloads(t) => z - t,
        }
    }
    fn rising(self) -> bool {
        matches!(self, Watch::Yields(_) | Watch::Reloads(_))
    }
    /// The size `g` is measured against: what the integrator's error tolerance on it scales
    /// with (atol = rtol · ATOL_FACTOR on each state, plus rtol times its size).
    fn scale(self, imp: &Impact, x: &X) -> f64 {
        match self {
            Watch::RateFalls => x[1].abs() + imp.force_and_rate(x).1.abs() + ATOL_FACTOR,
            Watch::Yields(t) | Watch::Separates(t) | Watch::Reloads(t) => t.abs() + ATOL_FACTOR,
        }
    }
}

/// The first watched crossing found on a step's dense output.
#[derive(Clone, Copy, Debug)]
struct Hit {
    /// When g crosses zero.
    t: f64,
    /// The start of the step it was found in, and the state there.
    t_prev: f64,
    x_prev: X,
    watch: Watch,
}

/// One phase as integrated: where it ended, on which event, and what it cost.
#[derive(Debug)]
pub(super) struct Integrated {
    /// The event it ended on; `None` at `t_stop`, at rest, when the cascade gave up before
    /// any event, or at an event the integration to it did not confirm (`spurious`).
    pub(super) hit: Option<Watch>,
    /// (τ, x) where it ended: the event, the last accepted step, or where the cascade gave up.
    pub(super) last: (f64, X),
    /// The grid's samples it covered, (τ, x) each.
    pub(super) samples: Vec<(f64, X)>,
    /// Steps taken (accepted and rejected), the re-integration to an event included.
    pub(super) steps: usize,
    /// The integrator gave up (step budget, step size underflow) before an event or `t_stop`.
    pub(super) failed: bool,
    /// A stiff integrator ran (some of) the phase.
    pub(super) stiff: bool,
    /// The stage of the cascade that finished the integration (see `integrator::CASCADE`).
    pub(super) stage: usize,
    /// The phase stopped at an event the integration to it did not confirm; it goes on.
    pub(super) spurious: bool,
    /// The accepted steps' ends (τ, x) up to `last` included, when the flow is kept
    /// (`flow`): where the oblique impact reads the normal motion of any law.
    pub(super) knots: Vec<(f64, X)>,
}

/// The custom watcher: finds the first watched crossing (terminal), and records evenly spaced
/// samples from the dense output when asked to.
struct Watcher<'a> {
    imp: &'a Impact,
    watches: Vec<Watch>,
    hit: Option<Hit>,
    grid: &'a [f64],
    samples: Vec<(f64, X)>,
    t_stop: f64,
    /// The last accepted step, where an event-less integration stopped.
    last: (f64, X),
    steps: usize,
    failed: bool,
    stiff: bool,
    stage: usize,
    spurious: bool,
    /// Keep the steps' ends (see `Integrated::knots`).
    keep: bool,
    knots: Vec<(f64, X)>,
}

impl Watcher<'_> {
    fn into_integrated(mut self) -> Integrated {
        // the phase's end is a knot whichever way it came (an event integrated to, `t_stop`,
        // rest, or where the cascade gave up)
        if self.keep && self.knots.last().is_none_or(|k| k.0 < self.last.0) {
            self.knots.push(self.last);
        }
        Integrated {
            hit: self.hit.map(|h| h.watch),
            last: self.last,
            samples: self.samples,
            steps: self.steps,
            failed: self.failed,
            stiff: self.stiff,
            stage: self.stage,
            spurious: self.spurious,
            knots: self.knots,
        }
    }
}

impl EachStep<X> for Watcher<'_> {
    fn watch(
        &mut self,
        (t_prev, y_prev): (f64, &X),
        (t_curr, y_curr): (f64, &X),
        dense: &mut impl FnMut(f64) -> X,
    ) -> bool {
        let mut at = |t: f64| if t == t_curr { *y_curr } else { dense(t) };
        let mut best: Option<(f64, Watch)> = None;
        for &w in &self.watches {
            let sign = if w.rising() { 1.0 } else { -1.0 };
            let (ga, gb) = (sign * w.g(self.imp, y_prev), sign * w.g(self.imp, y_curr));
            if ga < 0.0 && gb >= 0.0 {
                let t = brent(
                    |t| sign * w.g(self.imp, &at(t)),
                    t_prev,
                    t_curr,
                    ga,
                    gb,
                    1e-15 * t_curr.abs().max(1e-300),
                );
                if best.is_none_or(|(bt, _)| t < bt) {
                    best = Some((t, w));
                }
            }
        }
        self.last = (t_curr, *y_curr);
        let end = best.map_or(t_curr.min(self.t_stop), |(t, _)| t);
        while let Some(&ts) = self.grid.get(self.samples.len())
            && ts <= end
        {
            self.samples.push((ts, at(ts.max(t_prev))));
        }
        // a step that crosses an event ends at the event, integrated to (`confirm`)
        if self.keep && best.is_none() {
            self.knots.push((t_curr, *y_curr));
        }
        match best {
            Some((t, watch)) => {
                self.hit = Some(Hit {
                    t,
                    t_prev,
                    x_prev: *y_prev,
                    watch,
                });
                true
            }
            // at `t_stop`, or come to rest: no rebound can follow (see `cor_bound`)
            None => t_curr >= self.t_stop || self.imp.at_rest(y_curr),
        }
    }
}

/// Integrate one phase from (t0, x0) until a watched event or `t_stop`, down the integrator
/// cascade from its entry (the stiff one when the dashpot is stiff there, unless `explicit`
/// asks DOPRI5 to try first), or from `floor` if that is later; with `keep`, every accepted
/// step's end is kept (`Integrated::knots`).
pub(super) fn integrate(
    imp: &Impact,
    (t0, x0): (f64, X),
    t_stop: f64,
    watches: Vec<Watch>,
    grid: &[f64],
    (rtol, floor, explicit): (f64, usize, bool),
    keep: bool,
) -> Integrated {
    let mut w = Watcher {
        imp,
        watches,
        hit: None,
        grid,
        samples: Vec::new(),
        t_stop,
        last: (t0, x0),
        steps: 0,
        failed: false,
        stiff: false,
        stage: floor,
        spurious: false,
        keep,
        knots: Vec::new(),
    };
    // The crate reports giving up (out of steps, step size underflow) as an error; the watcher
    // then holds what was reached, and the phase goes on from there with the next integrator
    // of the cascade (see `integrator`). Only when the last one gives up is the phase failed:
    // never read as the horizon.
    let entry = if !explicit && imp.dashpot_rate(x0[0]) > STIFF {
        STIFF_ENTRY
    } else {
        0
    };
    // From `floor` on, then round to the stages between the entry and it: a floor is where a
    // phase that goes on after a noise crossing prefers to start (see `PhaseRunner`), not a
    // bar to the integrators above it, which may still carry it where those below give up.
    let stages = (entry.max(floor)..CASCADE.len()).chain(entry..floor);
    let Some(stage) = first_to_finish(stages, |method| {
        w.stiff |= method.is_stiff();
        let (t1, x1) = w.last;
        let run = solve_with(imp, t1, x1, t_stop, rtol, method, &mut w);
        w.steps += run.steps;
        !run.failed || w.hit.is_some()
    }) else {
        w.failed = true;
        return w.into_integrated();
    };
    w.stage = stage;
    if let Some(hit) = w.hit {
        confirm(&mut w, hit, rtol);
    }
    w.into_integrated()
}

/// Integrate from the start of the step `hit` was found in to its time, down the cascade from
/// the stage that found it, and keep the event only where that integration confirms it.
///
/// The event's state is integrated to the event time, not read off the dense output:
/// Radau5's continuous output is of lower order than its steps.
fn confirm(w: &mut Watcher, hit: Hit, rtol: f64) {
    let imp = w.imp;
    let mut end = EndState(hit.t_prev, hit.x_prev);
    let Some(stage) = first_to_finish(w.stage..CASCADE.len(), |method| {
        w.stiff |= method.is_stiff();
        let run = solve_with(imp, end.0, end.1, hit.t, rtol, method, &mut end);
        w.steps += run.steps;
        !run.failed
    }) else {
        w.failed = true;
        w.last = (end.0, end.1);
        return;
    };
    w.last = (hit.t, end.1);
    w.stage = stage;
    // An event the integration to it does not confirm was an artefact of the dense output
    // over a long step (Radau5 over thousands of ω0⁻¹ of creep can dip z̄ through z̄_f between
    // its points): the phase is not over, it goes on from there.
    let watch = hit.watch;
    let sign = if watch.rising() { 1.0 } else { -1.0 };
    let missed = -sign * watch.g(imp, &end.1);
    if missed > EVENT_SLACK * CASCADE[stage].rtol(rtol) * watch.scale(imp, &end.1) {
        w.hit = None;
        w.spurious = true;
    }
}

/// The first of the cascade's `stages`, in their order, at which `attempt` (with that stage's
/// integrator, from wherever the one before gave up) finishes; `None` when all give up. Each
/// stage is tried once at most, so a phase costs `CASCADE_BUDGET` at most.
fn first_to_finish(
    stages: impl IntoIterator<Item = usize>,
    mut attempt: impl FnMut(Integrator) -> bool,
) -> Option<usize> {
    stages.into_iter().find(|&i| attempt(CASCADE[i]))
}
