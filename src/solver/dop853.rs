//! One DOP853 run (the `differential-equations` crate's explicit Runge–Kutta 8(5,3)) as the
//! runs that follow a contact with events on its dense output take it: the compliant
//! target's (`target::numeric`), the pair's (`target::pair`) and the oblique reference
//! integration's (`oblique::reference`); and the solout that keeps only the last state
//! reached, to integrate to an event rather than read it off the dense output.

use differential_equations::interpolate::Interpolation;
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::prelude::{ControlFlag, Solout};
use differential_equations::solution::Solution;
use differential_equations::traits::State;

/// Integrate `ode` from (`t0`, `x0`) to `tf` by DOP853, every step handed to `out`: relative
/// tolerance `rtol`, absolute a hundredth of it (the states are of order 1), at most
/// `max_steps` steps. Whether the run reached `tf` (false: the step budget ran out).
pub fn run<Y: State<f64>, F: ODE<f64, Y>, O: Solout<f64, Y>>(
    ode: &F,
    (t0, x0): (f64, &Y),
    tf: f64,
    (rtol, max_steps): (f64, usize),
    out: &mut O,
) -> bool {
    let mut m = ExplicitRungeKutta::dop853()
        .rtol(rtol)
        .atol(rtol * 1e-2)
        .max_steps(max_steps);
    solve_ode(&mut m, ode, t0, tf, x0, out).is_ok()
}

/// A solout that keeps only the last state reached (τ, x): the end, or where the integrator
/// gave up.
pub struct EndState<Y>(pub f64, pub Y);

impl<Y: State<f64>> Solout<f64, Y> for EndState<Y> {
    fn solout<I>(
        &mut self,
        t: f64,
        _tp: f64,
        y: &Y,
        _yp: &Y,
        _i: &mut I,
        _s: &mut Solution<f64, Y>,
    ) -> ControlFlag<f64, Y>
    where
        I: Interpolation<f64, Y> + ?Sized,
    {
        (self.0, self.1) = (t, y.clone());
        ControlFlag::Continue
    }
}
