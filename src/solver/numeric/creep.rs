//! The end of a creep in closed form: a ball held on a weak dashpot's slow manifold, at an
//! indentation the integrators cannot resolve, finished analytically.
//!
//! In contact, z̄' = ᾱ' − ȳ' with ȳ' = 2ζ(F̄ − λȳ) (docs/model.md §2, Eqs. 5–6 normalized) gives,
//! exactly, F̄ = λȳ + (v − z̄')/(2ζ) with v = ᾱ'. So the ball and the element move as
//!     ȳ' = v − z̄',   v' = −λȳ − v/(2ζ) + z̄'/(2ζ),
//! a linear system the contact drives only through z̄. Holding z̄ at z̄_f (z̄' = 0) leaves
//!     w = (ȳ, v),   w' = B w,   B = [[0, 1], [−λ, −1/(2ζ)]],
//! with eigenvalues −1/(4ζ) ± √(1/(16ζ²) − λ), solved in closed form (`pair_flow`); along it
//! the force is F̄ = λȳ + v/(2ζ) = −ȳ'', and the ball leaves at its first zero, moving out at
//! v = −2ζλȳ: the element's own pace, the bound of `Impact::pace` met with equality.
//!
//! Why: a ball creeping out of a weak dashpot (λ < 1e-11, ζ > 100) sits at z̄ − z̄_f ~ 1e-16
//! (Hertz) for ~1e5 ω0⁻¹, inside every integrator's tolerance of the 3/2-power kink at z̄_f.
//! Integrated, it would cross z̄_f in the noise, phase after phase, never reaching its
//! separation within a bounded budget; closed, it answers (tests/physics/solver_agreement.rs,
//! `creeps_at_the_integrators_noise_floor_answer` and `closed_creeps_agree_with_the_exact_solver`).
//!
//! The error of holding z̄: the true motion differs by the forcing λ(z̄ − z̄_f) + z̄'/(2ζ). The
//! response of v to a unit impulse of it is at most 1 (it starts at 1 and the damped
//! oscillator's energy only falls), so v at the separation is off by at most
//!     ∫|λ(z̄ − z̄_f)| + |z̄'|/(2ζ) dτ ≤ δ (λT + 3/(2ζ)),
//! where δ bounds z̄ − z̄_f over the remaining time T (z̄ goes up to it and down to z̄_f at
//! most once: z̄' = 2ζ(λȳ + v/(2ζ) − F̄(z̄)), so z̄ rises only while the force the creep asks
//! for exceeds the contact's, and that force has at most one peak before its first zero). The
//! separation time it moves changes v only at second order: v' = −F̄ = 0 there. Where the pair
//! of roots is real, as in every weak dashpot's creep, the response falls within a few fast
//! times 2ζ to the slow mode's share, ≈ 4ζ²λ: the dashpot takes an early impulse up. Only the
//! last window before the separation then counts in full, with z̄ as deep as the largest force
//! asked in it makes the contact (`Creep::bound`), taken where the dashpot relaxes the contact
//! many times over in that window (`RELAXATIONS`). The refined bound is what lets a creep close
//! at all where δ/ζ alone would exceed `CREEP_TOL` of e (an elastic–plastic ball at
//! λ = 3.5e-15, ζ = 818 sits 9e-9 above z̄_f at its deepest: δ/ζ is 1.8e-3 of e, the refined
//! bound 1.4e-7). The closed form itself is checked against the integrated creep in
//! `the_closed_form_follows_the_integrated_creep_to_its_separation` below.

use super::{Impact, X};
use crate::model::contact::Unloading;
use crate::solver::propagator::pair_flow;
use crate::solver::{EventKind, Outcome, Sample};
use nalgebra::{Matrix2, Vector2};

/// The creep's flow from one state.
#[derive(Debug, Clone, Copy)]
pub(super) struct Creep {
    lambda: f64,
    zeta: f64,
    b: Matrix2<f64>,
    /// The eigenvalues as `pair_flow` takes them: centre −1/(4ζ), ((s2 − s3)/2)².
    centre: f64,
    q: f64,
    /// (ȳ, v) at its start.
    w0: Vector2<f64>,
}

impl Creep {
    /// The creep from (ȳ, v) = (y0, v0); ζ > 0.
    pub(super) fn new(lambda: f64, zeta: f64, y0: f64, v0: f64) -> Self {
        let centre = -0.25 / zeta;
        Creep {
            lambda,
            zeta,
            b: Matrix2::new(0.0, 1.0, -lambda, -0.5 / zeta),
            centre,
            q: centre * centre - lambda,
            w0: Vector2::new(y0, v0),
        }
    }

    /// (ȳ, v) at τ from the start.
    pub(super) fn at(&self, tau: f64) -> Vector2<f64> {
        self.flow(tau, self.w0)
    }

