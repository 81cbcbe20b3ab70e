//! The adaptive numerical solver for any contact law: the first-order system of docs/model.md
//! §2 in normalized form, x = (z̄, ᾱ', ȳ, Ē_d) with z̄ = ᾱ − ȳ,
//!     ᾱ'' = −F̄,   ȳ' = 2ζ(F̄ − λȳ),   z̄' = ᾱ' − ȳ',   Ē_d' = ȳ'²/(2ζ) = 2ζ(F̄ − λȳ)²,
//! integrated phase by phase with the `differential-equations` crate: DOPRI5, or, when the
//! dashpot makes the phase stiff or DOPRI5 gives up, a cascade of its stiff integrators (see
//! `integrator`). Events are located as in SciPy's `solve_ivp` (terminal, with a direction) by
//! a custom `Solout` that root-finds on the step's dense output (the crate's own
//! `EventSolout` skips the first step of each integration, and every phase here starts one),
//! then confirmed by integrating to them. A ball that can no longer leave above `REST_COR`
//! (see `Impact::cor_bound`) has come to rest: no rebound.

use super::{Outcome, SolveOptions};
use crate::model::contact::Contact;
use crate::model::params::Normalized;
use impact::Impact;
use runner::{PhaseRun, PhaseRunner};

pub use flow::NumericPath;

mod creep;
mod flow;
mod impact;
mod integrator;
mod phase;
mod runner;

type X = [f64; 4];

