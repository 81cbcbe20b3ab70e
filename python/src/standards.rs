//! `standards`: the governing bodies' tests, as `bouncelab standards --format json` writes them
//! (src/cli/standards.rs): the ball standards, the bat standards, the court pace, in one list.

use bouncelab::drop::deformation::DEFORMATION_STANDARDS;
use bouncelab::drop::standards::STANDARDS;
use bouncelab::oblique::court::ITF_COURT_PACE;
use bouncelab::target::bat::BAT_STANDARDS;
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// The standards, as `bouncelab standards --format json`: a list of dicts with `name`,
/// `title`, `test` (`kind` "drop", "cor", "bbcor", "court-pace" or "static", and its
/// conditions, SI),
/// `surface`, `window` ([lo, hi], None where unbounded), `balls`, `source` and `unconfirmed`.
/// The names of kind "drop" and "cor" are what `drop(standard=…)` and `batch(standard=…)` take.
#[pyfunction]
pub(crate) fn standards(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    // serde's values, as the command line's JSON, read back by Python's json: the same keys
    // and values without a hand-written copy of each struct (batch.rs does the same)
    let text = (|| {
        let mut all: Vec<serde_json::Value> = Vec::new();
        for s in &STANDARDS {
            all.push(serde_json::to_value(s)?);
        }
        for s in &BAT_STANDARDS {
            all.push(serde_json::to_value(s)?);
        }
        all.push(serde_json::to_value(ITF_COURT_PACE)?);
        for s in &DEFORMATION_STANDARDS {
            all.push(serde_json::to_value(s)?);
        }
        serde_json::to_string(&all)
    })()
    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}
