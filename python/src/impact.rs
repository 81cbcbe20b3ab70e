//! `Impact`: the answer to one impact as a Python object, built from the library's report of
//! the run ([`ImpactReport`], what `bouncelab run --format json` writes). On the linear law
//! the numbers come from the closed forms where they answer (`Ball::closed_form_summary`, to
//! 1e-12 of the exact solver) and the energy audit with the warnings that read it from the
//! exact solver's run on their first read (docs/python.md, "What a call costs").

use crate::{array, error, frozen_array};

// pickling and value equality (`__reduce__`, `__eq__`): a child module, so that it reads the
// fields without widening them
#[path = "impact_state.rs"]
mod state;
// one impact's run: the closed form or the solver (a child module: it fills the fields in)
#[path = "impact_run.rs"]
mod run;
use bouncelab::Ball;
use bouncelab::api::{ImpactReport, Intervals};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
pub(crate) use run::{impact, impact_on};
use std::borrow::Cow;
use std::sync::{Arc, OnceLock};

/// The answer to one impact, SI units; attribute names are the keys of `bouncelab run
/// --format json` (`lambda_` for `lambda`, a Python keyword).
#[pyclass(frozen, module = "bouncelab")]
pub(crate) struct Impact {
    #[pyo3(get)]
    preset: Option<String>,
    // the words borrowed where they are the library's own (no allocation a call)
    #[pyo3(get)]
    origin: Cow<'static, str>,
    #[pyo3(get)]
    parameters: Cow<'static, str>,
    #[pyo3(get)]
    law: Cow<'static, str>,
    #[pyo3(get)]
    method: Cow<'static, str>,
    #[pyo3(get)]
    mass: f64,
    #[pyo3(get)]
    k_p: f64,
    #[pyo3(get)]
    k_r: f64,
    #[pyo3(get)]
    c: f64,
    #[pyo3(get)]
    z_p: f64,
    #[pyo3(get)]
    k_h: f64,
    #[pyo3(get)]
    v0: f64,
    #[pyo3(get)]
    lambda_: f64,
    #[pyo3(get)]
    zeta: f64,
    #[pyo3(get)]
    zp_bar: f64,
    /// R, m (`None` for a ball that is no preset), as `run`'s JSON `radius`.
    #[pyo3(get)]
    radius: Option<f64>,
    /// ν of the preset's material (`None` for a ball that is no preset).
    #[pyo3(get)]
    poisson_ratio: Option<f64>,
    #[pyo3(get)]
    cor: f64,
    #[pyo3(get)]
    rebound: bool,
    #[pyo3(get)]
    max_force: f64,
    #[pyo3(get)]
    contact_time: Option<f64>,
    #[pyo3(get)]
    max_indentation: f64,
    #[pyo3(get)]
    permanent_indentation: f64,
    #[pyo3(get)]
    max_force_normalized: f64,
    #[pyo3(get)]
    contact_time_normalized: Option<f64>,
    /// (v0, cor, max_force, contact_time) measured, presets only
    measured: Option<[Option<f64>; 4]>,
    /// t, force, indentation, displacement, when the history was asked for
    history: Option<[Py<PyArray1<f64>>; 4]>,
    /// 95 % intervals on a fitted preset (docs/fitting.md, "Prediction intervals")
    intervals: Option<Intervals>,
    /// The energy budget and the warnings, once computed ([`Audit`]).
    audit: OnceLock<Audit>,
    /// The ball, kept until [`Impact::audit`] has run its audit (`None` once the audit was
    /// there from the start: the solver's own run, or a state that carried it); shared, so
    /// that the answer stays small to move and a preset's ball is not copied (catalog_cache.rs).
    ball: Option<Arc<Ball>>,
    /// The surface it ran on (the JSON's `surface`; the rigid plate unless `surface=`).
    surface: bouncelab::api::SurfaceUsed,
    /// The ball it ran and its conditions (the JSON's `ball` and `conditions`).
    named: (crate::answer::Record, crate::answer::Stated),
    /// Why the answer is not compared with `measured` (the JSON's `comparison_withheld`).
    withheld: Option<String>,
}

