//! `bouncelab._native`: the Python bindings of the bouncelab library (the package `bouncelab`
//! re-exports them; `bouncelab/__init__.pyi` types them). Keyword arguments in, SI units, the
//! names of the command line's JSON and CSV output, numpy arrays out. Every check and message
//! is the library's, which is the command line's: an error raises `ValueError` carrying the
//! line `bouncelab: error: …` would print (`NoAnswerError`, a `ValueError`, for an impact the
//! solver could not bring to an end: the command line's exit code 1).

use bouncelab::BallError;
use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

mod answer;
mod arguments;
mod arrays;
mod batch;
mod catalog_cache;
mod collide;
mod court;
mod drops;
mod fits;
mod impact;
mod interrupt;
mod mc;
mod oblique;
mod oblique_fit;
mod pair;
mod preset_balls;
mod preset_fits;
mod runs;
mod same;
mod shot;
mod standards;
mod statics;
mod surface;
mod sweeps;

// the helpers every call uses, by the names the modules import them by
pub(crate) use arguments::{
    array, floats, free_names, frozen_array, history_samples, interval_columns, law, of_argument,
    source,
};
use impact::Impact;
pub(crate) use preset_balls::{entry, load_catalog};

create_exception!(
    bouncelab,
    NoAnswerError,
    PyValueError,
    "The solver ran out of its step budget before the ball left or came to rest: no answer \
     (the command line's exit code 1). A nearby λ or ζ may answer."
);

/// A library error as a Python exception with the command line's message (control
/// characters made visible, as the command line shows them: bouncelab::sanitize).
pub(crate) fn error(e: BallError) -> PyErr {
    let message = bouncelab::sanitize::line(&e.to_string()).into_owned();
    if e.is_no_answer() {
        NoAnswerError::new_err(message)
    } else {
        PyValueError::new_err(message)
    }
}

pub(crate) fn value_error(message: String) -> PyErr {
    PyValueError::new_err(bouncelab::sanitize::line(&message).into_owned())
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Impact>()?;
    m.add_class::<collide::Collision>()?;
    m.add_function(wrap_pyfunction!(collide::collide, m)?)?;
    m.add_class::<oblique::ObliqueImpact>()?;
    m.add_function(wrap_pyfunction!(oblique::oblique, m)?)?;
    m.add("NoAnswerError", m.py().get_type::<NoAnswerError>())?;
    m.add_function(wrap_pyfunction!(preset_balls::presets, m)?)?;
    m.add_function(wrap_pyfunction!(runs::run, m)?)?;
    m.add_function(wrap_pyfunction!(runs::run_normalized, m)?)?;
    m.add_function(wrap_pyfunction!(runs::run_params, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_zeta, m)?)?;
    m.add_function(wrap_pyfunction!(sweeps::sweep_velocity, m)?)?;
    m.add_function(wrap_pyfunction!(preset_fits::fit, m)?)?;
    m.add_function(wrap_pyfunction!(drops::drop_test, m)?)?;
    m.add_function(wrap_pyfunction!(standards::standards, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_trace, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_cor_table, m)?)?;
    m.add_function(wrap_pyfunction!(fits::fit_drops, m)?)?;
    m.add_function(wrap_pyfunction!(oblique_fit::fit_oblique, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo, m)?)?;
    m.add_function(wrap_pyfunction!(arrays::impacts, m)?)?;
    m.add_function(wrap_pyfunction!(shot::shot, m)?)?;
    m.add_function(wrap_pyfunction!(shot::shots, m)?)?;
    m.add_function(wrap_pyfunction!(batch::batch, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_chunk, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_merge, m)?)?;
    m.add_function(wrap_pyfunction!(court::court, m)?)?;
    m.add_function(wrap_pyfunction!(statics::static_deflection, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_order_ranks, m)?)?;
    m.add_function(wrap_pyfunction!(mc::monte_carlo_report, m)?)?;
    Ok(())
}
