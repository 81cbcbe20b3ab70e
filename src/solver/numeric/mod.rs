//! The adaptive numerical solver for any contact law: the first-order system of MODEL.md §2 in
//! normalized form, x = (z̄, ᾱ', ȳ, Ē_d) with z̄ = ᾱ − ȳ,
//!     ᾱ'' = −F̄,   ȳ' = 2ζ(F̄ − λȳ),   z̄' = ᾱ' − ȳ',   Ē_d' = ȳ'²/(2ζ) = 2ζ(F̄ − λȳ)²,
//! integrated phase by phase with the `differential-equations` crate: DOPRI5, or Radau5 when
//! the dashpot makes the system stiff. Events are located as in SciPy's `solve_ivp` (terminal,
//! with a direction) by a custom `Solout` that root-finds on the step's dense output; the
//! crate's own `EventSolout` skips the first step of each integration, and every phase here
//! starts one.

use super::roots::brent;
use super::{EventKind, Outcome, SolveOptions};
use crate::model::contact::{Contact, ContactLaw, Unloading};
use crate::model::params::Normalized;
use differential_equations::interpolate::Interpolation;
use differential_equations::ode::ODE;
use differential_equations::prelude::{ControlFlag, Solout};
use differential_equations::solution::Solution;
use integrator::{EndState, Integrator, RunStats, solve_with};

mod integrator;

type X = [f64; 4];

/// Phase budget. A ball creeping into a weak dashpot (small λ, large ζ) can hold z̄ at its
/// peak, z̄' ≈ 0, for a long time; the integrator's noise then flips it between the loading and
/// unloading branches (which meet there, so the flips do not change the answer) many times,
/// each flip a short phase. What bounds the work is `TOTAL_STEPS`.
const MAX_PHASES: usize = 4096;
/// Step budget of one impact, over all its phases.
pub(super) const TOTAL_STEPS: usize = 1_000_000;
/// Absolute tolerance relative to rtol (normalized states are of order 1).
const ATOL_FACTOR: f64 = 1e-3;
/// Step budget of one Radau5 integration.
pub(super) const MAX_STEPS: usize = 100_000;
/// Step budget of DOPRI5 in one phase before Radau5 takes the rest of it over: a phase that
/// long is one where the dashpot, though not stiff by `STIFF`, creeps for many of its own time
/// constants (λ = 0 with a weak dashpot: the ball sinks in for ~40ζ), holding DOPRI5 to its
/// stability limit the whole way.
pub(super) const EXPLICIT_STEPS: usize = 20_000;
/// Above this stiffness (fastest dashpot rate 2ζ(1+λ), in units of ω0) DOPRI5 would be held
/// to its stability limit (a few thousand steps an impact at this value); Radau5 takes over.
/// Radau5 as the crate implements it holds COR and the energy balance less tightly than DOPRI5
/// (see `audit::energy_tolerance`), so DOPRI5 keeps every case it can do in bounded time.
const STIFF: f64 = 2000.0;
/// A ball whose remaining energy could not give it a COR above this has come to rest.
const REST_COR: f64 = 1e-9;

#[derive(Clone, Copy, Debug)]
enum Phase {
    Loading,
    Unloading(Unloading),
}

struct Impact {
    lambda: f64,
    zeta: f64,
    contact: Contact,
    phase: Phase,
}

impl Impact {
    fn force(&self, z: f64) -> f64 {
        match self.phase {
            Phase::Loading => self.contact.loading_force(z),
            Phase::Unloading(u) => self.contact.unloading_force(z, &u),
        }
    }
    /// An upper bound on the kinetic energy the ball can still leave with (normalized, units of
    /// m v0²): its kinetic energy, the recoverable energy of the contact on the current branch,
    /// and the recoil spring's. The dashpot only takes energy away, so e ≤ √(2 E).
    fn available_energy(&self, x: &X) -> f64 {
        let z = x[0];
        let contact = match self.phase {
            Phase::Loading => self.contact.loading_work(z),
            Phase::Unloading(u) => self.contact.unloading_work(z, &u),
        };
        0.5 * x[1] * x[1] + contact + 0.5 * self.lambda * x[2] * x[2]
    }

    /// (F̄, ȳ') at a state.
    fn force_and_rate(&self, x: &X) -> (f64, f64) {
        let f = self.force(x[0]);
        (f, 2.0 * self.zeta * (f - self.lambda * x[2]))
    }
}

