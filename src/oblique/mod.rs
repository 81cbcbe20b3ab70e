//! Oblique impacts: a ball arriving at an angle to the surface and spinning, with friction at
//! the contact (docs/oblique.md). The normal motion is today's impact unchanged, run at the
//! normal speed v_y = v sin θ; the tangential motion is the Cundall–Strack linear_history
//! model: a spring K_t on the contact point's tangential displacement u in parallel with a
//! dashpot c_t (0 unless given), their force capped by Coulomb friction μ F_n.
//!
//! The answer comes from [`solve`]: the exact normal flow of the linear law
//! (`solver::exact::NormalPath`) with the tangential motion in closed form phase by phase
//! (`tangential`): a harmonic oscillator in u while the point sticks, the normal impulse while
//! it slides, the switches root-found. [`mod@reference`] integrates the same model independently
//! (DOP853 with events at every switch); tests/physics/oblique.rs holds the two together.

mod closed;
pub mod court;
mod damped;
mod energy;
mod frictions;
mod input;
mod modes;
mod motion;
mod normal;
pub mod reference;
mod response;
mod surface;
mod tabulated;
mod tangential;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_surface;

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{Flow, SolveOptions, simulate_flow};
pub use closed::ClosedPath;
pub use frictions::solve_frictions;
use input::invalid;
pub use input::{Oblique, ObliqueError, ObliqueInvalid, mindlin_ratio};
pub use motion::{Local, NormalMotion};
pub use normal::NormalAt;
pub use response::{ObliqueEnergy, ObliqueHistory, ObliqueResponse};
pub use surface::{normal_response, solve_on};
pub use tangential::{Mode, Phase};

/// Most phases (stick or slip) one impact may switch through before it is called unresolved.
pub const MAX_PHASES: usize = 100_000;

/// The tangential problem in the normal impact's units (docs/model.md §5 with v0 = v_y):
/// τ = ω0 t, speeds over v_y, u ω0/v_y, forces over m v_y ω0.
#[derive(Debug, Clone, Copy)]
pub struct Scaled {
    /// μ.
    pub mu: f64,
    /// k̃ = K_t/K_p.
    pub kt: f64,
    /// κ.
    pub kappa: f64,
    /// g = 1 + 1/κ: dṽ_c/dτ = g F̃_t.
    pub g: f64,
    /// ω̃_t = √(k̃ g), the sticking oscillation's undamped rate.
    pub omega_t: f64,
    /// c̃ = c_t/(m ω0), the tangential dashpot (0: none).
    pub ct: f64,
    /// β = g c̃/2: while sticking ũ'' + 2β ũ' + ω̃_t² ũ = 0.
    pub beta: f64,
}

impl Scaled {
    /// The scaled problem of μ, k̃ = K_t/K_p and κ.
    pub fn new(mu: f64, kt: f64, kappa: f64) -> Scaled {
        Scaled::damped(mu, kt, 0.0, kappa)
    }

    /// The scaled problem with a tangential dashpot c̃ = c_t/(m ω0) (docs/oblique.md §1).
    pub fn damped(mu: f64, kt: f64, ct: f64, kappa: f64) -> Scaled {
        let g = 1.0 + 1.0 / kappa;
        Scaled {
            mu,
            kt,
            kappa,
            g,
            omega_t: (kt * g).sqrt(),
            ct,
            beta: g * ct / 2.0,
        }
    }

    /// The fastest rate of the sticking motion: ω̃_t while it oscillates (β ≤ ω̃_t), else the
    /// overdamped fast root β + √(β² − ω̃_t²).
    pub fn stick_rate(&self) -> f64 {
        if self.beta <= self.omega_t {
            self.omega_t
        } else {
            self.beta + (self.beta * self.beta - self.omega_t * self.omega_t).sqrt()
        }
    }
}

impl Scaled {
    /// The scaled problem of `oblique` over the normal impact of `params`: k̃ = K_t/K_p,
    /// c̃ = c_t/(m ω0) (F̃ = F/(m v_y ω0), so c_t v_c scales to c̃ ṽ_c).
    pub fn of(params: &ImpactParams, oblique: &Oblique) -> Scaled {
        Scaled::damped(
            oblique.friction,
            oblique.tangential_stiffness / params.k_p,
            oblique.tangential_damping / (params.mass * params.omega0()),
            oblique.inertia_factor,
        )
    }
}

/// One oblique impact of a ball with parameters `params` (their `v0` is ignored: the speed is
/// `v`), on the linear law, with `samples` history samples (0: none).
pub fn solve(
    params: &ImpactParams,
    v: f64,
    oblique: &Oblique,
    samples: usize,
) -> Result<ObliqueResponse, ObliqueError> {
    solve_law(params, ContactLaw::Linear, v, oblique, samples)
}

/// One oblique impact as [`solve`], on any contact law: the normal motion is `run`'s (the
/// exact flow for the linear law, the adaptive solver for the others, docs/oblique.md §2).
pub fn solve_law(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    samples: usize,
) -> Result<ObliqueResponse, ObliqueError> {
    let opts = SolveOptions::default().with_energy();
    solve_with(params, law, v, oblique, samples, &opts)
}

/// [`solve_law`] with the normal solver's options (tests run the linear law adaptively).
pub(crate) fn solve_with(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    samples: usize,
    opts: &SolveOptions,
) -> Result<ObliqueResponse, ObliqueError> {
    oblique.validate()?;
    NormalAt::with_options(params, law, v, oblique.angle_deg, opts)?.solve(oblique, samples)
}

/// What the reference integration starts from: the components of the arrival, the normal
/// flow and the scaled tangential problem.
pub(crate) struct Prepared {
    pub vx: f64,
    pub vy: f64,
    pub path: Flow,
    pub scaled: Scaled,
}

pub(crate) fn prepare(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
) -> Result<Prepared, ObliqueError> {
    oblique.validate()?;
    let theta = oblique.angle_deg.to_radians();
    // at 90° the normal impact is the very one `run` solves: v_y = v, not v sin(π/2)
    let (vy, vx) = if oblique.angle_deg == 90.0 {
        (v, 0.0)
    } else {
        (v * theta.sin(), v * theta.cos())
    };
    let normal_params = ImpactParams { v0: vy, ..*params };
    let opts = SolveOptions::default().with_energy();
    let (normal, path) = simulate_flow(&normal_params, law, &opts)?;
    if !normal.rebound {
        return Err(ObliqueError::NoRebound);
    }
    let path = path.ok_or(ObliqueError::NoFlow)?;
    let scaled = Scaled::of(params, oblique);
    Ok(Prepared {
        vx,
        vy,
        path,
        scaled,
    })
}
