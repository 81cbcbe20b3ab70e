//! The multi-parameter fits of `bouncelab fit` from Python: a force–time trace
//! (`--force-time`), a COR table (`--cor-table`) and drop tests (`--drop-height`/
//! `--rebound-height`). The arrays given are checked by the library's own readers (the ones
//! that read the command line's files), the fit is the library's [`Ball::fit`]; each function
//! returns a dict with the keys of `bouncelab fit --format json`.

use crate::arguments::ball::ball_pyfunction;
use crate::{array, error, floats, value_error};
use bouncelab::Ball;
use bouncelab::analysis::fit::{FitData, MultiFit, Param, parse_free};
use bouncelab::measured::{Air, CorPoint, CorTable, MeasuredError, Trace};
use bouncelab::model::params::ImpactParams;
use bouncelab::solver::SolveOptions;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::fmt::Write;

/// A number as the readers take it: shortest round trip (`NaN`, `inf` refused by them).
fn cell(out: &mut String, x: Option<f64>) {
    if let Some(x) = x {
        let _ = write!(out, "{x:?}");
    }
}

/// The table `columns` (header, values; `None` an empty cell) as CSV text for the readers.
fn csv(header: &[&str], rows: usize, columns: &[&dyn Fn(usize) -> Option<f64>]) -> String {
    let mut text = header.join(",");
    text.push('\n');
    for i in 0..rows {
        for (k, col) in columns.iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            cell(&mut text, col(i));
        }
        text.push('\n');
    }
    text
}

/// A reader's error about the arrays: "`what` row N: message", N the index into the arrays
/// (row 0 the first, as `impacts`' "element N" and `fit_oblique`'s "oblique row N" count; the
/// text's line `line` holds row `line − 2`, under its header).
fn data_error(what: &str, e: MeasuredError) -> PyErr {
    value_error(format!(
        "{what} row {}: {}",
        e.line.saturating_sub(2),
        e.message
    ))
}

/// Arrays `names` of lengths `a` and `b`: the same, and not empty (the readers would say "no
/// data rows after the header" of the text they were turned into).
fn same_length(names: [&str; 2], a: usize, b: usize) -> PyResult<()> {
    if a == 0 {
        return Err(value_error(format!("invalid {}: no value given", names[0])));
    }
    if a != b {
        return Err(value_error(format!(
            "{} and {} differ in length ({a} and {b})",
            names[0], names[1]
        )));
    }
    Ok(())
}

