//! `oblique`: one oblique impact with friction and spin (docs/oblique.md), as `bouncelab
//! oblique --format json`: the same fields, by the same names.

use crate::answer::{Record, Stated};
use crate::arguments::ball::ball_pyfunction;
use crate::{error, frozen_array, history_samples, value_error};
use bouncelab::api::ObliqueSpec;
use bouncelab::api::SurfaceUsed;
use bouncelab::oblique::ObliqueResponse;
use bouncelab::{Ball, BallError};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// An oblique impact, SI units; attribute names are the keys of `bouncelab oblique --format
/// json`: the ball (`preset`, `origin`, `parameters`, `law`), the tangential model it ran
/// (`friction`, `tangential_stiffness`, `inertia_factor`, `radius`) and the answer (`energy` a
/// dict of its terms; the history arrays `None` unless asked for).
#[pyclass(frozen, get_all, module = "bouncelab")]
pub(crate) struct ObliqueImpact {
    preset: Option<String>,
    origin: String,
    parameters: String,
    law: String,
    friction: f64,
    /// K_t as given, else Mindlin's from the preset's Poisson ratio (None without one).
    tangential_stiffness: Option<f64>,
    inertia_factor: f64,
    /// R (m), None for a ball without a measured radius.
    radius: Option<f64>,
    v_in: f64,
    angle_in_deg: f64,
    spin_in: f64,
    vx_in: f64,
    vy_in: f64,
    v_out: f64,
    angle_out_deg: f64,
    spin_out: f64,
    vx_out: f64,
    vy_out: f64,
    cor_normal: f64,
    cor_tangential: Option<f64>,
    apparent_friction: f64,
    slid_throughout: bool,
    grip_time: f64,
    contact_time: f64,
    max_normal_force: f64,
    max_friction_force: f64,
    energy: EnergyTerms,
    t: Option<Py<PyArray1<f64>>>,
    normal_force: Option<Py<PyArray1<f64>>>,
    friction_force: Option<Py<PyArray1<f64>>>,
    slip_velocity: Option<Py<PyArray1<f64>>>,
    spin: Option<Py<PyArray1<f64>>>,
    /// `Ball::oblique_warnings`, as the JSON's `warnings`.
    warnings: Vec<String>,
    /// c_t (kg/s) when the tangential spring had a dashpot (the JSON's key only then).
    tangential_damping: Option<f64>,
    /// The surface it ran on (the JSON's `surface`, docs/surfaces.md).
    surface: crate::surface::SurfaceObject,
    /// The ball it ran (the JSON's `ball` object, docs/cli.md "The ball object").
    ball: Record,
    /// The conditions it ran at (the JSON's `conditions`).
    conditions: Stated,
}

/// The energy terms' keys, in the JSON's order.
const ENERGY_KEYS: [&str; 8] = [
    "translational_in",
    "rotational_in",
    "translational_out",
    "rotational_out",
    "normal_dissipation",
    "friction_dissipation",
    "tangential_spring",
    "residual",
];

/// The energy terms (J; `residual` relative) under [`ENERGY_KEYS`], handed to Python as a new
/// dict at each read: a dict kept in the result and handed out would let `o.energy[k] = …`
/// change every later read (python/tests/test_frozen_results.py).
/// The second field: what the tangential dashpot took (J), a key only with a dashpot, before
/// `residual` as in the JSON.
struct EnergyTerms([f64; 8], Option<f64>);

impl<'py> IntoPyObject<'py> for &EnergyTerms {
    type Target = PyDict;
    type Output = Bound<'py, PyDict>;
    type Error = PyErr;

    fn into_pyobject(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (k, v) in ENERGY_KEYS.iter().zip(self.0) {
            if *k == "residual"
                && let Some(c) = self.1
            {
                d.set_item("tangential_damping", c)?;
            }
            d.set_item(k, v)?;
        }
        Ok(d)
    }
}

