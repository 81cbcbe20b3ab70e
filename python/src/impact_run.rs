//! One impact's run for `run`, `run_params` and `run_normalized`: the closed forms where they
//! answer, the audit left to its first read ([`Impact::audit`]); else the solver with its
//! audit (docs/python.md).

use super::{Audit, Impact};
use crate::error;
use bouncelab::Ball;
use bouncelab::api::SurfaceUsed;
use bouncelab::api::{ImpactReport, Intervals};
use pyo3::prelude::*;
use std::sync::Arc;

/// One impact of `ball`, its history sampled `samples` times when asked for. On the linear
/// law without a history, the closed forms where they answer (under a µs: the GIL kept) and
/// the audit left to the first read; else the solver with its audit, the GIL released while
/// it runs. The ball is shared (a preset's, built once: catalog_cache.rs) and kept by the
/// answer for its audit.
pub(crate) fn impact(
    py: Python<'_>,
    ball: Arc<Ball>,
    history: bool,
    samples: usize,
) -> PyResult<Py<Impact>> {
    impact_on(py, ball, SurfaceUsed::rigid_plate(), history, samples)
}

/// [`impact`] on `surface` (at rest), through `Ball::impact_on` as `bouncelab run --surface`
/// runs it: on the rigid plate the closed forms where they answer, else the solver with its
/// audit; on a surface that gives or moves, the ball against it, with no energy audit and the
/// preset's measurement (the rigid plate's) not carried.
pub(crate) fn impact_on(
    py: Python<'_>,
    ball: Arc<Ball>,
    surface: SurfaceUsed,
    history: bool,
    samples: usize,
) -> PyResult<Py<Impact>> {
    let rigid = surface.mechanics.is_rigid();
    if rigid
        && !history
        && let Some(s) = ball.closed_form_summary()
    {
        let intervals = fitted_intervals(py, &ball)?;
        let rep = ImpactReport::of_summary(&ball, &s);
        let mut impact = Impact::new(py, &ball, &rep, intervals, None);
        impact.ball = Some(ball);
        impact.surface = surface;
        // into its Python object here: the answer moved once, not through each caller
        return Py::new(py, impact);
    }
    // the library reads 0 samples as "no history": asked for, 0 is refused (as `run`'s)
    if history && samples == 0 {
        return Err(error(bouncelab::BallError::Samples(0)));
    }
    // the preset's measurement is the rigid plate's: not this impact's on a surface that
    // gives or moves (as `bouncelab run --surface` withholds it)
    let elsewhere = (!rigid && ball.measured.is_some()).then(|| {
        format!(
            "the measurement is on the rigid plate, this impact on surface {}",
            surface.name
        )
    });
    let ball = match elsewhere {
        Some(_) => Arc::new(Ball {
            measured: None,
            ..Arc::unwrap_or_clone(ball)
        }),
        None => ball,
    };
    let target = surface.mechanics.target();
    let n = if history { samples } else { 0 };
    let (r, intervals) = py
        .detach(|| {
            let r = ball.impact_on(&target, n)?;
            Ok::<_, bouncelab::BallError>((r, ball.intervals().transpose()?))
        })
        .map_err(error)?;
    let mut rep = ImpactReport::new(&ball, &r, history);
    // the surface's warnings after the impact's, as `bouncelab run --surface` gives them
    rep.warnings = ball.warnings_on(&r, &surface);
    let audit = Some(Audit::of(&rep));
    let mut impact = Impact::new(py, &ball, &rep, intervals, audit);
    impact.surface = surface;
    if elsewhere.is_some() {
        impact.withheld = elsewhere;
    }
    Py::new(py, impact)
}

/// The 95 % intervals of a fitted preset's impact (several solver runs: the GIL released),
/// `None` for any other ball.
fn fitted_intervals(py: Python<'_>, ball: &Ball) -> PyResult<Option<Intervals>> {
    if ball.fit.is_none() {
        return Ok(None);
    }
    py.detach(|| ball.intervals().transpose()).map_err(error)
}
