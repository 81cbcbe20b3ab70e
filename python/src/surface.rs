//! `surface=`: the surface an impact runs on (docs/surfaces.md), as the command line's
//! `--surface NAME` and its explicit options: a name (embedded or the user's surfaces), or a
//! dict of the explicit numbers (`stiffness`, `damping`, `mass`, `friction`,
//! `tangential_stiffness`, `tangential_damping`, and `name` for the surface they override);
//! and the `surface` object every answer carries, the command line's JSON `surface`
//! (src/cli/surface.rs).

use crate::{of_argument, value_error};
use bouncelab::api::{SurfaceError, SurfaceUsed};
use bouncelab::catalog::surfaces as catalog;
use bouncelab::target::surface::SurfaceMechanics;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// The keys a `surface=` dict may hold: `name`, the normal numbers (the command line's
/// `--surface-*`), then the tangential ones (`--friction`, `--tangential-*`), by the names
/// the answer's `overrides` give them (`SurfaceUsed::NORMAL`, `SurfaceUsed::TANGENTIAL`).
fn keys() -> impl Iterator<Item = &'static str> {
    std::iter::once("name")
        .chain(SurfaceUsed::NORMAL)
        .chain(SurfaceUsed::TANGENTIAL)
}

/// The surface an answer ran on as an answer holds it: the library's [`SurfaceUsed`] (the
/// command line's JSON `surface`), wrapped only because pyo3's conversion (the `surface`
/// attribute of a `get_all` answer) cannot be implemented for a type of another crate.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SurfaceObject(pub(crate) SurfaceUsed);

impl From<SurfaceUsed> for SurfaceObject {
    fn from(s: SurfaceUsed) -> SurfaceObject {
        SurfaceObject(s)
    }
}

impl std::ops::Deref for SurfaceObject {
    type Target = SurfaceUsed;

    fn deref(&self) -> &SurfaceUsed {
        &self.0
    }
}

/// The `surface` attribute of an answer: a new dict at each read (a kept dict handed out
/// would let `r.surface[k] = …` change every later read).
impl<'py> IntoPyObject<'py> for &SurfaceObject {
    type Target = PyDict;
    type Output = Bound<'py, PyDict>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        to_dict(py, self)
    }
}

/// The explicit numbers asked for over the named surface's.
#[derive(Default)]
struct Explicit {
    name: Option<String>,
    normal: [Option<f64>; 3],
    tangential: [Option<f64>; 3],
}

/// The JSON `surface` object as a dict, its keys in the JSON's order (∞ as `inf` where the
/// JSON writes `null`).
pub(crate) fn to_dict<'py>(py: Python<'py>, s: &SurfaceUsed) -> PyResult<Bound<'py, PyDict>> {
    crate::answer::dict(py, s)
}

/// The rigid plate's surface object: the `surface` of the answers that take no surface and
/// ran on it (`static`, `fit`, `batch`, `monte_carlo`, `fit_oblique`, `sweep_velocity`), as
/// the command line's JSON (docs/cli.md, "The surface of the commands that take no surface
/// options"), ∞ as inf as in every answer's.
pub(crate) fn rigid_plate(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    to_dict(py, &SurfaceUsed::rigid_plate())
}

/// The object back from [`to_dict`]'s dict (pickling); `None` (JSON null) reads as ∞ for
/// the stiffness and the mass.
pub(crate) fn from_dict(d: &Bound<'_, PyAny>) -> PyResult<SurfaceUsed> {
    let d = d.cast::<PyDict>()?;
    let get = |k: &str| -> PyResult<Bound<'_, PyAny>> {
        d.get_item(k)?
            .ok_or_else(|| value_error(format!("surface: missing key {k:?}")))
    };
    let inf = |k: &str| -> PyResult<f64> {
        Ok(get(k)?.extract::<Option<f64>>()?.unwrap_or(f64::INFINITY))
    };
    Ok(SurfaceUsed {
        name: get("name")?.extract()?,
        origin: get("origin")?.extract()?,
        mechanics: SurfaceMechanics {
            stiffness: inf("stiffness")?,
            damping: get("damping")?.extract()?,
            mass: inf("mass")?,
            friction: get("friction")?.extract()?,
            tangential_stiffness: get("tangential_stiffness")?.extract()?,
            tangential_damping: get("tangential_damping")?.extract()?,
        },
        overrides: get("overrides")?.extract()?,
    })
}