/// The fields that are plain values, in the JSON's order (before `energy`, the history and
/// `warnings`): one list for `to_dict`, `_from_state` and `==` (oblique_state.rs).
macro_rules! plain_fields {
    ($m:ident) => {
        $m!(
            preset,
            origin,
            parameters,
            law,
            friction,
            tangential_stiffness,
            inertia_factor,
            radius,
            v_in,
            angle_in_deg,
            spin_in,
            vx_in,
            vy_in,
            v_out,
            angle_out_deg,
            spin_out,
            vx_out,
            vy_out,
            cor_normal,
            cor_tangential,
            apparent_friction,
            slid_throughout,
            grip_time,
            contact_time,
            max_normal_force,
            max_friction_force
        )
    };
}

// pickling, copies and value equality: a child module, so that it reads the fields without
// widening them
#[path = "oblique_state.rs"]
mod state;

#[pymethods]
impl ObliqueImpact {
    fn __repr__(&self) -> String {
        format!(
            "ObliqueImpact(v_out={}, angle_out_deg={}, spin_out={}, cor_normal={}, \
             apparent_friction={})",
            self.v_out, self.angle_out_deg, self.spin_out, self.cor_normal, self.apparent_friction
        )
    }

    /// The keys of `bouncelab oblique --format json` in its order, the history arrays (the
    /// same read-only arrays as the attributes) only when there is a history.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        state::to_dict(self, py)
    }

    /// Pickling: the class's `_from_state` and `to_dict()` (every protocol).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::same::Reduced<'py>> {
        crate::same::reduce(slf, state::to_dict(slf.get(), slf.py())?)
    }

    /// The impact of a state [`ObliqueImpact::__reduce__`] wrote.
    #[classmethod]
    fn _from_state(
        _cls: &Bound<'_, pyo3::types::PyType>,
        state: &Bound<'_, PyDict>,
    ) -> PyResult<ObliqueImpact> {
        state::from_state(state)
    }

    /// Equal values: every attribute, the history arrays element by element.
    fn __eq__(&self, py: Python<'_>, other: PyRef<'_, ObliqueImpact>) -> PyResult<bool> {
        state::same(py, self, &other)
    }

    /// A frozen value (its arrays read-only) is its own copy.
    fn __copy__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    fn __deepcopy__(slf: Py<Self>, _memo: &Bound<'_, PyAny>) -> Py<Self> {
        slf
    }
}

/// The result of `r`, an oblique impact of `ball` as `spec` asked: the answer with the ball and
/// the tangential model that ran, each as the command line's JSON gives it (src/cli/oblique.rs).
fn build(
    py: Python<'_>,
    ball: &Ball,
    spec: &ObliqueSpec,
    r: ObliqueResponse,
    surface: SurfaceUsed,
) -> PyResult<ObliqueImpact> {
    let warnings = ball.oblique_warnings_on(&r, &surface);
    let header = ball.header();
    let e = &r.energy;
    let energy = EnergyTerms(
        [
            e.translational_in,
            e.rotational_in,
            e.translational_out,
            e.rotational_out,
            e.normal_dissipation,
            e.friction_dissipation,
            e.tangential_spring,
            e.residual,
        ],
        e.tangential_damping,
    );
    let (mut t, mut fn_, mut ft, mut vc, mut w) = (None, None, None, None, None);
    if let Some(h) = r.history {
        t = Some(frozen_array(py, h.t));
        fn_ = Some(frozen_array(py, h.normal_force));
        ft = Some(frozen_array(py, h.friction_force));
        vc = Some(frozen_array(py, h.slip_velocity));
        w = Some(frozen_array(py, h.spin));
    }
    Ok(ObliqueImpact {
        preset: header.preset.map(String::from),
        origin: header.origin.to_string(),
        parameters: ball.source.to_string(),
        law: header.law.to_string(),
        friction: spec.friction,
        tangential_stiffness: spec.tangential_stiffness.or(ball.tangential_stiffness()),
        inertia_factor: spec.inertia_factor.unwrap_or_else(|| ball.inertia_factor()),
        radius: Some(ball.radius()).filter(|r| !r.is_nan()),
        v_in: r.v_in,
        angle_in_deg: r.angle_in_deg,
        spin_in: r.spin_in,
        vx_in: r.vx_in,
        vy_in: r.vy_in,
        v_out: r.v_out,
        angle_out_deg: r.angle_out_deg,
        spin_out: r.spin_out,
        vx_out: r.vx_out,
        vy_out: r.vy_out,
        cor_normal: r.cor_normal,
        cor_tangential: r.cor_tangential,
        apparent_friction: r.apparent_friction,
        slid_throughout: r.slid_throughout,
        grip_time: r.grip_time,
        contact_time: r.contact_time,
        max_normal_force: r.max_normal_force,
        max_friction_force: r.max_friction_force,
        energy,
        t,
        normal_force: fn_,
        friction_force: ft,
        slip_velocity: vc,
        spin: w,
        warnings,
        tangential_damping: surface.mechanics.tangential_damping,
        surface: surface.into(),
        ball: Record::of(ball),
        conditions: Stated::of(ball),
    })
}

