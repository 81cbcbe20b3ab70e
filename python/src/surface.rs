//! `surface=`: the surface an impact runs on (docs/surfaces.md), as the command line's
//! `--surface NAME` and its explicit options: a name (embedded or the user's surfaces), or a
//! dict of the explicit numbers (`stiffness`, `damping`, `mass`, `friction`,
//! `tangential_stiffness`, `tangential_damping`, and `name` for the surface they override);
//! and the `surface` object every answer carries, the command line's JSON `surface`
//! (src/cli/surface.rs).

use crate::value_error;
use bouncelab::catalog::Origin;
use bouncelab::catalog::surfaces::{self as catalog, SurfaceEntry};
use bouncelab::target::Target;
use bouncelab::target::surface::Surface;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

/// The keys a `surface=` dict may hold, the normal ones first (the command line's
/// `--surface-*`), then the tangential ones (`--friction`, `--tangential-*`).
const KEYS: [&str; 7] = [
    "name",
    "stiffness",
    "damping",
    "mass",
    "friction",
    "tangential_stiffness",
    "tangential_damping",
];

/// The surface an answer ran on: the JSON `surface` object's fields, in its order.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SurfaceUsed {
    pub(crate) name: String,
    pub(crate) origin: String,
    pub(crate) stiffness: f64,
    pub(crate) damping: f64,
    pub(crate) mass: f64,
    pub(crate) friction: Option<f64>,
    pub(crate) tangential_stiffness: Option<f64>,
    pub(crate) tangential_damping: Option<f64>,
    pub(crate) overrides: Vec<String>,
}

/// The `surface` attribute of an answer: a new dict at each read (a kept dict handed out
/// would let `r.surface[k] = …` change every later read).
impl<'py> IntoPyObject<'py> for &SurfaceUsed {
    type Target = PyDict;
    type Output = Bound<'py, PyDict>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.to_dict(py)
    }
}

/// The explicit numbers asked for over the named surface's.
#[derive(Default)]
struct Explicit {
    name: Option<String>,
    normal: [Option<f64>; 3],
    tangential: [Option<f64>; 3],
}

impl SurfaceUsed {
    /// The rigid, immovable test plate (the default), its tangential quantities unset.
    pub(crate) fn rigid_plate() -> SurfaceUsed {
        used(&SurfaceEntry {
            surface: Surface::rigid_plate(),
            origin: Origin::Embedded,
        })
    }

    /// The normal part: a target at rest.
    pub(crate) fn target(&self) -> Target {
        Target {
            mass: self.mass,
            speed: 0.0,
            stiffness: self.stiffness,
            damping: self.damping,
        }
    }

    /// Whether the answer is the rigid plate's (rigid and immovable).
    pub(crate) fn is_rigid(&self) -> bool {
        self.stiffness == f64::INFINITY && self.mass == f64::INFINITY
    }

    /// One line for a text header, the command line's (`bouncelab::api::surface_label`).
    pub(crate) fn label(&self) -> String {
        let normal = (self.stiffness, self.damping, self.mass);
        bouncelab::api::surface_label(&self.name, normal, self.friction, &self.overrides)
    }

    /// The JSON `surface` object (∞ as `inf` where the JSON writes `null`).
    pub(crate) fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("name", &self.name)?;
        d.set_item("origin", &self.origin)?;
        d.set_item("stiffness", self.stiffness)?;
        d.set_item("damping", self.damping)?;
        d.set_item("mass", self.mass)?;
        d.set_item("friction", self.friction)?;
        d.set_item("tangential_stiffness", self.tangential_stiffness)?;
        d.set_item("tangential_damping", self.tangential_damping)?;
        d.set_item("overrides", &self.overrides)?;
        Ok(d)
    }

    /// The object back from [`SurfaceUsed::to_dict`]'s dict (pickling); `None` (JSON null)
    /// reads as ∞ for the stiffness and the mass.
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
            stiffness: inf("stiffness")?,
            damping: get("damping")?.extract()?,
            mass: inf("mass")?,
            friction: get("friction")?.extract()?,
            tangential_stiffness: get("tangential_stiffness")?.extract()?,
            tangential_damping: get("tangential_damping")?.extract()?,
            overrides: get("overrides")?.extract()?,
        })
    }

    /// The tangential quantities the answer used: each the argument, else the surface's own;
    /// an argument over the surface's own is recorded as an override (the command line's
    /// rule, src/cli/surface.rs `with_tangential`).
    pub(crate) fn with_tangential(mut self, given: [Option<f64>; 3]) -> SurfaceUsed {
        let names = ["friction", "tangential_stiffness", "tangential_damping"];
        let own = [
            &mut self.friction,
            &mut self.tangential_stiffness,
            &mut self.tangential_damping,
        ];
        let mut overrides = Vec::new();
        for ((slot, flag), name) in own.into_iter().zip(given).zip(names) {
            if flag.is_some() && slot.is_some() {
                overrides.push(name.to_string());
            }
            *slot = flag.or(*slot);
        }
        self.overrides.extend(overrides);
        self
    }
}

/// The surface entry's numbers, nothing overridden.
fn used(e: &SurfaceEntry) -> SurfaceUsed {
    let s = &e.surface;
    SurfaceUsed {
        name: s.name.clone(),
        origin: e.origin.to_string(),
        stiffness: s.stiffness,
        damping: s.damping,
        mass: s.mass,
        friction: s.friction,
        tangential_stiffness: s.tangential_stiffness,
        tangential_damping: s.tangential_damping,
        overrides: Vec::new(),
    }
}

/// `surface=` read: `None`, a name, or a dict of [`KEYS`].
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
        let k: String = k.extract()?;
        let at = KEYS.iter().position(|n| *n == k).ok_or_else(|| {
            value_error(format!(
                "invalid surface: unknown key {k:?} (one of {})",
                KEYS.join(", ")
            ))
        })?;
        if at == 0 {
            x.name = Some(v.extract()?);
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
/// for [`SurfaceUsed::with_tangential`].
pub(crate) fn resolve(arg: Option<&Bound<'_, PyAny>>) -> PyResult<(SurfaceUsed, [Option<f64>; 3])> {
    let x = explicit(arg)?;
    let mut s = match &x.name {
        None => SurfaceUsed::rigid_plate(),
        Some(name) => {
            let all = catalog::load(catalog::user_surfaces_dir().as_deref())
                .map_err(|e| value_error(e.to_string()))?;
            used(&catalog::find(&all, name).map_err(value_error)?)
        }
    };
    let names = ["stiffness", "damping", "mass"];
    for (name, value) in names.into_iter().zip(x.normal) {
        let Some(v) = value else { continue };
        s.overrides.push(name.to_string());
        match name {
            "stiffness" => s.stiffness = v,
            "damping" => s.damping = v,
            _ => s.mass = v,
        }
    }
    s.target().validate().map_err(|e| {
        value_error(
            e.to_string()
                .replace("target_stiffness", "surface stiffness")
                .replace("target_damping", "surface damping")
                .replace("target_mass", "surface mass"),
        )
    })?;
    if s.stiffness.is_infinite() && s.damping > 0.0 && x.normal[1].is_some() {
        return Err(value_error(
            "invalid surface damping: a rigid surface's dashpot does nothing; give its \
             stiffness too"
                .into(),
        ));
    }
    Ok((s, x.tangential))
}
