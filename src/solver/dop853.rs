//! One DOP853 run (the `differential-equations` crate's explicit Runge–Kutta 8(5,3)) as the
//! runs that follow a contact with events on its dense output take it: the compliant
//! target's (`target::numeric`), the pair's (`target::pair`) and the oblique reference
//! integration's (`oblique::reference`).

use super::each_step::{EachStep, Watched};
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::traits::State;

/// Integrate `ode` from (`t0`, `x0`) to `tf` by DOP853, every step handed to `out`: relative
/// tolerance `rtol`, absolute a hundredth of it (the states are of order 1), at most
/// `max_steps` steps. Whether the run reached `tf` (false: the step budget ran out).
pub fn run<Y: State<f64>, F: ODE<f64, Y>, O: EachStep<Y>>(
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
    solve_ode(&mut m, ode, t0, tf, x0, &mut Watched(out)).is_ok()
}
