//! `bouncelab._native`: the Python bindings of the bouncelab library (the package `bouncelab`
//! re-exports them; `bouncelab/__init__.pyi` types them). Keyword arguments in, SI units, the
//! names of the command line's JSON and CSV output, numpy arrays out. Every check and message
//! is the library's, which is the command line's: an error raises `ValueError` carrying the
//! line `bouncelab: error: …` would print (`NoAnswerError`, a `ValueError`, for an impact the
//! solver could not bring to an end: the command line's exit code 1).

use bouncelab::analysis::fit::Fit;
use bouncelab::api::{self, FitReport};
use bouncelab::catalog::{Catalog, Entry, Origin};
use bouncelab::model::params::ImpactParams;
use bouncelab::preset::ParamSource;
use bouncelab::{Ball, BallError, ContactLaw};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

mod arrays;
mod batch;
mod catalog_cache;
mod collide;
mod fits;
mod impact;
mod interrupt;
mod mc;
mod oblique;
mod oblique_fit;

use impact::{Impact, impact, interval_columns};

create_exception!(
    bouncelab,
    NoAnswerError,
    PyValueError,
    "The solver ran out of its step budget before the ball left or came to rest: no answer \
     (the command line's exit code 1). A nearby λ or ζ may answer."
);

/// A library error as a Python exception with the command line's message (control
/// characters made visible, as the command line shows them: bouncelab::sanitize).
fn error(e: BallError) -> PyErr {
    let message = bouncelab::sanitize::line(&e.to_string()).into_owned();
    if e.is_no_answer() {
        NoAnswerError::new_err(message)
    } else {
        PyValueError::new_err(message)
    }
}

fn value_error(message: String) -> PyErr {
    PyValueError::new_err(bouncelab::sanitize::line(&message).into_owned())
}

/// History samples when `history` is asked for; `samples` without it is refused, as the
/// command line refuses `--samples` without `--history`.
fn history_samples(history: bool, samples: Option<usize>) -> PyResult<usize> {
    match (history, samples) {
        (false, Some(n)) => Err(value_error(format!(
            "samples={n} applies only with history=True (the command line's --samples needs \
             --history)"
        ))),
        (_, n) => Ok(n.unwrap_or(400)),
    }
}

/// A contact law by its command-line name: linear, elastic-plastic, hertz.
fn law(name: &str) -> PyResult<ContactLaw> {
    name.parse::<ContactLaw>().map_err(value_error)
}

/// A parameter set by its command-line name: adopted, materials.
fn source(name: &str) -> PyResult<ParamSource> {
    match name {
        "adopted" => Ok(ParamSource::Adopted),
        "materials" => Ok(ParamSource::Materials),
        _ => Err(value_error(format!(
            "unknown parameter set '{name}' (expected adopted or materials)"
        ))),
    }
}

/// The presets the command line knows: the embedded ones and the user's folder
/// (`$XDG_CONFIG_HOME/bouncelab/presets`).
fn load_catalog() -> PyResult<Arc<Catalog>> {
    // kept between calls while the folder is unchanged (catalog_cache.rs)
    catalog_cache::user_catalog().map_err(|e| error(BallError::Catalog(e)))
}

fn entry<'c>(cat: &'c Catalog, name: &str) -> PyResult<&'c Entry> {
    cat.get(name).map_err(|e| error(BallError::Catalog(e)))
}

/// A preset ball with the command line's `--params`, `--law`, `--v0` applied.
fn preset_ball(
    preset: &str,
    params: Option<&str>,
    law_name: Option<&str>,
    v0: Option<f64>,
) -> PyResult<Ball> {
    if v0.is_none() {
        return shared_preset_ball(preset, params, law_name).map(Arc::unwrap_or_clone);
    }
    let cat = load_catalog()?;
    let entry = entry(&cat, preset)?;
    let params = params.map(source).transpose()?;
    let law_ = law_name.map(law).transpose()?;
    Ball::from_entry(entry, params, law_, v0).map_err(error)
}

/// A preset ball with the command line's `--params` and `--law` applied, at the preset's
/// speed: built once while the catalog holds (catalog_cache.rs), the same ball, checked the
/// same way, as [`preset_ball`] builds.
fn shared_preset_ball(
    preset: &str,
    params: Option<&str>,
    law_name: Option<&str>,
) -> PyResult<Arc<Ball>> {
    let choose = || {
        let params = params.map(source).transpose()?;
        Ok((params, law_name.map(law).transpose()?))
    };
    catalog_cache::preset_ball(preset, choose, error)
}

