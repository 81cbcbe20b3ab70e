//! The Monte Carlo from Python: `monte_carlo` (a whole run, as `bouncelab mc --format json`),
//! and the two halves the Dask path (`bouncelab/dask.py`) puts on a cluster:
//! `monte_carlo_chunk` (the samples of an index range, a task's work) and `monte_carlo_merge`
//! (the same summary from all the samples, in index order). A sample is a function of the
//! seed and its index alone (docs/scale.md), so the chunks give the single call's samples and
//! the merge its numbers, bit for bit.

use crate::arguments::ball::{BallChoice, ball_pyfunction};
use crate::{array, error, of_argument};
use bouncelab::analysis::mc::{
    Dist, McError, McSpec, McSummary, Samples, Spread, Stats, Varied, parse_correlate, parse_vary,
    summary,
};
use bouncelab::api::MonteCarlo;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `vary` as a dict {"k_p": 0.05, …} (fractions) or the command line's text "k_p=5%,…".
fn spreads(vary: &Bound<'_, PyAny>) -> PyResult<Vec<Spread>> {
    if let Ok(text) = vary.extract::<String>() {
        return parse_vary(&text).map_err(|e| error(e.into()));
    }
    let dict = vary.cast::<PyDict>().map_err(|_| {
        PyValueError::new_err("invalid vary: give a dict {\"k_p\": 0.05, …} or \"k_p=5%,…\"")
    })?;
    let mut out = Vec::new();
    for (k, v) in dict.iter() {
        let name: String = of_argument(k.py(), "vary", k.extract())?;
        let what = Varied::parse(&name).ok_or_else(|| error(McError::Unknown(name).into()))?;
        // a bool is an int to Python (`True` would be a spread of 1, 100 %): refused, as is
        // anything that is not a number (tests/test_numbers_typed.py)
        if v.is_instance_of::<pyo3::types::PyBool>() {
            return Err(PyValueError::new_err(format!(
                "invalid vary {}: {v} is not a number (give a fraction, e.g. 0.05)",
                what.name()
            )));
        }
        let spread = v.extract::<f64>().map_err(|_| {
            PyValueError::new_err(format!(
                "invalid vary {}: {} is not a number (give a fraction, e.g. 0.05)",
                what.name(),
                v.repr().map_or_else(|_| "?".into(), |r| r.to_string())
            ))
        })?;
        out.push(Spread { what, spread });
    }
    Ok(out)
}

/// The arguments every Monte Carlo function shares.
struct Request {
    ball: bouncelab::Ball,
    spec: McSpec,
}

fn request(
    choice: &BallChoice<'_>,
    vary: &Bound<'_, PyAny>,
    (samples, seed): (usize, u64),
    dist: &str,
    v0: Option<f64>,
    correlate: Option<&Bound<'_, PyAny>>,
) -> PyResult<Request> {
    let ball = choice.ball(v0)?;
    let dist = Dist::parse(dist).ok_or_else(|| {
        PyValueError::new_err(format!(
            "invalid dist: '{dist}' (choose from normal, uniform, lognormal)"
        ))
    })?;
    // vary="fit": the preset's own fit (as `mc --vary fit`), which gives its distribution
    // and correlations
    if vary.extract::<String>().is_ok_and(|v| v.trim() == "fit") {
        let refuse = |what: &str| {
            error(
                McError::Fit(format!(
                    "{what} does not go with it: the fit's own covariance gives the normal \
                     distribution and the correlations"
                ))
                .into(),
            )
        };
        if dist != Dist::Normal {
            return Err(refuse("dist"));
        }
        if correlate.is_some() {
            return Err(refuse("correlate"));
        }
        let spec = ball.fit_spec(samples, seed).map_err(error)?;
        return Ok(Request { ball, spec });
    }
    let spec = McSpec::new(spreads(vary)?, dist, samples, seed).map_err(|e| error(e.into()))?;
    let spec = match correlate {
        Some(c) => spec
            .with_correlation(pairs(c)?)
            .map_err(|e| error(e.into()))?,
        None => spec,
    };
    Ok(Request { ball, spec })
}

