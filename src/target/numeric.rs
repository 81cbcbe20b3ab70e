//! The integrated impact of the reduced ball on a compliant surface, any contact law
//! (docs/targets.md §4). State x = (z̄, ᾱ', ȳ, s̄), z̄ carried directly as in the adaptive
//! solver (docs/model.md §8):
//!
//! ```text
//! ᾱ'' = −F̄(z̄),   ȳ' = 2ζ(F̄ − λȳ),   s̄' = 2ζ_s(F̄ − λ_s s̄),   z̄' = ᾱ' − ȳ' − s̄'.
//! ```
//!
//! A surface without damping (c_s = 0) is a spring in series with the contact, s̄ = F̄/λ_s at
//! all times; differentiating it, s̄' = k z̄'/λ_s with k = dF̄/dz̄ on the branch in force, so that
//! z̄' = (ᾱ' − ȳ')/(1 + k/λ_s): the constraint is held by the equations rather than solved for.
//!
//! Phases as in the adaptive solver: loading until z̄' falls through 0 (unload from z̄_m),
//! unloading until z̄ falls to z̄_f (F = 0: separation) or rises back past z̄_m (reload). Each
//! phase is integrated by the `differential-equations` crate's DOP853; events are found on its
//! dense output (Brent) and the state there by integrating to them. Explicit only: a surface
//! dashpot so weak that the phase is stiff runs out of the step budget and says so (no answer).

use super::history::Samples;
use super::series::{MAX_PHASES, RELOAD, Series, Watch, X, first_event, state_at, watch_run};
use super::{Outcome, Surface, horizon};
use crate::model::contact::{Contact, ContactLaw, Unloading};
use crate::model::params::Normalized;
use crate::solver::roots::brent;
use crate::solver::{Method, Unresolved};
/// A ball whose remaining energy could not give it a COR above this has come to rest.
const REST_COR: f64 = 1e-9;

#[derive(Clone, Copy)]
enum Phase {
    Loading,
    Unloading(Unloading),
}

struct Chain {
    n: Normalized,
    s: Surface,
    contact: Contact,
    phase: Phase,
}

impl Chain {
    fn force(&self, z: f64) -> f64 {
        match &self.phase {
            Phase::Loading => self.contact.loading_force(z),
            Phase::Unloading(u) => self.contact.unloading_force(z, u),
        }
    }

    fn stiffness(&self, z: f64) -> f64 {
        match &self.phase {
            Phase::Loading => self.contact.loading_stiffness(z),
            Phase::Unloading(u) => self.contact.unloading_stiffness(z, u),
        }
    }

    /// Twice the energy still held; √ of it bounds the COR.
    fn energy2(&self, x: &X) -> f64 {
        let contact = match &self.phase {
            Phase::Loading => self.contact.loading_work(x[0]),
            Phase::Unloading(u) => self.contact.unloading_work(x[0], u),
        };
        let f = self.force(x[0]);
        let surface = if self.s.zeta_s.is_infinite() {
            f * f / self.s.lambda_s
        } else {
            self.s.lambda_s * x[3] * x[3]
        };
        x[1] * x[1] + 2.0 * contact + self.n.lambda * x[2] * x[2] + surface
    }
}

impl Series for Chain {
    /// (F̄, ȳ', s̄', z̄') at x.
    fn rates(&self, x: &X) -> (f64, f64, f64, f64) {
        let f = self.force(x[0]);
        let ydot = if self.n.zeta > 0.0 {
            2.0 * self.n.zeta * (f - self.n.lambda * x[2])
        } else {
            0.0
        };
        if self.s.zeta_s.is_infinite() {
            let zdot = (x[1] - ydot) / (1.0 + self.stiffness(x[0]) / self.s.lambda_s);
            let sdot = self.stiffness(x[0]) * zdot / self.s.lambda_s;
            (f, ydot, sdot, zdot)
        } else {
            let sdot = 2.0 * self.s.zeta_s * (f - self.s.lambda_s * x[3]);
            (f, ydot, sdot, x[1] - ydot - sdot)
        }
    }

    /// What ends the phase, as g crossing 0 upward: the turn (−z̄'), separation (z̄_f − z̄),
    /// reload (z̄ − z̄_m(1 + RELOAD)).
    fn watches(&self, x: &X) -> [f64; 2] {
        match &self.phase {
            Phase::Loading => [-self.rates(x).3, f64::NEG_INFINITY],
            Phase::Unloading(u) => [u.z_f - x[0], x[0] - u.z_m * (1.0 + RELOAD)],
        }
    }
}

/// Finds the first watched crossing on each step's dense output, and the surface's peak
/// deflection on it (where s̄' falls through 0).
struct Watcher<'a> {
    chain: &'a Chain,
    last: (f64, X),
    s_max: f64,
    /// Where s̄ peaks within a step (τ), and the step's start (τ, x) to integrate to it from.
    peaks: Vec<(f64, f64, X)>,
    /// The history asked for, read off the dense output up to the phase's end.
    samples: &'a mut Samples,
}

