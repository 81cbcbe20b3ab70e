//! `bouncelab.impacts`: many impacts from numpy arrays (issue 30 item 5). The arguments are
//! broadcast as numpy's ufuncs broadcast them (numpy's own `broadcast_shapes`, so the rules
//! and the errors are numpy's); the impacts run on all cores without the GIL
//! ([`bouncelab::api::first_pass`], then what it leaves, each row the answer `run_params`
//! gives, written into the answer's arrays); the answer is a dict of arrays of the broadcast
//! shape.

use crate::{error, law};
use bouncelab::analysis::work;
use bouncelab::api::{Columns, first_pass_stoppable};
use bouncelab::model::params::ImpactParams;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

/// An argument over the broadcast shape: one value for all, or one per element (flat, C
/// order).
enum Column<'a> {
    One(f64),
    Each(&'a [f64]),
}

impl Column<'_> {
    fn at(&self, i: usize) -> f64 {
        match self {
            Column::One(v) => *v,
            Column::Each(s) => s[i],
        }
    }
}

/// The argument `name` as a float64 array. Only numbers are taken (numpy's kinds b, i, u, f,
/// and objects that convert): a complex array would lose its imaginary part with no more than
/// numpy's `ComplexWarning`, a string array would be read as numbers; both raise `TypeError`
/// naming the argument, and a conversion that fails raises numpy's error naming it.
fn real_array<'py>(
    np: &Bound<'py, PyModule>,
    name: &str,
    a: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    // numpy's error, of its own type, naming the argument (an OverflowError is left to the
    // package's boundary, which names it with its value: bouncelab/_boundary.py)
    let named = |e: PyErr| {
        let py = a.py();
        if e.is_instance_of::<PyOverflowError>(py) {
            return e;
        }
        PyErr::from_type(e.get_type(py), format!("invalid {name}: {}", e.value(py)))
    };
    let any = np.call_method1("asarray", (a,)).map_err(named)?;
    let dtype = any.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !"biufO".contains(kind.as_str()) {
        return Err(PyTypeError::new_err(format!(
            "invalid {name}: an array of {} (expected real numbers)",
            dtype.str()?
        )));
    }
    np.call_method1("asarray", (any, "float64")).map_err(named)
}

/// Each argument (named by `names`) as a float64 array, and the shape they broadcast to
/// (numpy's rules and errors).
/// The most dimensions numpy's broadcasting takes.
const MAX_DIMS: usize = 32;

fn shapes<'py>(
    py: Python<'py>,
    names: &[&str],
    args: &[Bound<'py, PyAny>],
) -> PyResult<(Vec<Bound<'py, PyAny>>, Bound<'py, PyTuple>)> {
    let np = py.import("numpy")?;
    let arrays: Vec<Bound<'py, PyAny>> = names
        .iter()
        .zip(args)
        .map(|(name, a)| real_array(&np, name, a))
        .collect::<PyResult<_>>()?;
    // numpy broadcasts at most 32 dimensions (NPY_MAXARGS): a deeper array is the
    // argument's fault, named, a ValueError, before numpy's broadcast
    // (tests/test_arrays_hostile.py)
    for (name, a) in names.iter().zip(&arrays) {
        let ndim: usize = a.getattr("ndim")?.extract()?;
        if ndim > MAX_DIMS {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "invalid {name}: an array of {ndim} dimensions (at most {MAX_DIMS} broadcast)"
            )));
        }
    }
    let each: Vec<Bound<'py, PyAny>> = arrays
        .iter()
        .map(|a| a.getattr("shape"))
        .collect::<PyResult<_>>()?;
    let shape = np
        .call_method1("broadcast_shapes", PyTuple::new(py, each)?)?
        .cast_into::<PyTuple>()?;
    Ok((arrays, shape))
}

/// Each array flat, C-ordered, over `shape` (a size-1 array stays one value: no copy).
fn flatten<'py>(
    arrays: &[Bound<'py, PyAny>],
    shape: &Bound<'py, PyTuple>,
) -> PyResult<Vec<PyReadonlyArray1<'py, f64>>> {
    let np = shape.py().import("numpy")?;
    arrays
        .iter()
        .map(|a| {
            let size: usize = a.getattr("size")?.extract()?;
            let full = if size == 1 {
                a.clone()
            } else {
                np.call_method1("broadcast_to", (a, shape))?
            };
            np.call_method1("ascontiguousarray", (full,))?
                .call_method0("ravel")?
                .extract::<PyReadonlyArray1<'py, f64>>()
        })
        .collect()
}