/// A list of floats from a numpy array, a sequence, or one number.
fn floats(obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArray1<'_, f64>>() {
        return Ok(a.as_array().to_vec());
    }
    if let Ok(x) = obj.extract::<f64>() {
        return Ok(vec![x]);
    }
    obj.extract::<Vec<f64>>()
}

fn array<'py>(py: Python<'py>, v: Vec<f64>) -> Py<PyArray1<f64>> {
    PyArray1::from_vec(py, v).unbind()
}

/// One impact of a preset, as `bouncelab run --preset NAME [--law L] [--v0 V] [--lambda L]
/// [--zeta Z] [--params SET] [--history --samples N]`.
#[pyfunction]
#[pyo3(signature = (preset="superball", law=None, v0=None, lambda_=None, zeta=None, history=false, samples=None, params=None))]
#[allow(clippy::too_many_arguments)]
fn run(
    py: Python<'_>,
    preset: &str,
    law: Option<&str>,
    v0: Option<f64>,
    lambda_: Option<f64>,
    zeta: Option<f64>,
    history: bool,
    samples: Option<usize>,
    params: Option<&str>,
) -> PyResult<Py<Impact>> {
    let samples = history_samples(history, samples)?;
    let mut ball = match v0 {
        None => shared_preset_ball(preset, params, law)?,
        Some(_) => Arc::new(preset_ball(preset, params, law, v0)?),
    };
    // λ or ζ given: a ball of its own (with neither, the ball is as `with_lambda_zeta(None,
    // None)` leaves it: checked when built)
    if lambda_.is_some() || zeta.is_some() {
        let moved = Arc::unwrap_or_clone(ball).with_lambda_zeta(lambda_, zeta);
        ball = Arc::new(moved.map_err(error)?);
    }
    impact(py, ball, history, samples)
}