impl Watch for Watcher<'_> {
    fn step(
        &mut self,
        (t_prev, x_prev): (f64, &X),
        (t, x): (f64, &X),
        at: &mut dyn FnMut(f64) -> X,
    ) -> Option<(f64, usize)> {
        // the surface's peak deflection, where s̄' falls through 0 within the step
        let sdot = |x: &X| self.chain.rates(x).2;
        let (da, db) = (sdot(x_prev), sdot(x));
        if da > 0.0 && db <= 0.0 {
            let tp = brent(|tt| sdot(&at(tt)), t_prev, t, da, db, 1e-15 * t.abs());
            self.peaks.push((tp, t_prev, *x_prev));
        }
        self.s_max = self.s_max.max(x[3]);
        self.last = (t, *x);
        let best = first_event(self.chain, (t_prev, x_prev), (t, x), at);
        // the history's points in this step, up to the event that ends the phase
        let upto = best.map_or(t, |(tc, _)| tc);
        let chain = self.chain;
        self.samples.take(upto, |tt| {
            // the step's ends as they are: the first call's step has no length to interpolate
            let x = match tt {
                _ if tt <= t_prev => *x_prev,
                _ if tt >= t => *x,
                _ => at(tt),
            };
            let (f, _, _, _) = chain.rates(&x);
            [f, x[0], x[0] + x[2] + x[3], x[3]]
        });
        best
    }
}

/// The impact, any law; an error is the budget that ran out, with the phases taken.
#[cfg(test)]
pub(super) fn solve(
    n: &Normalized,
    law: ContactLaw,
    s: &Surface,
) -> Result<Outcome, (Unresolved, usize)> {
    solve_sampled(n, law, s, &mut Samples::none())
}

/// `solve` (a test build's), with the history at `samples`' times read off the dense output.
pub(super) fn solve_sampled(
    n: &Normalized,
    law: ContactLaw,
    s: &Surface,
    samples: &mut Samples,
) -> Result<Outcome, (Unresolved, usize)> {
    let contact = Contact {
        law,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let mut run = Run {
        chain: Chain {
            n: *n,
            s: *s,
            contact,
            phase: Phase::Loading,
        },
        t_max: horizon(n, s),
        t: 0.0,
        x: [0.0, 1.0, 0.0, 0.0],
        peaks: (0.0, 0.0, 0.0),
        samples,
    };
    for phases in 0..MAX_PHASES {
        if let Some(end) = run.phase().map_err(|r| (r, phases))? {
            return Ok(end);
        }
    }
    Err((Unresolved::Phases, MAX_PHASES))
}

/// A run between phases: the branch in force, where the next phase starts, and the peaks so
/// far (F̄_m, z̄_m, s̄_m).
struct Run<'s> {
    chain: Chain,
    t_max: f64,
    t: f64,
    x: X,
    peaks: (f64, f64, f64),
    samples: &'s mut Samples,
}

impl Run<'_> {
    /// One phase, to its event: the outcome when the run is over, `None` when another phase
    /// follows, or the budget that ran out.
    fn phase(&mut self) -> Result<Option<Outcome>, Unresolved> {
        let chain = &self.chain;
        let (f_max, z_max, mut s_max) = self.peaks;
        let mut w = Watcher {
            chain,
            last: (self.t, self.x),
            s_max,
            peaks: Vec::new(),
            samples: &mut *self.samples,
        };
        let (done, hit) = watch_run(chain, (self.t, self.x), self.t_max, &mut w);
        s_max = w.s_max;
        // each peak of the deflection, integrated to rather than read off the dense output
        for (tp, t0, x0) in std::mem::take(&mut w.peaks) {
            if let Some(at_peak) = state_at(chain, (t0, x0), tp) {
                s_max = s_max.max(at_peak[3]);
            }
        }
        let Some((tc, which, tp, xp)) = hit else {
            // the horizon: at rest, or no answer
            let (t_end, x_end) = w.last;
            return match (done, chain.energy2(&x_end).sqrt() < REST_COR) {
                (false, _) => Err(Unresolved::Steps),
                (true, true) => Ok(Some(outcome(
                    false,
                    t_end,
                    x_end[1],
                    (f_max, z_max, 0.0, s_max),
                ))),
                (true, false) => Err(Unresolved::Horizon),
            };
        };
        // the state at the event, integrated to it rather than read off the dense output
        let Some(end) = state_at(chain, (tp, xp), tc) else {
            return Err(Unresolved::Steps);
        };
        (self.t, self.x) = (tc, end);
        let x = self.x;
        self.peaks.2 = s_max.max(x[3]);
        match (self.chain.phase, which) {
            (Phase::Loading, _) => {
                let u = self.chain.contact.unload_from(x[0]);
                self.peaks.0 = f_max.max(u.f_m);
                self.peaks.1 = z_max.max(u.z_m);
                self.chain.phase = Phase::Unloading(u);
            }
            (Phase::Unloading(u), 0) => {
                // at rest, the fall of z̄ to z̄_f is the creep's rounding, not a separation
                let left = self.chain.energy2(&x).sqrt() >= REST_COR;
                let peaks = (f_max, z_max, u.z_f, self.peaks.2);
                return Ok(Some(outcome(left, tc, x[1], peaks)));
            }
            (Phase::Unloading(_), _) => self.chain.phase = Phase::Loading,
        }
        Ok(None)
    }
}

fn outcome(rebound: bool, tau: f64, v: f64, (f, z, z_f, s): (f64, f64, f64, f64)) -> Outcome {
    Outcome {
        rebound,
        tau_end: tau,
        velocity_end: v,
        f_max: f,
        z_max: z,
        z_f,
        s_max: s,
        method: Method::Numeric,
    }
}