/// Many impacts, SI units, from numbers or numpy arrays broadcast together as a ufunc's
/// arguments: a dict of arrays of the broadcast shape, `cor`, `max_force`, `contact_time`
/// (NaN where the ball stays at the wall), `max_indentation`, `permanent_indentation` and
/// `rebound` (bool). Element i is what `run_params` gives for the i-th values; `z_p = inf`
/// is no flattening and `k_h` defaults to the Hertz stiffness meeting K_p at z_p (Eq. 16).
#[pyfunction]
#[pyo3(signature = (*, m, k_p, c, k_r, v0, z_p=None, k_h=None, law="linear"))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn impacts<'py>(
    py: Python<'py>,
    m: Bound<'py, PyAny>,
    k_p: Bound<'py, PyAny>,
    c: Bound<'py, PyAny>,
    k_r: Bound<'py, PyAny>,
    v0: Bound<'py, PyAny>,
    z_p: Option<Bound<'py, PyAny>>,
    k_h: Option<Bound<'py, PyAny>>,
    law: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let law = self::law(law)?;
    // k_h left out is Eq. 16's at each element's K_p and z_p; one given is checked as given,
    // a NaN too (refused as `run_params` refuses it: test_a_k_h_given_as_nan_is_refused…)
    let k_h_default = k_h.is_none();
    let inf = f64::INFINITY.into_pyobject(py)?.into_any();
    let nan = f64::NAN.into_pyobject(py)?.into_any();
    let args = [m, k_p, c, k_r, v0, z_p.unwrap_or(inf), k_h.unwrap_or(nan)];
    let names = ["m", "k_p", "c", "k_r", "v0", "z_p", "k_h"];
    let (arrays, shape) = shapes(py, &names, &args)?;
    let n: usize = shape
        .iter()
        .map(|d| d.extract::<usize>())
        .product::<PyResult<usize>>()?;
    // the work limit before any copy, at the least the elements can cost (all in the Hertz
    // table; linear-law impacts count as Monte Carlo samples), then by what the first pass
    // found each element's path to be
    work::check_elements(law, work::Elements::at_least(n)).map_err(|e| error(e.into()))?;
    let flat = flatten(&arrays, &shape)?;
    let cols: Vec<Column<'_>> = flat
        .iter()
        .map(|a| {
            let s = a.as_slice()?;
            Ok(if a.len() == 1 && n != 1 {
                Column::One(s[0])
            } else {
                Column::Each(s)
            })
        })
        .collect::<PyResult<_>>()?;
    let params = |i: usize| {
        let (k_p, z_p, k_h) = (cols[1].at(i), cols[5].at(i), cols[6].at(i));
        let k_h = if k_h_default {
            ImpactParams::k_h_matching(k_p, if z_p.is_finite() { z_p } else { 1.0 })
        } else {
            k_h
        };
        ImpactParams {
            mass: cols[0].at(i),
            k_p,
            damping: cols[2].at(i),
            k_r: cols[3].at(i),
            v0: cols[4].at(i),
            z_p,
            k_h,
        }
    };
    // the answer's arrays, zeroed (numpy's calloc: pages the rows then write) and filled in
    // place without the GIL
    let numbers: [Bound<'py, PyArray1<f64>>; 5] =
        std::array::from_fn(|_| PyArray1::zeros(py, n, false));
    let rebound = PyArray1::<bool>::zeros(py, n, false);
    {
        let mut f = numbers.each_ref().map(|a| a.readwrite());
        let mut b = rebound.readwrite();
        let [cor, force, time, z_m, z_f] = f.each_mut().map(|a| a.as_slice_mut());
        let mut out = Columns::from_slices([cor?, force?, time?, z_m?, z_f?], b.as_slice_mut()?);
        // both passes in blocks, Ctrl-C read between them (`interrupt::detach_stoppable`)
        let rest = crate::interrupt::detach_stoppable(py, |stop| {
            let stop = || stop.load(std::sync::atomic::Ordering::Relaxed);
            first_pass_stoppable(law, &params, &mut out, &stop)
        })?
        .ok_or_else(stopped)?;
        work::check_elements(law, rest.elements()).map_err(|e| error(e.into()))?;
        crate::interrupt::detach_stoppable(py, |stop| {
            let stop = || stop.load(std::sync::atomic::Ordering::Relaxed);
            rest.answer_stoppable(&params, &mut out, &stop)
        })?
        .ok_or_else(stopped)?
        .map_err(|(i, e)| {
            let msg = format!("element {i}: {e}");
            if e.is_no_answer() {
                crate::NoAnswerError::new_err(msg)
            } else {
                PyValueError::new_err(msg)
            }
        })?;
    }
    let d = PyDict::new(py);
    for (name, a) in Columns::NUMBERS.into_iter().zip(numbers) {
        d.set_item(name, a.call_method1("reshape", (&shape,))?)?;
    }
    d.set_item("rebound", rebound.call_method1("reshape", (&shape,))?)?;
    Ok(d)
}

/// Work a flag stopped though no signal's exception was raised (a handler that returned):
/// said as Python says an interrupted call.
fn stopped() -> PyErr {
    pyo3::exceptions::PyKeyboardInterrupt::new_err("stopped")
}
