//! One integration of a phase with one integrator of the cascade (DOPRI5 on a budget, or
//! Radau5), reporting what it cost and whether it gave up rather than the crate's error.

use super::{ATOL_FACTOR, Impact, MAX_STEPS, X};
use differential_equations::interpolate::Interpolation;
use differential_equations::methods::{ExplicitRungeKutta, ImplicitRungeKutta};
use differential_equations::ode::{OrdinaryNumericalMethod, solve_ode};
use differential_equations::prelude::{ControlFlag, Solout};
use differential_equations::solution::Solution;

/// The integrator of one run: DOPRI5 with its step budget, or Radau5 (budget `MAX_STEPS`).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Integrator {
    Dopri5(usize),
    Radau5,
}

/// What one integration cost (at most: a failed run counts its whole budget), and whether the
/// integrator gave up.
pub(super) struct RunStats {
    pub steps: usize,
    pub failed: bool,
}

/// One integration with `method`.
pub(super) fn solve_with<O: Solout<f64, X>>(
    imp: &Impact,
    t0: f64,
    x0: X,
    tf: f64,
    rtol: f64,
    method: Integrator,
    out: &mut O,
) -> RunStats {
    let atol = rtol * ATOL_FACTOR;
    if let Integrator::Dopri5(budget) = method {
        let mut m = ExplicitRungeKutta::dopri5()
            .rtol(rtol)
            .atol(atol)
            .max_steps(budget);
        run(&mut m, budget, imp, t0, x0, tf, out)
    } else {
        // Radau5 (as Hairer's original) replaces a tolerance r by 0.1 r^(2/3) before use; hand
        // it the pre-image so that it runs at the tolerance asked for.
        let (rtol, atol) = (
            (10.0 * rtol).powf(1.5).max(1e-14),
            (10.0 * atol).powf(1.5).max(1e-16),
        );
        let mut m = ImplicitRungeKutta::radau5()
            .rtol(rtol)
            .atol(atol)
            .max_steps(MAX_STEPS);
        run(&mut m, MAX_STEPS, imp, t0, x0, tf, out)
    }
}

/// Integrate from t0 to tf into `out`. The crate's errors (out of steps, step size underflow)
/// carry no state `out` does not already hold; what is kept is that the run failed, and its
/// cost (an error does not say how many steps it took: out of steps counts as the budget).
fn run<S, O>(
    m: &mut S,
    budget: usize,
    imp: &Impact,
    t0: f64,
    x0: X,
    tf: f64,
    out: &mut O,
) -> RunStats
where
    S: OrdinaryNumericalMethod<f64, X> + Interpolation<f64, X>,
    O: Solout<f64, X>,
{
    if t0 >= tf {
        return RunStats {
            steps: 0,
            failed: false,
        };
    }
    match solve_ode(m, imp, t0, tf, &x0, out) {
        Ok(sol) => RunStats {
            steps: sol.steps.accepted + sol.steps.rejected,
            failed: false,
        },
        Err(_) => RunStats {
            // the error does not say how many steps were taken: at most the budget
            steps: budget,
            failed: true,
        },
    }
}

/// A solout that keeps only the final state.
pub(super) struct EndState(pub X);

impl Solout<f64, X> for EndState {
    fn solout<I>(
        &mut self,
        _t: f64,
        _tp: f64,
        y: &X,
        _yp: &X,
        _i: &mut I,
        _s: &mut Solution<f64, X>,
    ) -> ControlFlag<f64, X>
    where
        I: Interpolation<f64, X> + ?Sized,
    {
        self.0 = *y;
        ControlFlag::Continue
    }
}