    /// e^{Bτ} m = e^{cτ} (C m + S (B − cI) m), as in `pair_flow`.
    fn flow(&self, tau: f64, m: Vector2<f64>) -> Vector2<f64> {
        let (ec, es) = pair_flow(self.centre, self.q, tau);
        m * ec + (self.b * m - m * self.centre) * es
    }

    /// The contact force the creep carries at (ȳ, v): λȳ + v/(2ζ).
    pub(super) fn force(&self, w: &Vector2<f64>) -> f64 {
        self.lambda * w[0] + w[1] / (2.0 * self.zeta)
    }

    /// The first τ ≥ 0 at which the force functional of e^{Bτ} m vanishes; `None` if never.
    /// With p = F(m) > 0 and r = F((B − cI) m) it is the first zero of C p + S r:
    /// tanh(hτ) = hp/(−r) for a real pair (h = √q), tan(bτ) = bp/(−r) for a complex one.
    fn first_zero(&self, m: Vector2<f64>) -> Option<f64> {
        let p = self.force(&m);
        if p <= 0.0 {
            return Some(0.0);
        }
        let r = self.force(&(self.b * m - m * self.centre));
        if self.q > 0.0 {
            let h = self.q.sqrt();
            let x = h * p / -r;
            (r < 0.0 && x < 1.0).then(|| x.atanh() / h)
        } else if self.q == 0.0 {
            (r < 0.0).then(|| p / -r)
        } else {
            let b = (-self.q).sqrt();
            Some((b * p).atan2(-r) / b)
        }
    }

    /// The time from the start at which the ball leaves; `None`: it never does (λ = 0, a ball
    /// still moving in: the dashpot takes its speed as exp(−τ/(2ζ)) and nothing sends it back).
    pub(super) fn separation(&self) -> Option<f64> {
        self.first_zero(self.w0)
    }

    /// The largest force the creep asks of the contact from its start until `end` (`None`:
    /// for ever). The force is a sum of two exponentials or a damped cosine, with at most one
    /// peak before its first zero: where its rate, the same functional of e^{Bτ} B w0, vanishes.
    pub(super) fn peak_force(&self, end: Option<f64>) -> f64 {
        let f0 = self.force(&self.w0);
        match self.first_zero(self.b * self.w0) {
            // rising to the end (never, in a passive flow ending at a zero of the force)
            None => end.map_or(f64::INFINITY, |t| f0.max(self.force(&self.at(t)))),
            Some(peak) if end.is_none_or(|t| peak <= t) => f0.max(self.force(&self.at(peak))),
            // the peak comes after the end: falling all the way
            Some(_) => f0,
        }
    }
}

/// Where a creep finished in closed form ends: the state at the separation (or where the ball
/// was found at rest), and how many samples of the grid it covered.
#[derive(Debug, Clone, Copy)]
pub(super) struct Finished {
    pub t: f64,
    pub x: X,
    pub covered: usize,
}

/// A creep finished in closed form.
#[derive(Debug, Clone, Copy)]
pub(super) struct Closed {
    /// The flow from the state it was closed at, ᾱ kept (ȳ takes up z̄ − z̄_f).
    pub creep: Creep,
    /// When the ball leaves, from that state; `None`: it comes to rest.
    pub leaves: Option<f64>,
    /// The unloading branch it ends on.
    pub u: Unloading,
}

/// Close the contact from x (on the unloading branch `u`) when the error bound of the module
/// doc is within `tol` of the COR (or of `rest`, the COR below which a ball is at rest), with
/// z̄ known to `z_tol`. `None`: the creep must go on being integrated (the contact may still
/// load up, or the bound is too wide yet).
pub(super) fn close(
    imp: &Impact,
    u: &Unloading,
    x: &X,
    z_tol: f64,
    tol: f64,
    rest: f64,
) -> Option<Closed> {
    let usable = imp.zeta > 0.0 && x.iter().all(|v| v.is_finite());
    if !usable {
        return None;
    }
    let (z, v) = (x[0], x[1]);
    let creep = Creep::new(imp.lambda, imp.zeta, x[2] + (z - u.z_f), v);
    let leaves = creep.separation();
    // a ball that never leaves is held for ever: the bound needs no recoil spring for that
    if leaves.is_none() && imp.lambda != 0.0 {
        return None;
    }
    let peak = creep.peak_force(leaves);
    // (written so that a NaN reads as no)
    let below_the_branch_top = peak < u.f_m;
    if !below_the_branch_top {
        // the creep would load the contact back up to its last peak: not a creep's end
        return None;
    }
    let c = &imp.contact;
    // how far above z̄_f the contact sits while the creep asks at most F of it
    let depth = |f: f64| (c.unloading_indentation(f, u) - u.z_f).max(0.0) + z_tol;
    let delta = depth(peak).max((z - u.z_f).max(0.0) + z_tol);
    // ... provided the dashpot relaxes it there many times over in the window (see `bound`)
    let settled = |f: f64, window: f64| {
        let d = depth(f);
        let rate = 2.0 * imp.zeta * c.unloading_stiffness(u.z_f + d, u);
        (rate * window >= RELAXATIONS).then_some(d)
    };
    let error = match leaves {
        Some(end) => creep.bound(end, delta, settled),
        None => delta * 1.5 / imp.zeta,
    };
    let cor = leaves.map_or(0.0, |t| -creep.at(t)[1]);
    // A creep that asks less of the contact than its force at z̄_f + z_tol is below what the
    // integrators resolve: integrating it on is noise (crossings of z̄_f, a phase each, until
    // the budget runs out), and the closure is the better answer whatever its bound
    // (tests/physics/solver_agreement.rs, `closed_creeps_agree_with_the_exact_solver`: λ = 3.3e-10,
    // ζ = 1, a creep asking 1.7e-12 of a contact whose force is known to 3.7e-7).
    let unresolved = peak <= c.unloading_force(u.z_f + z_tol, u);
    (unresolved || error <= tol * cor.max(rest)).then_some(Closed {
        creep,
        leaves,
        u: *u,
    })
}

