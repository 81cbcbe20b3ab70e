//! What an oblique impact gives back, SI units (docs/oblique.md §3–4): the outgoing motion, the
//! energy's balance and, when asked for, the sampled histories.

use super::Phase;
use crate::solver::ImpactResponse;
use serde::Serialize;

/// The outgoing motion and what happened in contact, SI units (docs/oblique.md §3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ObliqueResponse {
    /// Incoming speed |v| (m/s).
    pub v_in: f64,
    /// Incoming angle to the surface (degrees).
    pub angle_in_deg: f64,
    /// Incoming spin ω (rad/s, > 0 topspin).
    pub spin_in: f64,
    /// v cos θ (m/s).
    pub vx_in: f64,
    /// v sin θ (m/s), toward the surface.
    pub vy_in: f64,
    /// Outgoing speed (m/s).
    pub v_out: f64,
    /// Outgoing angle to the surface, atan2(vy_out, vx_out) (degrees).
    pub angle_out_deg: f64,
    /// Outgoing spin (rad/s).
    pub spin_out: f64,
    /// Outgoing tangential speed (m/s).
    pub vx_out: f64,
    /// Outgoing normal speed (m/s), away from the surface.
    pub vy_out: f64,
    /// vy_out/vy_in: the normal impact's COR.
    pub cor_normal: f64,
    /// Cross's e_x = −v_c,out/v_c,in (v_c = v_x − Rω); `None` when the ball arrives rolling.
    pub cor_tangential: Option<f64>,
    /// |vx_in − vx_out|/(vy_in + vy_out), what a court test measures.
    pub apparent_friction: f64,
    /// Whether the contact point slid from first contact to separation.
    pub slid_throughout: bool,
    /// Time spent sticking (s).
    pub grip_time: f64,
    /// Contact time (s).
    pub contact_time: f64,
    /// Peak normal force (N).
    pub max_normal_force: f64,
    /// Peak |F_t| (N).
    pub max_friction_force: f64,
    /// Where the energy went.
    pub energy: ObliqueEnergy,
    /// The stick and slip phases, in order (τ in the normal impact's units).
    #[serde(skip)]
    pub phases: Vec<Phase>,
    /// The normal impact as `run` gives it at v_y.
    #[serde(skip)]
    pub normal: ImpactResponse,
    /// The sampled histories, when asked for: `t`, `normal_force`, `friction_force`,
    /// `slip_velocity`, `spin` beside the other keys.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub history: Option<ObliqueHistory>,
}

/// The energy of an oblique impact (J): what came in, what went out, and where the rest went;
/// `residual` is |in − out − losses| / in (docs/oblique.md §4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ObliqueEnergy {
    /// ½ m v² at arrival.
    pub translational_in: f64,
    /// ½ I ω² at arrival.
    pub rotational_in: f64,
    /// ½ m v² at separation.
    pub translational_out: f64,
    /// ½ I ω² at separation.
    pub rotational_out: f64,
    /// The normal model's losses: dashpot, contact (flattening) and what the recoil spring
    /// keeps (docs/model.md §8's audit).
    pub normal_dissipation: f64,
    /// Work of friction while sliding.
    pub friction_dissipation: f64,
    /// ½ K_t u² left in the tangential spring at separation (less what LAMMPS's reset put in
    /// it at first contact with a dashpot, ½ c_t² v_c,in²/K_t: docs/oblique.md §4).
    pub tangential_spring: f64,
    /// What the tangential dashpot c_t took while the point stuck, ∫c_t v_c² dt; present only
    /// with a dashpot (JSON key `tangential_damping` then).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential_damping: Option<f64>,
    /// |in − out − losses| / in.
    pub residual: f64,
}

/// The histories of an oblique impact, SI, evenly spaced in time over the contact.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ObliqueHistory {
    /// t (s).
    pub t: Vec<f64>,
    /// F_n (N).
    pub normal_force: Vec<f64>,
    /// F_t (N), the surface's force on the ball along +x.
    pub friction_force: Vec<f64>,
    /// v_c = v_x − Rω (m/s), the contact point's slip velocity.
    pub slip_velocity: Vec<f64>,
    /// ω (rad/s).
    pub spin: Vec<f64>,
}
