//! What an oblique impact is given (docs/oblique.md §1): the angle, spin, friction, tangential
//! stiffness, inertia factor and radius, checked field by field, and why an impact has no answer.

use crate::solver::SolveError;
use serde::Serialize;
use std::fmt;

/// The oblique part of an impact, SI units. Build it with [`Oblique::new`] (which checks it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Oblique {
    /// θ, the angle between the incoming path and the surface, degrees: 0 < θ ≤ 90.
    pub angle_deg: f64,
    /// ω, rad/s; positive is topspin for a ball moving in +x (the contact point moves back).
    pub spin: f64,
    /// μ, Coulomb's coefficient of friction, ≥ 0.
    pub friction: f64,
    /// K_t (N/m), > 0: the tangential spring.
    pub tangential_stiffness: f64,
    /// κ = I/(m R²), in (0, 1]: 0.4 for a solid ball, 2/3 for a thin shell.
    pub inertia_factor: f64,
    /// R (m), the undeformed radius.
    pub radius: f64,
    /// c_t (kg/s), ≥ 0: the tangential dashpot in parallel with K_t (0: none, the default;
    /// [`Oblique::with_tangential_damping`]).
    pub tangential_damping: f64,
}

/// A quantity of an oblique impact that is out of its domain, named as the command line
/// names it: "invalid angle: 0 (must lie in (0, 90] degrees)".
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueInvalid {
    /// `angle`, `spin`, `friction`, `tangential_stiffness`, `tangential_damping`,
    /// `inertia_factor` or `radius`.
    pub field: &'static str,
    /// The value given.
    pub value: f64,
    /// Why it is refused.
    pub reason: &'static str,
}

impl fmt::Display for ObliqueInvalid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = crate::text::number(self.value);
        write!(f, "invalid {}: {value} ({})", self.field, self.reason)
    }
}

/// Why an oblique impact has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ObliqueError {
    /// A quantity out of its domain (exit 2).
    #[error("{0}")]
    Invalid(ObliqueInvalid),
    /// The normal impact has no answer (see [`SolveError`]).
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// The normal impact does not rebound (λ = 0 and ζ ≥ 1): there is no outgoing motion.
    #[error("the ball does not rebound (λ = 0, ζ ≥ 1): no outgoing motion to report")]
    NoRebound,
    /// The normal motion asked for is not the linear law's (exit 2). No law is refused since
    /// every law's flow is kept (`solver::Flow`); kept so that callers' matches still hold.
    #[error(
        "invalid law: oblique impacts run the linear law only (its exact normal flow): use --law linear"
    )]
    Law,
    /// The adaptive normal run ended in a creep finished in closed form, which keeps no flow
    /// for the tangential motion to be driven by (exit 1).
    #[error(
        "no answer: the normal impact ends in a slow creep finished in closed form, which keeps no flow to drive the friction by"
    )]
    NoFlow,
    /// A quantity the ball does not carry (a ball that is no preset) and was not given (exit 2).
    #[error("invalid {0}: the ball is no preset and carries none: give it")]
    Missing(&'static str),
    /// The stick/slip switches did not come to an end within [`MAX_PHASES`](super::MAX_PHASES).
    #[error("no answer: more than 100000 stick/slip phases in one contact")]
    Phases,
}

impl ObliqueError {
    /// Whether it is no fault of the input (exit 1) rather than a bad value (exit 2).
    pub fn is_no_answer(&self) -> bool {
        matches!(
            self,
            ObliqueError::NoRebound
                | ObliqueError::Phases
                | ObliqueError::NoFlow
                | ObliqueError::Solve(SolveError::Unresolved { .. })
        )
    }
}

pub(super) fn invalid(field: &'static str, value: f64, reason: &'static str) -> ObliqueError {
    ObliqueError::Invalid(ObliqueInvalid {
        field,
        value,
        reason,
    })
}

impl Oblique {
    /// The oblique part, checked: the first quantity out of its domain is named.
    pub fn new(
        angle_deg: f64,
        spin: f64,
        friction: f64,
        tangential_stiffness: f64,
        inertia_factor: f64,
        radius: f64,
    ) -> Result<Oblique, ObliqueError> {
        let o = Oblique {
            angle_deg,
            spin,
            friction,
            tangential_stiffness,
            inertia_factor,
            radius,
            tangential_damping: 0.0,
        };
        o.validate()?;
        Ok(o)
    }

    /// The same with the tangential dashpot c_t (kg/s), checked.
    pub fn with_tangential_damping(self, c_t: f64) -> Result<Oblique, ObliqueError> {
        let o = Oblique {
            tangential_damping: c_t,
            ..self
        };
        o.validate()?;
        Ok(o)
    }

    /// Check every quantity (the fields are public: [`solve`](super::solve) checks them again).
    pub fn validate(&self) -> Result<(), ObliqueError> {
        let a = self.angle_deg;
        if !(a > 0.0 && a <= 90.0) {
            return Err(invalid("angle", a, "must lie in (0, 90] degrees"));
        }
        if !self.spin.is_finite() || self.spin.abs() > 1e9 {
            return Err(invalid(
                "spin",
                self.spin,
                "must be finite, |ω| ≤ 1e9 rad/s",
            ));
        }
        let mu = self.friction;
        if !(mu.is_finite() && (0.0..=1e6).contains(&mu)) {
            return Err(invalid("friction", mu, "must lie in [0, 1e6]"));
        }
        let k = self.tangential_stiffness;
        if !(k.is_finite() && k > 0.0) {
            return Err(invalid("tangential_stiffness", k, "must be positive"));
        }
        // bounded as K_p is (`model::checks::POSITIVE_RANGE`): the search grid's length grows
        // with √K_t, and past 1e15 it would overflow (tests/physics/oblique_bounded.rs)
        use crate::model::params::{MEANINGFUL_MAX, MEANINGFUL_MIN};
        if !(MEANINGFUL_MIN..=MEANINGFUL_MAX).contains(&k) {
            return Err(invalid(
                "tangential_stiffness",
                k,
                "out of the physically meaningful range 1e-15 … 1e15 N/m",
            ));
        }
        let c = self.tangential_damping;
        if !(c.is_finite() && (0.0..=MEANINGFUL_MAX).contains(&c)) {
            return Err(invalid(
                "tangential_damping",
                c,
                "must be finite, ≥ 0 and ≤ 1e15 kg/s",
            ));
        }
        let kappa = self.inertia_factor;
        if !(kappa > 0.0 && kappa <= 1.0) {
            return Err(invalid("inertia_factor", kappa, "must lie in (0, 1]"));
        }
        let r = self.radius;
        if !(r.is_finite() && r > 0.0) {
            return Err(invalid("radius", r, "must be positive"));
        }
        Ok(())
    }
}

/// Mindlin's ratio of tangential to normal stiffness, K_t/K_p = 2(1 − ν)/(2 − ν), for a
/// Poisson ratio ν (docs/oblique.md §1): 2/3 for rubber (ν = 0.5), 6/7 for ν = 0.25.
pub fn mindlin_ratio(poisson: f64) -> f64 {
    2.0 * (1.0 - poisson) / (2.0 - poisson)
}
