//! Oblique impacts on a surface that gives or moves (docs/oblique.md §11): the normal chain
//! with the surface in series — ball, contact, (c ∥ K_r), (K_s ∥ c_s), the surface's mass —
//! solved by the compliant solvers of `target` (docs/targets.md §4), the tangential model as
//! on the rigid plate (§1), driven by that chain's force (`tabulated`).
//!
//! What holds: at 90° without spin nothing moves tangentially, and the answer is the normal
//! impact on that surface, `collide`'s, to the last bit (its COR is the ball's rebound over
//! its arrival, the apparent COR e_A, = e for an immovable surface); on a rigid, immovable
//! surface the answer is [`super::solve_law`]'s, bit for bit (it is that call).

use super::normal::{arrival, bounded};
use super::tabulated::Tabulated;
use super::tangential::{self, Grid};
use super::{Oblique, ObliqueError, ObliqueResponse, Scaled, energy};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{History, ImpactResponse};
use crate::target::{Collision, Target, history};

/// Samples of the chain's force over the contact: the spline through them reads F̄ to
/// about 1e-10 of its peak (h⁴ with h = τ_f/4000), F̄' to about 1e-6 near the ends
/// (`tabulated::tests`).
const TABLE: usize = 4001;

/// One oblique impact of the ball (`params`, `law`) at speed `v` on the surface `target` (its
/// speed must be 0: the surface at rest), with `samples` history samples (0: none).
pub fn solve_on(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    target: &Target,
    samples: usize,
) -> Result<ObliqueResponse, ObliqueError> {
    if target.is_rigid() && target.mass == f64::INFINITY && target.speed == 0.0 {
        return super::solve_law(params, law, v, oblique, samples);
    }
    oblique.validate()?;
    if target.speed != 0.0 {
        return Err(super::invalid(
            "surface_speed",
            target.speed,
            "an oblique impact's surface is at rest",
        ));
    }
    let (vx, vy) = arrival(v, oblique.angle_deg)?;
    let normal_params = ImpactParams { v0: vy, ..*params };
    let h = history(&normal_params, law, target, vy, TABLE)?;
    if !h.collision.rebound {
        return Err(ObliqueError::NoRebound);
    }
    let w0 = params.omega0();
    let scale = params.mass * vy * w0;
    let tau_end = h.collision.contact_time.unwrap_or(f64::NAN) * w0;
    let motion = Tabulated::new(tau_end, h.force.iter().map(|f| f / scale).collect());
    let s = Scaled::of(params, oblique);
    bounded(&s, oblique, tau_end)?;
    let grid = Grid::new(&motion, &s);
    let (vx_n, w_n) = (vx / vy, oblique.radius * oblique.spin / vy);
    let run = tangential::run(&motion, &grid, &s, vx_n - w_n)?;
    let normal = normal_response(&normal_params, law, &h.collision, w0);
    let answer = energy::Answer {
        params: &normal_params,
        oblique,
        scaled: &s,
        vx,
        vy,
        v,
    };
    Ok(answer.response(&motion, run, normal, samples))
}

/// The normal impact on the surface (`collide`'s `c` of the ball `p` at v_y = `p.v0`, ω0 =
/// `w0`) as an [`ImpactResponse`], as the tangential answer and `run --surface` read it: its COR is the ball's
/// rebound speed over its arrival (the apparent COR, docs/targets.md §3), its peak force and
/// contact time the chain's; no energy audit (the losses are then ½ m v_y² (1 − e²), the
/// ball's normal kinetic energy lost, which includes what a moving surface carries away).
pub fn normal_response(
    p: &ImpactParams,
    law: ContactLaw,
    c: &Collision,
    w0: f64,
) -> ImpactResponse {
    let force = p.mass * p.v0 * w0;
    ImpactResponse {
        law,
        method: c.method,
        cor: c.apparent_cor,
        rebound: c.rebound,
        max_force: c.max_force,
        contact_time: c.contact_time,
        duration: c.contact_time.unwrap_or(f64::NAN),
        max_indentation: c.max_indentation,
        permanent_indentation: c.permanent_indentation,
        // the chain's recoil element is not reported by the compliant solvers
        element_displacement: f64::NAN,
        max_force_normalized: c.max_force / force,
        element_displacement_normalized: f64::NAN,
        contact_time_normalized: c.contact_time.map(|t| t * w0),
        normalized: p.normalized(),
        events: Vec::new(),
        energy: None,
        history: History::default(),
        steps: 0,
        stiff: false,
    }
}
