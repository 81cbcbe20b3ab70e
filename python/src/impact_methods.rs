//! What Python reads of an [`Impact`]: the history arrays, the intervals, the measurement,
//! the surface, ball and conditions, the energy audit (run on its first read:
//! [`Impact::audit`]), everything as a dict with the keys of `bouncelab run --format json`,
//! pickling, value equality and the repr.

use super::{ENERGY_KEYS, HISTORY_KEYS, Impact, MEASURED_KEYS, state};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

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

    /// The outputs the ball's record does not vouch for, by their keys (the JSON's
    /// `uncalibrated_outputs`): the model's alone; None when the record makes no claim
    /// (docs/presets.md, "The calibration record").
    #[getter]
    fn uncalibrated_outputs(&self) -> Option<Vec<String>> {
        self.uncalibrated.clone()
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
        d.set_item("uncalibrated_outputs", &self.uncalibrated)?;
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
