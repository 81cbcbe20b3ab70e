//! Following an integration step by step: the one [`Solout`] of the runs that watch the
//! `differential-equations` crate's steps (the adaptive solver's phases, the two-body runs,
//! the oblique reference integration), which hands each accepted step and its dense output
//! to an [`EachStep`]; and the watcher that keeps only the last state reached, to integrate
//! to an event rather than read it off the dense output.

use differential_equations::interpolate::Interpolation;
use differential_equations::prelude::{ControlFlag, Solout};
use differential_equations::solution::Solution;
use differential_equations::traits::State;

/// What follows a run step by step.
pub trait EachStep<Y> {
    /// The accepted step from `prev` (τ, y) to `end` (τ, y), `at` its dense output (the
    /// step's end where the method gives none at τ); whether the run stops there.
    fn watch(&mut self, prev: (f64, &Y), end: (f64, &Y), at: &mut impl FnMut(f64) -> Y) -> bool;
}

/// The integrator's view of an [`EachStep`]: every step handed to it, the run stopped where
/// it says.
pub struct Watched<'w, W>(pub &'w mut W);

impl<Y: State<f64>, W: EachStep<Y>> Solout<f64, Y> for Watched<'_, W> {
    fn solout<I>(
        &mut self,
        t: f64,
        t_prev: f64,
        y: &Y,
        y_prev: &Y,
        interp: &mut I,
        _s: &mut Solution<f64, Y>,
    ) -> ControlFlag<f64, Y>
    where
        I: Interpolation<f64, Y> + ?Sized,
    {
        let mut at = |tt: f64| interp.interpolate(tt).unwrap_or_else(|_| y.clone());
        if self.0.watch((t_prev, y_prev), (t, y), &mut at) {
            ControlFlag::Terminate
        } else {
            ControlFlag::Continue
        }
    }
}

/// A watcher that keeps only the last state reached (τ, x): the end, or where the integrator
/// gave up.
pub struct EndState<Y>(pub f64, pub Y);

impl<Y: Clone> EachStep<Y> for EndState<Y> {
    fn watch(&mut self, _: (f64, &Y), (t, y): (f64, &Y), _: &mut impl FnMut(f64) -> Y) -> bool {
        (self.0, self.1) = (t, y.clone());
        false
    }
}
