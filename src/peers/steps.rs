//! The time step an exported snippet needs, found by running the code's own integrator
//! (docs/peers.md §5). A code does not integrate the contact law exactly: the COR it gives
//! depends on its time step and on the *contact phase* — where in a step the ball meets the
//! wall — by an error of order h/t_c. Here the ball approaches at v0 from a gap
//! (2 + φ) v0 h, φ ∈ [0, 1), and is stepped exactly as the code steps it:
//!
//! - [`Scheme::SymplecticEuler`] — MuJoCo's `Euler` integrator (the default): the
//!   acceleration from the state at the step's start, then v ← v + h a, x ← x + h v;
//! - [`Scheme::VelocityVerlet`] — LAMMPS's `fix nve/sphere`: v ← v + h a/2, x ← x + h v, the
//!   force from the new x and the half-step v, v ← v + h a/2.
//!
//! A contact exists while the ball overlaps the wall (both codes); the COR is the speed out
//! over v0. [`Stepper::advised_step`] takes the largest h = t_c/N (t_c the model's contact time) for
//! which every phase of a dense set gives the target within a tolerance. The real codes
//! reproduce these steppers to rounding (python/tests/test_exports_real.py runs them).

use super::export::{ExportSet, STEP_TOL};
use super::{PeerBall, PeerError, PeerModel, impact};

/// How a code advances the ball's position and velocity over one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// MuJoCo `integrator="Euler"`: a(x, v), then v += h a, x += h v.
    SymplecticEuler,
    /// LAMMPS velocity Verlet: the force sees the new position and the half-step velocity.
    VelocityVerlet,
}

/// The advised step and what it was checked to give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// The time step h, s.
    pub h: f64,
    /// Steps per contact time, N = t_c / h.
    pub per_contact: u32,
    /// The largest |COR − target| over the phases checked at h.
    pub worst: f64,
}

/// Contact phases checked: φ = (j + 1/2)/PHASES, j = 0 … PHASES − 1.
pub const PHASES: u32 = 32;

/// Smallest and largest steps per contact time tried.
const N_MIN: u32 = 20;
const N_MAX: u32 = 100_000;

/// A code's integrator on a law: `scheme` stepping a ball that approaches the wall at `v0`,
/// `accel(δ, δ̇)` the wall's push per unit mass at indentation δ > 0 and indentation rate δ̇.
#[derive(Clone, Copy)]
pub struct Stepper<'a> {
    /// How the code advances the ball.
    pub scheme: Scheme,
    /// The wall's push per unit mass, (δ, δ̇) ↦ a.
    pub accel: &'a dyn Fn(f64, f64) -> f64,
    /// The approach speed, m/s.
    pub v0: f64,
}

impl Stepper<'_> {
    /// The COR at step `h` with the ball approaching from a gap (2 + `phase`) v0 h; `None`
    /// when it has not left the wall within `max_steps` steps.
    pub fn cor(&self, h: f64, phase: f64, max_steps: u64) -> Option<f64> {
        let (scheme, accel, v0) = (self.scheme, self.accel, self.v0);
        // x: the gap (negative = indentation δ = −x), v: the ball's velocity away from the wall
        let (mut x, mut v) = ((2.0 + phase) * v0 * h, -v0);
        let push = |x: f64, v: f64| if x < 0.0 { accel(-x, -v) } else { 0.0 };
        let mut a = push(x, v);
        let mut touched = false;
        for _ in 0..max_steps {
            match scheme {
                Scheme::SymplecticEuler => {
                    a = push(x, v);
                    v += h * a;
                    x += h * v;
                }
                Scheme::VelocityVerlet => {
                    v += 0.5 * h * a;
                    x += h * v;
                    a = push(x, v);
                    v += 0.5 * h * a;
                }
            }
            touched |= x < 0.0;
            if touched && x > 0.0 && v > 0.0 {
                return Some(v / v0);
            }
        }
        None
    }

    /// The worst |COR − target| over the phases at step `h` = t_c/`n`, each given 20 contact
    /// times of steps; `None` if some phase did not end.
    pub fn worst_over_phases(&self, h: f64, n: u32, target: f64) -> Option<f64> {
        let budget = 20 * u64::from(n) + 100;
        (0..PHASES)
            .map(|j| {
                let phase = (f64::from(j) + 0.5) / f64::from(PHASES);
                self.cor(h, phase, budget).map(|e| (e - target).abs())
            })
            .try_fold(0.0f64, |w, d| d.map(|d| w.max(d)))
    }

    /// The largest h = t_c/N, N = 20 · 1.25^j, at which every phase gives `target` within
    /// `tol`; `None` beyond N = 100 000 (then the snippet says no step was found).
    pub fn advised_step(&self, contact_time: f64, target: f64, tol: f64) -> Option<Step> {
        ladder().find_map(|n| {
            let h = contact_time / f64::from(n);
            let worst = self.worst_over_phases(h, n, target)?;
            (worst <= tol).then_some(Step {
                h,
                per_contact: n,
                worst,
            })
        })
    }
}

/// The steps per contact time tried, coarsest first: 20, 25, 32, 40, … ≤ 100 000.
pub fn ladder() -> impl Iterator<Item = u32> {
    std::iter::successors(Some(N_MIN), |&n| Some((f64::from(n) * 1.25).ceil() as u32))
        .take_while(|&n| n <= N_MAX)
}

/// The exports' laws, per unit mass in SI, stepped as each code steps them.
impl ExportSet {
    /// MuJoCo's Euler on the clipped Kelvin–Voigt law per unit mass (module docs).
    pub fn mujoco_step(&self, ball: &PeerBall) -> Result<Option<Step>, PeerError> {
        let (kk, bb) = (self.k / self.mass, self.kv_no_tension_eta / self.mass);
        let law = move |d: f64, dd: f64| (kk * d + bb * dd).max(0.0);
        self.step(
            ball,
            PeerModel::KelvinVoigtNoTension,
            self.kv_no_tension_eta,
            Scheme::SymplecticEuler,
            &law,
        )
    }

