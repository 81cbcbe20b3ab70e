//! One integration of a phase with one integrator of the cascade, reporting what it cost and
//! whether it gave up rather than the crate's error.
//!
//! Why a cascade: no single integrator of the `differential-equations` crate carries every
//! phase the domain holds. DOPRI5 is the most accurate but is held to its stability limit by a
//! stiff dashpot; the crate's Radau5 and BDF take stiff phases in few steps but can collapse
//! their step size ("step size too small") where the 3/2-power force has no second derivative
//! or where a creeping ball's state spans ten decades (z̄ ~ 1e-9 against ȳ ~ 1e4), and which
//! one collapses, and where, changes with the tolerance: no order of them passes every phase
//! at every tolerance. So a phase is handed down the list below from the state where the
//! previous one gave up, and only when all have given up is the phase failed (what holds then,
//! an answer or an honest "no answer", is checked over the domain by tests/physics/properties.rs,
//! `every_run_keeps_the_invariants`, and tests/physics/solver_agreement.rs,
//! `creeps_at_the_integrators_noise_floor_answer`).

use super::{ATOL_FACTOR, Impact, X};
use crate::solver::each_step::{EachStep, Watched};
use differential_equations::interpolate::Interpolation;
use differential_equations::methods::{
    BackwardDifferentiationFormula, ExplicitRungeKutta, ImplicitRungeKutta, Ordinary,
};
use differential_equations::ode::{OrdinaryNumericalMethod, solve_ode};
use differential_equations::prelude::Solout;

/// Step budget of DOPRI5 in one phase before the stiff integrators take the rest of it over: a
/// phase that long is one where the dashpot, though not stiff by `STIFF`, creeps for many of
/// its own time constants (λ = 0 with a weak dashpot: the ball sinks in for ~40ζ), holding
/// DOPRI5 to its stability limit the whole way.
pub(super) const EXPLICIT_STEPS: usize = 20_000;
/// Step budget of one stiff integration, and of DOPRI5 as the last resort.
pub(super) const MAX_STEPS: usize = 100_000;

/// An integrator of the cascade.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Integrator {
    /// DOPRI5 with its step budget.
    Dopri5(usize),
    /// Radau5 at the tolerance asked for times `LOOSEN^k`.
    Radau5(i32),
    /// Variable-order BDF (1–5) at the tolerance asked for times `LOOSEN^k`.
    Bdf(i32),
}

/// What a stiff integrator's tolerance is multiplied by at each retry. Two retries at most: a
/// run at 1e-10 ends no looser than 1e-6, still far inside what `audit::energy_tolerance`
/// allows a stiff run, and the response says it was stiff.
const LOOSEN: f64 = 100.0;

/// The order a phase is handed down in. A non-stiff phase starts at the top; a stiff one (see
/// `STIFF`) at Radau5. DOPRI5 on its full budget comes last: it passes where every implicit
/// method stalls on the 3/2-power kink at z̄ = z̄_f, when the phase is short enough.
pub(super) const CASCADE: [Integrator; 7] = [
    Integrator::Dopri5(EXPLICIT_STEPS),
    Integrator::Radau5(0),
    Integrator::Bdf(0),
    Integrator::Radau5(1),
    Integrator::Bdf(1),
    Integrator::Radau5(2),
    Integrator::Dopri5(MAX_STEPS),
];

/// Where a stiff phase enters the cascade.
pub(super) const STIFF_ENTRY: usize = 1;

impl Integrator {
    /// The most steps one integration with it can take.
    pub(super) const fn budget(self) -> usize {
        match self {
            Integrator::Dopri5(budget) => budget,
            Integrator::Radau5(_) | Integrator::Bdf(_) => MAX_STEPS,
        }
    }

    /// The relative tolerance it runs at when `rtol` is asked for.
    pub(super) fn rtol(self, rtol: f64) -> f64 {
        match self {
            Integrator::Dopri5(_) => rtol,
            Integrator::Radau5(k) | Integrator::Bdf(k) => rtol * LOOSEN.powi(k),
        }
    }

    /// Whether it is one of the implicit (stiff) integrators, whose COR and energy balance
    /// hold less tightly than DOPRI5's (see `audit::energy_tolerance`).
    pub(super) fn is_stiff(self) -> bool {
        !matches!(self, Integrator::Dopri5(_))
    }
}

/// The loosest tolerance an integrator of the cascade runs at when `rtol` is asked for.
pub(super) fn loosest(rtol: f64) -> f64 {
    CASCADE.iter().map(|m| m.rtol(rtol)).fold(rtol, f64::max)
}

/// The most steps one phase can take down the whole cascade.
pub(in crate::solver) const CASCADE_BUDGET: usize = {
    let mut sum = 0;
    let mut i = 0;
    while i < CASCADE.len() {
        sum += CASCADE[i].budget();
        i += 1;
    }
    sum
};

/// What one integration cost (at most: a failed run counts its whole budget), and whether the
/// integrator gave up.
pub(super) struct RunStats {
    pub steps: usize,
    pub failed: bool,
}

/// One integration with `method`.
pub(super) fn solve_with<O: EachStep<X>>(
    imp: &Impact,
    t0: f64,
    x0: X,
    tf: f64,
    rtol: f64,
    method: Integrator,
    out: &mut O,
) -> RunStats {
    let budget = method.budget();
    let out = &mut Watched(out);
    match method {
        Integrator::Dopri5(_) => {
            let mut m = ExplicitRungeKutta::dopri5()
                .rtol(rtol)
                .atol(rtol * ATOL_FACTOR)
                .max_steps(budget);
            run(&mut m, budget, imp, t0, x0, tf, out)
        }
        Integrator::Radau5(_) => {
            let rtol = method.rtol(rtol);
            // Radau5 (as Hairer's original) replaces a tolerance r by 0.1 r^(2/3) before use;
            // hand it the pre-image so that it runs at the tolerance asked for.
            let pre = |r: f64, floor: f64| (10.0 * r).powf(1.5).max(floor);
            let mut m = ImplicitRungeKutta::radau5()
                .rtol(pre(rtol, 1e-14))
                .atol(pre(rtol * ATOL_FACTOR, 1e-16))
                .max_steps(budget);
            run(&mut m, budget, imp, t0, x0, tf, out)
        }
        Integrator::Bdf(_) => {
            let rtol = method.rtol(rtol);
            let mut m: BackwardDifferentiationFormula<Ordinary, f64, X> =
                BackwardDifferentiationFormula::adaptive()
                    .rtol(rtol)
                    .atol(rtol * ATOL_FACTOR)
                    .max_steps(budget);
            run(&mut m, budget, imp, t0, x0, tf, out)
        }
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
