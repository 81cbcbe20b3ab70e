//! The presets the Python calls take their balls from: the user's catalog (kept between calls,
//! catalog_cache.rs), a preset's ball with the caller's choices, and `presets()`.

use crate::{catalog_cache, error, law, source};
use bouncelab::api::Overrides;
use bouncelab::catalog::{Catalog, Entry, Origin};
use bouncelab::{Ball, BallError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::Arc;

/// The presets the command line knows: the embedded ones and the user's folder
/// (`$XDG_CONFIG_HOME/bouncelab/presets`).
pub(crate) fn load_catalog() -> PyResult<Arc<Catalog>> {
    // kept between calls while the folder is unchanged (catalog_cache.rs)
    catalog_cache::user_catalog().map_err(|e| error(BallError::Catalog(e)))
}

pub(crate) fn entry<'c>(cat: &'c Catalog, name: &str) -> PyResult<&'c Entry> {
    cat.get(name).map_err(|e| error(BallError::Catalog(e)))
}

/// A preset ball with the command line's `--params`, `--law`, `--v0` applied.
pub(crate) fn preset_ball(
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

/// The command line's `--mass`, `--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p` from the
/// keyword arguments of the same names (SI units; `None` keeps the preset's).
pub(crate) fn overrides(
    mass: Option<f64>,
    radius: Option<f64>,
    k_p: Option<f64>,
    damping: Option<f64>,
    k_r: Option<f64>,
    z_p: Option<f64>,
) -> Overrides {
    Overrides {
        mass,
        radius,
        k_p,
        damping,
        k_r,
        z_p,
    }
}

/// [`preset_ball`] with parameter overrides set over the preset's, each checked and named as
/// the command line checks them (`Ball::from_entry_with`).
pub(crate) fn overridden_ball(
    preset: &str,
    params: Option<&str>,
    law_name: Option<&str>,
    v0: Option<f64>,
    set: &Overrides,
) -> PyResult<Ball> {
    if !set.any() {
        return preset_ball(preset, params, law_name, v0);
    }
    let cat = load_catalog()?;
    let entry = entry(&cat, preset)?;
    let params = params.map(source).transpose()?;
    let law_ = law_name.map(law).transpose()?;
    Ball::from_entry_with(entry, params, law_, v0, set).map_err(error)
}

/// A preset ball with the command line's `--params` and `--law` applied, at the preset's
/// speed: built once while the catalog holds (catalog_cache.rs), the same ball, checked the
/// same way, as [`preset_ball`] builds.
pub(crate) fn shared_preset_ball(
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

/// The presets, as `bouncelab presets --format json`: a list of dicts with name, origin,
/// description, law, parameters, lambda, zeta, v0.
#[pyfunction]
pub(crate) fn presets(py: Python<'_>) -> PyResult<Vec<Bound<'_, PyDict>>> {
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

/// `pressure=` (Pa, or a string with its unit: `"0.8bar"`, `"8psi"`, `"55kPa"`),
/// `temperature=` and `inflated_at=` (°C): the command line's `--pressure`, `--temperature`,
/// `--inflated-at`, for the library's one resolver (`Ball::at_conditions`).
pub(crate) fn conditions(
    pressure: Option<&Bound<'_, PyAny>>,
    temperature: Option<f64>,
    inflated_at: Option<f64>,
) -> PyResult<bouncelab::api::ConditionsSpec> {
    let pressure = match pressure {
        None => None,
        Some(p) => Some(match p.extract::<String>() {
            Ok(text) => bouncelab::conditions::pressure::parse("pressure", &text)
                .map_err(crate::value_error)?,
            Err(_) => p.extract::<f64>()?,
        }),
    };
    Ok(bouncelab::api::ConditionsSpec {
        pressure,
        temperature,
        inflated_at,
        ..Default::default()
    })
}

/// `ball` at the conditions asked (itself when none is).
pub(crate) fn at_conditions(
    ball: Arc<Ball>,
    spec: &bouncelab::api::ConditionsSpec,
) -> PyResult<Arc<Ball>> {
    if spec.is_empty() {
        return Ok(ball);
    }
    let moved = Arc::unwrap_or_clone(ball).at_conditions(spec);
    Ok(Arc::new(moved.map_err(error)?))
}
