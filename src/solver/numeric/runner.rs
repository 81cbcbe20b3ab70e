//! The phases of one impact, run one after another. A loading phase ends at the turn (z̄' = 0:
//! unload) or at yield (z̄ = z̄_p: loading goes on, on the linear stretch); an unloading phase at
//! the separation (z̄ = z̄_f, F = 0) or at a reload (z̄ back past z̄_m). `PhaseRunner` carries the
//! state from one phase to the next; each transition is one of its methods.

use super::creep::Closed;
use super::flow::Kept;
use super::impact::{Impact, Phase};
use super::integrator::{self, CASCADE};
use super::phase::{Integrated, Watch, integrate};
use super::{
    ATOL_FACTOR, MAX_FLIPS, MAX_PHASES, PACE_SLACK, RELOAD_SLACK, TOTAL_STEPS, X, horizon,
};
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;
use crate::solver::{EventKind, Outcome, Sample, Unresolved};

/// One run of every phase: the outcome and, with a grid, the samples (τ, F̄, z̄, ᾱ) on it.
pub(super) struct PhaseRun {
    pub(super) outcome: Outcome,
    pub(super) samples: Vec<Sample>,
    /// Every phase's steps, when kept (`PhaseRunner::keep`); `None` when a creep was finished
    /// in closed form, which leaves no steps to read the flow on.
    pub(super) kept: Option<Vec<Kept>>,
}

/// What follows a phase.
enum Next {
    /// Another phase, on this branch of the contact law.
    Phase(Phase),
    /// The creep is finished in closed form (see `creep`), and with it the run.
    Close(Closed),
    /// The run is over.
    End,
}

/// The state one phase hands to the next.
pub(super) struct PhaseRunner<'a> {
    /// The system, with the branch in force.
    imp: Impact,
    rtol: f64,
    /// How long a ball that may never leave is followed (see `horizon`).
    t_max: f64,
    /// The outward speed above which a ball at z̄_f has left, rather than touched it in the
    /// integrator's noise.
    left: f64,
    grid: &'a [f64],
    /// The samples of `grid` still to take.
    rest: &'a [f64],
    out: Outcome,
    samples: Vec<Sample>,
    /// Where the next phase starts.
    t: f64,
    x: X,
    /// The elastic–plastic loading has passed z̄_p: no yield is watched for.
    yielded: bool,
    phases_left: usize,
    flips_left: usize,
    /// The first stage of the integrator cascade the next phase may use (see `integrate`).
    floor: usize,
    /// Keep every phase's steps (the flow the oblique impact reads, `flow`).
    keep: bool,
    /// Every phase starts on DOPRI5, stiff or not (see `integrate` and `solve`'s recheck).
    explicit: bool,
    kept: Vec<Kept>,
    /// A creep was finished in closed form.
    closed: bool,
}

impl<'a> PhaseRunner<'a> {
    /// An impact at first touch, x = (z̄, ᾱ', ȳ, Ē_d) = (0, 1, 0, 0), loading.
    pub(super) fn new(n: &Normalized, contact: &Contact, rtol: f64, grid: &'a [f64]) -> Self {
        PhaseRunner {
            imp: Impact {
                lambda: n.lambda,
                zeta: n.zeta,
                contact: *contact,
                phase: Phase::Loading,
            },
            rtol,
            t_max: horizon(n),
            left: 100.0 * rtol * ATOL_FACTOR,
            grid,
            rest: grid,
            out: Outcome::default(),
            samples: Vec::with_capacity(grid.len()),
            t: 0.0,
            x: [0.0, 1.0, 0.0, 0.0],
            yielded: false,
            phases_left: MAX_PHASES,
            flips_left: MAX_FLIPS,
            floor: 0,
            keep: false,
            explicit: false,
            kept: Vec::new(),
            closed: false,
        }
    }

    /// The same runner keeping every phase's steps (see `flow`).
    pub(super) fn keeping(mut self) -> Self {
        self.keep = true;
        self
    }

    /// The same runner starting every phase on DOPRI5, the stiff ones too: their integrators
    /// take over only where DOPRI5 runs out of steps.
    pub(super) fn explicit(mut self) -> Self {
        self.explicit = true;
        self
    }

