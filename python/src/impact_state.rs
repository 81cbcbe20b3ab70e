//! An [`Impact`]'s state for pickling, and its value equality. The state is
//! [`Impact::to_dict`] (the keys of `bouncelab run --format json`, the history arrays when
//! there are any), so a pickle holds plain Python values and numpy arrays only.

use super::{Audit, ENERGY_KEYS, HISTORY_KEYS, Impact, MEASURED_KEYS};
use crate::frozen_array;
use bouncelab::api::Intervals;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::borrow::Cow;

/// `d[key]`, extracted; a missing key is an error naming it (`same::state_item`).
fn get<'py, T: FromPyObjectOwned<'py>>(d: &Bound<'py, PyDict>, key: &str) -> PyResult<T> {
    crate::same::state_item(d, key, "Impact state")
}

/// A dict of `keys` (or None) as an array of its values.
fn table<'py, T: FromPyObjectOwned<'py> + Copy + Default, const N: usize>(
    d: &Bound<'py, PyDict>,
    key: &str,
    keys: [&str; N],
) -> PyResult<Option<[T; N]>> {
    let Some(inner) = get::<Option<Bound<'py, PyDict>>>(d, key)? else {
        return Ok(None);
    };
    let mut out = [T::default(); N];
    for (slot, k) in out.iter_mut().zip(keys) {
        *slot = get(&inner, k)?;
    }
    Ok(Some(out))
}

/// The impact `state` describes.
pub(super) fn from_state(d: &Bound<'_, PyDict>) -> PyResult<Impact> {
    let py = d.py();
    let measured: Option<[Option<f64>; 4]> = table(d, "measured", MEASURED_KEYS)?;
    let energy: Option<[f64; 6]> = table(d, "energy", ENERGY_KEYS)?;
    let intervals = match d.get_item("cor_ci95")? {
        None => None,
        Some(_) => Some(Intervals {
            cor_ci95: get::<(f64, f64)>(d, "cor_ci95")?.into(),
            max_force_ci95: get::<(f64, f64)>(d, "max_force_ci95")?.into(),
            contact_time_ci95: get::<Option<(f64, f64)>>(d, "contact_time_ci95")?.map(Into::into),
        }),
    };
    let mut history = Vec::new();
    for k in HISTORY_KEYS {
        if let Some(a) = d.get_item(k)? {
            let a: PyReadonlyArray1<'_, f64> = a.extract()?;
            history.push(frozen_array(py, a.as_slice()?.to_vec()));
        }
    }
    Ok(Impact {
        preset: get(d, "preset")?,
        origin: Cow::Owned(get(d, "origin")?),
        parameters: Cow::Owned(get(d, "parameters")?),
        law: Cow::Owned(get(d, "law")?),
        method: Cow::Owned(get(d, "method")?),
        mass: get(d, "mass")?,
        k_p: get(d, "k_p")?,
        k_r: get(d, "k_r")?,
        c: get(d, "c")?,
        z_p: get(d, "z_p")?,
        k_h: get(d, "k_h")?,
        v0: get(d, "v0")?,
        lambda_: get(d, "lambda")?,
        zeta: get(d, "zeta")?,
        zp_bar: get(d, "zp_bar")?,
        radius: get(d, "radius")?,
        poisson_ratio: get(d, "poisson_ratio")?,
        cor: get(d, "cor")?,
        rebound: get(d, "rebound")?,
        max_force: get(d, "max_force")?,
        contact_time: get(d, "contact_time")?,
        max_indentation: get(d, "max_indentation")?,
        permanent_indentation: get(d, "permanent_indentation")?,
        max_force_normalized: get(d, "max_force_normalized")?,
        contact_time_normalized: get(d, "contact_time_normalized")?,
        measured,
        history: history.try_into().ok(),
        intervals,
        audit: Audit {
            energy,
            warnings: get(d, "warnings")?,
        }
        .into(),
        ball: None,
        surface: crate::same::state_surface(d)?,
        named: (get(d, "ball")?, get(d, "conditions")?),
        withheld: get(d, "comparison_withheld")?,
        uncalibrated: get(d, "uncalibrated_outputs")?,
    })
}

/// Equal numbers, a NaN equal to a NaN.
fn eq(a: f64, b: f64) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

fn eq_opt(a: Option<f64>, b: Option<f64>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => eq(a, b),
        (a, b) => a.is_none() && b.is_none(),
    }
}

fn eq_all(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| eq(*x, *y))
}

/// The history arrays' values (empty without a history).
fn series(py: Python<'_>, h: &Option<[Py<PyArray1<f64>>; 4]>) -> Vec<Vec<f64>> {
    h.iter()
        .flatten()
        .map(|a| a.bind(py).to_vec().unwrap_or_default())
        .collect()
}

/// Whether two impacts, with their audits, hold the same values.
pub(super) fn same(a: &Impact, a_audit: &Audit, b: &Impact, b_audit: &Audit) -> bool {
    let numbers = |i: &Impact| {
        [
            i.mass,
            i.k_p,
            i.k_r,
            i.c,
            i.z_p,
            i.k_h,
            i.v0,
            i.lambda_,
            i.zeta,
            i.zp_bar,
            i.cor,
            i.max_force,
            i.max_indentation,
            i.permanent_indentation,
            i.max_force_normalized,
        ]
    };
    let optional = |i: &Impact| {
        let m = i.measured.unwrap_or([None; 4]);
        [
            i.contact_time,
            i.contact_time_normalized,
            m[0],
            m[1],
            m[2],
            m[3],
        ]
    };
    let words = |i: &Impact| {
        (
            i.preset.clone(),
            i.origin.clone(),
            i.parameters.clone(),
            i.law.clone(),
            i.method.clone(),
            i.rebound,
            i.measured.is_some(),
            i.surface.clone(),
            i.named.clone(),
            i.withheld.clone(),
            i.uncalibrated.clone(),
        )
    };
    let bands = |i: &Impact| {
        i.intervals.map(|v| {
            let t = v.contact_time_ci95.unwrap_or([f64::NAN; 2]);
            [v.cor_ci95, v.max_force_ci95, t].concat()
        })
    };
    let histories = Python::attach(|py| {
        let (x, y) = (series(py, &a.history), series(py, &b.history));
        x.len() == y.len() && x.iter().zip(&y).all(|(p, q)| eq_all(p, q))
    });
    words(a) == words(b)
        && a_audit.warnings == b_audit.warnings
        && eq_all(&numbers(a), &numbers(b))
        && optional(a)
            .iter()
            .zip(optional(b))
            .all(|(x, y)| eq_opt(*x, y))
        && eq_all(
            &a_audit.energy.unwrap_or([f64::NAN; 6]),
            &b_audit.energy.unwrap_or([f64::NAN; 6]),
        )
        && a_audit.energy.is_some() == b_audit.energy.is_some()
        && match (bands(a), bands(b)) {
            (Some(x), Some(y)) => eq_all(&x, &y),
            (x, y) => x.is_none() && y.is_none(),
        }
        && histories
}