/// The fit as the command line's JSON has it (docs/fitting.md), with `model`: the model at
/// each data point (force, N, of a trace; COR of a table).
/// The dict of `bouncelab fit --format json`: the fit, and the fitted ball's impact at `v0`,
/// the data's speed (a trace's: the ball's; a table's or drop tests': the first row's), as
/// the command line reports it (`cor`, `max_force`, `contact_time`); `target_cor` as it
/// writes it for drop tests (the first drop's COR).
fn report<'py>(
    py: Python<'py>,
    ball: &Ball,
    kind: &str,
    f: &MultiFit,
    (v0, target_cor): (f64, Option<f64>),
) -> PyResult<Bound<'py, PyDict>> {
    let h = ball.header();
    let d = PyDict::new(py);
    d.set_item("preset", h.preset)?;
    d.set_item("origin", h.origin)?;
    d.set_item("parameters", h.parameters)?;
    d.set_item("law", h.law)?;
    d.set_item("data", kind)?;
    d.set_item("free", f.fitted.iter().map(|e| e.name).collect::<Vec<_>>())?;
    let p = &f.params;
    let n = p.normalized();
    for (k, v) in [
        ("k_p", p.k_p),
        ("c", p.damping),
        ("k_r", p.k_r),
        ("z_p", p.z_p),
        ("k_h", p.k_h),
        ("lambda", n.lambda),
        ("zeta", n.zeta),
        ("rms_residual", f.rms_residual),
        ("condition_number", f.condition),
    ] {
        d.set_item(k, v)?;
    }
    d.set_item("points", f.points)?;
    d.set_item("converged", f.converged)?;
    d.set_item("iterations", f.iterations)?;
    let fitted = PyDict::new(py);
    for e in &f.fitted {
        fitted.set_item(e.name, crate::answer::dict(py, e)?)?;
    }
    d.set_item("fitted", fitted)?;
    let correlation = PyDict::new(py);
    for (i, a) in f.names.iter().enumerate() {
        let row = PyDict::new(py);
        for (j, b) in f.names.iter().enumerate() {
            row.set_item(b, f.correlation[i][j])?;
        }
        correlation.set_item(a, row)?;
    }
    d.set_item("correlation", correlation)?;
    if let Some(t) = &f.time_offset {
        d.set_item("time_offset", t.value)?;
        let nuisance = PyDict::new(py);
        for e in f.time_offset.iter().chain(&f.baseline) {
            nuisance.set_item(e.name, crate::answer::dict(py, e)?)?;
        }
        d.set_item("nuisance", nuisance)?;
    }
    let fitted = Ball {
        params: ImpactParams { v0, ..f.params },
        ..ball.clone()
    };
    // as the command line solves it (default options: the same COR, F_m and t_f)
    let r = py
        .detach(|| fitted.impact_with(&SolveOptions::default()))
        .map_err(error)?;
    d.set_item("v0", v0)?;
    if let Some(e) = target_cor {
        d.set_item("target_cor", e)?;
    }
    d.set_item("cor", r.cor)?;
    d.set_item("max_force", r.max_force)?;
    d.set_item("contact_time", r.contact_time)?;
    d.set_item("warnings", f.warnings.clone())?;
    // whether the fit answered (docs/fitting.md): the caller checks `identified`, as the
    // command line's exit code does
    d.set_item("identified", f.identified)?;
    d.set_item("not_pinned", f.not_pinned.clone())?;
    d.set_item("on_bound", f.on_bound.clone())?;
    if let Some(t) = &f.lack_of_fit {
        d.set_item("lack_of_fit", crate::answer::dict(py, t)?)?;
    }
    if f.stated_sd {
        d.set_item("sd_stated", true)?;
    }
    if f.exact() {
        d.set_item("exact", true)?;
    }
    d.set_item("model", array(py, f.model.clone()))?;
    // the ball the fit started from, as the command line's `ball`
    d.set_item("ball", &crate::answer::Record::of(ball))?;
    // the rigid plate the fit assumed, and the conditions, as the command line's JSON
    d.set_item("surface", crate::surface::rigid_plate(py)?)?;
    d.set_item("conditions", &crate::answer::Stated::of(ball))?;
    Ok(d)
}

/// The `free` names (a list, or the command line's "k_r,z_p" as `batch` takes it), or the
/// library's default for the data.
fn free_list(
    free: Option<&Bound<'_, PyAny>>,
) -> PyResult<Option<Vec<bouncelab::analysis::fit::Param>>> {
    crate::free_names(free)?
        .map(|names| parse_free(&names).map_err(|e| value_error(e.to_string())))
        .transpose()
}

