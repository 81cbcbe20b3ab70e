//! The impact as the integrators see it: the contact branch in force, the first-order system
//! of docs/model.md §2 in normalized form, and what bounds the COR a ball can still leave with.

use super::creep::{self, Closed};
use super::{ATOL_FACTOR, CREEP_TOL, REST_COR, X};
use crate::model::contact::{Contact, ContactLaw, Unloading};
use differential_equations::linalg::Matrix;
use differential_equations::ode::ODE;

/// The branch of the contact law in force.
#[derive(Clone, Copy, Debug)]
pub(super) enum Phase {
    Loading,
    Unloading(Unloading),
}

/// One impact: the two dimensionless knobs, the contact law and the branch in force.
pub(super) struct Impact {
    pub(super) lambda: f64,
    pub(super) zeta: f64,
    pub(super) contact: Contact,
    pub(super) phase: Phase,
}

impl Impact {
    pub(super) fn force(&self, z: f64) -> f64 {
        match self.phase {
            Phase::Loading => self.contact.loading_force(z),
            Phase::Unloading(u) => self.contact.unloading_force(z, &u),
        }
    }

    /// An upper bound on the COR the ball can still leave with, from state x.
    ///
    /// Energy: the kinetic energy, the recoverable energy of the contact on the current branch
    /// and the recoil spring's; the dashpot only takes energy away, so e ≤ √(2 E).
    ///
    /// Impulse, with no recoil spring (λ = 0): the dashpot then carries the whole force,
    /// ȳ' = 2ζF̄, so z̄' = ᾱ' − 2ζF̄ ≤ −2ζF̄ once the ball moves out (ᾱ' ≤ 0, and it stays so,
    /// ᾱ'' = −F̄ ≤ 0). The impulse still to come, ∫F̄ dτ, is then at most ∫dz̄/(2ζ) over the
    /// fall of z̄ from where the ball turns, z̄*, to z̄_f ≥ 0: e ≤ −ᾱ' + (z̄* − z̄_f)/(2ζ).
    /// While the ball still moves in, z̄ can only rise where 2ζF̄(z̄) < ᾱ' ≤ ᾱ'_now, so z̄* is
    /// at most the larger of z̄ and the indentation where the branch carries ᾱ'_now/(2ζ).
    /// This is what ends a ball creeping into a weak dashpot: its kinetic energy decays only
    /// as exp(−τ/2ζ), but it sits at z̄ ≈ F̄⁻¹(ᾱ'/2ζ), far too shallow to send it back.
    ///
    /// Creep, with a recoil spring (λ > 0): ȳ ≥ 0 throughout (at ȳ = 0, ȳ' = 2ζF̄ ≥ 0), and
    /// the element retracts at −ȳ' = 2ζ(λȳ − F̄) ≤ 2ζλȳ. The ball stays in contact only while
    /// it moves out no faster than that, give or take what it and the contact store; so the
    /// spring's energy reaches the ball at a speed of 2ζλȳ at most, doubled for the overshoot of
    /// the ball on its contact when that drive sets in, and the rest at √(2(KE + W)) at most:
    /// e ≤ 4ζλȳ + √(2(KE + W)). An argument, not a proof (ȳ can still grow while the contact
    /// pushes harder than the spring, from energy the second term counts), and used only
    /// where it is far below the energy bound: a ball at the integrator's noise floor with a
    /// spring so soft that it holds ½λȳ² but drives the ball at only 2ζλȳ, whose separation
    /// (a crossing of z̄ ~ 1e-27) no integrator resolves; it is at rest, and the run answers
    /// (tests/physics/solver_agreement.rs, `adaptive_creeps_out_at_a_soft_spring`: λ = 1e-15, ζ = 5).
    pub(super) fn cor_bound(&self, x: &X) -> f64 {
        let (z, v) = (x[0], x[1]);
        let contact = match self.phase {
            Phase::Loading => self.contact.loading_work(z),
            Phase::Unloading(u) => self.contact.unloading_work(z, &u),
        };
        let energy = 0.5 * v * v + contact + 0.5 * self.lambda * x[2] * x[2];
        let by_energy = (2.0 * energy).sqrt();
        if self.zeta <= 0.0 {
            return by_energy;
        }
        if self.lambda != 0.0 {
            let stored = 0.5 * v * v + contact;
            let by_creep = 2.0 * self.pace(x).abs() + (2.0 * stored).sqrt();
            return by_energy.min(by_creep);
        }
        let (z_f, turn) = match self.phase {
            Phase::Loading => (0.0, self.contact.loading_indentation(v / (2.0 * self.zeta))),
            Phase::Unloading(u) => (
                u.z_f,
                self.contact
                    .unloading_indentation(v / (2.0 * self.zeta), &u),
            ),
        };
        let by_impulse = if v <= 0.0 {
            -v + (z - z_f).max(0.0) / (2.0 * self.zeta)
        } else {
            (z.max(turn) - z_f).max(0.0) / (2.0 * self.zeta)
        };
        by_energy.min(by_impulse)
    }

