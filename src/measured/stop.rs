//! The stop flag the readers look at (issue 54 item 6): a 10⁶-row trace held Ctrl-C for its
//! whole parse. The command line hands its SIGINT/SIGTERM flag over (as `atomic::stop_on`);
//! the library itself never sets it. tests/cli/signals_prompt.rs.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};

static STOP: OnceLock<Arc<AtomicBool>> = OnceLock::new();

/// Stop reading once `flag` is set: a read then fails with an "interrupted" error at the row
/// it reached (`table::read_each`), and the whole-text scans end early (`rows`).
pub fn stop_on(flag: Arc<AtomicBool>) {
    let _ = STOP.set(flag);
}

/// Whether the flag given to [`stop_on`] is set.
pub(super) fn stopped() -> bool {
    STOP.get().is_some_and(|f| f.load(Ordering::Relaxed))
}