/// Phase budget. A ball creeping into a weak dashpot (small λ, large ζ) can hold z̄ at its
/// peak, z̄' ≈ 0, for a long time; the integrator's noise then flips it between the loading and
/// unloading branches (which meet there, so the flips do not change the answer) many times,
/// each flip a short phase. What bounds the work is `TOTAL_STEPS`. A flip between branches
/// that coincide (an elastic contact, z̄_f = 0: the unloading branch is the loading law
/// itself) is not counted here but against `MAX_FLIPS`: it changes no force, and a real
/// turning point held for thousands of ω0⁻¹ flips tens of thousands of times, a few steps each
/// (tests/physics/solver_agreement.rs, `creeps_leave_at_the_springs_pace`: Hertz, λ = 7.6e-9, ζ = 1e4).
const MAX_PHASES: usize = 4096;
/// Budget of flips between coinciding branches (see `MAX_PHASES`); each records an event.
const MAX_FLIPS: usize = 1 << 17;
/// Step budget of one impact, over all its phases.
pub(super) const TOTAL_STEPS: usize = 1_000_000;
/// Absolute tolerance relative to rtol (normalized states are of order 1).
const ATOL_FACTOR: f64 = 1e-3;
pub(super) use integrator::CASCADE_BUDGET;
/// How far, in units of the integrator's tolerance on the watched quantity, the integration to
/// an event may end short of the crossing and still confirm it (see `integrate`).
const EVENT_SLACK: f64 = 1e3;
/// How far past z̄_m, in units of the tolerance on z̄, the ball must rise before an unloading
/// phase turns back to loading. At a slow turning point (a ball creeping into a weak dashpot
/// against a soft recoil spring, z̄ within 1e-13 of z̄_m for many ω0⁻¹) the integrator's noise
/// would otherwise cross z̄_m back and forth, a phase each time, without end. Between z̄_m and
/// the switch the unloading branch goes on smoothly past z̄_m (see
/// `Contact::unloading_force`); the force there is set by the slow motion (F̄ ≈ λȳ + ᾱ'/2ζ on
/// the creeping manifold) whatever the branch, so what the late switch moves is z̄ by at most
/// this much, and the peak the next unloading starts from.
pub(crate) const RELOAD_SLACK: f64 = 100.0;
/// Above this stiffness (fastest dashpot rate, see `Impact::dashpot_rate`) DOPRI5 would be held
/// to its stability limit (a few thousand steps an impact at this value); Radau5 takes over.
/// Radau5 as the crate implements it holds COR and the energy balance less tightly than DOPRI5
/// (see `audit::energy_tolerance`), so DOPRI5 keeps every case it can do in bounded time.
const STIFF: f64 = 2000.0;
/// How much slower than the element the recoil spring retracts (2ζλȳ) a ball may still move
/// out at a crossing of z̄_f and be taken to have left. A real separation outruns the element
/// (z̄' = ᾱ' + 2ζλȳ < 0 there, with no force), so e ≥ 2ζλȳ_f; a grazing one, on the slow
/// manifold of a weak dashpot, leaves at that pace within the integrator's noise, and z̄' at
/// z̄_f never clears it: taking it at 1e-3 of the pace finds it to that, and turns away
/// crossings made in the noise with the ball moving out far slower (`audit`'s
/// outruns_the_element holds every answer to 2e-3 of the pace; tests/physics/solver_agreement.rs,
/// `creeps_leave_at_the_springs_pace`, λ = 4.2e-8, ζ = 6.3, elastic–plastic).
const PACE_SLACK: f64 = 1e-3;
/// The relative error of the COR up to which a creep may be finished in closed form (the bound
/// of `creep`): ten times tighter than the integrated creep, which ends at a grazing
/// separation found to `PACE_SLACK`.
const CREEP_TOL: f64 = 0.1 * PACE_SLACK;
/// A run the stiff integrators carried whose energy balance (`residual`) is looser than this
/// many rtol is run again with DOPRI5 first (`checked_run`). The stiff integrators' error
/// estimates can pass steps far less accurate than rtol: under Hertz at λ = 30, ζ = 40 the
/// balance closed to 7.8e-8 at rtol 1e-10 and the COR was 6e-8 off, the same at rtol 1e-14,
/// where DOPRI5 closes the balance to 1e-13 and meets the independent reference to 4e-14
/// (tests/physics/solver_agreement.rs, `stiff_runs_are_checked_by_their_energy_balance`). DOPRI5's
/// own balance reaches ~35 rtol (`audit::energy_tolerance`), hence the margin.
const RECHECK: f64 = 100.0;
/// DOPRI5's reach along the negative real axis, in steps of 1/rate: a recheck is run only
/// where DOPRI5 can cross the contact within its step budget (`integrator::EXPLICIT_STEPS`).
const DOPRI5_REACH: f64 = 3.3;
/// A ball whose remaining energy could not give it a COR above this has come to rest.
const REST_COR: f64 = 1e-9;

/// How long to follow a ball that may never leave: a hundred times the sum of the contact
/// times (linear spring π; Hertz alone 2.94 z̄_m with z̄_m = (5/(4κ))^{2/5}, long when the
/// contact is soft against the speed), the dashpot creep time 2ζ and the recoil relaxation
/// time 1/(2ζλ). Capped only where τ itself would lose its digits against the step sizes of
/// the contact (1e18 ω0⁻¹, λ ≈ 5e-19 at ζ = 1): a recoil spring as soft as λ = 1e-12 releases
/// the ball only after ~1/(2ζλ), and that must lie inside the horizon for the run to answer
/// (tests/physics/properties.rs, `every_run_keeps_the_invariants`, draws λ down to 1e-15).
fn horizon(n: &Normalized) -> f64 {
    let relax = if n.lambda > 0.0 && n.zeta > 0.0 {
        1.0 / (2.0 * n.zeta * n.lambda)
    } else {
        0.0
    };
    let hertz = 2.95 * (1.25 / n.kappa).powf(0.4);
    (100.0 * (std::f64::consts::PI + hertz + 2.0 * n.zeta + relax)).min(1e18)
}