/// `surface=` read: `None`, a name, or a dict of [`keys`].
fn explicit(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Explicit> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return Ok(Explicit::default());
    };
    if let Ok(s) = arg.cast::<PyString>() {
        return Ok(Explicit {
            name: Some(s.extract()?),
            ..Explicit::default()
        });
    }
    let Ok(d) = arg.cast::<PyDict>() else {
        return Err(value_error(
            "invalid surface: a surface name or a dict of its numbers (docs/surfaces.md)".into(),
        ));
    };
    let mut x = Explicit::default();
    for (k, v) in d.iter() {
        let k: String = of_argument(d.py(), "surface", k.extract())?;
        let at = keys().position(|n| n == k).ok_or_else(|| {
            let all: Vec<&str> = keys().collect();
            value_error(format!(
                "invalid surface: unknown key {k:?} (one of {})",
                all.join(", ")
            ))
        })?;
        if at == 0 {
            x.name = Some(of_argument(d.py(), "surface", v.extract())?);
            continue;
        }
        let n: f64 = v
            .extract()
            .map_err(|_| value_error(format!("invalid surface {k}: a number")))?;
        match at {
            1..=3 => x.normal[at - 1] = Some(n),
            _ => x.tangential[at - 4] = Some(n),
        }
    }
    Ok(x)
}

/// The surface `surface=` asks for: the named one (the rigid plate when none) from the
/// embedded and the user's surfaces, its normal numbers overridden by the dict's, checked
/// as the command line checks them; and the tangential numbers the dict gives (μ, K_t, c_t),
/// for `SurfaceUsed::with_tangential`.
pub(crate) fn resolve(arg: Option<&Bound<'_, PyAny>>) -> PyResult<(SurfaceUsed, [Option<f64>; 3])> {
    let x = explicit(arg)?;
    let named = match &x.name {
        None => SurfaceUsed::rigid_plate(),
        Some(name) => {
            let all = catalog::load(catalog::user_surfaces_dir().as_deref())
                .map_err(|e| value_error(e.to_string()))?;
            SurfaceUsed::from_entry(&catalog::find(&all, name).map_err(value_error)?)
        }
    };
    let s = named.with_normal(x.normal).map_err(|e| match e {
        SurfaceError::Invalid(e) => value_error(
            e.to_string()
                .replace("target_stiffness", "surface stiffness")
                .replace("target_damping", "surface damping")
                .replace("target_mass", "surface mass"),
        ),
        SurfaceError::RigidDashpot(_) => value_error(
            "invalid surface damping: a rigid surface's dashpot does nothing; give its \
             stiffness too"
                .into(),
        ),
    })?;
    Ok((s, x.tangential))
}

/// The surface of a normal impact (`run`, `collide`, `drop`): [`resolve`]'s, refusing the
/// tangential numbers the impact cannot use, as the command line refuses `run --friction`
/// (test_surfaces.py::test_a_normal_impact_refuses_tangential_numbers).
pub(crate) fn resolve_normal(arg: Option<&Bound<'_, PyAny>>) -> PyResult<SurfaceUsed> {
    let (surface, tangential) = resolve(arg)?;
    match SurfaceUsed::TANGENTIAL
        .iter()
        .zip(tangential)
        .find(|(_, v)| v.is_some())
    {
        Some((key, _)) => Err(value_error(format!(
            "invalid surface {key}: a normal impact uses no tangential numbers (oblique, \
             court and shot do; docs/surfaces.md)"
        ))),
        None => Ok(surface),
    }
}