ball_pyfunction! {
    /// Several parameters fitted to a force–time trace, as `bouncelab fit --force-time FILE`:
    /// `time` (s, increasing) and `force` (N) arrays; the contact start in the data's clock and
    /// the force baseline are fitted too, and without `v0` the impact speed (as `free` with
    /// "v0", the warnings saying so first: `Ball::free_trace_speed`).
    signature = (time, force, *, preset="superball", free=None, v0=None, law=None, params=None,);
    fn fit_trace<'py>(
        py,
        time: &Bound<'py, PyAny>,
        force: &Bound<'py, PyAny>,
        preset: &str,
        free: Option<&Bound<'py, PyAny>>,
        v0: Option<f64>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let (t, f) = (floats(time, "time")?, floats(force, "force")?);
        same_length(["time", "force"], t.len(), f.len())?;
        let text = csv(
            &["time_s", "force_N"],
            t.len(),
            &[&|i| Some(t[i]), &|i| Some(f[i])],
        );
        let trace = Trace::parse(&text).map_err(|e| data_error("trace", e))?;
        // a trace with no pulse, named by the row of its largest force, before the fit would
        // name it by the line and column of the text above (`2:5: empty pulse …`)
        trace.summary().map_err(|e| data_error("trace", e))?;
        let ball = choice.ball(v0)?;
        // without `v0` the trace's speed is fitted too and the warnings say so first, as the
        // command line's `fit --force-time` without `--v0` (it was held at the preset's here)
        let mut free = free_list(free)?.unwrap_or_else(|| Param::defaults(true, 0, ball.law));
        let speed_fitted = Ball::free_trace_speed(&mut free, true, v0.is_some());
        let data = FitData::Trace(&trace);
        let mut fit = fit_with_warnings(py, &ball, data, Some(&free), &[ball.params.v0])?;
        if speed_fitted {
            fit.warnings.insert(0, ball.speed_fitted_warning());
        }
        // the trace's speed: the ball's, or the fit's where it was fitted
        report(py, &ball, "force-time trace", &fit, (fit.params.v0, None))
    }
}

ball_pyfunction! {
    /// Several parameters fitted to COR against impact speed, as `bouncelab fit --cor-table FILE`:
    /// `v0` (m/s) and `cor` arrays, and optionally the COR's standard deviations (weights) and the
    /// peak forces (N) and contact times (s) measured at each speed (NaN: not measured).
    signature = (v0, cor, *, cor_sd=None, max_force=None, contact_time=None, preset="superball", free=None, law=None, params=None,);
    fn fit_cor_table<'py>(
        py,
        v0: &Bound<'py, PyAny>,
        cor: &Bound<'py, PyAny>,
        cor_sd: Option<&Bound<'py, PyAny>>,
        max_force: Option<&Bound<'py, PyAny>>,
        contact_time: Option<&Bound<'py, PyAny>>,
        preset: &str,
        free: Option<&Bound<'py, PyAny>>,
        law: Option<&str>,
        params: Option<&str>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let (v, e) = (floats(v0, "v0")?, floats(cor, "cor")?);
        same_length(["v0", "cor"], v.len(), e.len())?;
        let optional = |name: &str, a: Option<&Bound<'py, PyAny>>| -> PyResult<Vec<f64>> {
            match a {
                Some(a) => {
                    let x = floats(a, name)?;
                    same_length(["v0", name], v.len(), x.len())?;
                    Ok(x)
                }
                None => Ok(vec![f64::NAN; v.len()]),
            }
        };
        let sd = optional("cor_sd", cor_sd)?;
        let fm = optional("max_force", max_force)?;
        let tf = optional("contact_time", contact_time)?;
        // NaN is "not measured": an empty cell
        let given = |x: f64| (!x.is_nan()).then_some(x);
        let text = csv(
            &["v0", "cor", "cor_sd", "max_force_N", "contact_time_s"],
            v.len(),
            &[
                &|i| Some(v[i]),
                &|i| Some(e[i]),
                &|i| given(sd[i]),
                &|i| given(fm[i]),
                &|i| given(tf[i]),
            ],
        );
        let table = CorTable::parse(&text).map_err(|e| data_error("COR table", e))?;
        let free = free_list(free)?;
        let ball = choice.ball(None)?;
        let speeds: Vec<f64> = table.points.iter().map(|p| p.v0).collect();
        let data = FitData::Cor(&table.points);
        let fit = fit_with_warnings(py, &ball, data, free.as_deref(), &speeds)?;
        report(py, &ball, "COR table", &fit, (v[0], None))
    }
}

