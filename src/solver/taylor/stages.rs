//! An impact under the Hertz or elastic–plastic law as a machine fed one step's series at a
//! time: the Hertz loading to separation or to yield, the straight stretch (Eq. 11, run
//! whole: its linear steps are cheap), the 3/2-power unloading (Eq. 12). [`super::summary`]
//! feeds it series of its own; `super::batch` feeds several in step with series computed in
//! lanes. Both take the same steps, so they give the same bits.

use super::power::{self, Next, Phase};
use super::{Budget, POWER_RULES, Point, STIFF, Summary, Sys, finish, hertz_start, linear};
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;

/// Where the impact is.
#[derive(Debug, Clone, Copy)]
enum Stage {
    /// On the Hertz branch from first touch.
    Loading,
    /// On the 3/2-power unloading from the peak (z̄_m, F̄_m) to z̄_f, in the Hertz scale.
    Unloading { z_m: f64, f_m: f64, z_f: f64 },
}

/// What a fed step left of the impact.
pub(super) enum Progress {
    /// It goes on: feed the series at [`PowerImpact::phase`]'s state.
    Go,
    /// It ended: its summary, or `None` where the steps do not answer (`super::summary`).
    Done(Option<Summary>),
}

/// One impact under way, in the Hertz scale (`super::power_law`'s: L = κ^{−2/5}).
#[derive(Debug, Clone, Copy)]
pub(super) struct PowerImpact {
    pub sys: Sys,
    pub phase: Phase,
    law: ContactLaw,
    /// L
    l: f64,
    /// ẑ_p (∞ under Hertz)
    zp: f64,
    budget: Budget,
    stage: Stage,
}

impl PowerImpact {
    /// The impact of `n` under `law` (Hertz or elastic–plastic) at first touch, or `None`
    /// where the steps do not take it on: parameters not finite, or a phase too stiff
    /// (`STIFF`).
    pub(super) fn new(n: &Normalized, law: ContactLaw) -> Option<PowerImpact> {
        Self::within(n, law, STIFF, Budget::new())
    }

    /// [`PowerImpact::new`] with a stiffness cut `stiff` and the steps of `budget`: a stiff
    /// phase needs steps about its rate's inverse, so a higher cut wants a larger budget
    /// (`super::peak_displacement`, which follows the impact only to the centre's turn).
    pub(super) fn within(
        n: &Normalized,
        law: ContactLaw,
        stiff: f64,
        budget: Budget,
    ) -> Option<PowerImpact> {
        let (sys, l, zp, stiffness) = Self::scaled(n, law)?;
        if stiffness > stiff {
            return None;
        }
        let (hertz, start) = hertz_start();
        Some(PowerImpact {
            sys,
            phase: Phase::new(hertz, start, zp.sqrt(), false, POWER_RULES),
            law,
            l,
            zp,
            budget,
            stage: Stage::Loading,
        })
    }

    /// The system of `n` under `law` in the Hertz scale, L, ẑ_p and the stiffness
    /// 2ζ̂(k + λ̂)·τ̂ the steps meet; `None` where the parameters are not finite.
    fn scaled(n: &Normalized, law: ContactLaw) -> Option<(Sys, f64, f64, f64)> {
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        if !(ok(n.lambda) && ok(n.zeta) && n.kappa.is_finite() && n.kappa > 0.0 && n.zp_bar > 0.0) {
            return None;
        }
        let l = n.kappa.powf(-0.4);
        let sys = Sys {
            lambda: n.lambda * l * l,
            zeta: n.zeta / l,
        };
        let zp = if law == ContactLaw::Hertz {
            f64::INFINITY
        } else {
            n.zp_bar / l
        };
        // the contact's stiffness in the Hertz scale: 1.5 √ẑ ≈ 1.6 at the Hertz peak, L² past
        // yield; the Hertz contact time is 2.94 (5/4)^{2/5} ≈ 3.2
        let k = if zp < 1.1 { 1.6f64.max(l * l) } else { 1.6 };
        Some((sys, l, zp, 2.0 * sys.zeta * (k + sys.lambda) * 3.2))
    }