    /// Run every phase to the end of the impact, or until a budget is spent.
    pub(super) fn run(mut self) -> PhaseRun {
        while self.run_phase() {}
        self.finish()
    }

    /// Run the next phase and turn to the one after it; false when the run is over.
    fn run_phase(&mut self) -> bool {
        if let Some(reason) = self.budget_spent() {
            self.out.unresolved = Some(reason);
            return false;
        }
        let z0 = self.x[0];
        self.unload_if_turned(z0);
        if self.has_left(z0) {
            return false;
        }
        let watches = self.watches(z0);
        let (start, rtol) = ((self.t, self.x), self.rtol);
        let phase = integrate(
            &self.imp,
            start,
            self.t_max,
            watches,
            self.rest,
            (rtol, self.floor, self.explicit),
            self.keep,
        );
        if self.keep {
            let mut knots = Vec::with_capacity(phase.knots.len() + 1);
            knots.push(start);
            knots.extend(&phase.knots);
            self.kept.push(Kept {
                imp_phase: self.imp.phase,
                knots,
            });
        }
        let closing = self.check_end(&phase);
        self.record(&phase, z0);
        (self.t, self.x) = phase.last;
        // a new phase starts at the top of the cascade; a phase that goes on keeps its floor
        let carried = std::mem::take(&mut self.floor);
        let next = match closing {
            Some(c) => Next::Close(c),
            None => self.transition(&phase, carried),
        };
        if let Next::Close(c) = &next {
            self.close(c);
        }
        if let Phase::Unloading(u) = self.imp.phase {
            self.out.z_f = u.z_f;
        }
        if self.out.unresolved.is_some() {
            return false;
        }
        let Next::Phase(p) = next else {
            return false;
        };
        self.count(p);
        self.imp.phase = p;
        true
    }

    /// Why no further phase may start, if a budget is spent.
    fn budget_spent(&self) -> Option<Unresolved> {
        if self.phases_left == 0 {
            Some(Unresolved::Phases)
        } else if self.flips_left == 0 {
            Some(Unresolved::Flips)
        } else if self.out.steps > TOTAL_STEPS {
            Some(Unresolved::Steps)
        } else {
            None
        }
    }

    /// A loading phase that begins with z̄' ≤ 0 (a reload or a yield met at the turning point
    /// itself) has already turned: its unload is now. Watching for z̄' to fall through 0 would
    /// never fire, and the ball would leave on the loading branch.
    fn unload_if_turned(&mut self, z0: f64) {
        let turned = matches!(self.imp.phase, Phase::Loading)
            && self.t > 0.0
            && Watch::RateFalls.g(&self.imp, &self.x) <= 0.0;
        if turned {
            self.out.event(self.t, EventKind::Unload, z0);
            self.imp.phase = Phase::Unloading(self.imp.contact.unload_from(z0));
        }
    }

    /// An unloading phase that goes on from z̄ ≤ z̄_f (after a crossing made in the noise while
    /// the ball still moved in) is watched for z̄ falling through z̄_f: if the two already move
    /// apart (z̄' < 0 with no force), that never comes and the ball would fly off unseen to the
    /// horizon. It has left, now: whether it rebounds is whether it moves out faster than
    /// `left` (test: `solver_agreement`'s weak-dashpot separations).
    fn has_left(&mut self, z0: f64) -> bool {
        let Phase::Unloading(u) = self.imp.phase else {
            return false;
        };
        let apart = self.t > 0.0 && z0 <= u.z_f && Watch::RateFalls.g(&self.imp, &self.x) < 0.0;
        if apart {
            self.out.rebound = -self.x[1] > self.left;
            if self.out.rebound {
                self.out.event(self.t, EventKind::Separation, z0);
            }
        }
        apart
    }

