//! Ctrl-C in long native work: the library's [`Watch`] asks Python for its signals between
//! chunks of work (a fit's model runs, a sweep's chunks of impacts), so that Ctrl-C raises
//! `KeyboardInterrupt` within a fraction of a second (python/tests/test_boundary.py).

use bouncelab::BallError;
use bouncelab::analysis::work::Watch;
use pyo3::prelude::*;
use std::cell::{Cell, RefCell};
use std::time::{Duration, Instant};

/// How often the GIL is taken to look for a signal: often enough for a prompt Ctrl-C,
/// rarely enough to cost nothing.
const EVERY: Duration = Duration::from_millis(20);

/// A watch that runs Python's signal handlers (without the GIL held in between).
pub struct Signals {
    last: Cell<Instant>,
    error: RefCell<Option<PyErr>>,
}

impl Signals {
    fn new() -> Signals {
        Signals {
            last: Cell::new(Instant::now()),
            error: RefCell::new(None),
        }
    }
}

impl Watch for Signals {
    fn step(&self, _done: u64) -> bool {
        if self.last.get().elapsed() < EVERY {
            return true;
        }
        self.last.set(Instant::now());
        match Python::attach(|py| py.check_signals()) {
            Ok(()) => true,
            Err(e) => {
                *self.error.borrow_mut() = Some(e);
                false
            }
        }
    }
}

/// Run `work` without the GIL, watched for signals; a signal's exception (KeyboardInterrupt)
/// is raised in place of the interrupted work's error, any other error by `error`.
pub fn detach_watched<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&dyn Watch) -> Result<T, BallError> + Send,
) -> PyResult<T> {
    let (result, raised) = py.detach(|| {
        let watch = Signals::new();
        let r = work(&watch);
        (r, watch.error.into_inner())
    });
    match (result, raised) {
        (Ok(v), _) => Ok(v),
        (Err(_), Some(e)) => Err(e),
        (Err(e), None) => Err(crate::error(e)),
    }
}