/// One impact of the normalized ball (m = K_p = v0 = 1), as `bouncelab run --normalized`.
#[pyfunction]
#[pyo3(signature = (lambda_=1.0, zeta=0.1, zp_bar=None, law="linear", history=false, samples=None))]
fn run_normalized(
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
#[allow(clippy::too_many_arguments)]
fn run_params(
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

/// The presets, as `bouncelab presets --format json`: a list of dicts with name, origin,
/// description, law, parameters, lambda, zeta, v0.
#[pyfunction]
fn presets(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
    let cat = load_catalog()?;
    cat.entries()
        .iter()
        .map(|e| {
            let p = &e.preset;
            let n = p.params().normalized();
            let d = PyDict::new(py);
            d.set_item("name", &p.name)?;
            d.set_item(
                "origin",
                match &e.origin {
                    Origin::Embedded => "embedded".to_string(),
                    Origin::File(f) => f.display().to_string(),
                },
            )?;
            d.set_item("description", &p.description)?;
            d.set_item("law", p.law.name())?;
            d.set_item("parameters", p.parameters.name())?;
            d.set_item("lambda", n.lambda)?;
            d.set_item("zeta", n.zeta)?;
            d.set_item("v0", p.measured.v0)?;
            d.set_item("radius", p.measured.radius)?;
            d.set_item("poisson_ratio", p.material.poisson)?;
            let kappa = p.measured.inertia_factor;
            d.set_item(
                "inertia_factor",
                kappa.unwrap_or(bouncelab::api::SOLID_INERTIA_FACTOR),
            )?;
            Ok(d)
        })
        .collect()
}

fn none_as_nan(x: Option<f64>) -> f64 {
    x.unwrap_or(f64::NAN)
}

/// COR, F̄_m and τ_f against ζ for each λ on the normalized ball, as `bouncelab sweep zeta`:
/// a dict of numpy arrays with the CSV's columns (lambda, zeta, cor, max_force_normalized,
/// contact_time_normalized; NaN where the ball does not rebound), rows grouped by λ. The GIL
/// is released while the points run (in parallel).
#[pyfunction]
#[pyo3(signature = (lambdas, zetas, law="linear"))]
fn sweep_zeta<'py>(
    py: Python<'py>,
    lambdas: &Bound<'py, PyAny>,
    zetas: &Bound<'py, PyAny>,
    law: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let (lambdas, zetas, law) = (floats(lambdas)?, floats(zetas)?, self::law(law)?);
    let rows = interrupt::detach_watched(py, |w| {
        bouncelab::api::sweep_zeta_watched(&lambdas, &zetas, law, w)
    })?;
    let col = |f: fn(&bouncelab::analysis::sweep::ZetaPoint) -> f64| {
        array(py, rows.iter().map(f).collect())
    };
    let d = PyDict::new(py);
    d.set_item("lambda", col(|r| r.lambda))?;
    d.set_item("zeta", col(|r| r.zeta))?;
    d.set_item("cor", col(|r| r.cor))?;
    d.set_item("max_force_normalized", col(|r| r.max_force_normalized))?;
    d.set_item(
        "contact_time_normalized",
        col(|r| none_as_nan(r.contact_time_normalized)),
    )?;
    Ok(d)
}

/// COR, peak force, contact time and permanent indentation against impact speed for a preset,
/// as `bouncelab sweep velocity`: a dict of numpy arrays with the CSV's columns (v0, cor,
/// max_force, contact_time, permanent_indentation; NaN contact_time where the ball does not
/// rebound). The GIL is released while the speeds run (in parallel).
#[pyfunction]
#[pyo3(signature = (preset="superball", speeds=None, law=None, params=None))]
fn sweep_velocity<'py>(
    py: Python<'py>,
    preset: &str,
    speeds: Option<&Bound<'py, PyAny>>,
    law: Option<&str>,
    params: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let ball = preset_ball(preset, params, law, None)?;
    let speeds = match speeds {
        Some(s) => floats(s)?,
        // the command line's default: 60 speeds from 0.1 to 3 times the preset's
        None => {
            bouncelab::analysis::sweep::lin_space(0.1 * ball.params.v0, 3.0 * ball.params.v0, 60)
        }
    };
    let rows = interrupt::detach_watched(py, |w| ball.sweep_velocity_watched(&speeds, w))?;
    let col = |f: fn(&bouncelab::analysis::sweep::VelocityPoint) -> f64| {
        array(py, rows.iter().map(f).collect())
    };
    let d = PyDict::new(py);
    d.set_item("v0", col(|r| r.v0))?;
    d.set_item("cor", col(|r| r.cor))?;
    d.set_item("max_force", col(|r| r.max_force))?;
    d.set_item("contact_time", col(|r| none_as_nan(r.contact_time)))?;
    d.set_item("permanent_indentation", col(|r| r.permanent_indentation))?;
    // a fitted preset's 95 % intervals at each speed (docs/fitting.md), as the CSV's columns
    if let Some(fit) = ball.fit.as_ref().filter(|f| api::holds(&ball.params, f)) {
        let bands = py
            .detach(|| {
                rows.iter()
                    .map(|r| {
                        let p = ImpactParams {
                            v0: r.v0,
                            ..ball.params
                        };
                        let i = api::intervals(&p, ball.law, fit)?;
                        let t = i.contact_time_ci95.unwrap_or([f64::NAN; 2]);
                        Ok([i.cor_ci95, i.max_force_ci95, t])
                    })
                    .collect::<Result<Vec<_>, BallError>>()
            })
            .map_err(error)?;
        interval_columns(py, &d, ["cor", "max_force", "contact_time"], &bands)?;
    }
    Ok(d)
}

/// The recoil spring K_r (and λ) that makes the model's COR equal a measured one, at the
/// preset's ζ, z_p and v0 (or the `v0` given), as `bouncelab fit --cor E`: a dict with the
/// keys of `bouncelab fit --format json`.
#[pyfunction]
#[pyo3(signature = (cor, preset="superball", v0=None, law=None, params=None))]
fn fit<'py>(
    py: Python<'py>,
    cor: f64,
    preset: &str,
    v0: Option<f64>,
    law: Option<&str>,
    params: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let ball = preset_ball(preset, params, law, v0)?;
    let f: Fit = py.detach(|| ball.fit_cor(cor)).map_err(error)?;
    let r = FitReport::new(&ball, cor, &f);
    let d = PyDict::new(py);
    d.set_item("preset", r.ball.preset)?;
    d.set_item("origin", r.ball.origin)?;
    d.set_item("parameters", r.ball.parameters)?;
    d.set_item("law", r.ball.law)?;
    d.set_item("v0", r.v0)?;
    d.set_item("target_cor", r.target_cor)?;
    d.set_item("k_r", r.k_r)?;
    d.set_item("lambda", r.lambda)?;
    d.set_item("zeta", r.zeta)?;
    d.set_item("cor", r.cor)?;
    d.set_item("k_p", r.k_p)?;
    d.set_item("preset_k_r", r.preset_k_r)?;
    d.set_item("preset_lambda", r.preset_lambda)?;
    Ok(d)
}