    /// What the phase starting at z̄0 watches for.
    fn watches(&self, z0: f64) -> Vec<Watch> {
        let contact = &self.imp.contact;
        match self.imp.phase {
            Phase::Loading
                if contact.law == ContactLaw::ElasticPlastic
                    && !self.yielded
                    && z0 < contact.zp_bar =>
            {
                vec![Watch::RateFalls, Watch::Yields(contact.zp_bar)]
            }
            Phase::Loading => vec![Watch::RateFalls],
            Phase::Unloading(u) => {
                let past = RELOAD_SLACK * self.rtol * (u.z_m.abs() + ATOL_FACTOR);
                vec![Watch::Separates(u.z_f), Watch::Reloads(u.z_m + past)]
            }
        }
    }

    /// A phase the integrators could not end: a creep finished in closed form where the
    /// cascade gave up (see `creep`), or the run unresolved — also when the horizon came
    /// first, with the ball neither gone nor at rest.
    fn check_end(&mut self, phase: &Integrated) -> Option<Closed> {
        let x_end = &phase.last.1;
        if phase.failed {
            let closing = self.imp.close_creep(x_end, integrator::loosest(self.rtol));
            if closing.is_none() {
                self.out.unresolved = Some(Unresolved::GaveUp);
            }
            return closing;
        }
        if phase.hit.is_none() && !phase.spurious && !self.imp.at_rest(x_end) {
            self.out.unresolved = Some(Unresolved::Horizon);
        }
        None
    }

    /// Book a phase from z̄0: its cost, its samples, the contact's work, the peaks.
    fn record(&mut self, phase: &Integrated, z0: f64) {
        self.out.steps += phase.steps;
        self.out.stiff |= phase.stiff;
        let imp = &self.imp;
        let taken = phase.samples.iter().map(|&(tau, xs)| {
            let z = xs[0];
            Sample {
                tau,
                force: imp.force(z),
                z,
                alpha: z + xs[2],
            }
        });
        self.samples.extend(taken);
        self.rest = &self.rest[phase.samples.len()..];
        let contact = &self.imp.contact;
        let z_end = phase.last.1[0];
        self.out.contact_work += match self.imp.phase {
            Phase::Loading => contact.loading_work(z_end) - contact.loading_work(z0),
            Phase::Unloading(u) => {
                contact.unloading_work(z_end, &u) - contact.unloading_work(z0, &u)
            }
        };
        if let Phase::Loading = self.imp.phase {
            self.out.z_max = self.out.z_max.max(z_end);
            self.out.f_max = self.out.f_max.max(contact.loading_force(z_end));
        }
    }

    /// What follows a phase that ended at (t, x) on its event, or without one.
    fn transition(&mut self, phase: &Integrated, carried: usize) -> Next {
        match (self.imp.phase, phase.hit) {
            (Phase::Loading, Some(Watch::Yields(_))) => self.yield_here(),
            (Phase::Loading, Some(_)) => self.unload_here(),
            (Phase::Unloading(u), Some(Watch::Reloads(_))) => self.reload_here(&u),
            (Phase::Unloading(u), Some(_)) => self.separate_here(&u, phase.stage),
            // an unconfirmed event: the same phase goes on, from the same floor
            (p, None) if phase.spurious => {
                self.floor = carried;
                Next::Phase(p)
            }
            (_, None) => Next::End,
        }
    }

    /// z̄ rose through z̄_p: the elastic–plastic loading goes on, on its linear stretch.
    fn yield_here(&mut self) -> Next {
        self.yielded = true;
        self.out.event(self.t, EventKind::Yield, self.x[0]);
        Next::Phase(Phase::Loading)
    }

    /// z̄' fell through 0: unloading from z̄_m = z̄ (Eqs. 18–19 give its z̄_f).
    fn unload_here(&mut self) -> Next {
        let z = self.x[0];
        self.out.event(self.t, EventKind::Unload, z);
        Next::Phase(Phase::Unloading(self.imp.contact.unload_from(z)))
    }

    /// z̄ rose back past z̄_m: loading again, from where the loading branch carries the
    /// unloading force (see `Impact::reload_where_forces_meet`).
    fn reload_here(&mut self, u: &crate::model::contact::Unloading) -> Next {
        let z = self.x[0];
        self.out.event(self.t, EventKind::Reload, z);
        self.yielded = z >= self.imp.contact.zp_bar;
        self.out.contact_work -= self.imp.reload_where_forces_meet(u, &mut self.x);
        Next::Phase(Phase::Loading)
    }