/// `correlate` as a dict {"k_p:c": 0.5, …} or the command line's text "k_p:c=0.5,…".
fn pairs(c: &Bound<'_, PyAny>) -> PyResult<Vec<(Varied, Varied, f64)>> {
    let text = match c.extract::<String>() {
        Ok(t) => t,
        Err(_) => {
            let dict = c.cast::<PyDict>().map_err(|_| {
                PyValueError::new_err(
                    "invalid correlate: give a dict {\"k_p:c\": 0.5, …} or \"k_p:c=0.5,…\"",
                )
            })?;
            let mut items = Vec::new();
            for (k, v) in dict.iter() {
                let (k, v) = of_argument(
                    c.py(),
                    "correlate",
                    k.extract::<String>()
                        .and_then(|k| Ok((k, v.extract::<f64>()?))),
                )?;
                items.push(format!("{k}={v}"));
            }
            items.join(",")
        }
    };
    parse_correlate(&text).map_err(|e| error(e.into()))
}

/// The quantiles' keys, in the order of `bouncelab::analysis::mc::PROBS`.
const QUANTILE_KEYS: [&str; 9] = ["1", "2.5", "5", "25", "50", "75", "95", "97.5", "99"];

fn stats_dict<'py>(py: Python<'py>, s: &Stats) -> PyResult<Bound<'py, PyDict>> {
    let q = PyDict::new(py);
    for (name, v) in QUANTILE_KEYS.iter().zip(s.q.values()) {
        q.set_item(name, v)?;
    }
    let d = PyDict::new(py);
    d.set_item("n", s.n)?;
    d.set_item("mean", s.mean)?;
    d.set_item("sd", s.sd)?;
    d.set_item("min", s.min)?;
    d.set_item("max", s.max)?;
    d.set_item("q", q)?;
    // the 95 % intervals (bouncelab::analysis::mc_interval): an open end is None, as the
    // JSON's null — not NaN, which no dict equals, and runs under 368 samples have them
    let q_ci = PyDict::new(py);
    for (name, ci) in QUANTILE_KEYS.iter().zip(s.q_ci.values()) {
        let end = |x: f64| (!x.is_nan()).then_some(x);
        q_ci.set_item(name, vec![end(ci[0]), end(ci[1])])?;
    }
    d.set_item("mean_se", s.mean_se)?;
    d.set_item("mean_ci", s.mean_ci.to_vec())?;
    d.set_item("q_ci", q_ci)?;
    Ok(d)
}

/// The dict of `bouncelab mc --format json` (NaN where the JSON has null).
fn report<'py>(py: Python<'py>, r: &Request, s: &McSummary) -> PyResult<Bound<'py, PyDict>> {
    let vary = PyDict::new(py);
    for v in &r.spec.vary {
        vary.set_item(v.what.name(), v.spread)?;
    }
    let stats = PyDict::new(py);
    stats.set_item("cor", stats_dict(py, &s.stats.cor)?)?;
    stats.set_item("max_force", stats_dict(py, &s.stats.max_force)?)?;
    stats.set_item("contact_time", stats_dict(py, &s.stats.contact_time)?)?;
    let d = PyDict::new(py);
    d.set_item("samples", r.spec.samples)?;
    d.set_item("seed", r.spec.seed)?;
    d.set_item("preset", r.ball.name.as_deref())?;
    d.set_item("law", r.ball.law.name())?;
    d.set_item("v0", r.ball.params.v0)?;
    d.set_item("dist", r.spec.dist.name())?;
    d.set_item("vary", vary)?;
    if let Some(c) = &r.spec.correlation {
        let pairs = PyDict::new(py);
        for (a, b, rho) in &c.pairs {
            pairs.set_item(format!("{}:{}", a.name(), b.name()), rho)?;
        }
        d.set_item("correlate", pairs)?;
    }
    d.set_item("no_rebound", s.no_rebound)?;
    d.set_item("stats", stats)?;
    d.set_item("warnings", r.ball.mc_warnings(&r.spec, &s.stats))?;
    crate::answer::stated(&d, &r.ball)?;
    // plain `mc` samples on the rigid plate (`McReport::surface`): as every answer's surface
    // dict gives it (∞ as inf, where the JSON writes null)
    d.set_item("surface", crate::surface::rigid_plate(py)?)?;
    Ok(d)
}

