//! One impact: `run` (a preset), `run_normalized` and `run_params`, as `bouncelab run`; the
//! answer an `Impact` (impact.rs, its run impact_run.rs).

use crate::impact::{Impact, impact, impact_on};
use crate::{
    error, history_samples, law, overridden_ball, overrides, shared_preset_ball, value_error,
};
use bouncelab::Ball;
use bouncelab::model::params::ImpactParams;
use pyo3::prelude::*;
use std::sync::Arc;

/// One impact of a preset, as `bouncelab run --preset NAME [--law L] [--v0 V] [--lambda L]
/// [--zeta Z] [--params SET] [--history --samples N] [--mass M] [--radius R] [--k-p K_P]
/// [--damping C] [--k-r K_R] [--z-p Z_P] [--pressure P] [--temperature T] [--inflated-at T0]
/// [--surface NAME --surface-stiffness K_S …]`
/// (`pressure` in Pa, or a string with its unit, "0.8bar"; `surface=`: a name or a dict of its
/// numbers, python/src/surface.rs).
#[pyfunction]
#[pyo3(signature = (preset="superball", law=None, v0=None, lambda_=None, zeta=None, history=false, samples=None, params=None, *, mass=None, radius=None, k_p=None, damping=None, k_r=None, z_p=None, pressure=None, temperature=None, inflated_at=None, surface=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn run(
    py: Python<'_>,
    preset: &str,
    law: Option<&str>,
    v0: Option<f64>,
    lambda_: Option<f64>,
    zeta: Option<f64>,
    history: bool,
    samples: Option<usize>,
    params: Option<&str>,
    mass: Option<f64>,
    radius: Option<f64>,
    k_p: Option<f64>,
    damping: Option<f64>,
    k_r: Option<f64>,
    z_p: Option<f64>,
    pressure: Option<&Bound<'_, PyAny>>,
    temperature: Option<f64>,
    inflated_at: Option<f64>,
    surface: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<Impact>> {
    let (surface, _) = crate::surface::resolve(surface)?;
    let samples = history_samples(history, samples)?;
    let spec = crate::preset_balls::conditions(pressure, temperature, inflated_at)?;
    let set = overrides(mass, radius, k_p, damping, k_r, z_p);
    // one parameter set twice is refused, as the command line refuses --k-r with --lambda
    if k_r.is_some() && lambda_.is_some() {
        return Err(value_error(
            "k_r and lambda_ both set K_r: give one of them".into(),
        ));
    }
    if damping.is_some() && zeta.is_some() {
        return Err(value_error(
            "damping and zeta both set c: give one of them".into(),
        ));
    }
    let mut ball = match (v0, set.any()) {
        (None, false) => shared_preset_ball(preset, params, law)?,
        _ => Arc::new(overridden_ball(preset, params, law, v0, &set)?),
    };
    // the conditions before λ and ζ, as the command line resolves its ball
    ball = crate::preset_balls::at_conditions(ball, &spec)?;
    // λ or ζ given: a ball of its own (with neither, the ball is as `with_lambda_zeta(None,
    // None)` leaves it: checked when built)
    if lambda_.is_some() || zeta.is_some() {
        let moved = Arc::unwrap_or_clone(ball).with_lambda_zeta(lambda_, zeta);
        ball = Arc::new(moved.map_err(error)?);
    }
    impact_on(py, ball, surface, history, samples)
}

/// One impact of the normalized ball (m = K_p = v0 = 1), as `bouncelab run --normalized`.
#[pyfunction]
#[pyo3(signature = (lambda_=1.0, zeta=0.1, zp_bar=None, law="linear", history=false, samples=None))]
pub(crate) fn run_normalized(
    py: Python<'_>,
    lambda_: f64,
    zeta: f64,
    zp_bar: Option<f64>,
    law: &str,
    history: bool,
    samples: Option<usize>,
) -> PyResult<Py<Impact>> {
    let samples = history_samples(history, samples)?;
    let ball = Ball::normalized(lambda_, zeta, zp_bar, self::law(law)?).map_err(error)?;
    impact(py, Arc::new(ball), history, samples)
}

/// One impact of a ball given by its parameters, SI units. `z_p = inf` (the default) is no
/// flattening; `k_h` defaults to the Hertz stiffness that meets K_p at z_p (Eq. 16).
#[pyfunction]
#[pyo3(signature = (*, m, k_p, c, k_r, v0, z_p=f64::INFINITY, k_h=None, law="linear", history=false, samples=None))]
// help()'s signature with z_p's default as Python reads 1e999: inf (pyo3 writes "..." for
// f64::INFINITY; test_the_stub_and_help_give_each_function_as_it_is)
#[pyo3(
    text_signature = "(*, m, k_p, c, k_r, v0, z_p=1e999, k_h=None, law='linear', history=False, samples=None)"
)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn run_params(
    py: Python<'_>,
    m: f64,
    k_p: f64,
    c: f64,
    k_r: f64,
    v0: f64,
    z_p: f64,
    k_h: Option<f64>,
    law: &str,
    history: bool,
    samples: Option<usize>,
) -> PyResult<Py<Impact>> {
    let samples = history_samples(history, samples)?;
    let k_h = k_h.unwrap_or_else(|| {
        ImpactParams::k_h_matching(k_p, if z_p.is_finite() { z_p } else { 1.0 })
    });
    let params = ImpactParams {
        mass: m,
        k_p,
        damping: c,
        k_r,
        z_p,
        k_h,
        v0,
    };
    let ball = Ball::from_params(params, self::law(law)?).map_err(error)?;
    impact(py, Arc::new(ball), history, samples)
}