    /// z̄ fell through z̄_f, where there is no force. A real separation leaves with z̄' < 0
    /// there: z̄' = ᾱ' + 2ζλȳ, the ball outrunning the element the recoil spring retracts (so
    /// e ≥ 2ζλȳ, `Impact::pace`). A ball creeping into a weak dashpot approaches z̄_f only
    /// asymptotically, and a stiff integrator can cross it in its noise while the ball still
    /// moves in, or moves out slower than the element: that is no separation. Once the ball has
    /// come to rest (see `Impact::cor_bound`) it is no rebound; before, the creep is finished in
    /// closed form where its error bound allows (see `creep`), or else the phase goes on, for a
    /// recoil spring that still holds energy can yet push the ball out.
    fn separate_here(&mut self, u: &crate::model::contact::Unloading, stage: usize) -> Next {
        let x = self.x;
        let pace = (1.0 - PACE_SLACK) * self.imp.pace(&x);
        self.out.rebound = -x[1] > self.left.max(pace);
        if self.out.rebound {
            self.out.event(self.t, EventKind::Separation, x[0]);
            return Next::End;
        }
        if self.imp.at_rest(&x) {
            return Next::End;
        }
        if let Some(c) = self.imp.close_creep(&x, CASCADE[stage].rtol(self.rtol)) {
            return Next::Close(c);
        }
        // From z̄_f itself, not from the crossing's state, which a loosened stiff integrator
        // confirms only to its own wide tolerance: below z̄_f the phase would start with the ball
        // already past its separation, and a contact bump inside one long step would hide the
        // real one. The snap moves the ball alone, by what the integrator cannot tell apart, at
        // no force: no energy changes hands.
        self.x[0] = self.x[0].max(u.z_f);
        // And from the next integrator of the cascade on (round to the others if all below
        // give up): the one that crossed z̄_f in its noise would cross it again, a phase each
        // step or so, where the creep still has far to go.
        self.floor = (stage + 1).min(CASCADE.len() - 1);
        Next::Phase(self.imp.phase)
    }

    /// Finish the run along a creep in closed form.
    fn close(&mut self, c: &Closed) {
        self.closed = true;
        let start = (self.t, self.x);
        let end = c.finish(
            &self.imp,
            start,
            self.rest,
            self.left,
            &mut self.samples,
            &mut self.out,
        );
        (self.t, self.x) = (end.t, end.x);
        self.rest = &self.rest[end.covered..];
    }

    /// Count a change of branch against its budget: a flip between branches that coincide (an
    /// elastic contact, z̄_f = 0: the unloading branch is the loading law itself) changes no
    /// force and counts against `MAX_FLIPS`, any other against `MAX_PHASES`.
    fn count(&mut self, next: Phase) {
        let flip = matches!(
            (self.imp.phase, next),
            (Phase::Unloading(u), Phase::Loading) | (Phase::Loading, Phase::Unloading(u))
                if u.z_f == 0.0
        );
        if flip {
            self.flips_left -= 1;
        } else {
            self.phases_left -= 1;
        }
    }

    /// The outcome at the end of the run, and the samples: those past the end (rounding at
    /// τ_end) take the final state.
    fn finish(mut self) -> PhaseRun {
        let (x, out) = (self.x, &mut self.out);
        out.tau_end = self.t;
        out.velocity_end = x[1];
        out.y_end = x[2];
        out.dashpot = Some(x[3]);
        while let Some(&tau) = self.grid.get(self.samples.len()) {
            let last = self.samples.last().copied().unwrap_or(Sample {
                tau,
                force: 0.0,
                z: 0.0,
                alpha: x[0] + x[2],
            });
            self.samples.push(Sample { tau, ..last });
        }
        let kept = (self.keep && !self.closed).then_some(self.kept);
        PhaseRun {
            outcome: self.out,
            samples: self.samples,
            kept,
        }
    }
}
