//! `ObliqueImpact`'s state and value: [`to_dict`] (the keys of `bouncelab oblique --format
//! json`, the history arrays with a history), the impact rebuilt from it (pickling), and `==`.

use super::{ENERGY_KEYS, EnergyTerms, ObliqueImpact};
use crate::frozen_array;
use crate::same::Same;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::conversion::FromPyObjectOwned;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The history's keys, in the JSON's order.
const HISTORY_KEYS: [&str; 5] = [
    "t",
    "normal_force",
    "friction_force",
    "slip_velocity",
    "spin",
];

fn history(o: &ObliqueImpact) -> [&Option<Py<PyArray1<f64>>>; 5] {
    [
        &o.t,
        &o.normal_force,
        &o.friction_force,
        &o.slip_velocity,
        &o.spin,
    ]
}

pub(super) fn to_dict<'py>(o: &ObliqueImpact, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    // c_t, a key only with a dashpot, after K_t as in the JSON
    macro_rules! put {
        ($($k:ident),*) => { $(
            d.set_item(stringify!($k), &o.$k)?;
            if stringify!($k) == "tangential_stiffness"
                && let Some(c) = o.tangential_damping
            {
                d.set_item("tangential_damping", c)?;
            }
        )* };
    }
    plain_fields!(put);
    d.set_item("energy", &o.energy)?;
    for (k, a) in HISTORY_KEYS.iter().zip(history(o)) {
        if let Some(a) = a {
            d.set_item(k, a.clone_ref(py))?;
        }
    }
    d.set_item("warnings", &o.warnings)?;
    d.set_item("ball", &o.ball)?;
    d.set_item("surface", crate::surface::to_dict(py, &o.surface)?)?;
    d.set_item("conditions", &o.conditions)?;
    Ok(d)
}

/// `d[key]`, extracted; a missing key is an error naming it (`same::state_item`).
fn get<'py, T: FromPyObjectOwned<'py>>(d: &Bound<'py, PyDict>, key: &str) -> PyResult<T> {
    crate::same::state_item(d, key, "ObliqueImpact state")
}

pub(super) fn from_state(d: &Bound<'_, PyDict>) -> PyResult<ObliqueImpact> {
    let py = d.py();
    let e: Bound<'_, PyDict> = get(d, "energy")?;
    let mut energy = [0.0; 8];
    for (v, k) in energy.iter_mut().zip(ENERGY_KEYS) {
        *v = get(&e, k)?;
    }
    // the arrays read-only again (a pickle's arrays are the unpickler's, writeable)
    let array = |k: &str| -> PyResult<Option<Py<PyArray1<f64>>>> {
        d.get_item(k)?
            .map(|a| {
                let a: PyReadonlyArray1<'_, f64> = a.extract()?;
                Ok(frozen_array(py, a.as_slice()?.to_vec()))
            })
            .transpose()
    };
    macro_rules! take {
        ($($k:ident),*) => {
            ObliqueImpact {
                $($k: get(d, stringify!($k))?,)*
                energy: EnergyTerms(energy, match e.get_item("tangential_damping")? {
                    Some(c) => Some(c.extract()?),
                    None => None,
                }),
                t: array("t")?,
                normal_force: array("normal_force")?,
                friction_force: array("friction_force")?,
                slip_velocity: array("slip_velocity")?,
                spin: array("spin")?,
                warnings: get(d, "warnings")?,
                tangential_damping: match d.get_item("tangential_damping")? {
                    Some(c) => c.extract()?,
                    None => None,
                },
                surface: crate::same::state_surface(d)?.into(),
                ball: get(d, "ball")?,
                conditions: get(d, "conditions")?,
            }
        };
    }
    Ok(plain_fields!(take))
}

/// Every field equal, a NaN equal to a NaN (as `Impact`'s), the arrays element by element.
pub(super) fn same(py: Python<'_>, a: &ObliqueImpact, b: &ObliqueImpact) -> PyResult<bool> {
    macro_rules! all_same {
        ($($k:ident),*) => { true $(&& a.$k.same(&b.$k))* };
    }
    if !(plain_fields!(all_same)
        && a.energy.0.same(&b.energy.0)
        && a.energy.1.same(&b.energy.1)
        && a.warnings == b.warnings
        && a.tangential_damping.same(&b.tangential_damping)
        && a.surface == b.surface
        && a.ball == b.ball
        && a.conditions == b.conditions)
    {
        return Ok(false);
    }
    for (x, y) in history(a).into_iter().zip(history(b)) {
        match (x, y) {
            (None, None) => {}
            (Some(x), Some(y)) => {
                if !x
                    .bind(py)
                    .readonly()
                    .as_slice()?
                    .same(y.bind(py).readonly().as_slice()?)
                {
                    return Ok(false);
                }
            }
            _ => return Ok(false),
        }
    }
    Ok(true)
}