    /// The speed at which the recoil spring retracts the element when the contact carries no
    /// force, 2ζλȳ: what a ball must outrun to leave (see `PACE_SLACK`).
    pub(super) fn pace(&self, x: &X) -> f64 {
        2.0 * self.zeta * self.lambda * x[2]
    }

    /// The fastest rate of the dashpot from z̄ on in this phase, in units of ω0: 2ζ times the
    /// stiffness it works against, the contact's (its steepest on the branch ahead: dF̄/dz̄ grows
    /// with z̄ on every branch but the elastic–plastic law's linear stretch) plus the recoil
    /// spring's. An elastic–plastic unloading branch deep in the plastic range is as steep as
    /// 1.5 F̄_m/(z̄_m − z̄_f), hundreds of times the loading slope.
    pub(super) fn dashpot_rate(&self, z: f64) -> f64 {
        let c = &self.contact;
        let slope = match (self.phase, c.law) {
            // steepest at its top
            (Phase::Unloading(u), _) => c.unloading_stiffness(u.z_m, &u),
            // (from z̄ = 0 on too, where the ball meets the wall)
            (Phase::Loading, ContactLaw::Linear) => 1.0,
            (Phase::Loading, ContactLaw::Hertz) => c.loading_stiffness(z),
            // the Hertz stretch up to z̄_p, then the linear one
            (Phase::Loading, ContactLaw::ElasticPlastic) => {
                c.loading_stiffness(z.min(c.zp_bar)).max(1.0)
            }
        };
        2.0 * self.zeta * (slope + self.lambda)
    }

    /// The rest of an unloading phase from x in closed form, where the error bound of `creep`
    /// allows it, with z̄ known to the tolerance `z_rtol` of the integrator that reached x.
    pub(super) fn close_creep(&self, x: &X, z_rtol: f64) -> Option<Closed> {
        let Phase::Unloading(u) = self.phase else {
            return None;
        };
        let z_tol = z_rtol * (x[0].abs() + ATOL_FACTOR);
        creep::close(self, &u, x, z_tol, CREEP_TOL, REST_COR)
    }

    /// Move a reload, found `RELOAD_SLACK` tolerances past z̄_m on the unloading branch `u`,
    /// to where the loading branch carries the same force, when that is lower: the element
    /// takes the difference up through the dashpot. Returns the work the contact did.
    ///
    /// Why: past yield the elastic–plastic loading branch is steeper at z̄_m than the branch
    /// that unloads from it (the two meet there), so the loading force at the reload exceeds
    /// the unloading one by (slope difference) × slack. Against a weak dashpot that jump turns
    /// z̄' negative at once (2ζ × it, against a creep of z̄' ~ 6e-9): an unload, a reload a
    /// slack higher, and so on without end. At the same force the ball goes on creeping in on
    /// the loading branch (tests/physics/solver_agreement.rs,
    /// `a_creep_past_yield_reloads_at_the_same_force`). The ball stays put; the element moves
    /// by Δ = z̄ − z̄', the spring taking λȳΔ of the contact's FΔ and the dashpot (F − λȳ)Δ, so
    /// the energy balance is kept.
    pub(super) fn reload_where_forces_meet(&self, u: &Unloading, x: &mut X) -> f64 {
        let (z, spring) = (x[0], self.lambda * x[2]);
        let f = self.contact.unloading_force(z, u);
        let at = self.contact.loading_indentation(f);
        let delta = z - at;
        // (no dashpot, no element to move; written so that a NaN reads as no)
        let lower = delta > 0.0 && f >= spring && self.zeta > 0.0;
        if !lower {
            return 0.0;
        }
        x[0] = at;
        x[2] += delta;
        x[3] += (f - spring) * delta;
        f * delta
    }

    /// The ball has come to rest: no rebound above `REST_COR` can follow.
    pub(super) fn at_rest(&self, x: &X) -> bool {
        self.cor_bound(x) < REST_COR
    }

