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

/// Run `work` without the GIL on a thread of its own while this one asks Python for its
/// signals every [`EVERY`]: on one (Ctrl-C's `KeyboardInterrupt`) the flag `work` is given
/// turns true, `work` is waited for — it reads the flag between small pieces, so it ends
/// within one piece — and the signal's exception is raised; else `work`'s answer. For work
/// done in parallel (rayon) that cannot carry a [`Watch`], whose `Cell`s stay on one thread:
/// `batch`'s balls, `impacts`' blocks (issue 54 item 6: Ctrl-C took 9.4 s and 3.1 s;
/// python/tests/test_interrupt_latency.py).
pub fn detach_stoppable<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&std::sync::atomic::AtomicBool) -> T + Send,
) -> PyResult<T> {
    use std::sync::atomic::{AtomicBool, Ordering};
    let stop = AtomicBool::new(false);
    let (answer, raised) = py.detach(|| {
        std::thread::scope(|s| {
            let worker = s.spawn(|| work(&stop));
            let mut raised = None;
            while !worker.is_finished() {
                std::thread::sleep(Duration::from_millis(5));
                if raised.is_none()
                    && let Err(e) = Python::attach(|py| py.check_signals())
                {
                    raised = Some(e);
                    stop.store(true, Ordering::Relaxed);
                }
            }
            let answer = worker.join();
            (answer, raised)
        })
    });
    match (answer, raised) {
        (_, Some(e)) => Err(e),
        (Ok(v), None) => Ok(v),
        (Err(panic), None) => std::panic::resume_unwind(panic),
    }
}
