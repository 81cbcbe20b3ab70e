//! `fit` (the recoil spring that gives a measured COR, as `bouncelab fit --cor`) and `drop`
//! (a preset dropped bounce by bounce, as `bouncelab drop`).

use crate::impact::interval_columns;
use crate::{array, error, interrupt, preset_ball, value_error};
use bouncelab::analysis::fit::Fit;
use bouncelab::api::FitReport;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The recoil spring K_r (and λ) that makes the model's COR equal a measured one, at the
/// preset's ζ, z_p and v0 (or the `v0` given), as `bouncelab fit --cor E`: a dict with the
/// keys of `bouncelab fit --format json`.
#[pyfunction]
#[pyo3(signature = (cor, preset="superball", v0=None, law=None, params=None))]
pub(crate) fn fit<'py>(
    py: Python<'py>,
    cor: f64,
    preset: &str,
    v0: Option<f64>,
    law: Option<&str>,
    params: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let ball = preset_ball(preset, params, law, v0)?;
    let f: Fit = py.detach(|| ball.fit_cor(cor)).map_err(error)?;
    let r = FitReport::new(&ball, cor, &f);
    let d = PyDict::new(py);
    d.set_item("preset", r.ball.preset)?;
    d.set_item("origin", r.ball.origin)?;
    d.set_item("parameters", r.ball.parameters)?;
    d.set_item("law", r.ball.law)?;
    d.set_item("v0", r.v0)?;
    d.set_item("target_cor", r.target_cor)?;
    d.set_item("k_r", r.k_r)?;
    d.set_item("lambda", r.lambda)?;
    d.set_item("zeta", r.zeta)?;
    d.set_item("cor", r.cor)?;
    d.set_item("k_p", r.k_p)?;
    d.set_item("preset_k_r", r.preset_k_r)?;
    d.set_item("preset_lambda", r.preset_lambda)?;
    Ok(d)
}

/// A preset ball dropped onto a rigid plate, bounce by bounce, as `bouncelab drop` (without
/// `--standard`): a dict with `height`, `drag` and `bounces`, the latter a dict of numpy arrays
/// with the JSON's per-bounce keys (v_in, v_out, cor, rebound_height, contact_time, max_force,
/// t_start), one entry a bounce.
#[pyfunction(name = "drop")]
#[pyo3(signature = (preset="superball", height=1.0, bounces=10, min_rebound=0.001, drag=true, drag_coefficient=None, air_density=None, law=None, params=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn drop_test<'py>(
    py: Python<'py>,
    preset: &str,
    height: f64,
    bounces: usize,
    min_rebound: f64,
    drag: bool,
    drag_coefficient: Option<f64>,
    air_density: Option<f64>,
    law: Option<&str>,
    params: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    use bouncelab::drop::{Air, Bounce, DropSetup};
    if !drag && (drag_coefficient.is_some() || air_density.is_some()) {
        // as the command line refuses --no-drag with --drag-coefficient or --air-density
        return Err(value_error(
            "drag=False cannot be used with drag_coefficient or air_density".into(),
        ));
    }
    let ball = preset_ball(preset, params, law, None)?;
    let air = drag.then(|| Air {
        density: air_density.unwrap_or(Air::default().density),
        drag_coefficient: drag_coefficient.unwrap_or(Air::default().drag_coefficient),
    });
    let setup = DropSetup {
        height,
        air,
        bounces,
        min_rebound,
    };
    let run = interrupt::detach_watched(py, |w| ball.drop_test_watched(&setup, w))?;
    let col = |f: fn(&Bounce) -> f64| array(py, run.bounces.iter().map(f).collect());
    let b = PyDict::new(py);
    b.set_item("v_in", col(|r| r.v_in))?;
    b.set_item("v_out", col(|r| r.v_out))?;
    b.set_item("cor", col(|r| r.cor))?;
    b.set_item("rebound_height", col(|r| r.rebound_height))?;
    b.set_item("contact_time", col(|r| r.contact_time))?;
    b.set_item("max_force", col(|r| r.max_force))?;
    b.set_item("t_start", col(|r| r.t_start))?;
    if let Some(bands) =
        interrupt::detach_watched(py, |w| ball.drop_intervals_watched(&setup, w).transpose())?
    {
        let names = ["cor", "max_force", "contact_time", "rebound_height"];
        interval_columns(py, &b, names, &bands)?;
    }
    let d = PyDict::new(py);
    d.set_item("height", run.setup.height)?;
    d.set_item("drag", run.drag())?;
    d.set_item("bounces", b)?;
    let mut warnings = ball.drop_warnings(&run).map_err(error)?;
    // a ball fitted to drops in another air than this drop's says so, as the command line's
    warnings.extend(ball.drop_air_warning(run.setup.air));
    d.set_item("warnings", warnings)?;
    Ok(d)
}
