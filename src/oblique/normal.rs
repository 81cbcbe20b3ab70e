//! The normal half of an oblique impact, solved once and reused: what a fit of μ, K_t and κ
//! (`analysis::fit::oblique`) or a map over μ runs many tangential motions over, for the
//! normal impact does not depend on them (docs/oblique.md §1).

use super::{Oblique, ObliqueError, ObliqueResponse, Scaled, energy, tangential};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{Flow, ImpactResponse, SolveOptions, simulate_flow};

/// A ball's normal impact at speed v and angle θ, with its flow.
pub struct NormalAt {
    params: ImpactParams,
    v: f64,
    angle_deg: f64,
    vx: f64,
    vy: f64,
    normal: ImpactResponse,
    path: Flow,
}

impl NormalAt {
    /// The normal impact of `params` under `law` at speed `v` and `angle_deg` (0 < θ ≤ 90),
    /// as `run` solves it at v_y = v sin θ (v itself at 90°).
    pub fn new(
        params: &ImpactParams,
        law: ContactLaw,
        v: f64,
        angle_deg: f64,
    ) -> Result<NormalAt, ObliqueError> {
        Self::with_options(
            params,
            law,
            v,
            angle_deg,
            &SolveOptions::default().with_energy(),
        )
    }

    pub(crate) fn with_options(
        params: &ImpactParams,
        law: ContactLaw,
        v: f64,
        angle_deg: f64,
        opts: &SolveOptions,
    ) -> Result<NormalAt, ObliqueError> {
        if !(angle_deg > 0.0 && angle_deg <= 90.0) {
            return Err(super::invalid(
                "angle",
                angle_deg,
                "must lie in (0, 90] degrees",
            ));
        }
        let theta = angle_deg.to_radians();
        // at 90° the normal impact is the very one `run` solves: v_y = v, not v sin(π/2)
        let (vy, vx) = if angle_deg == 90.0 {
            (v, 0.0)
        } else {
            (v * theta.sin(), v * theta.cos())
        };
        let params = ImpactParams { v0: vy, ..*params };
        let (normal, path) = simulate_flow(&params, law, opts)?;
        if !normal.rebound {
            return Err(ObliqueError::NoRebound);
        }
        let path = path.ok_or(ObliqueError::NoFlow)?;
        Ok(NormalAt {
            params,
            v,
            angle_deg,
            vx,
            vy,
            normal,
            path,
        })
    }

    /// The normal impact as `run` gives it at v_y.
    pub fn normal(&self) -> &ImpactResponse {
        &self.normal
    }

    /// The oblique impact over this normal one; `oblique.angle_deg` must be this one's, and
    /// `samples` history samples (0: none).
    pub fn solve(
        &self,
        oblique: &Oblique,
        samples: usize,
    ) -> Result<ObliqueResponse, ObliqueError> {
        oblique.validate()?;
        if oblique.angle_deg != self.angle_deg {
            return Err(super::invalid(
                "angle",
                oblique.angle_deg,
                "must be the angle the normal impact was solved at",
            ));
        }
        let s = Scaled::new(
            oblique.friction,
            oblique.tangential_stiffness / self.params.k_p,
            oblique.inertia_factor,
        );
        let (vx_n, w_n) = (self.vx / self.vy, oblique.radius * oblique.spin / self.vy);
        let run = tangential::run(&self.path, &s, vx_n - w_n)?;
        let answer = energy::Answer {
            params: &self.params,
            oblique,
            scaled: &s,
            vx: self.vx,
            vy: self.vy,
            v: self.v,
        };
        Ok(answer.response(&self.path, run, self.normal.clone(), samples))
    }
}