pub(crate) fn solve(n: &Normalized, contact: &Contact, opts: &SolveOptions) -> Outcome {
    let (first, explicit) = checked_run(n, contact, opts.rtol, false);
    let mut out = first.outcome;
    if opts.samples == 0 {
        return out;
    }
    let grid: Vec<f64> = (0..opts.samples)
        .map(|j| {
            if opts.samples > 1 {
                out.tau_end * j as f64 / (opts.samples - 1) as f64
            } else {
                0.0
            }
        })
        .collect();
    let again = runner(n, contact, opts.rtol, &grid, explicit).run();
    out.steps += again.outcome.steps;
    out.samples = again.samples;
    out
}

/// The run of `solve` (without samples: the very same integration) and its flow, which the
/// oblique impact reads at any τ (src/oblique/); `None` when a creep was finished in closed
/// form and left no steps to read.
pub(crate) fn solve_path(
    n: &Normalized,
    contact: &Contact,
    opts: &SolveOptions,
) -> (Outcome, Option<NumericPath>) {
    let (run, _) = checked_run(n, contact, opts.rtol, true);
    let imp = Impact {
        lambda: n.lambda,
        zeta: n.zeta,
        contact: *contact,
        phase: impact::Phase::Loading,
    };
    let path = run.kept.map(|k| NumericPath::new(&imp, &k));
    (run.outcome, path)
}

/// A runner from first touch; `explicit` starts every phase on DOPRI5.
fn runner<'a>(
    n: &Normalized,
    contact: &Contact,
    rtol: f64,
    grid: &'a [f64],
    explicit: bool,
) -> PhaseRunner<'a> {
    let r = PhaseRunner::new(n, contact, rtol, grid);
    if explicit { r.explicit() } else { r }
}

/// The run, checked by its energy balance: one the stiff integrators carried and that closes
/// looser than `RECHECK` rtol is run again with DOPRI5 first, where DOPRI5 can cross the
/// contact within its step budget, and the better-balanced of the two is kept (with both
/// runs' steps). The flag says whether that was the DOPRI5 run (the samples' run follows it).
fn checked_run(n: &Normalized, contact: &Contact, rtol: f64, keep: bool) -> (PhaseRun, bool) {
    let keeping = |r: PhaseRunner<'static>| if keep { r.keeping() } else { r };
    let mut first = keeping(runner(n, contact, rtol, &[], false)).run();
    if !worth_rechecking(n, contact, &first.outcome, rtol) {
        return (first, false);
    }
    let mut again = keeping(runner(n, contact, rtol, &[], true)).run();
    let steps = first.outcome.steps + again.outcome.steps;
    let better = again.outcome.unresolved.is_none()
        && residual(n, &again.outcome) < residual(n, &first.outcome);
    if better {
        again.outcome.steps = steps;
        (again, true)
    } else {
        first.outcome.steps = steps;
        (first, false)
    }
}

/// Whether `o`, a finished run, should be run again on DOPRI5 (see `checked_run`).
fn worth_rechecking(n: &Normalized, contact: &Contact, o: &Outcome, rtol: f64) -> bool {
    if !(o.stiff && o.rebound && o.unresolved.is_none()) || residual(n, o) <= RECHECK * rtol {
        return false;
    }
    let imp = Impact {
        lambda: n.lambda,
        zeta: n.zeta,
        contact: *contact,
        phase: impact::Phase::Loading,
    };
    imp.dashpot_rate(o.z_max) * o.tau_end / DOPRI5_REACH <= integrator::EXPLICIT_STEPS as f64
}

/// The energy balance of a finished run as a fraction of the impact energy ½ (normalized:
/// docs/model.md §5), ½(1 − ᾱ'²) = Ē_d + ∮F̄ dz̄ + ½λȳ², as `EnergyBudget::relative_residual`
/// reads it in SI.
fn residual(n: &Normalized, o: &Outcome) -> f64 {
    let v = o.velocity_end;
    let loss = 0.5 * (1.0 - v * v);
    let held = o.dashpot.unwrap_or(0.0) + o.contact_work + 0.5 * n.lambda * o.y_end * o.y_end;
    (loss - held).abs() / 0.5
}
