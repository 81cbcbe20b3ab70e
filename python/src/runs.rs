//! One impact: `run` (a preset), `run_normalized` and `run_params`, as `bouncelab run`; the
//! answer an `Impact` (impact.rs, its run impact_run.rs).

use crate::arguments::ball::ball_pyfunction;
use crate::impact::{Impact, impact, impact_on};
use crate::{error, history_samples, law};
use bouncelab::Ball;
use bouncelab::model::params::ImpactParams;
use pyo3::prelude::*;
use std::sync::Arc;

ball_pyfunction! {
    /// One impact of a preset, as `bouncelab run --preset NAME [--law L] [--v0 V] [--lambda L]
    /// [--zeta Z] [--params SET] [--history --samples N] [--surface NAME --surface-stiffness
    /// K_S …]` and the ball's arguments (python/src/arguments/ball.rs: `--mass` … `--z-p`,
    /// `--pressure`, `--temperature`, `--inflated-at`, `--after`, `--half-life`; `surface=`: a
    /// name or a dict of its numbers, python/src/surface.rs).
    signature = (preset="superball", law=None, v0=None, lambda_=None, zeta=None, history=false, samples=None, params=None, *, surface=None,);
    fn run<'py>(
        py,
        preset: &str,
        law: Option<&str>,
        v0: Option<f64>,
        lambda_: Option<f64>,
        zeta: Option<f64>,
        history: bool,
        samples: Option<usize>,
        params: Option<&str>,
        surface: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Py<Impact>>;
    ball choice = (preset, params, law);
    {
        let surface = crate::surface::resolve_normal(surface)?;
        let samples = history_samples(history, samples)?;
        // one parameter set twice is refused, as the command line refuses --k-r with --lambda
        choice.check_lambda_zeta(lambda_, zeta)?;
        // the conditions before λ and ζ, as the command line resolves its ball
        let mut ball = choice.resolve(v0)?;
        // λ or ζ given: a ball of its own (with neither, the ball is as `with_lambda_zeta(None,
        // None)` leaves it: checked when built); ζ beside a temperature that shifts c is
        // refused by the library's rule, the command line's (`Ball::with_lambda_zeta_at`)
        if lambda_.is_some() || zeta.is_some() {
            let temperature = choice.conditions.temperature;
            let moved = Arc::unwrap_or_clone(ball).with_lambda_zeta_at(temperature, lambda_, zeta);
            ball = Arc::new(moved.map_err(error)?);
        }
        impact_on(py, ball, surface, history, samples)
    }
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
