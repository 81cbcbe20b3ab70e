//! `drop`: a preset dropped bounce by bounce, and judged against a standard, as `bouncelab drop
//! --format json` (src/cli/drop.rs), under its keys.

use crate::arguments::ball::{BallChoice, ball_pyfunction};
use crate::interval_columns;
use crate::{array, error, interrupt, value_error};
use bouncelab::BallError;
use bouncelab::analysis::statics::StaticDeflection;
use bouncelab::api::{self, Ball};
use bouncelab::drop::conditions::PressureLoss;
use bouncelab::drop::deformation::{self, DeformationStandard};
use bouncelab::drop::standards::{self, Standard, Verdict};
use bouncelab::drop::{Air, Bounce, DropRun, DropSetup};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Release height without a standard (m): the command line's `--height` default
/// (`cli::drop::DEFAULT_HEIGHT`, a feature the package does not build).
const DEFAULT_HEIGHT: f64 = 1.0;

ball_pyfunction! {
    /// A preset ball dropped onto a rigid plate, bounce by bounce, as `bouncelab drop --format
    /// json`: released from rest at `height` (m, the bottom of the ball; None: the standard's drop
    /// height, else 1 m). A dict with `height`, `drag`, `bounces` (a dict of numpy arrays with the
    /// JSON's per-bounce keys, one entry a bounce), `warnings`, and with `standard` named (as
    /// `bouncelab standards` lists them), `standard`: the verdict (name, window, measured, verdict,
    /// margin, judged_at_height_m: the standard's own drop height, None for a COR test) of that
    /// standard's own test in this drop's air, whatever `height` says. No standard
    /// is judged unless named, as on the command line; a preset's own is the one whose `balls`
    /// list it in `standards()`.
    #[pyo3(name = "drop")]
    signature = (preset="superball", height=None, bounces=10, min_rebound=0.001, drag=true, drag_coefficient=None, air_density=None, law=None, params=None, standard=None, *, surface=None,);
    fn drop_test<'py>(
        py,
        preset: &str,
        height: Option<f64>,
        bounces: usize,
        min_rebound: f64,
        drag: bool,
        drag_coefficient: Option<f64>,
        air_density: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
        standard: Option<&str>,
        surface: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let fall = (height, bounces, min_rebound);
        let air = (drag, drag_coefficient, air_density);
        drop_of(py, &choice, fall, air, standard, surface)
    }
}

/// [`drop_test`]'s body: the ball of `choice` dropped from `height`.
fn drop_of<'py>(
    py: Python<'py>,
    choice: &BallChoice<'_>,
    (height, bounces, min_rebound): (Option<f64>, usize, f64),
    (drag, drag_coefficient, air_density): (bool, Option<f64>, Option<f64>),
    standard: Option<&str>,
    surface: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    if !drag && (drag_coefficient.is_some() || air_density.is_some()) {
        // as the command line refuses --no-drag with --drag-coefficient or --air-density
        return Err(value_error(
            "drag=False cannot be used with drag_coefficient or air_density".into(),
        ));
    }
    // the standard first, as the command line looks it up before the ball
    let judged = standard.map(find).transpose()?;
    let (standard, static_standard, leak_test) = match judged {
        None => (None, None, None),
        Some(Judged::Impact(s)) => (Some(s), None, None),
        Some(Judged::Static(d)) => (None, Some(d), None),
        Some(Judged::Leak(t)) => (None, None, Some(t)),
    };
    // the pressure-loss test runs the ball at its conditions, with the caller's half-life
    let leak = leak_test
        .map(|t| {
            let flag = |n: &str| format!("{}=", n.replace('-', "_"));
            let c = api::leak_test_conditions(t, &choice.conditions, flag).map_err(value_error)?;
            let v = api::judge_leak(t, c.half_life.unwrap_or(f64::NAN)).map_err(value_error)?;
            Ok::<_, PyErr>((c, v))
        })
        .transpose()?;
    let ball = match &leak {
        Some((conditions, _)) => BallChoice {
            conditions: *conditions,
            ..*choice
        }
        .resolve(None)?,
        None => choice.resolve(None)?,
    };
    // a standard runs the ball at its test's conditions, and says when it is off them
    let (ball, off_conditions) = match standard {
        Some(s) => ball
            .as_ref()
            .clone()
            .at_standard(s, &choice.conditions)
            .map_err(error)?,
        None => (ball.as_ref().clone(), None),
    };
    let radius = ball.drop_ball().radius;
    let air = drag.then(|| Air {
        density: air_density.unwrap_or(Air::default().density),
        drag_coefficient: drag_coefficient.unwrap_or(Air::default().drag_coefficient),
    });
    let setup = DropSetup {
        // no height: the standard's drop (its bottom-of-ball height), as `--height`'s default
        height: height
            .or_else(|| standard.and_then(|s| s.release_height(radius)))
            .unwrap_or(DEFAULT_HEIGHT),
        air,
        bounces,
        min_rebound,
    };
    // each bounce on the surface at rest (`bouncelab drop --surface`): on the rigid plate
    // today's drop, with a fitted preset's intervals; elsewhere none (they are the rigid
    // plate's)
    let surface = crate::surface::resolve_normal(surface)?;
    let target = surface.mechanics.target();
    let rigid = surface.mechanics.is_rigid();
    let run = interrupt::detach_watched(py, |w| match rigid {
        true => ball.drop_test_watched(&setup, w),
        false => bouncelab::drop::drop_on_watched(&ball.drop_ball(), &setup, &target, w)?
            .ok_or(BallError::Interrupted),
    })?;
    let d = PyDict::new(py);
    d.set_item("height", run.setup.height)?;
    d.set_item("drag", run.drag())?;
    d.set_item("bounces", bounce_columns(py, &ball, &run, rigid)?)?;
    if let Some(s) = standard {
        // judged on the standard's own drop (or COR test) in this drop's air, whatever
        // `height` says: the command line's verdict (docs/drop.md, "Standards")
        let dball = ball.drop_ball();
        let v = py
            .detach(|| s.judge_on(&dball, air, &target))
            .map_err(|e| error(e.into()))?;
        let verdict = verdict_dict(py, &v)?;
        // the height judged at, as the command line's `judged_at_height_m` (None: a COR test)
        verdict.set_item("judged_at_height_m", s.release_height(dball.radius))?;
        d.set_item("standard", verdict)?;
    }
    // the command line's warnings of a judged drop (`Ball::judged_drop_warnings`)
    let statics = match static_standard {
        Some(s) => {
            let (verdict, deflection) = static_verdict(py, s, &ball)?;
            d.set_item("standard", verdict)?;
            Some((s, deflection))
        }
        None => None,
    };
    let statics_run = statics.as_ref().map(|(s, deflection)| (*s, deflection));
    let mut warnings = ball
        .judged_drop_warnings(&run, height.is_some(), standard, statics_run, &surface)
        .map_err(error)?;
    // a ball fitted to drops in another air than this drop's says so, as the command line's
    warnings.extend(ball.drop_air_warning(run.setup.air));
    warnings.extend(off_conditions);
    d.set_item("warnings", warnings)?;
    // the bounces' outputs its record does not vouch for, as the JSON's
    let not = ball.uncalibrated_outputs(&bouncelab::preset::Output::DROP);
    d.set_item("uncalibrated_outputs", crate::impact::keys(not.as_deref()))?;
    d.set_item("surface", crate::surface::to_dict(py, &surface)?)?;
    if let Some((_, v)) = &leak {
        d.set_item("pressure_loss", crate::answer::json(py, v)?)?;
    }
    crate::answer::stated(&d, &ball)?;
    Ok(d)
}