    /// LAMMPS's velocity Verlet on each `fix` line's law: hooke with tension, hooke clipped,
    /// and hertz with the exact Tsuji damping when a `coeff_restitution` input reaches it.
    pub fn lammps_steps(
        &self,
        ball: &PeerBall,
    ) -> Result<Vec<(PeerModel, Option<Step>)>, PeerError> {
        let (m, k, eta, eta_c) = (self.mass, self.k, self.kv_eta, self.kv_no_tension_eta);
        let (k_h, eta_t) = (self.k_h, self.tsuji_eta);
        let kv = move |d: f64, dd: f64| (k * d + eta * dd) / m;
        let kvc = move |d: f64, dd: f64| (k * d + eta_c * dd).max(0.0) / m;
        let ts =
            move |d: f64, dd: f64| (k_h * d * d.sqrt() + eta_t * d.sqrt().sqrt() * dd).max(0.0) / m;
        let vv = Scheme::VelocityVerlet;
        let mut out = vec![
            (
                PeerModel::KelvinVoigt,
                self.step(ball, PeerModel::KelvinVoigt, eta, vv, &kv)?,
            ),
            (
                PeerModel::KelvinVoigtNoTension,
                self.step(ball, PeerModel::KelvinVoigtNoTension, eta_c, vv, &kvc)?,
            ),
        ];
        if self.tsuji_e_in().is_some() {
            out.push((
                PeerModel::Tsuji,
                self.step(ball, PeerModel::Tsuji, eta_t, vv, &ts)?,
            ));
        }
        Ok(out)
    }

    /// The advised step for one model's law under `scheme`; `None` without a rebound or when
    /// no step up to t_c/100 000 holds.
    fn step(
        &self,
        ball: &PeerBall,
        model: PeerModel,
        damping: f64,
        scheme: Scheme,
        law: &dyn Fn(f64, f64) -> f64,
    ) -> Result<Option<Step>, PeerError> {
        let r = impact(model, ball, damping, 0)?;
        let stepper = Stepper {
            scheme,
            accel: law,
            v0: self.v0,
        };
        Ok(r.contact_time
            .and_then(|t_c| stepper.advised_step(t_c, self.target_cor, STEP_TOL)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Without a wall force the ball never turns: no answer, not a made-up COR.
    #[test]
    fn no_force_no_rebound() {
        let none = |_: f64, _: f64| 0.0;
        for scheme in [Scheme::SymplecticEuler, Scheme::VelocityVerlet] {
            let s = Stepper {
                scheme,
                accel: &none,
                v0: 1.0,
            };
            assert_eq!(s.cor(1e-3, 0.5, 10_000), None);
        }
    }

    /// An undamped linear spring: velocity Verlet conserves the shadow energy, so the COR
    /// tends to 1 as h → 0 with an error O(h) from the step the contact starts in, and
    /// both schemes converge to the same limit.
    #[test]
    fn undamped_spring_converges_to_one() {
        let spring = |d: f64, _: f64| 1.0e4 * d;
        let t_c = std::f64::consts::PI / 100.0;
        for scheme in [Scheme::SymplecticEuler, Scheme::VelocityVerlet] {
            let s = Stepper {
                scheme,
                accel: &spring,
                v0: 1.0,
            };
            let coarse = s.worst_over_phases(t_c / 20.0, 20, 1.0).unwrap();
            let fine = s.worst_over_phases(t_c / 2000.0, 2000, 1.0).unwrap();
            assert!(
                fine < 2e-3 && fine < coarse / 20.0,
                "{scheme:?}: {coarse} → {fine}"
            );
        }
    }

    /// The advised step meets its tolerance and the next coarser rung of the ladder does not;
    /// the clipped Kelvin–Voigt COR it approaches is the closed form (docs/peers.md §3).
    #[test]
    fn advised_step_is_the_coarsest_that_holds() {
        let zeta: f64 = 0.2;
        let target = (-2.0 * zeta * zeta.acos() / (1.0 - zeta * zeta).sqrt()).exp();
        let (k, eta) = (1.0e4, 2.0 * zeta * 100.0);
        let kv = move |d: f64, dd: f64| (k * d + eta * dd).max(0.0);
        // clipped contact time 2 arccos ζ / ω_d
        let t_c = 2.0 * zeta.acos() / (100.0 * (1.0 - zeta * zeta).sqrt());
        for (scheme, tol) in [
            (Scheme::SymplecticEuler, 2e-3),
            (Scheme::VelocityVerlet, 1e-3),
        ] {
            let stepper = Stepper {
                scheme,
                accel: &kv,
                v0: 1.0,
            };
            let s = stepper.advised_step(t_c, target, tol).unwrap();
            assert!(s.worst <= tol && s.per_contact > N_MIN, "{scheme:?} {s:?}");
            assert!((s.h * f64::from(s.per_contact) - t_c).abs() < 1e-15);
            let coarser = ladder().take_while(|&n| n < s.per_contact).last().unwrap();
            let h = t_c / f64::from(coarser);
            let w = stepper.worst_over_phases(h, coarser, target).unwrap();
            assert!(w > tol, "{scheme:?}: N = {coarser} already holds ({w})");
            let fine = stepper
                .worst_over_phases(t_c / 5e4, 50_000, target)
                .unwrap();
            assert!(fine < 2e-5, "{scheme:?}: {fine} at N = 50 000");
        }
    }
}