ball_pyfunction! {
    /// One oblique impact of a preset, as `bouncelab oblique --preset NAME [--v0 V] --angle DEG
    /// [--spin W] --friction MU [--tangential-stiffness K_T] [--inertia-factor KAPPA] [--law L]
    /// [--history --samples N] [--surface NAME --surface-stiffness K_S … --tangential-damping C_T]`
    /// (`surface=`: a name or a dict of its numbers, python/src/surface.rs; `friction` the
    /// surface's when not given, required when it has none).
    signature = (preset="superball", *, angle, friction=None, v0=None, spin=0.0, tangential_stiffness=None, inertia_factor=None, law=None, params=None, history=false, samples=None, surface=None, tangential_damping=None,);
    fn oblique<'py>(
        py,
        preset: &str,
        angle: f64,
        friction: Option<f64>,
        v0: Option<f64>,
        spin: f64,
        tangential_stiffness: Option<f64>,
        inertia_factor: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
        history: bool,
        samples: Option<usize>,
        surface: Option<&Bound<'py, PyAny>>,
        tangential_damping: Option<f64>,
    ) -> PyResult<ObliqueImpact>;
    ball choice = (preset, params, law);
    {
        let tangential = [friction, tangential_stiffness, tangential_damping];
        let (surface, friction) = tangential_surface(surface, tangential)?;
        // `run`'s rule: samples only with a history, and at least two of them (the library's
        // `oblique` reads 0 as "no history", which history=True, samples=0 must not ask for)
        let samples = history_samples(history, samples)?;
        if history && samples < 2 {
            return Err(error(BallError::Samples(samples)));
        }
        let ball = choice.resolve(v0)?;
        let spec = ObliqueSpec {
            v: v0,
            angle_deg: angle,
            spin,
            friction,
            tangential_stiffness: surface.mechanics.tangential_stiffness,
            inertia_factor,
        };
        let n = if history { samples } else { 0 };
        let r = ball
            .oblique_on(&spec, surface.mechanics.tangential_damping, n, &surface.mechanics.target())
            .map_err(error)?;
        build(py, &ball, &spec, r, surface)
    }
}

/// The surface of `oblique` and `court`: `surface=` with the tangential arguments (μ, K_t, c_t)
/// over the surface's own, as the command line's `surface_of`; μ must come from one of them.
pub(crate) fn tangential_surface(
    surface: Option<&Bound<'_, PyAny>>,
    args: [Option<f64>; 3],
) -> PyResult<(SurfaceUsed, f64)> {
    let (surface, given) = crate::surface::resolve(surface)?;
    // an argument over the dict's number is refused: one quantity given twice
    let names = ["friction", "tangential_stiffness", "tangential_damping"];
    let mut tangential = [None; 3];
    for (i, (a, g)) in args.into_iter().zip(given).enumerate() {
        if a.is_some() && g.is_some() {
            return Err(value_error(format!(
                "{} given twice: as an argument and in surface=",
                names[i]
            )));
        }
        tangential[i] = a.or(g);
    }
    let surface = surface.with_tangential(tangential);
    let Some(friction) = surface.mechanics.friction else {
        return Err(value_error(format!(
            "invalid friction: the surface {} gives no μ (docs/surfaces.md): give friction",
            surface.name
        )));
    };
    Ok((surface, friction))
}
