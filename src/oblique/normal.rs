//! The normal half of an oblique impact, solved once and reused: what a fit of μ, K_t and κ
//! (`analysis::fit::oblique`) or a map over μ runs many tangential motions over, for the
//! normal impact does not depend on them (docs/oblique.md §1).

use super::energy;
use super::tangential::{self, Grid};
use super::{ClosedPath, Local, NormalMotion, Oblique, ObliqueError, ObliqueResponse, Scaled};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::exact::PathPoint;
use crate::solver::{Flow, ImpactResponse, Method, SolveError, SolveOptions, simulate_flow};
use std::sync::{Arc, Mutex};

/// A ball's normal impact at speed v and angle θ, with its flow.
pub struct NormalAt {
    params: ImpactParams,
    v: f64,
    angle_deg: f64,
    vx: f64,
    vy: f64,
    normal: ImpactResponse,
    path: Motion,
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
        let (vx, vy) = arrival(v, angle_deg)?;
        let params = ImpactParams { v0: vy, ..*params };
        // The linear law's normal motion in closed form where it answers (`closed`: a fifth of
        // the exact solver's instructions), else the solver's flow; at 90° always the solver's,
        // so that the answer is `run`'s to the last bit (tests/physics/oblique_laws.rs,
        // `angle_90_is_run_on_every_law`).
        let closed = law == ContactLaw::Linear && opts.method.is_none() && angle_deg != 90.0;
        if closed && opts.samples == 0 {
            params.validate().map_err(SolveError::from)?;
            if let Some((normal, path)) = ClosedPath::solve(&params) {
                return Ok(NormalAt {
                    params,
                    v,
                    angle_deg,
                    vx,
                    vy,
                    normal,
                    path: Motion::Closed(path),
                    grid: Mutex::new(None),
                });
            }
        }
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
            path: Motion::Flow(path),
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
        let s = Scaled::of(&self.params, oblique);
        let (vx_n, w_n) = (self.vx / self.vy, oblique.radius * oblique.spin / self.vy);
        bounded(&s, oblique, self.path.end())?;
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

/// The arrival's components (v_x, v_y) at speed `v` and `angle_deg` (0 < θ ≤ 90), or the
/// angle's refusal.
pub(super) fn arrival(v: f64, angle_deg: f64) -> Result<(f64, f64), ObliqueError> {
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
    // a normal speed below the meaningful range is the angle's doing when v is in it:
    // `--angle 1e-15` said "invalid v0: 1.2e-16" (issue 54 item 9; tests/cli/field_names.rs)
    use crate::model::params::MEANINGFUL_MIN;
    if vy < MEANINGFUL_MIN && v >= MEANINGFUL_MIN && v.is_finite() {
        return Err(super::invalid(
            "angle",
            angle_deg,
            "the normal speed v sin θ falls below 1e-15 m/s: give a larger angle",
        ));
    }
    Ok((vx, vy))
}

/// The refusal of a tangential motion whose search grid would pass [`MAX_GRID`] points: the
/// grid steps a fifth of the sticking oscillation's radian, ω̃_t = √(K_t/K_p·(1 + 1/κ)), so a
/// tiny κ or a huge K_t once asked 10⁸ points (3 GB) or more (tests/physics/oblique_bounded.rs). The
/// field named is the factor that drives ω̃_t most: 1/κ or K_t/K_p.
pub(super) fn bounded(s: &Scaled, oblique: &Oblique, tf: f64) -> Result<(), ObliqueError> {
    if Grid::steps(s, tf) <= MAX_GRID as f64 {
        return Ok(());
    }
    let reason = "too fast a sticking oscillation: √(K_t/K_p·(1 + 1/κ)) asks more than 200000 \
                  search steps in one contact (docs/oblique.md §2)";
    Err(if 1.0 / s.kappa > s.kt {
        super::invalid("inertia_factor", oblique.inertia_factor, reason)
    } else {
        super::invalid("tangential_stiffness", oblique.tangential_stiffness, reason)
    })
}

/// Most points of the tangential search's grid (24 B each: 4.8 MB, a few ms to read).
pub const MAX_GRID: usize = 200_000;

/// The normal motion a [`NormalAt`] holds: the closed form, or a solver's flow.
// one a `NormalAt`, read at every point of its impacts: kept inline, not boxed
#[allow(clippy::large_enum_variant)]
enum Motion {
    Closed(ClosedPath),
    Flow(Flow),
}

impl NormalMotion for Motion {
    fn at(&self, tau: f64) -> PathPoint {
        match self {
            Motion::Closed(c) => c.at(tau),
            Motion::Flow(f) => f.at(tau),
        }
    }
    fn end(&self) -> f64 {
        match self {
            Motion::Closed(c) => c.end(),
            Motion::Flow(f) => NormalMotion::end(f),
        }
    }
    fn kinks(&self) -> Vec<f64> {
        match self {
            Motion::Closed(c) => c.kinks(),
            Motion::Flow(f) => f.kinks(),
        }
    }
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        match self {
            Motion::Closed(c) => c.grid(h),
            Motion::Flow(f) => f.grid(h),
        }
    }
    fn local(&self, a: f64, b: f64) -> Option<Local<'_>> {
        match self {
            Motion::Closed(c) => c.local(a, b),
            Motion::Flow(f) => f.local(a, b),
        }
    }
}