/// How many of its own relaxation times the contact must have in the late window of `bound`
/// to be taken to follow the force the creep asks of it.
const RELAXATIONS: f64 = 20.0;

impl Creep {
    /// The bound of the module doc on the error of v at the separation `end`, z̄ staying
    /// within `delta` of z̄_f. Refined where the pair is real (the creeps of a weak dashpot):
    /// v's response to an impulse then falls from 1 to the slow mode's |s_a|/(2h) ≈ 4ζ²λ
    /// within a few fast times 2ζ (the dashpot takes it up), so only the last window Θ
    /// before the separation counts in full, and there z̄ is within the depth `late` gives
    /// for the largest force the creep asks in it (`None`: the contact does not settle there).
    fn bound(&self, end: f64, delta: f64, late: impl Fn(f64, f64) -> Option<f64>) -> f64 {
        let held = |d: f64, span: f64| d * (self.lambda * span + 1.5 / self.zeta);
        let whole = held(delta, end);
        if self.q <= 0.0 {
            return whole;
        }
        let h = self.q.sqrt();
        // the fast root, and the slow one from their product λ (c + h cancels)
        let fast = self.centre - h;
        let slow = self.lambda / fast;
        [10.0, 20.0, 40.0, 80.0]
            .into_iter()
            .map(|k| 2.0 * self.zeta * k)
            .filter(|&window| window < end)
            .filter_map(|window| {
                let from = Creep {
                    w0: self.at(end - window),
                    ..*self
                };
                let d = late(from.peak_force(Some(window)), window)?;
                let kernel = (slow.abs() + fast.abs() * (fast * window).exp()) / (2.0 * h);
                Some(kernel * whole + held(d, window))
            })
            .fold(whole, f64::min)
    }
}

impl Closed {
    /// Finish the run from (t, x) along the creep: the state at the separation (or where the
    /// ball was found at rest), the samples of `grid` it covers, the contact's last work and
    /// the energy the creep dissipated, and whether the ball left (moving out faster than
    /// `left`, as a separation the integrators find).
    pub(super) fn finish(
        &self,
        imp: &Impact,
        (t, x): (f64, X),
        grid: &[f64],
        left: f64,
        samples: &mut Vec<Sample>,
        out: &mut Outcome,
    ) -> Finished {
        let (c, u) = (&imp.contact, &self.u);
        let tau = self.leaves.unwrap_or(0.0);
        let w = self.creep.at(tau);
        let covered = grid.iter().take_while(|&&ts| ts <= t + tau).count();
        samples.extend(grid[..covered].iter().map(|&ts| {
            let w = self.creep.at((ts - t).max(0.0));
            let f = self.creep.force(&w).max(0.0);
            Sample {
                tau: ts,
                force: f,
                z: c.unloading_indentation(f, u),
                alpha: u.z_f + w[0],
            }
        }));
        // What the contact gives back from z̄ to z̄_f is work on the branch; the rest of the
        // mechanical energy the creep loses is the dashpot's: along the flow by its energy
        // identity, E' = −v²/(2ζ) for E = ½v² + ½λȳ² (exact for it), and, at its start, the
        // element taking up z̄ − z̄_f at the force the contact carried.
        let mechanical = |v: f64, y: f64, z: f64| {
            0.5 * v * v + 0.5 * imp.lambda * y * y + c.unloading_work(z, u)
        };
        let lost = mechanical(x[1], x[2], x[0]) - mechanical(w[1], w[0], u.z_f);
        out.contact_work += c.unloading_work(u.z_f, u) - c.unloading_work(x[0], u);
        out.rebound = self.leaves.is_some() && -w[1] > left;
        if out.rebound {
            out.event(t + tau, EventKind::Separation, u.z_f);
        }
        Finished {
            t: t + tau,
            x: [u.z_f, w[1], w[0], x[3] + lost],
            covered,
        }
    }
}

#[cfg(test)]
mod tests;
