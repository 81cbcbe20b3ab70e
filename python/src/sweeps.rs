//! `sweep_zeta` and `sweep_velocity`, as `bouncelab sweep zeta` and `bouncelab sweep velocity`:
//! dicts of numpy arrays with the CSV's columns.

use crate::arguments::ball::ball_pyfunction;
use crate::interval_columns;
use crate::{array, error, floats, interrupt, law, value_error};
use bouncelab::BallError;
use bouncelab::api;
use bouncelab::model::params::{ImpactParams, validate_lambda_zeta};
use pyo3::prelude::*;
use pyo3::types::PyDict;

pub(crate) fn none_as_nan(x: Option<f64>) -> f64 {
    x.unwrap_or(f64::NAN)
}

/// COR, F̄_m and τ_f against ζ for each λ on the normalized ball, as `bouncelab sweep zeta`:
/// a dict of numpy arrays with the CSV's columns (lambda, zeta, cor, max_force_normalized,
/// contact_time_normalized; NaN where the ball does not rebound), rows grouped by λ. The GIL
/// is released while the points run (in parallel).
#[pyfunction]
#[pyo3(signature = (lambdas, zetas, law="linear"))]
pub(crate) fn sweep_zeta<'py>(
    py: Python<'py>,
    lambdas: &Bound<'py, PyAny>,
    zetas: &Bound<'py, PyAny>,
    law: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let (lambdas, zetas, law) = (
        floats(lambdas, "lambdas")?,
        floats(zetas, "zetas")?,
        self::law(law)?,
    );
    // each value checked in order and named by its index, as `sweep_velocity` names a speed:
    // the sweep's own check said "invalid zeta: -1", which names neither the argument nor
    // the element (python/tests/test_arguments.py)
    for (i, &l) in lambdas.iter().enumerate() {
        validate_lambda_zeta(l, 1.0).map_err(|e| value_error(format!("lambdas[{i}]: {e}")))?;
    }
    for (i, &z) in zetas.iter().enumerate() {
        validate_lambda_zeta(0.0, z).map_err(|e| value_error(format!("zetas[{i}]: {e}")))?;
    }
    let rows = interrupt::detach_watched(py, |w| {
        bouncelab::api::sweep_zeta_watched(&lambdas, &zetas, law, w)
    })?;
    let col = |f: fn(&bouncelab::analysis::sweep::ZetaPoint) -> f64| {
        array(py, rows.iter().map(f).collect())
    };
    let d = PyDict::new(py);
    d.set_item("lambda", col(|r| r.lambda))?;
    d.set_item("zeta", col(|r| r.zeta))?;
    d.set_item("cor", col(|r| r.cor))?;
    d.set_item("max_force_normalized", col(|r| r.max_force_normalized))?;
    d.set_item(
        "contact_time_normalized",
        col(|r| none_as_nan(r.contact_time_normalized)),
    )?;
    Ok(d)
}

ball_pyfunction! {
    /// COR, peak force, contact time and permanent indentation against impact speed for a preset,
    /// as `bouncelab sweep velocity`: a dict of numpy arrays with the CSV's columns (v0, cor,
    /// max_force, contact_time, permanent_indentation; NaN contact_time where the ball does not
    /// rebound), and the JSON's `max_indentation`, `warnings` (a list of lists, one a row) and
    /// `uncalibrated_outputs` (the outputs the ball's record does not vouch for).
    /// The GIL is released while the speeds run (in parallel).
    signature = (preset="superball", speeds=None, law=None, params=None, *,);
    fn sweep_velocity<'py>(
        py,
        preset: &str,
        speeds: Option<&Bound<'py, PyAny>>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let ball = choice.ball(None)?;
        let speeds = match speeds {
            Some(s) => floats(s, "speeds")?,
            // the command line's default: 60 speeds from 0.1 to 3 times the preset's
            None => {
                bouncelab::analysis::sweep::lin_space(0.1 * ball.params.v0, 3.0 * ball.params.v0, 60)
            }
        };
        // each speed checked in order first and named by its index, as `impacts` names an
        // element: the parallel sweep's own check reports whichever bad speed a thread met first,
        // as "invalid v0", which names neither the argument nor the element
        for (i, &v0) in speeds.iter().enumerate() {
            ImpactParams { v0, ..ball.params }
                .validate()
                .map_err(|e| value_error(format!("speeds[{i}]: {e}")))?;
        }
        let rows = interrupt::detach_watched(py, |w| ball.sweep_velocity_watched(&speeds, w))?;
        let col = |f: fn(&bouncelab::analysis::sweep::VelocityPoint) -> f64| {
            array(py, rows.iter().map(f).collect())
        };
        let d = PyDict::new(py);
        d.set_item("v0", col(|r| r.v0))?;
        d.set_item("cor", col(|r| r.cor))?;
        d.set_item("max_force", col(|r| r.max_force))?;
        d.set_item("contact_time", col(|r| none_as_nan(r.contact_time)))?;
        d.set_item("permanent_indentation", col(|r| r.permanent_indentation))?;
        // what `sweep velocity --format json` adds to the CSV's columns: each row's peak
        // indentation and its warnings (one list a row: an indentation or the centre past the
        // ball's radius, `Ball::velocity_row_warning`, the command line's own function, so the two
        // give the same: python/tests/test_arguments.py)
        d.set_item("max_indentation", col(|r| r.max_indentation))?;
        let warnings: Vec<Vec<String>> =
            py.detach(|| rows.iter().map(|r| ball.velocity_row_warnings(r)).collect());
        d.set_item("warnings", warnings)?;
        // a fitted preset's 95 % intervals at each speed (docs/fitting.md), as the CSV's columns
        if let Some(fit) = ball.fit.as_ref().filter(|f| api::holds(&ball.params, f)) {
            let bands = py
                .detach(|| {
                    rows.iter()
                        .map(|r| {
                            let p = ImpactParams {
                                v0: r.v0,
                                ..ball.params
                            };
                            let i = api::intervals(&p, ball.law, fit)?;
                            let t = i.contact_time_ci95.unwrap_or([f64::NAN; 2]);
                            Ok([i.cor_ci95, i.max_force_ci95, t])
                        })
                        .collect::<Result<Vec<_>, BallError>>()
                })
                .map_err(error)?;
            interval_columns(py, &d, ["cor", "max_force", "contact_time"], &bands)?;
        }
        // the outputs its record does not vouch for, as the JSON's
        let not = ball.uncalibrated_outputs(&bouncelab::preset::Output::IMPACT);
        d.set_item("uncalibrated_outputs", crate::impact::keys(not.as_deref()))?;
        // the ball swept and its conditions, as the JSON's `ball` and `conditions`
        crate::answer::stated(&d, &ball)?;
        d.set_item("surface", crate::surface::rigid_plate(py)?)?;
        Ok(d)
    }
}
