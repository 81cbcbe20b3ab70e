//! `bouncelab.batch`: a batch of balls from one CSV, one fit and one verdict each against a
//! standard, as `bouncelab batch FILE --format json` (docs/batch.md). The library splits the
//! batch ([`bouncelab::analysis::batch::split`]) and judges each ball
//! ([`Ball::judge_in_batch`]); this file reads the batch and the trace files it names, as the
//! command line's `src/cli/batch.rs` reads them (the same checks, the same messages), and
//! returns the JSON document's structure as a dict (serde_json's, so the keys, the order and
//! the `None`s are the command line's: python/tests/test_batch.py compares them).

use crate::arguments::ball::ball_pyfunction;
use crate::{error, value_error};
use bouncelab::Ball;
use bouncelab::analysis::batch::{BallData, split};
use bouncelab::analysis::fit::parse_free;
use bouncelab::api::{BatchReport, BatchSetup};
use bouncelab::drop::standards::{self, Standard};
use bouncelab::measured::bounded::{MAX_DATA_BYTES, ReadError, read_bounded};
use bouncelab::measured::{Air, Data, Trace};
use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use rayon::prelude::*;
use std::borrow::Cow;
use std::path::{Path, PathBuf};

/// A file that cannot be read: `OSError` with the command line's message (its exit 1).
fn os_error(path: &Path, msg: impl std::fmt::Display) -> PyErr {
    PyOSError::new_err(
        bouncelab::sanitize::line(&format!("{}: {msg}", path.display())).into_owned(),
    )
}

/// A data file's text, read by the library's reader (`measured::bounded::read_bounded`, the
/// command line's): what the system refuses and what is not a regular file an `OSError`, a
/// file past [`MAX_DATA_BYTES`] or not UTF-8 (named at the line and column of its first
/// byte that is not) a `ValueError`.
pub(crate) fn read_text(path: &Path) -> PyResult<String> {
    read_bounded(path).map_err(|e| match e {
        ReadError::Io(why) => os_error(path, why),
        ReadError::Directory | ReadError::NotRegular => os_error(path, "is not a regular file"),
        ReadError::TooLarge(n) => value_error(format!(
            "{}: is {n} bytes; a data file is at most {MAX_DATA_BYTES} bytes",
            path.display()
        )),
        ReadError::NotUtf8 { line, column } => value_error(format!(
            "{}:{line}:{column}: not UTF-8 text",
            path.display()
        )),
    })
}

/// The batch's balls with their data as the file gives them: rows, or a trace file's name
/// (relative to the batch's folder) read only when the ball's turn comes and dropped after its
/// fit ([`data_of`]; issue 54 items 4 and 9: every trace was read first and held to the end,
/// 31 MB a ball of a 10⁶-row trace), as the command line's `src/cli/batch.rs`. The library's
/// `split` refuses a batch beyond `analysis::batch::MAX_BALLS` balls.
fn load(file: &Path) -> PyResult<Vec<(String, usize, BallData)>> {
    let text = read_text(file)?;
    let rows = split(&text).map_err(|e| value_error(format!("{}:{e}", file.display())))?;
    Ok(rows.into_iter().map(|b| (b.id, b.line, b.data)).collect())
}

/// Ball `id`'s data: its rows, or its trace file read now; an error (a `ValueError`'s text)
/// at the batch `file`'s line and column naming the ball.
fn data_of<'a>(file: &Path, id: &str, data: &'a BallData) -> Result<Cow<'a, Data>, String> {
    let (path, line, column) = match data {
        BallData::Measured(d) => return Ok(Cow::Borrowed(d)),
        BallData::TraceFile { path, line, column } => (path, line, column),
    };
    let at = |e: String| format!("{}:{line}:{column}: trace of '{id}': {e}", file.display());
    let path = file.parent().unwrap_or(Path::new("")).join(path);
    let text = read_text(&path).map_err(|e| at(e.to_string()))?;
    let t = Trace::parse(&text).map_err(|e| at(format!("{}:{e}", path.display())))?;
    Ok(Cow::Owned(Data::Trace(t)))
}

/// `standard`, or the preset's own (as the command line's `--standard`).
fn standard(name: Option<&str>, ball: &Ball) -> PyResult<&'static Standard> {
    match name {
        Some(name) => standards::find(name).map_err(|e| value_error(e.to_string())),
        None => ball
            .name
            .as_deref()
            .and_then(standards::for_ball)
            .ok_or_else(|| {
                value_error(format!(
                    "standard= is needed: {} has no standard of its own (bouncelab.standards() \
                 lists them)",
                    ball.label()
                ))
            }),
    }
}