/// A preset ball dropped onto a rigid plate, bounce by bounce, as `bouncelab drop` (without
/// `--standard`): a dict with `height`, `drag` and `bounces`, the latter a dict of numpy arrays
/// with the JSON's per-bounce keys (v_in, v_out, cor, rebound_height, contact_time, max_force,
/// t_start), one entry a bounce.
#[pyfunction(name = "drop")]
#[pyo3(signature = (preset="superball", height=1.0, bounces=10, min_rebound=0.001, drag=true, drag_coefficient=None, air_density=None, law=None, params=None))]
#[allow(clippy::too_many_arguments)]
fn drop_test<'py>(
    py: Python<'py>,
    preset: &str,
    height: f64,
    bounces: usize,
    min_rebound: f64,
    drag: bool,
    drag_coefficient: Option<f64>,
    air_density: Option<f64>,
    law: Option<&str>,
    params: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    use bouncelab::drop::{Air, Bounce, DropSetup};
    if !drag && (drag_coefficient.is_some() || air_density.is_some()) {
        // as the command line refuses --no-drag with --drag-coefficient or --air-density
        return Err(value_error(
            "drag=False cannot be used with drag_coefficient or air_density".into(),
        ));
    }
    let ball = preset_ball(preset, params, law, None)?;
    let air = drag.then(|| Air {
        density: air_density.unwrap_or(Air::default().density),
        drag_coefficient: drag_coefficient.unwrap_or(Air::default().drag_coefficient),
    });
    let setup = DropSetup {
        height,
        air,
        bounces,
        min_rebound,
    };
    let run = interrupt::detach_watched(py, |w| ball.drop_test_watched(&setup, w))?;
    let col = |f: fn(&Bounce) -> f64| array(py, run.bounces.iter().map(f).collect());
    let b = PyDict::new(py);
    b.set_item("v_in", col(|r| r.v_in))?;
    b.set_item("v_out", col(|r| r.v_out))?;
    b.set_item("cor", col(|r| r.cor))?;
    b.set_item("rebound_height", col(|r| r.rebound_height))?;
    b.set_item("contact_time", col(|r| r.contact_time))?;
    b.set_item("max_force", col(|r| r.max_force))?;
    b.set_item("t_start", col(|r| r.t_start))?;
    if let Some(bands) =
        interrupt::detach_watched(py, |w| ball.drop_intervals_watched(&setup, w).transpose())?
    {
        let names = ["cor", "max_force", "contact_time", "rebound_height"];
        interval_columns(py, &b, names, &bands)?;
    }
    let d = PyDict::new(py);
    d.set_item("height", run.setup.height)?;
    d.set_item("drag", run.drag())?;
    d.set_item("bounces", b)?;
    d.set_item("warnings", ball.drop_warnings(&run).map_err(error)?)?;
    Ok(d)
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Impact>()?;
    m.add_class::<collide::Collision>()?;
    m.add_function(wrap_pyfunction!(collide::collide, m)?)?;
    m.add_class::<oblique::ObliqueImpact>()?;
    m.add_function(wrap_pyfunction!(oblique::oblique, m)?)?;
    m.add("NoAnswerError", m.py().get_type::<NoAnswerError>())?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(run_normalized, m)?)?;
    m.add_function(wrap_pyfunction!(run_params, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_zeta, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_velocity, m)?)?;
    m.add_function(wrap_pyfunction!(fit, m)?)?;
    m.add_function(wrap_pyfunction!(drop_test, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_trace, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_cor_table, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_drops, m)?)?;
    m.add_function(wrap_pyfunction!(oblique_fit::fit_oblique, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo, m)?)?;
    m.add_function(wrap_pyfunction!(arrays::impacts, m)?)?;
    m.add_function(wrap_pyfunction!(batch::batch, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_chunk, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_merge, m)?)?;
    Ok(())
}
