//! What every answer names beside its numbers, as the command line's JSON gives it: the ball
//! it ran (the `ball` object, docs/cli.md "The ball object": `Ball::record_json`), the
//! conditions it ran at (`conditions`: the ball's), and why the comparison with the preset's
//! measurement is withheld (`comparison_withheld`: `Ball::measurement_withheld`). Each is the
//! library's own struct, turned into Python values through the JSON the command line writes
//! (serde_json, then Python's `json`), so the keys, their order and their nulls are the
//! command line's. The other objects an answer holds as a library type (the `surface`, a
//! fit's estimates, a shot's `end` and `net`) go over by [`dict`]: the same keys in the same
//! order, but a number stays a number where the JSON has null for it (∞ `inf`, NaN `nan`).

use bouncelab::Ball;
use bouncelab::api::BallRecord;
use bouncelab::conditions::Conditions;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::Serialize;

/// `value` as the command line's JSON writes it, read back by Python's `json` (a non-finite
/// number is JSON's null: `None`).
pub(crate) fn json<'py>(py: Python<'py>, value: &impl Serialize) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value).map_err(|e| PyValueError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}

/// `value`'s serde form as Python values, with no JSON between (pythonize): a struct a dict
/// in its fields' order (`flatten`ed fields in place, `skip`ped ones left out), an `f64` a
/// float, ∞ and NaN kept (where [`json`] gives `None`), an integer an int, a `Vec` a list, a
/// fixed-size array or a tuple a tuple, `None` `None`, a unit variant its (renamed) name.
pub(crate) fn dict<'py>(py: Python<'py>, value: &impl Serialize) -> PyResult<Bound<'py, PyDict>> {
    Ok(pythonize::pythonize(py, value)?.cast_into::<PyDict>()?)
}

/// The ball an answer ran (the JSON's `ball` object), kept by a result object (`Impact`,
/// `ObliqueImpact`, `Collision`): handed out as a new dict at each read, read back from one
/// (a pickle's state).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Record(pub(crate) BallRecord);

/// The conditions an answer ran at (the JSON's `conditions`), kept as [`Record`] is (the
/// leak, for the warnings only, is not kept).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stated(pub(crate) Conditions);

impl Record {
    pub(crate) fn of(ball: &Ball) -> Record {
        Record(ball.record_json())
    }
}

impl Stated {
    pub(crate) fn of(ball: &Ball) -> Stated {
        Stated(Conditions {
            leak: None,
            ..ball.conditions
        })
    }
}

/// Each handed to Python as the command line's JSON of it: a new dict at each read.
macro_rules! into_json {
    ($($t:ty),*) => {$(
        impl<'py> IntoPyObject<'py> for &$t {
            type Target = PyAny;
            type Output = Bound<'py, PyAny>;
            type Error = PyErr;

            fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                json(py, &self.0)
            }
        }
    )*};
}
into_json!(Record, Stated);

/// `d[k]`, named when absent (`same::state_item`).
fn item<'py>(d: &Bound<'py, PyDict>, k: &str) -> PyResult<Bound<'py, PyAny>> {
    crate::same::state_item(d, k, "state")
}

impl<'a, 'py> FromPyObject<'a, 'py> for Record {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Record> {
        let r = obj.cast::<PyDict>()?;
        let r = &*r;
        // JSON's null for an infinite c or z_p
        let inf = |k: &str| -> PyResult<f64> {
            Ok(item(r, k)?
                .extract::<Option<f64>>()?
                .unwrap_or(f64::INFINITY))
        };
        let law: String = item(r, "law")?.extract()?;
        let law = law
            .parse::<bouncelab::ContactLaw>()
            .map_err(crate::value_error)?;
        Ok(Record(BallRecord {
            name: item(r, "name")?.extract()?,
            origin: item(r, "origin")?.extract()?,
            law: law.name(),
            mass: item(r, "mass")?.extract()?,
            radius: item(r, "radius")?.extract()?,
            k_p: item(r, "k_p")?.extract()?,
            c: inf("c")?,
            k_r: item(r, "k_r")?.extract()?,
            z_p: inf("z_p")?,
            k_h: item(r, "k_h")?.extract()?,
            inertia_factor: item(r, "inertia_factor")?.extract()?,
            overrides: item(r, "overrides")?.extract()?,
            // absent without an override (`ball.kept`, issue 52)
            kept: r
                .get_item("kept")?
                .map(|k| k.extract())
                .transpose()?
                .unwrap_or_default(),
        }))
    }
}

impl<'a, 'py> FromPyObject<'a, 'py> for Stated {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Stated> {
        let c = obj.cast::<PyDict>()?;
        let c = &*c;
        Ok(Stated(Conditions {
            temperature_c: item(c, "temperature_c")?.extract()?,
            pressure_gauge_pa: item(c, "pressure_gauge_pa")?.extract()?,
            atmosphere_pa: item(c, "atmosphere_pa")?.extract()?,
            leak: None,
        }))
    }
}

/// `d` with the ball object of `ball` under `ball` and its `conditions`: an answer built as a
/// dict (`drop`, `monte_carlo`, `fit`, …), as the command line's JSON.
pub(crate) fn stated(d: &Bound<'_, PyDict>, ball: &Ball) -> PyResult<()> {
    d.set_item("ball", &Record::of(ball))?;
    d.set_item("conditions", &Stated::of(ball))
}