/// A standard `drop` judges, of the kind `drop --standard` finds it (src/cli/drop.rs): the
/// pressure-loss test first, then an impact standard, then a static one.
enum Judged {
    Impact(&'static Standard),
    Static(&'static DeformationStandard),
    Leak(&'static PressureLoss),
}

/// The standard named `name`; an unknown name is refused listing every one `drop --standard`
/// takes, a bat or court standard naming the command that judges it
/// (`api::not_a_drop_standard`, the command line's message).
fn find(name: &str) -> PyResult<Judged> {
    if let Some(t) = api::pressure_loss_test(name) {
        return Ok(Judged::Leak(t));
    }
    match (standards::find(name), deformation::find(name)) {
        (Ok(s), _) => Ok(Judged::Impact(s)),
        (Err(_), Some(d)) => Ok(Judged::Static(d)),
        (Err(_), None) => Err(value_error(api::not_a_drop_standard(name))),
    }
}

/// A static standard's verdict on the ball (the model's static chain, not the drop), as the
/// command line's `standard` with its `static` report, and the static deflection it judged.
fn static_verdict<'py>(
    py: Python<'py>,
    d: &DeformationStandard,
    ball: &Ball,
) -> PyResult<(Bound<'py, PyDict>, StaticDeflection)> {
    let dball = ball.drop_ball();
    let s = py.detach(|| d.deflection(&dball, dball.law));
    let v = d.judge(&dball).ok_or_else(|| {
        value_error(format!(
            "standard {}: the model gives no static deflection of this ball: {}",
            d.name,
            s.forward.as_ref().err().map_or("", |e| e.as_str())
        ))
    })?;
    let verdict = verdict_dict(py, &v)?;
    verdict.set_item("judged_at_height_m", py.None())?;
    verdict.set_item(
        "static",
        crate::answer::json(py, &api::static_test_report(d, &s))?,
    )?;
    Ok((verdict, s))
}

/// The bounces as columns under the JSON's per-bounce keys, with a fitted preset's 95 %
/// intervals (`cor_ci95_lo`, … as `bouncelab drop`'s `cor_ci95`).
fn bounce_columns<'py>(
    py: Python<'py>,
    ball: &Ball,
    run: &DropRun,
    rigid: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let col = |f: fn(&Bounce) -> f64| array(py, run.bounces.iter().map(f).collect());
    let b = PyDict::new(py);
    b.set_item("v_in", col(|r| r.v_in))?;
    b.set_item("v_out", col(|r| r.v_out))?;
    b.set_item("cor", col(|r| r.cor))?;
    b.set_item("rebound_height", col(|r| r.rebound_height))?;
    b.set_item("contact_time", col(|r| r.contact_time))?;
    b.set_item("max_force", col(|r| r.max_force))?;
    b.set_item("t_start", col(|r| r.t_start))?;
    let setup = run.setup;
    if !rigid {
        return Ok(b);
    }
    if let Some(bands) =
        interrupt::detach_watched(py, |w| ball.drop_intervals_watched(&setup, w).transpose())?
    {
        let names = ["cor", "max_force", "contact_time", "rebound_height"];
        interval_columns(py, &b, names, &bands)?;
    }
    Ok(b)
}

/// The verdict under the JSON's `standard` keys: `window` [lo, hi] with `None` for a bound the
/// standard does not set, `verdict` "pass" or "fail".
fn verdict_dict<'py>(py: Python<'py>, v: &Verdict) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", v.name)?;
    d.set_item("window", v.window.to_vec())?;
    d.set_item("measured", v.measured)?;
    d.set_item("verdict", if v.pass { "pass" } else { "fail" })?;
    d.set_item("margin", v.margin)?;
    Ok(d)
}
