//! What the two integrated runs of a contact in series with two relaxing elements share: the
//! compliant target's (`numeric`: the ball's pair ȳ and the surface s̄, docs/targets.md §4)
//! and the two deforming balls' (`pair`: ball 1's ȳ₁ and ball 2's ȳ₂, docs/targets.md §8).
//! Both follow the state x = (z̄, ᾱ', ȳ, s̄) with
//!
//! ```text
//! ᾱ'' = −F̄,   ȳ' and s̄' each element's own rate,   z̄' = ᾱ' − ȳ' − s̄',
//! ```
//!
//! one phase (loading, unloading) at a time, each by DOP853 (the `differential-equations`
//! crate) at [`RTOL`], and end a phase where one of two watched functions rises through 0
//! (the turn; separation or reload), found by Brent on the dense output, the state there
//! integrated to rather than read off it.

use crate::solver::dop853;
use crate::solver::each_step::{EachStep, EndState};
use crate::solver::roots::first_rising;
use differential_equations::ode::ODE;

/// State (z̄, ᾱ', ȳ, s̄).
pub(super) type X = [f64; 4];

/// Tolerance of DOP853 (relative; absolute 1e-2 of it: states are of order 1).
pub(super) const RTOL: f64 = 1e-12;
/// Step budget of one phase.
pub(super) const MAX_STEPS: usize = 200_000;
/// Phase budget (load, unload, reload …).
pub(super) const MAX_PHASES: usize = 256;
/// How far past z̄_m, relative, an unloading contact must rise before it reloads (against the
/// integrator's noise at a slow turn, as `solver::numeric::RELOAD_SLACK`).
pub(super) const RELOAD: f64 = 1e-9;

/// A contact in series with two relaxing elements, on the branch in force.
pub(super) trait Series {
    /// (F̄, ȳ', s̄', z̄') at x.
    fn rates(&self, x: &X) -> (f64, f64, f64, f64);

    /// What ends the phase, as g crossing 0 upward: the turn (−z̄'), separation, reload.
    fn watches(&self, x: &X) -> [f64; 2];
}

/// A series' equations of motion as the integrator takes them (module docs).
struct Motion<'a, S>(&'a S);

impl<S: Series> ODE<f64, X> for Motion<'_, S> {
    fn diff(&self, _t: f64, x: &X, dx: &mut X) {
        let (f, ydot, sdot, zdot) = self.0.rates(x);
        *dx = [zdot, -f, ydot, sdot];
    }
}

/// Integrate `series` from (`t0`, `x0`) to `tf`, every step handed to `out`; whether it got
/// there within [`MAX_STEPS`] (nothing to do when `t0` is already at or past `tf`).
fn integrate<S: Series, O: EachStep<X>>(series: &S, t0: f64, x0: X, tf: f64, out: &mut O) -> bool {
    t0 >= tf || dop853::run(&Motion(series), (t0, &x0), tf, (RTOL, MAX_STEPS), out)
}

/// The state at `tc`, integrated to it from the step's start (`tp`, `xp`) rather than read off
/// the dense output; `None` when the step budget ran out first.
pub(super) fn state_at<S: Series>(series: &S, (tp, xp): (f64, X), tc: f64) -> Option<X> {
    let mut end = EndState(tp, xp);
    integrate(series, tp, xp, tc, &mut end).then_some(end.1)
}

/// The first watched crossing within the step from (`t_prev`, `x_prev`) to (`t`, `x`), `at`
/// the step's dense output: its time and which watch.
pub(super) fn first_event<S: Series>(
    series: &S,
    (t_prev, x_prev): (f64, &X),
    (t, x): (f64, &X),
    at: &mut dyn FnMut(f64) -> X,
) -> Option<(f64, usize)> {
    let (ga, gb) = (series.watches(x_prev), series.watches(x));
    first_rising(ga, gb, t_prev, t, |i, tt| series.watches(&at(tt))[i])
}

/// What follows a run step by step on the dense output: the event that ends the phase within
/// the step from (`t_prev`, `x_prev`) to (`t`, `x`), `at` the step's dense output, as
/// [`first_event`] gives it (and whatever else the watcher keeps on the way).
pub(super) trait Watch {
    fn step(
        &mut self,
        prev: (f64, &X),
        end: (f64, &X),
        at: &mut dyn FnMut(f64) -> X,
    ) -> Option<(f64, usize)>;
}

/// Watches for the ends of the phase only.
pub(super) struct FirstEvent<'a, S>(pub &'a S);

impl<S: Series> Watch for FirstEvent<'_, S> {
    fn step(
        &mut self,
        prev: (f64, &X),
        end: (f64, &X),
        at: &mut dyn FnMut(f64) -> X,
    ) -> Option<(f64, usize)> {
        first_event(self.0, prev, end, at)
    }
}

/// A phase's event: its τ, which watch, and the step's start (τ, x) to integrate to it from.
pub(super) type Hit = (f64, usize, f64, X);

/// The integrator's view of a [`Watch`]: every step handed to it, the run stopped at the
/// first event.
struct Watching<'w, W> {
    watch: &'w mut W,
    hit: Option<Hit>,
}

impl<W: Watch> EachStep<X> for Watching<'_, W> {
    fn watch(
        &mut self,
        (t_prev, x_prev): (f64, &X),
        end: (f64, &X),
        at: &mut impl FnMut(f64) -> X,
    ) -> bool {
        let Some((tc, i)) = self.watch.step((t_prev, x_prev), end, at) else {
            return false;
        };
        self.hit = Some((tc, i, t_prev, *x_prev));
        true
    }
}

/// Integrate `series` from (`t0`, `x0`) toward `tf` under `watch`: whether the run ended
/// within [`MAX_STEPS`] (at `tf` or at an event), and the event, if one ended it.
pub(super) fn watch_run<S: Series, W: Watch>(
    series: &S,
    (t0, x0): (f64, X),
    tf: f64,
    watch: &mut W,
) -> (bool, Option<Hit>) {
    let mut w = Watching { watch, hit: None };
    let done = integrate(series, t0, x0, tf, &mut w);
    (done, w.hit)
}
