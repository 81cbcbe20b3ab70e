//! The presets the Python calls take their balls from: the user's catalog (kept between calls,
//! catalog_cache.rs), a preset's ball with the caller's choices, and `presets()`.

use crate::{catalog_cache, error};
use bouncelab::BallError;
use bouncelab::api::PresetRow;
use bouncelab::catalog::{Catalog, Entry};
use pyo3::prelude::*;
use std::sync::Arc;

/// The presets the command line knows: the embedded ones and the user's folder
/// (`$XDG_CONFIG_HOME/bouncelab/presets`), the files it skipped warned of but the one a call
/// asking for `asked` ends with the error of (`catalog_cache::warn_skipped`).
pub(crate) fn load_catalog(asked: Option<&str>) -> PyResult<Arc<Catalog>> {
    // kept between calls while the folder is unchanged (catalog_cache.rs)
    let cat = catalog_cache::user_catalog().map_err(|e| error(BallError::Catalog(e)))?;
    catalog_cache::warn_skipped(&cat, asked)?;
    Ok(cat)
}

pub(crate) fn entry<'c>(cat: &'c Catalog, name: &str) -> PyResult<&'c Entry> {
    cat.get(name).map_err(|e| error(BallError::Catalog(e)))
}

/// The presets, as `bouncelab presets --format json`: a list of dicts with name, origin,
/// description, law, parameters, lambda, zeta, v0, radius, poisson_ratio, inertia_factor, the
/// `calibration` record (None for a preset without one) and `aerodynamics`, the flight model
/// the ball flies on (None: the assumed smooth sphere).
#[pyfunction]
pub(crate) fn presets(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    let cat = load_catalog(None)?;
    let rows: Vec<PresetRow> = cat.entries().iter().map(PresetRow::of).collect();
    crate::answer::json(py, &rows)
}
