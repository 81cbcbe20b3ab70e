//! Oblique impacts of a [`Ball`] and the ITF court pace (docs/oblique.md), as `bouncelab
//! oblique` and `bouncelab court` run them.

use super::{Ball, BallError};
use crate::oblique::court::pace_category;
use crate::oblique::{self, Oblique, ObliqueError, ObliqueResponse, mindlin_ratio};
use crate::target::Target;
use serde::Serialize;

pub use crate::model::materials::SOLID_INERTIA_FACTOR;

/// What an oblique impact asks beyond the ball; `None` takes the ball's own (its preset's
/// speed, Mindlin's K_t from its Poisson ratio, its preset's κ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObliqueSpec {
    /// Incoming speed |v|, m/s.
    pub v: Option<f64>,
    /// Angle between the incoming path and the surface, degrees, 0 < θ ≤ 90.
    pub angle_deg: f64,
    /// Incoming spin, rad/s (> 0 topspin).
    pub spin: f64,
    /// μ.
    pub friction: f64,
    /// K_t, N/m.
    pub tangential_stiffness: Option<f64>,
    /// κ.
    pub inertia_factor: Option<f64>,
}

/// The ITF Court Pace Rating (ITF CS 01/02) of a surface of friction μ for this ball: 30 m/s
/// at 16°, no spin; CPR = 100(1 − μ_app) + 150(0.81 − e_y).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CourtPace {
    /// The rating.
    pub cpr: f64,
    /// 1 slow … 5 fast, from the rating rounded to the nearest integer.
    pub category: u8,
    /// "slow", "medium-slow", "medium", "medium-fast" or "fast".
    pub category_name: &'static str,
    /// μ_app = |Δv_x|/(v_y,in + v_y,out).
    pub apparent_friction: f64,
    /// e_y = v_y,out/v_y,in.
    pub cor_normal: f64,
    /// Outgoing speed, m/s.
    pub v_out: f64,
    /// Outgoing angle to the surface, degrees.
    pub angle_out_deg: f64,
    /// Outgoing spin, rad/s.
    pub spin_out: f64,
    /// What the caller should know about this answer ([`Ball::oblique_warnings`] of the
    /// test's impact); `[]` when nothing.
    pub warnings: Vec<String>,
}

impl Ball {
    /// κ = I/(m R²): the preset's, else a solid ball's 0.4.
    pub fn inertia_factor(&self) -> f64 {
        self.measured
            .as_ref()
            .and_then(|m| m.inertia_factor)
            .unwrap_or(SOLID_INERTIA_FACTOR)
    }

    /// Mindlin's K_t = 2(1 − ν)/(2 − ν) K_p from the preset's Poisson ratio (`None` for a
    /// ball that is no preset).
    pub fn tangential_stiffness(&self) -> Option<f64> {
        self.poisson_ratio
            .map(|nu| mindlin_ratio(nu) * self.params.k_p)
    }

    /// The warnings of an oblique impact `r` of this ball: those of its normal impact at
    /// v sin θ ([`Ball::warnings`]: a peak indentation beyond the radius, an energy balance
    /// that does not close).
    pub fn oblique_warnings(&self, r: &ObliqueResponse) -> Vec<String> {
        // the normal impact is this ball's at v_y, not at its v0 (the reach's second run)
        let normal = Ball {
            params: crate::model::params::ImpactParams {
                v0: r.vy_in,
                ..self.params
            },
            ..self.clone()
        };
        normal.warnings(&r.normal)
    }

    /// The warnings of an oblique impact `r` of this ball on `surface` (`oblique`, a shot's
    /// bounces, Python's alike): [`Ball::oblique_warnings`], then the surface's
    /// ([`super::SurfaceUsed::warnings`]).
    pub fn oblique_warnings_on(
        &self,
        r: &ObliqueResponse,
        surface: &super::SurfaceUsed,
    ) -> Vec<String> {
        let mut w = self.oblique_warnings(r);
        w.extend(surface.warnings());
        w
    }

