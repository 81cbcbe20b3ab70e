//! Value equality of a result's fields for Python's `==`: a NaN equals a NaN, as `Impact`'s
//! (impact_state.rs), so that a result and its pickled copy compare equal whatever it holds
//! (python/tests/test_pickle.py); and the pickle itself ([`reduce`], and [`state_item`] and
//! [`state_surface`] reading a state back).

use bouncelab::api::SurfaceUsed;
use pyo3::conversion::FromPyObjectOwned;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// What `__reduce__` returns: the class's `_from_state` and the state it is rebuilt from.
pub(crate) type Reduced<'py> = (Bound<'py, PyAny>, (Bound<'py, PyDict>,));

/// A result's `__reduce__` (pickling, `copy.copy`, `copy.deepcopy`): its class's
/// `_from_state` called on `state`, the result's `to_dict()`.
pub(crate) fn reduce<'py, T: pyo3::PyClass>(
    slf: &Bound<'py, T>,
    state: Bound<'py, PyDict>,
) -> PyResult<Reduced<'py>> {
    Ok((
        slf.as_any().get_type().getattr("_from_state")?.into_any(),
        (state,),
    ))
}

/// `key`'s value in a pickle's state `d`, extracted; absent, a `ValueError` "`what` without
/// 'KEY'" (`what` the state's: "Impact state"): a bad pickle is a bad value
/// (python/tests/test_arrays_hostile.py).
pub(crate) fn state_item<'py, T: FromPyObjectOwned<'py>>(
    d: &Bound<'py, PyDict>,
    key: &str,
    what: &str,
) -> PyResult<T> {
    d.get_item(key)?
        .ok_or_else(|| PyValueError::new_err(format!("{what} without '{key}'")))?
        .extract()
        .map_err(Into::into)
}

/// The surface of a pickle's state `d`: its `surface` dict, the rigid plate where the state
/// has none (a pickle written before the answers named their surface).
pub(crate) fn state_surface(d: &Bound<'_, PyDict>) -> PyResult<SurfaceUsed> {
    match d.get_item("surface")? {
        Some(s) => crate::surface::from_dict(&s),
        None => Ok(SurfaceUsed::rigid_plate()),
    }
}

pub(crate) trait Same {
    fn same(&self, other: &Self) -> bool;
}

impl Same for f64 {
    fn same(&self, other: &f64) -> bool {
        self == other || (self.is_nan() && other.is_nan())
    }
}

impl<T: Same> Same for Option<T> {
    fn same(&self, other: &Self) -> bool {
        match (self, other) {
            (Some(a), Some(b)) => a.same(b),
            (a, b) => a.is_none() && b.is_none(),
        }
    }
}

impl<T: Same> Same for [T] {
    fn same(&self, other: &Self) -> bool {
        self.len() == other.len() && self.iter().zip(other).all(|(a, b)| a.same(b))
    }
}

impl<T: Same, const N: usize> Same for [T; N] {
    fn same(&self, other: &Self) -> bool {
        self[..].same(&other[..])
    }
}

/// Types whose `==` is already value equality without NaN.
macro_rules! same_as_eq {
    ($($t:ty),*) => {
        $(impl Same for $t {
            fn same(&self, other: &Self) -> bool {
                self == other
            }
        })*
    };
}

same_as_eq!(bool, String, Vec<String>);
