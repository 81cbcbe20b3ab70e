//! The real explorer under a pseudo-terminal with the test fault `panic-in-worker` (its first
//! worker thread, the sweeps', panics at its first job): the explorer goes on in its full
//! screen — raw mode, the alternate screen kept, no panic text over it — the sweeps view says
//! the sweep stopped and why, `R` retries on a new thread, and `q` quits with the terminal
//! restored.
#![cfg(unix)]

use crate::pty;

use pty::{Explorer, LEAVE_ALT_SCREEN};
use rustix::termios::LocalModes;

#[test]
fn a_worker_that_panics_is_reported_and_the_explorer_goes_on() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, before) = Explorer::started(home.path(), Some("panic-in-worker"), &[]);
    x.send(b"\t"); // the sweeps view: its sweep goes to the worker, which panics
    x.wait_for("panic-in-worker:");
    let out = x.output();
    assert!(!out.contains("panicked at"), "{}", out.escape_debug());
    assert!(!out.contains(LEAVE_ALT_SCREEN), "the full screen was left");
    let now = x.termios_now();
    assert!(
        !now.local_modes.contains(LocalModes::ICANON),
        "raw mode was left"
    );
    x.send(b"R");
    x.wait_for("retrying");
    x.send(b"q");
    x.finish_restored(&before);
}