/// A Monte Carlo function of Python's: the arguments all three share (`preset`, `vary`,
/// `samples`, `seed`, `dist`, `v0`, `law`, `params`, then the function's own, then
/// `correlate` and the ball's arguments, python/src/arguments/ball.rs), keyword-only, read once
/// into the [`Request`] `$r` its body starts from.
/// `samples` has a default where one is given (`monte_carlo`'s 10 000); the Dask halves take
/// it as the run's, always given. Written once here so that the single call and the Dask path
/// cannot drift apart in a name or a default (`test_dask*.py` hold their answers equal).
/// `samples`' default is a token tree, not a `literal` fragment: pyo3 writes help()'s
/// signature from the tokens it sees, and a fragment's are hidden ("samples=Ellipsis").
macro_rules! mc_pyfunction {
    (
        $(#[$attr:meta])*
        fn $name:ident<$lt:lifetime>($py:ident, $r:ident; samples $(= $samples:tt)?;
            $($arg:ident: $ty:ty $(= $default:tt)?),* $(,)?) -> $ret:ty $body:block
    ) => {
        ball_pyfunction! {
            $(#[$attr])*
            signature = (*, preset="superball", vary, samples $(= $samples)?, seed=0, dist="normal", v0=None, law=None, params=None, $($arg $(= $default)?,)* correlate=None,);
            fn $name<$lt>(
                $py,
                preset: &str,
                vary: &Bound<$lt, PyAny>,
                samples: usize,
                seed: u64,
                dist: &str,
                v0: Option<f64>,
                law: Option<&str>,
                params: Option<&str>,
                $($arg: $ty,)*
                correlate: Option<Bound<$lt, PyAny>>,
            ) -> $ret;
            ball choice = (preset, params, law);
            {
                let $r = request(&choice, vary, (samples, seed), dist, v0, correlate.as_ref())?;
                $body
            }
        }
    };
}

mc_pyfunction! {
    /// A Monte Carlo over a preset's parameter tolerances, as `bouncelab mc --format json`: a dict
    /// with its keys (`samples`, `seed`, `stats` → `cor`, `max_force`, `contact_time` → `n`,
    /// `mean`, `sd`, `min`, `max`, `q` → `"1"` … `"99"`, the 95 % intervals `mean_se`,
    /// `mean_ci`, `q_ci` → `"1"` … `"99"` → [lo, hi], …, `warnings`). With `return_samples`, `values`
    /// holds each sample's cor, max_force, contact_time (NaN: no rebound) and varied parameters
    /// as numpy arrays. The GIL is released while the samples run (in parallel).
    fn monte_carlo<'py>(py, r; samples = 10_000; return_samples: bool = false)
        -> PyResult<Bound<'py, PyDict>>
    {
        let mc: MonteCarlo =
            crate::interrupt::detach_watched(py, |w| r.ball.monte_carlo_watched(&r.spec, w))?;
        let d = report(py, &r, &mc.summary)?;
        if return_samples {
            d.set_item("values", values(py, &r, mc.samples)?)?;
        }
        Ok(d)
    }
}

/// `monte_carlo`'s `values`: each sample's varied parameters, cor, max_force, contact_time.
fn values<'py>(py: Python<'py>, r: &Request, samples: Samples) -> PyResult<Bound<'py, PyDict>> {
    let values = PyDict::new(py);
    let sampler = r.ball.sampler(&r.spec);
    let inputs: Vec<Vec<f64>> = (0..samples.len() as u64)
        .map(|i| sampler.inputs(i))
        .collect();
    for (k, v) in r.spec.vary.iter().enumerate() {
        values.set_item(
            v.what.name(),
            array(py, inputs.iter().map(|x| x[k]).collect()),
        )?;
    }
    let Samples {
        cor,
        max_force,
        contact_time,
        ..
    } = samples;
    values.set_item("cor", array(py, cor))?;
    values.set_item("max_force", array(py, max_force))?;
    values.set_item("contact_time", array(py, contact_time))?;
    Ok(values)
}

type Columns = (Py<PyArray1<f64>>, Py<PyArray1<f64>>, Py<PyArray1<f64>>);

