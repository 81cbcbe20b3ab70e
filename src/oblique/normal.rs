//! The normal half of an oblique impact, solved once and reused: what a fit of μ, K_t and κ
//! (`analysis::fit::oblique`) or a map over μ runs many tangential motions over, for the
//! normal impact does not depend on them (docs/oblique.md §1).

use super::tangential::{self, Grid};
use super::{Oblique, ObliqueError, ObliqueResponse, Scaled, energy};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{Flow, ImpactResponse, Method, SolveOptions, simulate_flow};
use std::sync::{Arc, Mutex};

/// A ball's normal impact at speed v and angle θ, with its flow.
pub struct NormalAt {
    params: ImpactParams,
    v: f64,
    angle_deg: f64,
    vx: f64,
    vy: f64,
    normal: ImpactResponse,
    path: Flow,
    /// The tangential search's grid of the last tangential motion run over this one (its step
    /// depends on K_t and κ only): a map over μ or a fit's evaluations read the flow once.
    grid: Mutex<Option<Arc<Grid>>>,
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
        // The exact flow's losses are taken as the normal motion's kinetic energy lost
        // (`energy::normal_losses`), not by the dashpot's quadrature, which was half the cost of
        // an oblique impact; `the_normal_losses_are_the_audited_ones` holds the two together.
        let exact = law == ContactLaw::Linear && opts.method != Some(Method::Numeric);
        let opts = SolveOptions {
            energy: opts.energy && !exact,
            ..*opts
        };
        let (normal, path) = simulate_flow(&params, law, &opts)?;
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
            grid: Mutex::new(None),
        })
    }

    /// The search grid for the scaled problem `s`: the one kept when its step is the same (the
    /// same points, read the same way: answers equal to the last bit, `frictions_equal_solve`).
    fn grid_for(&self, s: &Scaled) -> Arc<Grid> {
        let h = Grid::step_of(s, self.path.end());
        let mut kept = self.grid.lock().unwrap_or_else(|e| e.into_inner());
        match &*kept {
            Some(g) if g.h() == h => g.clone(),
            _ => {
                let g = Arc::new(Grid::new(&self.path, s));
                *kept = Some(g.clone());
                g
            }
        }
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
        let grid = self.grid_for(&s);
        let run = tangential::run(&self.path, &grid, &s, vx_n - w_n)?;
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