ball_pyfunction! {
    /// A batch of balls in one CSV file — an `id` column and the columns `fit` reads (drop tests,
    /// a COR table, a trace, or a `trace` column naming each ball's trace file) — each ball fitted
    /// from the preset and judged against `standard` (default: the preset's own), as `bouncelab
    /// batch FILE --format json`: a dict with `preset`, `law`, `standard`, `summary` (`n`,
    /// `mean`, `sd`, `min`, `max`, `failures`, `cpk`, their 95 % intervals `mean_ci` and
    /// `cpk_ci`, `mean_ci_clipped` (whether `mean_ci` was cut to where the value can lie), `balls`, `identified`, `no_answer`, `unsure`, `free`) and `balls` (one dict a
    /// ball: `id`, `cor`, `measured`, its 95 % interval `measured_ci95`, `verdict`, `margin`,
    /// `warnings`, `error`, `verdict_from`, `readings`, `model_measured`, `fit_error`, …), `None`
    /// where the JSON has null. A ball tested at the standard's condition is judged on its own
    /// readings whether or not it can be fitted (a failed fit says why in its `fit_error`); a ball
    /// without such readings that cannot be fitted says why in its `error` and the batch goes on
    /// (`summary["no_answer"]` counts them: the command line's exit 1). Bad input raises `ValueError` naming the file, line and column; a file that
    /// cannot be read, `OSError`. `free` is a list of names or the command line's "k_p,c". The balls are fitted in parallel without the GIL.
    signature = (file, *, standard=None, preset="superball", params=None, law=None, v0=None, free=None, drag_coefficient=None, air_density=1.204,);
    fn batch<'py>(
        py,
        file: PathBuf,
        standard: Option<&str>,
        preset: &str,
        params: Option<&str>,
        law: Option<&str>,
        v0: Option<f64>,
        free: Option<&Bound<'py, PyAny>>,
        drag_coefficient: Option<f64>,
        air_density: f64,
    ) -> PyResult<Bound<'py, PyAny>>;
    ball choice = (preset, params, law);
    {
        let ball = choice.ball(v0)?;
        let standard = self::standard(standard, &ball)?;
        let free = crate::free_names(free)?;
        let free = free
            .as_deref()
            .map(parse_free)
            .transpose()
            .map_err(|e| value_error(e.to_string()))?;
        let air = drag_coefficient.map(|cd| Air {
            density: air_density,
            drag_coefficient: cd,
        });
        // the library checks the air once, whatever the data (as the command line)
        ball.drops_to_cor(&[], air).map_err(error)?;
        let balls = load(&file)?;
        let setup = BatchSetup {
            standard,
            free: free.as_deref(),
            air,
            rebound_sd: None,
        };
        // each ball looks at the flag Ctrl-C raises before its fit starts: the batch stops
        // within the fits under way (`interrupt::detach_stoppable`; issue 54 item 6: 9.4 s)
        let text = crate::interrupt::detach_stoppable(py, |stop| {
            let outcomes: Option<Result<Vec<_>, String>> = balls
                .par_iter()
                .map(|(id, line, source)| {
                    (!stop.load(std::sync::atomic::Ordering::Relaxed)).then(|| {
                        let data = data_of(&file, id, source)?;
                        Ok(ball.judge_in_batch(id, *line, &data, &setup))
                    })
                })
                .collect();
            outcomes.map(|o| {
                o.map(|o| serde_json::to_string(&BatchReport::new(&ball, standard, &o)))
            })
        })?
        .ok_or_else(|| pyo3::exceptions::PyKeyboardInterrupt::new_err("stopped"))?
        .map_err(value_error)?;
        let text = text.map_err(|e| value_error(e.to_string()))?;
        let d = py.import("json")?.call_method1("loads", (text,))?;
        // the document is the command line's JSON; its surface the rigid plate as every
        // answer's surface dict gives it (∞ as inf, where the JSON writes null)
        d.set_item("surface", crate::surface::rigid_plate(py)?)?;
        // the conditions the ball ran at, as the command line's last key
        d.set_item("conditions", &crate::answer::Stated::of(&ball))?;
        Ok(d)
    }
}