/// What `bouncelab run` reports from the exact solver's run with its energy audit: the
/// budget, and the warnings (an indentation beyond the radius, a budget that does not close).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Audit {
    /// (initial_kinetic, final_kinetic, dashpot, contact, spring, relative_residual)
    energy: Option<[f64; 6]>,
    /// What the caller should know about this answer (the JSON's `warnings`).
    warnings: Vec<String>,
}

impl Audit {
    /// The audit of the report of a run with its energy budget.
    fn of(rep: &ImpactReport<'_>) -> Audit {
        Audit {
            energy: rep.energy.map(|e| {
                let b = e.budget;
                [
                    b.initial_kinetic,
                    b.final_kinetic,
                    b.dashpot,
                    b.contact,
                    b.spring,
                    e.relative_residual,
                ]
            }),
            warnings: rep.warnings.clone(),
        }
    }
}

const MEASURED_KEYS: [&str; 4] = ["v0", "cor", "max_force", "contact_time"];
const ENERGY_KEYS: [&str; 6] = [
    "initial_kinetic",
    "final_kinetic",
    "dashpot",
    "contact",
    "spring",
    "relative_residual",
];
const HISTORY_KEYS: [&str; 4] = ["t", "force", "indentation", "displacement"];

impl Impact {
    /// The library's report of the run (`bouncelab run --format json`), as Python values;
    /// without its audit, the caller keeps the ball in it for [`Impact::audit`].
    fn new(
        py: Python<'_>,
        ball: &Ball,
        rep: &ImpactReport<'_>,
        intervals: Option<Intervals>,
        audit: Option<Audit>,
    ) -> Impact {
        let series = |s: Option<&[f64]>| s.map(|v| frozen_array(py, v.to_vec()));
        let h = [rep.t, rep.force, rep.indentation, rep.displacement].map(series);
        Impact {
            preset: rep.ball.preset.map(String::from),
            origin: match rep.ball.origin {
                "embedded" => Cow::Borrowed("embedded"),
                "normalized" => Cow::Borrowed("normalized"),
                "parameters" => Cow::Borrowed("parameters"),
                other => Cow::Owned(other.to_string()),
            },
            parameters: Cow::Borrowed(ball.source),
            law: Cow::Borrowed(rep.ball.law),
            method: Cow::Borrowed(rep.method.name()),
            mass: rep.mass,
            k_p: rep.k_p,
            k_r: rep.k_r,
            c: rep.c,
            z_p: rep.z_p,
            k_h: rep.k_h,
            v0: rep.v0,
            lambda_: rep.lambda,
            zeta: rep.zeta,
            zp_bar: rep.zp_bar,
            radius: rep.radius,
            poisson_ratio: rep.poisson_ratio,
            cor: rep.cor,
            rebound: rep.rebound,
            max_force: rep.max_force,
            contact_time: rep.contact_time,
            max_indentation: rep.max_indentation,
            permanent_indentation: rep.permanent_indentation,
            max_force_normalized: rep.max_force_normalized,
            contact_time_normalized: rep.contact_time_normalized,
            measured: rep
                .measured
                .map(|m| [Some(m.v0), m.cor, m.max_force, m.contact_time]),
            history: match h {
                [Some(t), Some(f), Some(z), Some(a)] => Some([t, f, z, a]),
                _ => None,
            },
            intervals,
            audit: audit.map_or_else(OnceLock::new, OnceLock::from),
            ball: None,
            surface: bouncelab::api::SurfaceUsed::rigid_plate(),
            named: (
                crate::answer::Record(rep.record.clone()),
                crate::answer::Stated::of(ball),
            ),
            withheld: rep.comparison_withheld.clone(),
        }
    }