impl ODE<f64, X> for Impact {
    fn diff(&self, _t: f64, x: &X, dx: &mut X) {
        let (f, ydot) = self.force_and_rate(x);
        // z̄, not ᾱ, is carried: z̄ = ᾱ − ȳ by subtraction loses all of its digits when the ball
        // creeps into a weak dashpot (ᾱ, ȳ large, z̄ tiny), and the force is a function of z̄.
        dx[0] = x[1] - ydot;
        dx[1] = -f;
        dx[2] = ydot;
        dx[3] = if self.zeta > 0.0 {
            ydot * ydot / (2.0 * self.zeta)
        } else {
            0.0
        };
    }
}

/// What a phase watches for, with the direction of the crossing.
#[derive(Clone, Copy, Debug)]
enum Watch {
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
    fn g(self, imp: &Impact, x: &X) -> f64 {
        let z = x[0];
        match self {
            Watch::RateFalls => x[1] - imp.force_and_rate(x).1,
            Watch::Yields(t) | Watch::Separates(t) | Watch::Reloads(t) => z - t,
        }
    }
    fn rising(self) -> bool {
        matches!(self, Watch::Yields(_) | Watch::Reloads(_))
    }
}

/// The custom solout: finds the first watched crossing (terminal), and records evenly spaced
/// samples from the dense output when asked to.
struct Watcher<'a> {
    imp: &'a Impact,
    watches: Vec<Watch>,
    /// The first watched crossing: (time, the step's start, the step's start state, watch).
    hit: Option<(f64, f64, X, Watch)>,
    grid: &'a [f64],
    next_sample: usize,
    samples: Vec<(f64, X)>,
    t_stop: f64,
    /// The last accepted step, where an event-less integration stopped.
    last: (f64, X),
    /// Steps taken (accepted and rejected), the re-integration to an event included.
    steps: usize,
    /// The integrator gave up (step budget, step size underflow) before an event or `t_stop`.
    failed: bool,
    /// Radau5 ran (some of) the phase.
    stiff: bool,
}

impl Solout<f64, X> for Watcher<'_> {
    fn solout<I>(
        &mut self,
        t_curr: f64,
        t_prev: f64,
        y_curr: &X,
        y_prev: &X,
        interp: &mut I,
        _s: &mut Solution<f64, X>,
    ) -> ControlFlag<f64, X>
    where
        I: Interpolation<f64, X> + ?Sized,
    {
        let mut at = |t: f64| {
            if t == t_curr {
                *y_curr
            } else {
                interp.interpolate(t).unwrap_or(*y_curr)
            }
        };
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
        while self.next_sample < self.grid.len() && self.grid[self.next_sample] <= end {
            let t = self.grid[self.next_sample].max(t_prev);
            self.samples.push((self.grid[self.next_sample], at(t)));
            self.next_sample += 1;
        }
        match best {
            Some((t, w)) => {
                self.hit = Some((t, t_prev, *y_prev, w));
                ControlFlag::Terminate
            }
            None if t_curr >= self.t_stop => ControlFlag::Terminate,
            // come to rest: no rebound can follow (see `available_energy`)
            None if self.imp.available_energy(y_curr) < 0.5 * REST_COR * REST_COR => {
                ControlFlag::Terminate
            }
            None => ControlFlag::Continue,
        }
    }
}

/// Integrate one phase from (t0, x0) until a watched event or `t_stop`.
fn integrate<'a>(
    imp: &'a Impact,
    t0: f64,
    x0: X,
    t_stop: f64,
    watches: Vec<Watch>,
    grid: &'a [f64],
    rtol: f64,
) -> Watcher<'a> {
    let mut w = Watcher {
        imp,
        watches,
        hit: None,
        grid,
        next_sample: 0,
        samples: Vec::new(),
        t_stop,
        last: (t0, x0),
        steps: 0,
        failed: false,
        stiff: false,
    };
    // The crate reports giving up (out of steps, step size underflow) as an error; the watcher
    // then holds what was reached. The phase goes on from there with the next integrator of
    // the cascade: DOPRI5 on its short budget → Radau5 (a long phase at DOPRI5's stability
    // limit) → DOPRI5 on the full budget (Radau5's Newton iteration can stall where the
    // 3/2-power force has no second derivative, at z̄ = z̄_f). Only when the last one gives up
    // is the phase failed: never read as the horizon.
    let mut method = if 2.0 * imp.zeta * (1.0 + imp.lambda) > STIFF {
        Integrator::Radau5
    } else {
        Integrator::Dopri5(EXPLICIT_STEPS)
    };
    let mut run = solve_with(imp, t0, x0, t_stop, rtol, method, &mut w);
    w.stiff = method == Integrator::Radau5;
    while run.failed && w.hit.is_none() {
        method = match method {
            Integrator::Dopri5(EXPLICIT_STEPS) => Integrator::Radau5,
            Integrator::Radau5 => Integrator::Dopri5(MAX_STEPS),
            Integrator::Dopri5(_) => break,
        };
        w.stiff |= method == Integrator::Radau5;
        let (t1, x1) = w.last;
        let rest = solve_with(imp, t1, x1, t_stop, rtol, method, &mut w);
        run = RunStats {
            steps: run.steps + rest.steps,
            failed: rest.failed,
        };
    }
    w.steps = run.steps;
    w.failed = run.failed;
    if let Some((t, t_prev, x_prev, _)) = w.hit {
        // The event's state is integrated to the event time, not read off the dense output:
        // Radau5's continuous output is of lower order than its steps.
        let mut end = EndState(x_prev);
        let run = solve_with(imp, t_prev, x_prev, t, rtol, method, &mut end);
        w.steps += run.steps;
        w.failed |= run.failed;
        w.last = (t, end.0);
    }
    w
}

