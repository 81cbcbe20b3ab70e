//! Value equality of a result's fields for Python's `==`: a NaN equals a NaN, as `Impact`'s
//! (impact_state.rs), so that a result and its pickled copy compare equal whatever it holds
//! (python/tests/test_pickle.py); and the pickle itself ([`reduce`]).

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
