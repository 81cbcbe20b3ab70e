//! The arguments as the command line reads them, resolved here for every binding: a contact
//! law and a parameter set by their names, `samples` only with a history, the `free` names,
//! floats from numbers, sequences or numpy arrays; the ball a call runs from its preset and
//! keyword arguments ([`ball`]); and numpy arrays out. (`surface=` is surface.rs's, with the
//! surface's dicts both ways.)

pub(crate) mod ball;

use crate::value_error;
use bouncelab::ContactLaw;
use bouncelab::preset::ParamSource;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

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

/// The `free` parameters' names: a list of them, or the command line's `--free` text
/// ("k_r,z_p"); `None` when not given. Anything else is a `TypeError` naming `free`.
pub(crate) fn free_names(free: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Vec<String>>> {
    free.map(|f| match f.extract::<String>() {
        Ok(text) => Ok(text.split(',').map(str::to_string).collect()),
        Err(_) => f.extract::<Vec<String>>().map_err(|e| {
            PyTypeError::new_err(format!(
                "invalid free: {} (expected a list of names or the text \"k_r,z_p\")",
                e.value(f.py())
            ))
        }),
    })
    .transpose()
}

/// `result`'s error marked as the argument `name`'s, for an argument the native code reads by
/// hand (a `PyAny` it converts itself): the note `while processing 'NAME'` PyO3 puts on the
/// error of an argument it extracts (Python 3.11's notes), which the boundary
/// (bouncelab/_boundary.py) reads to raise the error again naming the argument and its value.
pub(crate) fn of_argument<T>(py: Python<'_>, name: &str, result: PyResult<T>) -> PyResult<T> {
    result.inspect_err(|e| {
        // before Python 3.11 there is no `add_note`, and the error goes as it is (as PyO3's)
        let note = format!("while processing '{name}'");
        let _ = e
            .value(py)
            .call_method1(pyo3::intern!(py, "add_note"), (note,));
    })
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

/// A list of floats from a numpy array, a sequence, or one number: the argument `name`, which
/// an error names (a 2-D array or a string is neither, and PyO3's own message would not say
/// which argument it was about).
pub(crate) fn floats(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    if let Ok(a) = obj.extract::<PyReadonlyArray1<'_, f64>>() {
        return Ok(a.as_array().to_vec());
    }
    if let Ok(x) = obj.extract::<f64>() {
        return Ok(vec![x]);
    }
    obj.extract::<Vec<f64>>().map_err(|e| {
        let py = obj.py();
        PyErr::from_type(
            e.get_type(py),
            format!(
                "invalid {name}: {} (expected one number, a sequence of numbers or a 1-D array)",
                e.value(py)
            ),
        )
    })
}

pub(crate) fn array<'py>(py: Python<'py>, v: Vec<f64>) -> Py<PyArray1<f64>> {
    PyArray1::from_vec(py, v).unbind()
}

/// `v` as a numpy array Python cannot write, for an array a result keeps and hands out at
/// every read (`Impact.t`, `ObliqueImpact.spin`, …): a write would change what the result
/// shows, compares and pickles (python/tests/test_frozen_results.py). The flag stays off:
/// numpy sets it back only on an array that owns its memory, and this one's is Rust's.
pub(crate) fn frozen_array<'py>(py: Python<'py>, v: Vec<f64>) -> Py<PyArray1<f64>> {
    let a = PyArray1::from_vec(py, v);
    // a new array has no other borrow, so `readwrite` cannot fail here
    let _ = a.readwrite().make_nonwriteable();
    a.unbind()
}

/// `NAME_ci95_lo` and `NAME_ci95_hi` arrays in `d`, one entry per row of `bands`.
pub(crate) fn interval_columns<const N: usize>(
    py: Python<'_>,
    d: &Bound<'_, PyDict>,
    names: [&str; N],
    bands: &[[[f64; 2]; N]],
) -> PyResult<()> {
    for (k, name) in names.iter().enumerate() {
        for (side, end) in ["lo", "hi"].iter().enumerate() {
            let v: Vec<f64> = bands.iter().map(|b| b[k][side]).collect();
            d.set_item(format!("{name}_ci95_{end}"), array(py, v))?;
        }
    }
    Ok(())
}
