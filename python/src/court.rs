//! `court`: the ITF Court Pace Rating of a surface (ITF CS 01/02) from the oblique impact of
//! the ball at 30 m/s and 16° without spin (docs/oblique.md §6), as `bouncelab court --format
//! json`: the library's rating (`Ball::court_pace_on`) and calibration
//! (`Ball::calibrate_court`) under the JSON's keys.

use crate::ball_args::ball_pyfunction;
use crate::oblique::tangential_surface;
use crate::{error, value_error};
use bouncelab::Ball;
use bouncelab::api::CourtCalibration;
use pyo3::prelude::*;
use pyo3::types::PyDict;

ball_pyfunction! {
    /// The ITF court pace of a surface for the ball, as `bouncelab court --preset NAME
    /// [--friction MU] [--surface NAME --surface-stiffness K_S …] [--surface-cor E]
    /// --format json`: `surface=` a name or a dict of its numbers (python/src/surface.rs),
    /// `friction` μ (the surface's when not given, required when it has none), `surface_cor`
    /// a measured vertical COR e the court is calibrated to (c_s solved, K_s held: the dict's
    /// `stiffness`, else the ball's K_p, an assumption the answer states). A dict with the
    /// JSON's keys: the ball, `standard`, `friction`, `cpr`, `category`, `category_name`,
    /// `apparent_friction`, `cor_normal`, `v_out`, `angle_out_deg`, `spin_out`, `warnings`,
    /// `surface`, `calibration` (with `surface_cor`), `computed_on`, `ball`, `conditions`.
    signature = (preset="superball", *, friction=None, surface=None, surface_cor=None, tangential_stiffness=None, inertia_factor=None, tangential_damping=None, law=None, params=None,);
    fn court<'py>(
        py,
        preset: &str,
        friction: Option<f64>,
        surface: Option<&Bound<'py, PyAny>>,
        surface_cor: Option<f64>,
        tangential_stiffness: Option<f64>,
        inertia_factor: Option<f64>,
        tangential_damping: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let ball = choice.resolve(None)?;
        let tangential = [friction, tangential_stiffness, tangential_damping];
        let (mut surface, friction) = tangential_surface(surface, tangential)?;
        let calibration = match surface_cor {
            Some(e) => Some(calibrate(&ball, e, &mut surface)?),
            None => None,
        };
        let computed_on = format!(
            "the model's bounce of {} at 30 m/s and 16° without spin on {}",
            ball.label(),
            surface.label()
        );
        let tangential = (
            surface.tangential_stiffness,
            inertia_factor,
            surface.tangential_damping,
        );
        let pace = py
            .detach(|| ball.court_pace_on(friction, tangential, &surface.target()))
            .map_err(error)?;
        let d = crate::answer::json(py, &ball.header())?.cast_into::<PyDict>()?;
        d.set_item("standard", "itf-court-pace")?;
        d.set_item("friction", friction)?;
        if let Some(c) = surface.tangential_damping {
            d.set_item("tangential_damping", c)?;
        }
        d.update(crate::answer::json(py, &pace)?.cast::<pyo3::types::PyMapping>()?)?;
        d.set_item("surface", crate::surface::to_dict(py, &surface)?)?;
        if let Some(c) = &calibration {
            d.set_item("calibration", crate::answer::json(py, c)?)?;
        }
        d.set_item("computed_on", computed_on)?;
        crate::answer::stated(&d, &ball)?;
        Ok(d)
    }
}

/// The surface calibrated to the measured e at the ITF test, as `court --surface-cor E`: c_s
/// solved, K_s held (the dict's `stiffness`, else the ball's K_p), the surface's numbers and
/// overrides changed as the command line changes them.
fn calibrate(
    ball: &Ball,
    e: f64,
    surface: &mut bouncelab::api::SurfaceUsed,
) -> PyResult<CourtCalibration> {
    let given = |k: &str| surface.overrides.iter().any(|o| o == k);
    if given("damping") {
        // as the command line refuses --surface-cor with --surface-damping
        return Err(value_error(
            "surface_cor solves the surface's damping: give no damping in surface=".into(),
        ));
    }
    let stiffness = given("stiffness").then_some(surface.stiffness);
    let c = ball
        .calibrate_court(e, stiffness, surface.mass)
        .map_err(error)?;
    // as the command line calibrates and names it
    surface.calibrated(&c, "court --surface-cor");
    Ok(c)
}