    /// dF̄/dz̄ on the branch in force.
    pub(super) fn stiffness(&self, z: f64) -> f64 {
        match self.phase {
            Phase::Loading => self.contact.loading_stiffness(z),
            Phase::Unloading(u) => self.contact.unloading_stiffness(z, &u),
        }
    }

    /// (F̄, ȳ') at a state.
    pub(super) fn force_and_rate(&self, x: &X) -> (f64, f64) {
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

    /// The Jacobian of `diff`, written out rather than left to the crate's forward
    /// differences: those perturb each state by 1.5e-8 · max(|x|, 1), wider than the
    /// indentations a creeping ball lives on (z̄ ~ 1e-5 down to 1e-16) and than its distance to
    /// a kink of the force: near the elastic–plastic yield point z̄_p a difference reaches
    /// across it into the linear branch and gives the wrong slope, on which Radau5's Newton
    /// iteration converges only on steps near the dashpot's time (tests/physics/solver_agreement.rs,
    /// `a_yield_met_mid_creep_against_a_stiff_contact_answers`; the written-out form is
    /// `the_jacobian_is_the_derivative_of_the_system` below).
    ///
    /// With k = dF̄/dz̄ and ȳ' = 2ζ(F̄ − λȳ): ∂ȳ'/∂z̄ = 2ζk, ∂ȳ'/∂ȳ = −2ζλ, and
    /// Ē_d' = ȳ'²/(2ζ) has the gradient (ȳ'/ζ) ∇ȳ' = 2ȳ' (k, 0, −λ, 0).
    fn jacobian(&self, _t: f64, x: &X, j: &mut Matrix<f64>) {
        let (_, ydot) = self.force_and_rate(x);
        let k = self.stiffness(x[0]);
        let (rate_z, rate_y) = (2.0 * self.zeta * k, -2.0 * self.zeta * self.lambda);
        // (no dashpot: ȳ' = 0 and no loss)
        let loss = if self.zeta > 0.0 { 2.0 * ydot } else { 0.0 };
        let rows: [X; 4] = [
            [-rate_z, 1.0, -rate_y, 0.0],
            [-k, 0.0, 0.0, 0.0],
            [rate_z, 0.0, rate_y, 0.0],
            [loss * k, 0.0, -loss * self.lambda, 0.0],
        ];
        for (i, row) in rows.iter().enumerate() {
            for (c, value) in row.iter().enumerate() {
                j[(i, c)] = *value;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The written-out Jacobian against central differences, on every law and branch, at
    /// states clear of the kinks (z̄ = 0, z̄_f, z̄_p) by far more than the difference step.
    #[test]
    fn the_jacobian_is_the_derivative_of_the_system() {
        let contact = |law| Contact {
            law,
            zp_bar: 0.1,
            kappa: 1.3,
        };
        let mut cases = Vec::new();
        for law in [
            ContactLaw::Linear,
            ContactLaw::Hertz,
            ContactLaw::ElasticPlastic,
        ] {
            let c = contact(law);
            for (lambda, zeta) in [(0.2, 0.7), (0.0, 40.0), (3.0, 0.0)] {
                // below and past yield on loading; on the branch unloading from z̄_m = 0.3
                for (phase, z) in [
                    (Phase::Loading, 0.05),
                    (Phase::Loading, 0.3),
                    (Phase::Unloading(c.unload_from(0.3)), 0.25),
                ] {
                    let imp = Impact {
                        lambda,
                        zeta,
                        contact: c,
                        phase,
                    };
                    cases.push((imp, [z, -0.4, 0.35, 0.01]));
                }
            }
        }
        for (imp, x) in cases {
            let mut j = Matrix::zeros(4, 4);
            imp.jacobian(0.0, &x, &mut j);
            for col in 0..4 {
                let h = 1e-6;
                let (mut up, mut down) = (x, x);
                up[col] += h;
                down[col] -= h;
                let (mut f_up, mut f_down) = ([0.0; 4], [0.0; 4]);
                imp.diff(0.0, &up, &mut f_up);
                imp.diff(0.0, &down, &mut f_down);
                for row in 0..4 {
                    let numeric = (f_up[row] - f_down[row]) / (2.0 * h);
                    let scale = 1.0 + numeric.abs();
                    assert!(
                        (j[(row, col)] - numeric).abs() < 1e-6 * scale,
                        "∂f{row}/∂x{col} = {} written, {numeric} differenced ({:?}, {:?})",
                        j[(row, col)],
                        imp.contact.law,
                        imp.phase
                    );
                }
            }
        }
    }
}