/// How long to follow a ball that may never leave: a hundred times the sum of the contact
/// times (linear spring π; Hertz alone 2.94 z̄_m with z̄_m = (5/(4κ))^{2/5}, long when the
/// contact is soft against the speed), the dashpot creep time 2ζ and the recoil relaxation
/// time 1/(2ζλ).
fn horizon(n: &Normalized) -> f64 {
    let relax = if n.lambda > 0.0 && n.zeta > 0.0 {
        1.0 / (2.0 * n.zeta * n.lambda)
    } else {
        0.0
    };
    let hertz = 2.95 * (1.25 / n.kappa).powf(0.4);
    (100.0 * (std::f64::consts::PI + hertz + 2.0 * n.zeta + relax)).min(1e9)
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
    let mut phases_left = MAX_PHASES;
    loop {
        if phases_left == 0 {
            out.unresolved = Some("more than 4096 load–unload phases");
            break;
        }
        if out.steps > TOTAL_STEPS {
            out.unresolved = Some("the step budget of the impact ran out");
            break;
        }
        phases_left -= 1;
        let z0 = x[0];
        // A loading phase that begins with z̄' ≤ 0 (a reload or a yield met at the turning
        // point itself) has already turned: its unload is now. Watching for z̄' to fall
        // through 0 would never fire, and the ball would leave on the loading branch.
        if matches!(imp.phase, Phase::Loading) && t > 0.0 && Watch::RateFalls.g(&imp, &x) <= 0.0 {
            out.events.push((t, EventKind::Unload, z0));
            imp.phase = Phase::Unloading(contact.unload_from(z0));
        }
        let watches = match imp.phase {
            Phase::Loading
                if contact.law == ContactLaw::ElasticPlastic && !yielded && z0 < contact.zp_bar =>
            {
                vec![Watch::RateFalls, Watch::Yields(contact.zp_bar)]
            }
            Phase::Loading => vec![Watch::RateFalls],
            Phase::Unloading(u) => vec![Watch::Separates(u.z_f), Watch::Reloads(z0)],
        };
        let w = integrate(&imp, t, x, t_max, watches, rest, rtol);
        let hit = w.hit.map(|h| h.3);
        let (t_end, x_end) = w.last;
        out.steps += w.steps;
        out.stiff |= w.stiff;
        if w.failed {
            out.unresolved = Some("the integrator gave up before the end of contact");
        } else if hit.is_none() && imp.available_energy(&x_end) >= 0.5 * REST_COR * REST_COR {
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
        let next = match (imp.phase, hit) {
            (Phase::Loading, Some(Watch::Yields(_))) => {
                yielded = true;
                out.events.push((t, EventKind::Yield, z_end));
                Some(Phase::Loading)
            }
            (Phase::Loading, Some(_)) => {
                out.events.push((t, EventKind::Unload, z_end));
                Some(Phase::Unloading(contact.unload_from(z_end)))
            }
            (Phase::Unloading(_), Some(Watch::Reloads(_))) => {
                out.events.push((t, EventKind::Reload, z_end));
                yielded = z_end >= contact.zp_bar;
                Some(Phase::Loading)
            }
            (Phase::Unloading(_), Some(_)) => {
                // A real separation leaves with α' < 0. A ball that settles onto the wall (λ = 0,
                // ζ ≥ 1) approaches z_f only asymptotically; the integrator can then cross it in
                // its noise, with a "rebound" speed at the tolerance level: that is no rebound.
                out.rebound = -x_end[1] > 100.0 * rtol * ATOL_FACTOR;
                if out.rebound {
                    out.events.push((t, EventKind::Separation, z_end));
                }
                None
            }
            (_, None) => None,
        };
        if let Phase::Unloading(u) = imp.phase {
            out.z_f = u.z_f;
        }
        if out.unresolved.is_some() {
            break;
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
