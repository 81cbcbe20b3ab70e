//! The adaptive numerical solver for any contact law: the first-order system of MODEL.md §2 in
//! normalized form, x = (z̄, ᾱ', ȳ, Ē_d) with z̄ = ᾱ − ȳ,
//!     ᾱ'' = −F̄,   ȳ' = 2ζ(F̄ − λȳ),   z̄' = ᾱ' − ȳ',   Ē_d' = ȳ'²/(2ζ) = 2ζ(F̄ − λȳ)²,
//! integrated phase by phase with the `differential-equations` crate: DOPRI5, or, when the
//! dashpot makes the phase stiff or DOPRI5 gives up, a cascade of its stiff integrators (see
//! `integrator`). Events are located as in SciPy's `solve_ivp` (terminal, with a direction) by
//! a custom `Solout` that root-finds on the step's dense output (the crate's own
//! `EventSolout` skips the first step of each integration, and every phase here starts one),
//! then confirmed by integrating to them. A ball that can no longer leave above `REST_COR`
//! (see `Impact::cor_bound`) has come to rest: no rebound.

use super::{EventKind, Outcome, SolveOptions};
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;
use impact::{Impact, Phase};
use integrator::CASCADE;
use phase::{Watch, integrate};

mod creep;
mod impact;
mod integrator;
mod phase;

type X = [f64; 4];

/// Phase budget. A ball creeping into a weak dashpot (small λ, large ζ) can hold z̄ at its
/// peak, z̄' ≈ 0, for a long time; the integrator's noise then flips it between the loading and
/// unloading branches (which meet there, so the flips do not change the answer) many times,
/// each flip a short phase. What bounds the work is `TOTAL_STEPS`. A flip between branches
/// that coincide (an elastic contact, z̄_f = 0: the unloading branch is the loading law
/// itself) is not counted here but against `MAX_FLIPS`: it changes no force, and a real
/// turning point can flip tens of thousands of times (Hertz, λ = 7.6e-9, ζ = 1e4: 23 804
/// flips over 8 300 ω0⁻¹ of creep at ᾱ' ≈ 0.5, 5 steps each).
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
/// would otherwise cross z̄_m back and forth, a phase each time, until the phase budget ran
/// out. Between z̄_m and the switch the unloading branch goes on smoothly past z̄_m (see
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
/// crossings made in the noise with the ball moving out far slower (3.7e-8 against 6.7e-6 at
/// λ = 4.2e-8, ζ = 6.3, elastic–plastic, once taken for the separation).
const PACE_SLACK: f64 = 1e-3;
/// The relative error of the COR up to which a creep may be finished in closed form (the bound
/// of `creep`): ten times tighter than the integrated creep, which ends at a grazing
/// separation found to `PACE_SLACK`.
const CREEP_TOL: f64 = 0.1 * PACE_SLACK;
/// A ball whose remaining energy could not give it a COR above this has come to rest.
const REST_COR: f64 = 1e-9;

/// How long to follow a ball that may never leave: a hundred times the sum of the contact
/// times (linear spring π; Hertz alone 2.94 z̄_m with z̄_m = (5/(4κ))^{2/5}, long when the
/// contact is soft against the speed), the dashpot creep time 2ζ and the recoil relaxation
/// time 1/(2ζλ). Capped only where τ itself would lose its digits against the step sizes of
/// the contact (1e18 ω0⁻¹, λ ≈ 5e-19 at ζ = 1); a cap at 1e9, as there was, cut the release of a
/// recoil spring as soft as λ = 1e-12 and left such runs without an answer.
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
    let first = run_phases(n, contact, opts.rtol, &[]);
    if opts.samples == 0 {
        return first.0;
    }
    let (mut out, _) = first;
    let grid: Vec<f64> = (0..opts.samples)
        .map(|j| {
            if opts.samples > 1 {
                out.tau_end * j as f64 / (opts.samples - 1) as f64
            } else {
                0.0
            }
        })
        .collect();
    let (again, samples) = run_phases(n, contact, opts.rtol, &grid);
    out.steps += again.steps;
    out.samples = samples;
    out
}