mc_pyfunction! {
    /// The samples `start … start + count` of the run `monte_carlo` would make with the same
    /// arguments: (cor, max_force, contact_time) as numpy arrays — one Dask task's work. With
    /// `check_only`, every argument and the work limit for `count` samples are checked and empty
    /// arrays returned (the Dask client's check before it sends a task).
    fn monte_carlo_chunk<'py>(py, r; samples; start: u64, count: usize, check_only: bool = false)
        -> PyResult<Columns>
    {
        let samples = r.spec.samples;
        if start.saturating_add(count as u64) > samples as u64 {
            return Err(PyValueError::new_err(format!(
                "invalid chunk: samples {start} … {} lie beyond the run's {samples}",
                start.saturating_add(count as u64)
            )));
        }
        if check_only {
            r.ball.check_samples(count).map_err(|e| error(e.into()))?;
            return Ok((array(py, vec![]), array(py, vec![]), array(py, vec![])));
        }
        let s = py
            .detach(|| r.ball.monte_carlo_samples(&r.spec, start, count))
            .map_err(error)?;
        Ok((
            array(py, s.cor),
            array(py, s.max_force),
            array(py, s.contact_time),
        ))
    }
}

mc_pyfunction! {
    /// The dict `monte_carlo` returns, from all the samples of the run (cor, max_force,
    /// contact_time, in index order: the chunks of `monte_carlo_chunk` concatenated).
    fn monte_carlo_merge<'py>(py, r; samples;
        cor: PyReadonlyArray1<'py, f64>,
        max_force: PyReadonlyArray1<'py, f64>,
        contact_time: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyDict>>
    {
        let samples = r.spec.samples;
        let all = Samples {
            start: 0,
            cor: cor.as_array().to_vec(),
            max_force: max_force.as_array().to_vec(),
            contact_time: contact_time.as_array().to_vec(),
        };
        let lens = [all.cor.len(), all.max_force.len(), all.contact_time.len()];
        if lens.iter().any(|&n| n != samples) {
            return Err(PyValueError::new_err(format!(
                "invalid merge: {lens:?} values for a run of {samples} samples"
            )));
        }
        let s = py.detach(|| summary(&r.spec, &all));
        report(py, &r, &s)
    }
}

/// The 0-based ranks of the order statistics a run's summary reads from `n` values of a
/// quantity (`bouncelab::analysis::mc::order_ranks`): what the Dask client's streaming merge
/// finds on the workers (`bouncelab/dask.py`, docs/scale.md).
#[pyfunction]
pub(crate) fn monte_carlo_order_ranks(n: usize) -> Vec<usize> {
    if n == 0 {
        return vec![];
    }
    bouncelab::analysis::mc::order_ranks(n)
}

/// One quantity's statistics from the streaming merge's dict: `n`, `mean`, `sd`, `min`,
/// `max` and `order`, its order statistics at `monte_carlo_order_ranks(n)`.
fn merged_stats(d: &Bound<'_, PyDict>) -> PyResult<Stats> {
    let get = |k: &str| -> PyResult<Bound<'_, PyAny>> {
        d.get_item(k)?
            .ok_or_else(|| PyValueError::new_err(format!("invalid merge: no '{k}'")))
    };
    let n: usize = get("n")?.extract()?;
    if n == 0 {
        return Ok(bouncelab::analysis::mc::stats_of(&[]));
    }
    let order: Vec<f64> = get("order")?.extract()?;
    if order.len() != bouncelab::analysis::mc::order_ranks(n).len() {
        return Err(PyValueError::new_err(format!(
            "invalid merge: {} order statistics for {n} values",
            order.len()
        )));
    }
    let extremes = [get("min")?.extract()?, get("max")?.extract()?];
    Ok(bouncelab::analysis::mc::stats_from_order(
        n,
        get("mean")?.extract()?,
        get("sd")?.extract()?,
        extremes,
        &order,
    ))
}

mc_pyfunction! {
    /// The dict `monte_carlo` returns, from a streaming merge's per-quantity statistics (dicts
    /// of `n`, `mean`, `sd`, `min`, `max` and `order`: the order statistics at
    /// `monte_carlo_order_ranks(n)`) and the run's count of samples without rebound: the
    /// Dask client's merge in memory that does not grow with the samples (docs/scale.md).
    fn monte_carlo_report<'py>(py, r; samples;
        cor: Bound<'py, PyDict>,
        max_force: Bound<'py, PyDict>,
        contact_time: Bound<'py, PyDict>,
        no_rebound: usize,
    ) -> PyResult<Bound<'py, PyDict>>
    {
        let s = McSummary {
            spec: r.spec.clone(),
            no_rebound,
            stats: bouncelab::analysis::mc::McStats {
                cor: merged_stats(&cor)?,
                max_force: merged_stats(&max_force)?,
                contact_time: merged_stats(&contact_time)?,
            },
        };
        report(py, &r, &s)
    }
}
