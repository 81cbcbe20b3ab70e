//! One impact's numbers without its energy audit, for a caller that asks for many one at a
//! time (Python's `run`, issue 30 item 5): on the linear law the closed forms of
//! [`crate::map::fast`] where they answer — [`crate::map::fast::summary`] while the ball does
//! not flatten (F̄_m ≤ z̄_p), [`crate::map::fast::flattening`] where it does — each held to the
//! exact solver at 1e-12 (tests/physics/map_precision.rs, tests/physics/map_flatten.rs, tests/physics/run_summary.rs),
//! in about a fifth of the exact solver's time with its energy audit (BENCHMARKS.md).
//!
//! The audit (the dashpot's dissipation by quadrature on the exact flow, docs/model.md §8)
//! and the warnings that read it are not computed here: a caller that reports them runs
//! [`Ball::impact`] for them, as `bouncelab run` does (docs/python.md).

use super::Ball;
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;
use crate::solver::{ImpactResponse, Method};
use serde::Serialize;

/// What one impact came to, SI units: the fields of [`ImpactResponse`] of the same names; the
/// JSON answer's keys `cor` … `contact_time_normalized` ([`super::ImpactReport`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactOutcome {
    /// e.
    pub cor: f64,
    /// Whether the ball left the wall.
    pub rebound: bool,
    /// F_m, N.
    pub max_force: f64,
    /// t_f, s (`None` without a rebound).
    pub contact_time: Option<f64>,
    /// z_m, m.
    pub max_indentation: f64,
    /// z_f, m.
    pub permanent_indentation: f64,
    /// F̄_m.
    pub max_force_normalized: f64,
    /// τ_f (`None` without a rebound).
    pub contact_time_normalized: Option<f64>,
}

/// What `run` reports of one impact apart from its energy budget, its warnings and its
/// history, SI units: the fields of [`ImpactResponse`] of the same names.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactSummary {
    /// The solver whose answer this is: [`Method::Exact`] for the linear law's closed forms
    /// too (the exact solution of the same flow, evaluated in closed form).
    pub method: Method,
    /// e, rebound, F_m, t_f, z_m, z_f, F̄_m, τ_f.
    pub outcome: ImpactOutcome,
    /// λ, ζ, z̄_p, κ.
    pub normalized: Normalized,
}

impl From<&ImpactResponse> for ImpactOutcome {
    fn from(r: &ImpactResponse) -> ImpactOutcome {
        ImpactOutcome {
            cor: r.cor,
            rebound: r.rebound,
            max_force: r.max_force,
            contact_time: r.contact_time,
            max_indentation: r.max_indentation,
            permanent_indentation: r.permanent_indentation,
            max_force_normalized: r.max_force_normalized,
            contact_time_normalized: r.contact_time_normalized,
        }
    }
}

impl From<&ImpactResponse> for ImpactSummary {
    fn from(r: &ImpactResponse) -> ImpactSummary {
        ImpactSummary {
            method: r.method,
            outcome: r.into(),
            normalized: r.normalized,
        }
    }
}

impl Ball {
    /// The impact's summary by the linear law's closed forms (module docs); `None` where they
    /// do not answer — another law, no rebound, a reload after flattening, a run whose
    /// rounding bound cannot keep 1e-13 — and the caller runs [`Ball::impact`]. The SI values
    /// are formed as the solvers form theirs (F = F̄ · m v0 ω0, t = τ · 1/ω0, z = z̄ · v0/ω0).
    ///
    /// ```
    /// let golf = bouncelab::Ball::from_preset("golf")?;
    /// let s = golf.closed_form_summary().expect("golf does not flatten at 1.47 m/s");
    /// let r = golf.impact()?;
    /// assert!((s.outcome.cor - r.cor).abs() <= 1e-12 * r.cor);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn closed_form_summary(&self) -> Option<ImpactSummary> {
        if self.law != ContactLaw::Linear || self.params.validate().is_err() {
            return None;
        }
        let p = &self.params;
        let n = p.normalized();
        let s = match crate::map::fast::summary(n.lambda, n.zeta) {
            Some(s) if s.max_force <= n.zp_bar => s,
            // it flattens (or the closed form without flattening did not answer, when the
            // flattening one does not either): the lanes' code on one lane, else the scalar
            // closed form — a map's cell and a row of `impacts` bit for bit
            // (tests/physics/map_flatten_lanes.rs `one_lane_is_the_maps_lane_bit_for_bit`)
            _ => crate::map::fast::lanes::flattening_one(n.lambda, n.zeta, n.zp_bar)?,
        };
        if !(s.cor > 0.0 && s.cor <= 1.0) {
            return None;
        }
        let contact = Contact {
            law: ContactLaw::Linear,
            zp_bar: n.zp_bar,
            kappa: n.kappa,
        };
        // loading is F̄ = z̄ on the linear law (docs/model.md §3): z̄_m = F̄_m; z̄_f by Eqs. 18–19
        let (z_m, z_f) = (s.max_force, contact.permanent_indentation(s.max_force));
        let w0 = p.omega0();
        let (t, z, f) = (1.0 / w0, p.v0 / w0, p.mass * p.v0 * w0);
        Some(ImpactSummary {
            method: Method::Exact,
            outcome: ImpactOutcome {
                cor: s.cor,
                rebound: true,
                max_force: s.max_force * f,
                contact_time: Some(s.contact_time * t),
                max_indentation: z_m * z,
                permanent_indentation: z_f * z,
                max_force_normalized: s.max_force,
                contact_time_normalized: Some(s.contact_time),
            },
            normalized: n,
        })
    }
}