    /// The stiffness 2ζ̂(k + λ̂)·τ̂ the steps meet in the impact of `n` under `law` (the
    /// estimate [`PowerImpact::within`] cuts at), `None` where the parameters are not finite.
    pub(super) fn stiffness(n: &Normalized, law: ContactLaw) -> Option<f64> {
        Self::scaled(n, law).map(|(.., stiffness)| stiffness)
    }

    /// L, the Hertz scale's length: ẑ = z̄/L.
    pub(super) fn scale(&self) -> f64 {
        self.l
    }

    /// Takes one step of the budget before a step's series is fed; `false` when none is left
    /// (the impact then has no answer).
    pub(super) fn take_step(&mut self) -> bool {
        self.budget.take().is_some()
    }

    /// One step, given the series of order L − 1 at the phase's state.
    pub(super) fn feed<const L: usize>(&mut self, c: &[[f64; L]; 4]) -> Progress {
        let next = self.phase.advance(c, &self.budget);
        self.after(next)
    }

    /// [`PowerImpact::feed`] given what the step's lanes evaluated (`Phase::advance_by`):
    /// the step `h`, s(h) and (s'(0), s'(h)).
    pub(super) fn feed_by<const L: usize>(
        &mut self,
        c: &[[f64; L]; 4],
        h: f64,
        s_end: f64,
        ds: (f64, f64),
    ) -> Progress {
        let next = self.phase.advance_by(c, h, s_end, Some(ds), &self.budget);
        self.after(next)
    }

    /// A quiet step's end `x` (`Phase::is_quiet`), as [`PowerImpact::feed`] would take it.
    pub(super) fn take(&mut self, x: [f64; 4]) -> Progress {
        let next = self.phase.take(x, &self.budget);
        self.after(next)
    }

    /// The impact after a step that left `next`.
    fn after(&mut self, next: Next) -> Progress {
        match next {
            Next::Go => Progress::Go,
            Next::Fail => Progress::Done(None),
            Next::Done(run) => self.next_stage(run),
        }
    }

    /// The impact after a phase's end.
    fn next_stage(&mut self, run: power::Run) -> Progress {
        let l = self.l;
        match (self.stage, run.end) {
            (Stage::Loading, power::End::Separated(p)) => {
                let s = run.s_max;
                Progress::Done(finish(p, s * s, s * s * s, 0.0, l, &self.budget))
            }
            (Stage::Loading, power::End::Yield(p)) => match self.unloading_from_yield(p) {
                Some(()) => Progress::Go,
                None => Progress::Done(None),
            },
            (Stage::Unloading { z_m, f_m, z_f }, power::End::Separated(p)) => {
                Progress::Done(finish(p, z_m, f_m, z_f, l, &self.budget))
            }
            (Stage::Unloading { .. }, power::End::Yield(_)) => Progress::Done(None),
        }
    }

    /// From yield at `p`: the straight stretch (Eq. 11) to the peak, then the unloading
    /// phase set up from it (Eqs. 12, 18–19); `None` where the stretch does not turn.
    fn unloading_from_yield(&mut self, p: Point) -> Option<()> {
        let zp = self.zp;
        let f_p = zp * zp.sqrt();
        let line = linear::Branch {
            k: self.l * self.l,
            z0: zp,
            f0: f_p,
        };
        let linear::End::Turned(top) = linear::stretch(&self.sys, &line, p, &mut self.budget)?
        else {
            return None;
        };
        let z_m = top.z;
        let f_m = line.k * (z_m - zp) + f_p;
        let contact = Contact {
            law: self.law,
            zp_bar: zp,
            kappa: 1.0,
        };
        let z_f = contact.permanent_indentation(z_m);
        let unload = power::Branch {
            z0: z_f,
            b: z_m - z_f,
            a: f_m,
        };
        if unload.b.is_nan() || unload.b <= 0.0 {
            return None;
        }
        self.phase = Phase::new(unload, top, f64::INFINITY, true, POWER_RULES);
        self.stage = Stage::Unloading { z_m, f_m, z_f };
        Some(())
    }
}