    /// One oblique impact (docs/oblique.md), with `samples` history samples (0: none), as
    /// `bouncelab oblique`. The normal motion is `run`'s, on the ball's law.
    ///
    /// ```
    /// use bouncelab::{Ball, api::ObliqueSpec};
    /// let ball = Ball::from_preset("tennis")?;
    /// let spec = ObliqueSpec { v: Some(25.0), angle_deg: 16.0, spin: 300.0, friction: 0.6,
    ///                          tangential_stiffness: None, inertia_factor: None };
    /// let r = ball.oblique(&spec, 0)?;
    /// assert!(r.vy_out < r.vy_in && r.vx_out < r.vx_in);
    /// assert!(r.energy.residual < 1e-12);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn oblique(
        &self,
        spec: &ObliqueSpec,
        samples: usize,
    ) -> Result<ObliqueResponse, BallError> {
        self.oblique_damped(spec, None, samples)
    }

    /// [`Ball::oblique`] with a tangential dashpot c_t (kg/s) in parallel with K_t, as LAMMPS's
    /// linear_history applies it (docs/oblique.md §1; `None` or 0: none), as `bouncelab
    /// oblique --tangential-damping`.
    pub fn oblique_damped(
        &self,
        spec: &ObliqueSpec,
        tangential_damping: Option<f64>,
        samples: usize,
    ) -> Result<ObliqueResponse, BallError> {
        self.oblique_on(spec, tangential_damping, samples, &Target::wall())
    }

    /// [`Ball::oblique_damped`] on a surface that gives or moves, `surface` at rest
    /// (docs/oblique.md §11; `Target::wall()`: the rigid plate, the very same answer).
    pub fn oblique_on(
        &self,
        spec: &ObliqueSpec,
        tangential_damping: Option<f64>,
        samples: usize,
        surface: &Target,
    ) -> Result<ObliqueResponse, BallError> {
        if samples == 1 || samples > super::MAX_SAMPLES {
            return Err(BallError::Samples(samples));
        }
        let no = |field| BallError::from(ObliqueError::Missing(field));
        let radius = Some(self.radius())
            .filter(|r| r.is_finite())
            .ok_or_else(|| no("radius"))?;
        let k_t = match spec.tangential_stiffness {
            Some(k) => k,
            None => self
                .tangential_stiffness()
                .ok_or_else(|| no("tangential_stiffness"))?,
        };
        let kappa = spec.inertia_factor.unwrap_or_else(|| self.inertia_factor());
        let o = Oblique::new(spec.angle_deg, spec.spin, spec.friction, k_t, kappa, radius)?
            .with_tangential_damping(tangential_damping.unwrap_or(0.0))?;
        let v = spec.v.unwrap_or(self.params.v0);
        if !(v.is_finite() && v > 0.0) {
            return Err(BallError::Invalid {
                field: "v0",
                value: v,
                reason: "must be positive".into(),
            });
        }
        Ok(oblique::solve_on(
            &self.params,
            self.law,
            v,
            &o,
            surface,
            samples,
        )?)
    }

    /// The ITF Court Pace Rating of a surface of friction `friction` (ITF CS 01/02: 30 m/s at
    /// 16°, no spin), as `bouncelab court`.
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("tennis")?;
    /// let pace = ball.court_pace(0.6, None, None)?;
    /// assert!((1..=5).contains(&pace.category));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn court_pace(
        &self,
        friction: f64,
        tangential_stiffness: Option<f64>,
        inertia_factor: Option<f64>,
    ) -> Result<CourtPace, BallError> {
        self.court_pace_damped(friction, tangential_stiffness, inertia_factor, None)
    }

    /// [`Ball::court_pace`] with a tangential dashpot c_t, kg/s ([`Ball::oblique_damped`]).
    pub fn court_pace_damped(
        &self,
        friction: f64,
        tangential_stiffness: Option<f64>,
        inertia_factor: Option<f64>,
        tangential_damping: Option<f64>,
    ) -> Result<CourtPace, BallError> {
        let tangential = (tangential_stiffness, inertia_factor, tangential_damping);
        self.court_pace_on(friction, tangential, &Target::wall())
    }

    /// [`Ball::court_pace_damped`] on a court that gives or moves (docs/oblique.md §6, §11):
    /// μ_app and e_y both from the test's bounce on it. `tangential` is (K_t, κ, c_t).
    pub fn court_pace_on(
        &self,
        friction: f64,
        tangential: (Option<f64>, Option<f64>, Option<f64>),
        surface: &Target,
    ) -> Result<CourtPace, BallError> {
        let (tangential_stiffness, inertia_factor, tangential_damping) = tangential;
        let spec = ObliqueSpec {
            v: Some(30.0),
            angle_deg: 16.0,
            spin: 0.0,
            friction,
            tangential_stiffness,
            inertia_factor,
        };
        let r = self.oblique_on(&spec, tangential_damping, 0, surface)?;
        let cpr = 100.0 * (1.0 - r.apparent_friction) + 150.0 * (0.81 - r.cor_normal);
        let (category, category_name) = pace_category(cpr);
        Ok(CourtPace {
            cpr,
            category,
            category_name,
            apparent_friction: r.apparent_friction,
            cor_normal: r.cor_normal,
            v_out: r.v_out,
            angle_out_deg: r.angle_out_deg,
            spin_out: r.spin_out,
            warnings: self.oblique_warnings(&r),
        })
    }
}
