//! `Impact`: the answer to one impact as a Python object, built from the library's report of
//! the run ([`ImpactReport`], what `bouncelab run --format json` writes). On the linear law
//! the numbers come from the closed forms where they answer (`Ball::closed_form_summary`, to
//! 1e-12 of the exact solver) and the energy audit with the warnings that read it from the
//! exact solver's run on their first read (docs/python.md, "What a call costs").

use crate::{error, frozen_array};

// pickling and value equality (`__reduce__`, `__eq__`): a child module, so that it reads the
// fields without widening them
#[path = "impact_state.rs"]
mod state;
// one impact's run: the closed form or the solver (a child module: it fills the fields in)
#[path = "impact_run.rs"]
mod run;
// what Python reads of it: getters, `to_dict`, pickling, equality, repr (a child module: it
// reads the fields)
#[path = "impact_methods.rs"]
mod methods;
use bouncelab::Ball;
use bouncelab::api::{ImpactReport, Intervals};
use numpy::PyArray1;
use pyo3::prelude::*;
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
    /// The outputs its ball's record does not vouch for, by their keys (the JSON's
    /// `uncalibrated_outputs`; `None`: the record makes no claim).
    uncalibrated: Option<Vec<String>>,
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

/// Outputs by their JSON keys (`Ball::uncalibrated_outputs`'s, for the dicts of `run`,
/// `sweep_velocity` and `drop`).
pub(crate) fn keys(outputs: Option<&[bouncelab::preset::Output]>) -> Option<Vec<String>> {
    outputs.map(|o| o.iter().map(|o| o.key().to_string()).collect())
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
        let o = &rep.outcome;
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
            cor: o.cor,
            rebound: o.rebound,
            max_force: o.max_force,
            contact_time: o.contact_time,
            max_indentation: o.max_indentation,
            permanent_indentation: o.permanent_indentation,
            max_force_normalized: o.max_force_normalized,
            contact_time_normalized: o.contact_time_normalized,
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
            uncalibrated: keys(rep.uncalibrated_outputs.as_deref()),
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
        let mut rep = ImpactReport::new(ball, &r, false);
        // the surface it ran on says its own (an assumed-rigid one: `SurfaceUsed::warnings`)
        rep.warnings = ball.warnings_on(&r, &self.surface);
        let _ = self.audit.set(Audit::of(&rep));
        Ok(self.audit.get().expect("set above, or by another thread"))
    }

    fn series(&self, py: Python<'_>, i: usize) -> Option<Py<PyArray1<f64>>> {
        self.history.as_ref().map(|h| h[i].clone_ref(py))
    }
}
