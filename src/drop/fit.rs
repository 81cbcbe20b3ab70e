//! Fitting a ball's damping to a standard's nominal COR (docs/drop.md, "The new balls"):
//! where no measured force pulse exists, the presets take their stiffness K_p and flattening
//! threshold z_p from the literature or the rules, hold λ = K_r/K_p, and fit the dashpot c so
//! that the model's COR at the standard's impact speed equals the COR that puts the ball in the
//! middle of the window (with drag, for a drop test).
//!
//! At fixed λ, e falls from 1 as ζ grows from 0, reaches a minimum, and climbs back towards 1
//! (docs/model.md §6, Fig. 2): the fit takes the smallest ζ that reaches the target (the
//! branch on which e falls), found by a scan on a geometric grid and then Brent's method.

use super::standards::{Standard, Test};
use super::{Air, DropBall, DropError, Flight, impact};
use crate::model::params::{ImpactParams, damping_for_zeta};
use crate::solver::roots::brent;

/// The COR at the standard's impact speed that puts `ball` in the middle of a two-sided
/// window, and that speed (m/s); `None` for a one-sided window (no middle).
pub fn nominal_cor(standard: &Standard, ball: &DropBall, air: Option<Air>) -> Option<(f64, f64)> {
    let [Some(lo), Some(hi)] = standard.window else {
        return None;
    };
    Some(cor_for(standard, ball, air, 0.5 * (lo + hi)))
}

/// The COR at the standard's impact speed for which the standard measures `measured` (a
/// rebound height in the standard's convention, or a COR), and that speed (m/s).
pub fn cor_for(
    standard: &Standard,
    ball: &DropBall,
    air: Option<Air>,
    measured: f64,
) -> (f64, f64) {
    match standard.test {
        Test::Drop { rebound_ref, .. } => {
            let flight = Flight::new(ball.params.mass, ball.radius, air);
            let release = standard.release_height(ball.radius).unwrap_or(f64::NAN);
            let v_in = flight.fall_speed(release);
            let rebound = measured - rebound_ref.offset(ball.radius);
            (flight.launch_speed_for(rebound) / v_in, v_in)
        }
        Test::Cor { speed } => (measured, speed),
    }
}

/// Grid of the scan: ζ from 1e-3 by factors of 1.25 up to 1e3.
const ZETA_START: f64 = 1e-3;
const ZETA_STEP: f64 = 1.25;
const ZETA_END: f64 = 1e3;

/// The damping c (kg/s) for which `ball`, with K_r = λ K_p, has COR `target` at `speed`:
/// the smallest such ζ (module docs). Errors when no ζ on the grid reaches the target.
pub fn fit_damping(
    ball: &DropBall,
    lambda: f64,
    speed: f64,
    target: f64,
) -> Result<ImpactParams, DropError> {
    let p = ball.params;
    let at = |zeta: f64| ImpactParams {
        k_r: lambda * p.k_p,
        damping: damping_for_zeta(p.mass, p.k_p, zeta),
        ..p
    };
    let cor = |zeta: f64| -> Result<f64, DropError> {
        let b = DropBall {
            params: at(zeta),
            ..*ball
        };
        Ok(impact(&b, speed)?.cor - target)
    };
    let (mut z0, mut g0) = (ZETA_START, cor(ZETA_START)?);
    while z0 < ZETA_END {
        let z1 = z0 * ZETA_STEP;
        let g1 = cor(z1)?;
        if g0 > 0.0 && g1 <= 0.0 {
            // solve in ln ζ: e is smooth in it over the decades the grid spans
            let zeta = brent(
                |l| cor(l.exp()).unwrap_or(f64::NAN),
                z0.ln(),
                z1.ln(),
                g0,
                g1,
                1e-12,
            )
            .exp();
            return Ok(at(zeta));
        }
        (z0, g0) = (z1, g1);
    }
    Err(DropError::Input {
        field: "cor",
        value: target,
        reason: "out of reach of this ball at any damping",
    })
}
