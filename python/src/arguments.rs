//! The arguments as the command line reads them: a contact law and a parameter set by their
//! names, `samples` only with a history, floats from numbers, sequences or numpy arrays, and
//! numpy arrays out.

use crate::value_error;
use bouncelab::ContactLaw;
use bouncelab::preset::ParamSource;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;

/// History samples when `history` is asked for; `samples` without it is refused, as the
/// command line refuses `--samples` without `--history`.
pub(crate) fn history_samples(history: bool, samples: Option<usize>) -> PyResult<usize> {
    match (history, samples) {
        (false, Some(n)) => Err(value_error(format!(
            "samples={n} applies only with history=True (the command line's --samples needs \
             --history)"
        ))),
        (_, n) => Ok(n.unwrap_or(400)),
    }
}

/// A contact law by its command-line name: linear, elastic-plastic, hertz.
pub(crate) fn law(name: &str) -> PyResult<ContactLaw> {
    name.parse::<ContactLaw>().map_err(value_error)
}

/// A parameter set by its command-line name: adopted, materials.
pub(crate) fn source(name: &str) -> PyResult<ParamSource> {
    match name {
        "adopted" => Ok(ParamSource::Adopted),
        "materials" => Ok(ParamSource::Materials),
        _ => Err(value_error(format!(
            "unknown parameter set '{name}' (expected adopted or materials)"
        ))),
    }
}

/// A list of floats from a numpy array, a sequence, or one number.
pub(crate) fn floats(obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArray1<'_, f64>>() {
        return Ok(a.as_array().to_vec());
    }
    if let Ok(x) = obj.extract::<f64>() {
        return Ok(vec![x]);
    }
    obj.extract::<Vec<f64>>()
}

pub(crate) fn array<'py>(py: Python<'py>, v: Vec<f64>) -> Py<PyArray1<f64>> {
    PyArray1::from_vec(py, v).unbind()
}
