//! `court`: the ITF Court Pace Rating of a surface (ITF CS 01/02) from the oblique impact of
//! the ball at 30 m/s and 16° without spin (docs/oblique.md §6), as `bouncelab court --format
//! json`: the library's rating (`Ball::court_pace_on`) and calibration
//! (`Ball::calibrate_court`) under the JSON's keys.

use crate::arguments::ball::ball_pyfunction;
use crate::batch::read_text;
use crate::oblique::tangential_surface;
use crate::{error, value_error};
use bouncelab::Ball;
use bouncelab::api::{CourtCalibration, CourtMeasured, court_measured};
use bouncelab::measured::parse_court;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

ball_pyfunction! {
    /// The ITF court pace of a surface for the ball, as `bouncelab court --preset NAME
    /// [--friction MU] [--surface NAME --surface-stiffness K_S …] [--surface-cor E]
    /// --format json`: `surface=` a name or a dict of its numbers (python/src/surface.rs),
    /// `friction` μ (the surface's when not given, required when it has none), `surface_cor`
    /// a measured vertical COR e the court is calibrated to (c_s solved, K_s held: the dict's
    /// `stiffness`, else the ball's K_p, an assumption the answer states). A dict with the
    /// JSON's keys: the ball, `standard`, `friction`, `cpr`, `category`, `category_name`,
    /// `apparent_friction`, `cor_normal`, `v_out`, `angle_out_deg`, `spin_out`, `warnings`,
    /// `surface`, `calibration` (with `surface_cor` or `fit`), `measured` (with `fit`),
    /// `computed_on`, `ball`, `conditions`. `fit` a file of measured ITF test bounces (CSV:
    /// v_in, angle_in, v_out, angle_out in m/s and degrees), as `court --fit FILE`: their mean
    /// μ_app and e are the friction and the e the court is calibrated to.
    signature = (preset="tennis", *, friction=None, surface=None, surface_cor=None, fit=None, tangential_stiffness=None, inertia_factor=None, tangential_damping=None, law=None, params=None,);
    fn court<'py>(
        py,
        preset: &str,
        friction: Option<f64>,
        surface: Option<&Bound<'py, PyAny>>,
        surface_cor: Option<f64>,
        fit: Option<PathBuf>,
        tangential_stiffness: Option<f64>,
        inertia_factor: Option<f64>,
        tangential_damping: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let measured = fit.map(|path| measured(path, [friction, surface_cor])).transpose()?;
        let ball = choice.resolve(None)?;
        let friction = measured.as_ref().map(|(m, _)| m.apparent_friction).or(friction);
        let tangential = [friction, tangential_stiffness, tangential_damping];
        let (mut surface, friction) = tangential_surface(surface, tangential)?;
        // the measured e, as `--fit` calibrates to it, else the one given
        let target = match &measured {
            Some((m, how)) => Some((m.cor_normal, how.as_str())),
            None => surface_cor.map(|e| (e, "court --surface-cor")),
        };
        let calibration = match target {
            Some((e, how)) => Some(calibrate(&ball, e, &mut surface, how)?),
            None => None,
        };
        let (pace, computed_on) = py
            .detach(|| ball.court_pace_on_surface(friction, inertia_factor, &surface))
            .map_err(error)?;
        let d = crate::answer::json(py, &ball.header())?.cast_into::<PyDict>()?;
        d.set_item("standard", "itf-court-pace")?;
        d.set_item("friction", friction)?;
        if let Some(c) = surface.mechanics.tangential_damping {
            d.set_item("tangential_damping", c)?;
        }
        d.update(crate::answer::json(py, &pace)?.cast::<pyo3::types::PyMapping>()?)?;
        d.set_item("surface", crate::surface::to_dict(py, &surface)?)?;
        if let Some(c) = &calibration {
            d.set_item("calibration", crate::answer::json(py, c)?)?;
        }
        if let Some((m, _)) = &measured {
            d.set_item("measured", crate::answer::json(py, m)?)?;
        }
        d.set_item("computed_on", computed_on)?;
        crate::answer::stated(&d, &ball)?;
        Ok(d)
    }
}

/// The means of the measured bounces in `path` (`court --fit FILE`) and how the court is
/// calibrated to them; refused beside `friction` or `surface_cor`, which they give, as the
/// command line refuses `--fit` with `--friction` or `--surface-cor`. A cell that does not
/// read is named `FILE:LINE:COLUMN: message`, as the command line names it.
fn measured(path: PathBuf, given: [Option<f64>; 2]) -> PyResult<(CourtMeasured, String)> {
    if given.iter().any(Option::is_some) {
        return Err(value_error(
            "fit measures μ_app and e: give no friction or surface_cor with it".into(),
        ));
    }
    let text = read_text(&path)?;
    let shown = path.display().to_string();
    let rows = parse_court(&text).map_err(|e| value_error(format!("{shown}:{e}")))?;
    let name = path
        .file_name()
        .map_or_else(|| shown.clone(), |n| n.to_string_lossy().into_owned());
    Ok((court_measured(name, &rows), format!("court --fit {shown}")))
}

/// The surface calibrated to the measured e at the ITF test, as `court --surface-cor E` (or
/// `--fit FILE`, `how`): c_s solved, K_s held (the dict's `stiffness`, else the ball's K_p),
/// the surface's numbers and overrides changed as the command line changes them.
fn calibrate(
    ball: &Ball,
    e: f64,
    surface: &mut bouncelab::api::SurfaceUsed,
    how: &str,
) -> PyResult<CourtCalibration> {
    let given = |k: &str| surface.overrides.iter().any(|o| o == k);
    if given("damping") {
        // as the command line refuses --surface-cor and --fit with --surface-damping
        return Err(value_error(
            "surface_cor and fit solve the surface's damping: give no damping in surface=".into(),
        ));
    }
    let stiffness = given("stiffness").then_some(surface.mechanics.stiffness);
    let c = ball
        .calibrate_court(e, stiffness, surface.mechanics.mass)
        .map_err(error)?;
    // as the command line calibrates and names it
    surface.calibrated(&c, how);
    Ok(c)
}
