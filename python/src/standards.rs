//! `standards`: the governing bodies' tests, as `bouncelab standards --format json` writes them
//! (`bouncelab::api::standards`): the ball standards, the bat standards, the court pace, the
//! pressure-loss and static tests, in one list.

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// The standards, as `bouncelab standards --format json`: a list of dicts with `name`,
/// `title`, `test` (`kind` "drop", "cor", "bbcor", "court-pace" or "static", and its
/// conditions, SI),
/// `surface`, `window` ([lo, hi], None where unbounded), `balls`, `source` and `unconfirmed`.
/// The names of kind "drop" and "cor" are what `drop(standard=…)` and `batch(standard=…)` take.
#[pyfunction]
pub(crate) fn standards(py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
    // the command line's list (`api::standards`) as its JSON, read back by Python's json: the
    // same keys and values without a hand-written copy of each struct (batch.rs does the
    // same); through a `Value`, so that the keys are in serde_json's order, as the CLI's
    let text = serde_json::to_value(bouncelab::api::standards())
        .and_then(|v| serde_json::to_string(&v))
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}