/// Run every phase; with a grid, also return the samples (τ, F̄, z̄, ᾱ) on it.
fn run_phases(
    n: &Normalized,
    contact: &Contact,
    rtol: f64,
    grid: &[f64],
) -> (Outcome, Vec<[f64; 4]>) {
    let mut imp = Impact {
        lambda: n.lambda,
        zeta: n.zeta,
        contact: *contact,
        phase: Phase::Loading,
    };
    let mut out = Outcome::default();
    let mut samples = Vec::with_capacity(grid.len());
    let (mut t, mut x): (f64, X) = (0.0, [0.0, 1.0, 0.0, 0.0]);
    let t_max = horizon(n);
    let mut yielded = false;
    let mut rest = grid;
    let (mut phases_left, mut flips_left) = (MAX_PHASES, MAX_FLIPS);
    // The first stage of the integrator cascade a phase may use (see `integrate`).
    let mut floor = 0;
    // the outward speed above which a ball at z̄_f has left, rather than touched it in the noise
    let left = 100.0 * rtol * ATOL_FACTOR;
    loop {
        if phases_left == 0 {
            out.unresolved = Some("more than 4096 load–unload phases");
            break;
        }
        if flips_left == 0 {
            out.unresolved = Some("more than 131072 flips between load and unload at a turn");
            break;
        }
        if out.steps > TOTAL_STEPS {
            out.unresolved = Some("the step budget of the impact ran out");
            break;
        }
        let z0 = x[0];
        // A loading phase that begins with z̄' ≤ 0 (a reload or a yield met at the turning
        // point itself) has already turned: its unload is now. Watching for z̄' to fall
        // through 0 would never fire, and the ball would leave on the loading branch.
        if matches!(imp.phase, Phase::Loading) && t > 0.0 && Watch::RateFalls.g(&imp, &x) <= 0.0 {
            out.events.push((t, EventKind::Unload, z0));
            imp.phase = Phase::Unloading(contact.unload_from(z0));
        }
        // An unloading phase that goes on from z̄ ≤ z̄_f (after a crossing made in the noise
        // while the ball still moved in) is watched for z̄ falling through z̄_f: if the two
        // already move apart (z̄' < 0 with no force), that never comes and the ball flies off
        // unseen to the horizon (λ = 1e-15, ζ = 11, elastic–plastic: z̄ = −7e8 there). It has
        // left, now.
        if let Phase::Unloading(u) = imp.phase
            && t > 0.0
            && z0 <= u.z_f
            && Watch::RateFalls.g(&imp, &x) < 0.0
        {
            out.rebound = -x[1] > left;
            if out.rebound {
                out.events.push((t, EventKind::Separation, z0));
            }
            break;
        }
        let watches = match imp.phase {
            Phase::Loading
                if contact.law == ContactLaw::ElasticPlastic && !yielded && z0 < contact.zp_bar =>
            {
                vec![Watch::RateFalls, Watch::Yields(contact.zp_bar)]
            }
            Phase::Loading => vec![Watch::RateFalls],
            Phase::Unloading(u) => {
                let past = RELOAD_SLACK * rtol * (u.z_m.abs() + ATOL_FACTOR);
                vec![Watch::Separates(u.z_f), Watch::Reloads(u.z_m + past)]
            }
        };
        let w = integrate(&imp, (t, x), t_max, watches, rest, rtol, floor);
        let hit = w.hit.map(|h| h.3);
        let (t_end, x_end) = w.last;
        out.steps += w.steps;
        out.stiff |= w.stiff;
        // A creep finished in closed form (see `creep`): where the integrators gave up on it,
        // or crossed z̄_f in their noise.
        let mut closing = None;
        if w.failed {
            closing = imp.close_creep(&x_end, integrator::loosest(rtol));
            if closing.is_none() {
                out.unresolved = Some("the integrator gave up before the end of contact");
            }
        } else if hit.is_none() && !w.spurious && !imp.at_rest(&x_end) {
            // the horizon came first: the ball neither left nor came to rest
            out.unresolved = Some("the ball neither left nor came to rest within the horizon");
        }
        let consumed = w.next_sample;
        let phase_samples: Vec<[f64; 4]> = w
            .samples
            .iter()
            .map(|(ts, xs)| [*ts, imp.force(xs[0]), xs[0], xs[0] + xs[2]])
            .collect();
        samples.extend(phase_samples);
        rest = &rest[consumed..];
        let z_end = x_end[0];
        out.contact_work += match imp.phase {
            Phase::Loading => contact.loading_work(z_end) - contact.loading_work(z0),
            Phase::Unloading(u) => {
                contact.unloading_work(z_end, &u) - contact.unloading_work(z0, &u)
            }
        };
        if let Phase::Loading = imp.phase {
            out.z_max = out.z_max.max(z_end);
            out.f_max = out.f_max.max(contact.loading_force(z_end));
        }
        t = t_end;
        x = x_end;
        // a new phase starts at the top of the cascade; a phase that goes on keeps its floor
        let carried = std::mem::take(&mut floor);
        let next = match (imp.phase, hit) {
            _ if closing.is_some() => None,
            (Phase::Loading, Some(Watch::Yields(_))) => {
                yielded = true;
                out.events.push((t, EventKind::Yield, z_end));
                Some(Phase::Loading)
            }
            (Phase::Loading, Some(_)) => {
                out.events.push((t, EventKind::Unload, z_end));
                Some(Phase::Unloading(contact.unload_from(z_end)))
            }
            (Phase::Unloading(u), Some(Watch::Reloads(_))) => {
                out.events.push((t, EventKind::Reload, z_end));
                yielded = z_end >= contact.zp_bar;
                out.contact_work -= imp.reload_where_forces_meet(&u, &mut x);
                Some(Phase::Loading)
            }
            (Phase::Unloading(u), Some(_)) => {
                // A real separation leaves with z̄' < 0 at z̄_f, where there is no force:
                // z̄' = ᾱ' + 2ζλȳ, the ball outrunning the element the recoil spring retracts
                // (so e ≥ 2ζλȳ). A ball creeping into a weak dashpot approaches z_f only
                // asymptotically; a stiff integrator can cross it in its noise while the ball
                // still moves in, or moves out slower than the element. That is no separation
                // (it was taken for one at λ = 4.2e-8, ζ = 6.3, elastic–plastic: e = 3.7e-8,
                // with the element retracting at 6.7e-6): once the ball has come to rest (see
                // `cor_bound`) it is no rebound; before, the creep is finished in closed form
                // where its error bound allows (see `creep`), or else the phase goes on, for a
                // recoil spring that still holds energy can yet push the ball out.
                out.rebound = -x_end[1] > left.max((1.0 - PACE_SLACK) * imp.pace(&x_end));
                if out.rebound {
                    out.events.push((t, EventKind::Separation, z_end));
                    None
                } else if imp.at_rest(&x_end) {
                    None
                } else if let Some(c) = imp.close_creep(&x_end, CASCADE[w.stage].rtol(rtol)) {
                    closing = Some(c);
                    None
                } else {
                    // From z̄_f itself, not from the crossing's state (the event was confirmed
                    // to within its tolerance, but a loosened stiff integrator's is wide: 6e-6
                    // at λ = 4e-8, ζ = 6.3, elastic–plastic). Below z̄_f the phase would start
                    // with the ball already past its separation, and a contact bump inside one
                    // long step would hide the real one (the ball flew off to the horizon).
                    // The snap moves the ball alone, by what the integrator cannot tell apart,
                    // at no force: no energy changes hands.
                    x[0] = x[0].max(u.z_f);
                    // And from the next integrator of the cascade on (round to the others if
                    // all below give up): the one that crossed z̄_f in its noise would cross
                    // it again, a phase each ~0.4 ω0⁻¹, where the creep still has ~1e5 to go.
                    // Seen at λ = 1e-15, ζ = 1e4, elastic–plastic: Radau5 accepts steps from
                    // z̄_f + 5e-9 (where the force balances the creep) to z̄_f − 1.7e-7, across
                    // the 3/2-power kink; BDF holds the creep to the separation (e = 4.4e-7,
                    // the spring's drive 2ζλȳ at the grazing separation).
                    floor = (w.stage + 1).min(CASCADE.len() - 1);
                    Some(imp.phase)
                }
            }
            // an unconfirmed event: the same phase goes on
            (p, None) if w.spurious => {
                floor = carried;
                Some(p)
            }
            (_, None) => None,
        };
        if let Some(c) = closing {
            let used;
            (t, x, used) = c.finish(&imp, (t, x), rest, left, &mut samples, &mut out);
            rest = &rest[used..];
        }
        if let Phase::Unloading(u) = imp.phase {
            out.z_f = u.z_f;
        }
        if out.unresolved.is_some() {
            break;
        }
        let flip = matches!(
            (imp.phase, next),
            (Phase::Unloading(u), Some(Phase::Loading)) | (Phase::Loading, Some(Phase::Unloading(u)))
                if u.z_f == 0.0
        );
        if flip {
            flips_left -= 1;
        } else {
            phases_left -= 1;
        }
        match next {
            Some(p) => imp.phase = p,
            None => break,
        }
    }
    out.tau_end = t;
    out.velocity_end = x[1];
    out.y_end = x[2];
    out.dashpot = Some(x[3]);
    // samples past the end (rounding at τ_end) take the final state
    while samples.len() < grid.len() {
        let ts = grid[samples.len()];
        let mut last = samples
            .last()
            .copied()
            .unwrap_or([ts, 0.0, 0.0, x[0] + x[2]]);
        last[0] = ts;
        samples.push(last);
    }
    (out, samples)
}
