//! The partner of a pair of balls in an answer (`collide(target_preset=…)`): the command
//! line's JSON `pair` object (`api::Partner`: its preset, m_eff, R_eff, and its ball object
//! and conditions as every answer writes its own), handed to Python as a dict and read back
//! from one (a pickle's state).

use crate::answer::{Record, Stated};
use bouncelab::api::Partner;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The partner of a pair, kept as the library's [`Partner`]: handed out as the JSON's `pair`
/// object (a new dict at each read, its `ball` and `conditions` as every answer's), read back
/// from one (a pickle's state).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PairObject(pub(crate) Partner);

impl<'py> IntoPyObject<'py> for &PairObject {
    type Target = PyDict;
    type Output = Bound<'py, PyDict>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = &self.0;
        let d = PyDict::new(py);
        d.set_item("preset", &p.preset)?;
        d.set_item("effective_mass", p.effective_mass)?;
        d.set_item("effective_radius", p.effective_radius)?;
        d.set_item("ball", &Record(p.ball.clone()))?;
        d.set_item("conditions", &Stated(p.conditions))?;
        Ok(d)
    }
}

impl<'a, 'py> FromPyObject<'a, 'py> for PairObject {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<PairObject> {
        let d = obj.cast::<PyDict>()?;
        let d = &*d;
        let ball: Record = crate::same::state_item(d, "ball", "pair")?;
        let conditions: Stated = crate::same::state_item(d, "conditions", "pair")?;
        Ok(PairObject(Partner {
            preset: crate::same::state_item(d, "preset", "pair")?,
            effective_mass: crate::same::state_item(d, "effective_mass", "pair")?,
            effective_radius: crate::same::state_item(d, "effective_radius", "pair")?,
            ball: ball.0,
            conditions: conditions.0,
        }))
    }
}