    /// The energy budget and the warnings: `bouncelab run`'s, from the exact solver's run of
    /// the kept ball with its audit the first time they are read (the GIL released while it
    /// runs, and not held by a lock meanwhile: two threads may both run it, and the first to
    /// finish keeps its answer, the same numbers).
    pub(crate) fn audit(&self, py: Python<'_>) -> PyResult<&Audit> {
        if let Some(a) = self.audit.get() {
            return Ok(a);
        }
        let Some(ball) = self.ball.as_ref() else {
            unreachable!("an impact without its audit keeps its ball")
        };
        let r = py.detach(|| ball.impact()).map_err(error)?;
        let _ = self
            .audit
            .set(Audit::of(&ImpactReport::new(ball, &r, false)));
        Ok(self.audit.get().expect("set above, or by another thread"))
    }

    fn series(&self, py: Python<'_>, i: usize) -> Option<Py<PyArray1<f64>>> {
        self.history.as_ref().map(|h| h[i].clone_ref(py))
    }
}

#[pymethods]
impl Impact {
    /// Times t (s) of the history, or None without `history=True`.
    #[getter]
    fn t(&self, py: Python<'_>) -> Option<Py<PyArray1<f64>>> {
        self.series(py, 0)
    }

    /// Force F(t) (N), or None without `history=True`.
    #[getter]
    fn force(&self, py: Python<'_>) -> Option<Py<PyArray1<f64>>> {
        self.series(py, 1)
    }

    /// Indentation z(t) (m), or None without `history=True`.
    #[getter]
    fn indentation(&self, py: Python<'_>) -> Option<Py<PyArray1<f64>>> {
        self.series(py, 2)
    }

    /// Displacement α(t) of the centre of mass (m), or None without `history=True`.
    #[getter]
    fn displacement(&self, py: Python<'_>) -> Option<Py<PyArray1<f64>>> {
        self.series(py, 3)
    }

    /// The 95 % interval (lo, hi) of the COR on a preset saved by `fit --save`, else None.
    #[getter]
    fn cor_ci95(&self) -> Option<(f64, f64)> {
        self.intervals.map(|i| i.cor_ci95.into())
    }

    /// The 95 % interval (lo, hi) of the peak force (N) on a fitted preset, else None.
    #[getter]
    fn max_force_ci95(&self) -> Option<(f64, f64)> {
        self.intervals.map(|i| i.max_force_ci95.into())
    }

    /// The 95 % interval (lo, hi) of the contact time (s) on a fitted preset, else None.
    #[getter]
    fn contact_time_ci95(&self) -> Option<(f64, f64)> {
        self.intervals
            .and_then(|i| i.contact_time_ci95)
            .map(Into::into)
    }