ball_pyfunction! {
    /// Several parameters fitted to drop tests, as `bouncelab fit --drop-height H --rebound-height
    /// R …`: drop and rebound heights (m) of the bottom of the ball, turned into impact speeds and
    /// CORs in vacuum, or with quadratic drag when `drag_coefficient` is given (air density
    /// `air_density`, kg/m³). Each drop weighs by its rebound height's reading (σ_e = σ_R ∂e/∂R,
    /// docs/fitting.md): with `rebound_height_sd` = σ_R (m) each COR carries σ_e (`drops["cor_sd"]`)
    /// and the lack of fit is χ²; without it the scale comes from the misses. The dict adds
    /// `drops`: the heights with the speed and COR of each.
    signature = (drop_heights, rebound_heights, *, preset="superball", free=None, drag_coefficient=None, air_density=1.204, law=None, params=None, rebound_height_sd=None,);
    fn fit_drops<'py>(
        py,
        drop_heights: &Bound<'py, PyAny>,
        rebound_heights: &Bound<'py, PyAny>,
        preset: &str,
        free: Option<&Bound<'py, PyAny>>,
        drag_coefficient: Option<f64>,
        air_density: f64,
        law: Option<&str>,
        params: Option<&str>,
        rebound_height_sd: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>>;
    ball choice = (preset, params, law);
    {
        let (h, r) = (
            floats(drop_heights, "drop_heights")?,
            floats(rebound_heights, "rebound_heights")?,
        );
        same_length(["drop_heights", "rebound_heights"], h.len(), r.len())?;
        let free = free_list(free)?;
        let ball = choice.ball(None)?;
        let air = drag_coefficient.map(|cd| Air {
            density: air_density,
            drag_coefficient: cd,
        });
        let pairs: Vec<(f64, f64)> = h.iter().copied().zip(r.iter().copied()).collect();
        let points: Vec<CorPoint> = ball
            .drops_to_cor_read(&pairs, air, rebound_height_sd)
            .map_err(error)?;
        let speeds: Vec<f64> = points.iter().map(|p| p.v0).collect();
        let fit = fit_with_warnings(py, &ball, FitData::Cor(&points), free.as_deref(), &speeds)?;
        let d = report(
            py,
            &ball,
            "drop test",
            &fit,
            (points[0].v0, Some(points[0].cor)),
        )?;
        let drops = PyDict::new(py);
        drops.set_item("drop_height", array(py, h))?;
        drops.set_item("rebound_height", array(py, r))?;
        drops.set_item("v0", array(py, points.iter().map(|p| p.v0).collect()))?;
        drops.set_item("cor", array(py, points.iter().map(|p| p.cor).collect()))?;
        if rebound_height_sd.is_some() {
            let sd = points
                .iter()
                .map(|p| p.cor_sd.unwrap_or(f64::NAN))
                .collect();
            drops.set_item("cor_sd", array(py, sd))?;
        }
        d.set_item("drops", drops)?;
        // the air the drops were taken in, as the command line's `air` (None: vacuum)
        let air_dict = air
            .map(|a| -> PyResult<Bound<'_, PyDict>> {
                let a_d = PyDict::new(py);
                a_d.set_item("drag_coefficient", a.drag_coefficient)?;
                a_d.set_item("air_density", a.density)?;
                Ok(a_d)
            })
            .transpose()?;
        d.set_item("air", air_dict)?;
        Ok(d)
    }
}

/// The ball's parameters `free` fitted to `data`, Ctrl-C heard (`interrupt::detach_watched`),
/// with the warnings of its fitted ball at the fastest of the data's `speeds` (m/s; a
/// trace's: the ball's v0), as `bouncelab fit` adds them (`Ball::fitted_warnings`: pressed
/// past its radius, an energy balance that does not close); the dicts lacked them
/// (python/tests/test_fits.py).
fn fit_with_warnings(
    py: Python<'_>,
    ball: &Ball,
    data: FitData<'_>,
    free: Option<&[bouncelab::analysis::fit::Param]>,
    speeds: &[f64],
) -> PyResult<MultiFit> {
    let mut fit = crate::interrupt::detach_watched(py, |w| ball.fit_watched(data, free, w))?;
    let w = py.detach(|| ball.fit_warnings(&fit, speeds));
    fit.warnings.extend(w);
    Ok(fit)
}
