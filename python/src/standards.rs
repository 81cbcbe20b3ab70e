//! `standards`: the governing bodies' tests, as `bouncelab standards --format json` writes them
//! (src/cli/standards.rs): the ball standards, the bat standards, the court pace, in one list.

use bouncelab::drop::conditions::{PRESSURE_LOSS, of};
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
            let mut v = serde_json::to_value(s)?;
            // each ball standard's test conditions, as the command line's (issue 56)
            v["conditions"] = conditions_json(s.name);
            all.push(v);
        }
        for s in &BAT_STANDARDS {
            all.push(serde_json::to_value(s)?);
        }
        all.push(serde_json::to_value(ITF_COURT_PACE)?);
        for p in &PRESSURE_LOSS {
            all.push(serde_json::json!({
                "name": p.name,
                "title": p.title,
                "test": {"kind": "pressure-loss", "hours": p.hours, "pressure": p.pressure,
                         "temperature": p.temperature},
                "window": [null, p.max_loss],
                "source": p.source,
                "unconfirmed": p.unconfirmed,
                "balls": p.balls,
                "conditions": conditions_json(p.name),
            }));
        }
        for s in &DEFORMATION_STANDARDS {
            all.push(serde_json::to_value(s)?);
        }
        serde_json::to_string(&all)
    })()
    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}

/// A standard's test conditions, as `bouncelab standards --format json` gives them.
fn conditions_json(name: &str) -> serde_json::Value {
    let c = of(name);
    serde_json::json!({
        "temperature_c": c.temperature_c,
        "pressure_gauge_pa": c.pressure_gauge_pa,
        "source": c.source,
    })
}