    /// What was measured (v0, cor, max_force, contact_time), presets only.
    #[getter]
    fn measured<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(m) = self.measured else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        for (k, v) in MEASURED_KEYS.iter().zip(m) {
            d.set_item(k, v)?;
        }
        Ok(Some(d))
    }

    /// The surface it ran on, as the JSON's `surface` object (docs/surfaces.md): name,
    /// origin, stiffness, damping, mass (∞: rigid, fixed), friction, tangential_stiffness,
    /// tangential_damping, overrides.
    #[getter]
    fn surface<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        crate::surface::to_dict(py, &self.surface)
    }

    /// The ball it ran, as the JSON's `ball` object (docs/cli.md, "The ball object"): name,
    /// origin, law, mass, radius, k_p, c, k_r, z_p, k_h, inertia_factor, overrides.
    #[getter]
    fn ball<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.named.0.into_pyobject(py)
    }

    /// Why the answer is not compared with the preset's measurement (an override changed
    /// the ball, or it ran elsewhere than the measurement), else None.
    #[getter]
    fn comparison_withheld(&self) -> Option<String> {
        self.withheld.clone()
    }

    /// The conditions it ran at: temperature_c, pressure_gauge_pa (None for a solid ball),
    /// atmosphere_pa.
    #[getter]
    fn conditions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        self.named.1.into_pyobject(py)
    }

    /// The energy budget (J): initial_kinetic, final_kinetic, dashpot, contact, spring and
    /// relative_residual.
    #[getter]
    fn energy<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(e) = self.audit(py)?.energy else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        for (k, v) in ENERGY_KEYS.iter().zip(e) {
            d.set_item(k, v)?;
        }
        Ok(Some(d))
    }

    /// What the caller should know about this answer (the JSON's `warnings`): an
    /// indentation beyond the ball's radius, an energy balance that does not close.
    #[getter]
    fn warnings(&self, py: Python<'_>) -> PyResult<Vec<String>> {
        Ok(self.audit(py)?.warnings.clone())
    }

    /// Everything as a dict with the keys of `bouncelab run --format json` (`lambda`, not
    /// `lambda_`; the history arrays when asked for). Infinite z_p or c stay `inf` (the JSON
    /// writes `null`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("preset", &self.preset)?;
        d.set_item("origin", &self.origin)?;
        d.set_item("parameters", &self.parameters)?;
        d.set_item("law", &self.law)?;
        d.set_item("ball", self.ball(py)?)?;
        d.set_item("comparison_withheld", &self.withheld)?;
        d.set_item("method", &self.method)?;
        let numbers = [
            ("mass", self.mass),
            ("k_p", self.k_p),
            ("k_r", self.k_r),
            ("c", self.c),
            ("z_p", self.z_p),
            ("k_h", self.k_h),
            ("v0", self.v0),
            ("lambda", self.lambda_),
            ("zeta", self.zeta),
            ("zp_bar", self.zp_bar),
        ];
        for (k, v) in numbers {
            d.set_item(k, v)?;
        }
        d.set_item("radius", self.radius)?;
        d.set_item("poisson_ratio", self.poisson_ratio)?;
        d.set_item("cor", self.cor)?;
        d.set_item("rebound", self.rebound)?;
        d.set_item("max_force", self.max_force)?;
        d.set_item("contact_time", self.contact_time)?;
        d.set_item("max_indentation", self.max_indentation)?;
        d.set_item("permanent_indentation", self.permanent_indentation)?;
        d.set_item("max_force_normalized", self.max_force_normalized)?;
        d.set_item("contact_time_normalized", self.contact_time_normalized)?;
        d.set_item("measured", self.measured(py)?)?;
        d.set_item("energy", self.energy(py)?)?;
        d.set_item("warnings", self.warnings(py)?)?;
        if self.intervals.is_some() {
            d.set_item("cor_ci95", self.cor_ci95())?;
            d.set_item("max_force_ci95", self.max_force_ci95())?;
            d.set_item("contact_time_ci95", self.contact_time_ci95())?;
        }
        for (i, k) in HISTORY_KEYS.iter().enumerate() {
            if let Some(a) = self.series(py, i) {
                d.set_item(k, a)?;
            }
        }
        d.set_item("surface", crate::surface::to_dict(py, &self.surface)?)?;
        d.set_item("conditions", self.conditions(py)?)?;
        Ok(d)
    }

    /// Pickling (and `copy.copy`, `copy.deepcopy`): rebuilt from [`Impact::to_dict`] by
    /// `Impact._from_state` (python/tests/test_pickle.py).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::same::Reduced<'py>> {
        crate::same::reduce(slf, slf.get().to_dict(slf.py())?)
    }

    /// The impact of a state [`Impact::__reduce__`] wrote.
    #[classmethod]
    fn _from_state(
        _cls: &Bound<'_, pyo3::types::PyType>,
        state: &Bound<'_, PyDict>,
    ) -> PyResult<Impact> {
        state::from_state(state)
    }

    /// Equal values: every attribute, the history arrays element by element (a NaN equals a
    /// NaN, so that a copy equals its original).
    fn __eq__(&self, py: Python<'_>, other: PyRef<'_, Impact>) -> PyResult<bool> {
        Ok(state::same(self, self.audit(py)?, &other, other.audit(py)?))
    }

    fn __repr__(&self) -> String {
        let who = match &self.preset {
            Some(p) => format!("preset='{p}', "),
            None => String::new(),
        };
        let t_f = self
            .contact_time
            .map_or("None".to_string(), |t| format!("{t:?}"));
        format!(
            "Impact({who}law='{}', v0={:?}, cor={:?}, max_force={:?}, contact_time={t_f}, \
             rebound={})",
            self.law,
            self.v0,
            self.cor,
            self.max_force,
            if self.rebound { "True" } else { "False" }
        )
    }
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
