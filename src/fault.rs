//! Test-only fault injection, switched on by `BOUNCELAB_TEST_FAULT=<name>` in a build with the
//! `test-faults` feature (the tests' build: see Cargo.toml). Without it no fault is ever active
//! and neither the variable's name nor the faults' code is compiled into the product.
//!
//! These switches exist so that the tests under a pseudo-terminal (`tests/tui/tui_pty.rs`,
//! `tests/tui/tui_save_pty.rs`) can make the real binary fail at a chosen point: a panic inside
//! the explorer's event loop (is the terminal restored?), a panic in one of its worker threads
//! (does the view say so, and does the explorer go on?) and a pause in the middle of writing
//! a preset file (does a SIGKILL there leave a truncated preset?).

/// The environment variable that switches a fault on.
#[cfg(feature = "test-faults")]
pub const ENV: &str = "BOUNCELAB_TEST_FAULT";

/// A failure a test can ask for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// `panic-in-loop`: the explorer's event loop panics at the first key press.
    PanicInLoop,
    /// `pause-mid-save`: saving a preset stops for [`PAUSE`] after writing part of the
    /// temporary file, long enough for a test to kill the process there.
    PauseMidSave,
    /// `slow-work`: each step of watched long work (a fit's model run) takes 20 ms more, so
    /// that a test can signal the command mid-work (tests/cli/cli_progress_pty.rs).
    SlowWork,
    /// `panic-in-worker`: the explorer's first worker thread panics at its first job (the
    /// sweeps' thread: `Tab` to the sweeps view), once a process, so that a test can see the
    /// view say its computation stopped and `R` retry it (tests/tui/tui_worker_pty.rs).
    PanicInWorker,
    /// `slow-start`: a command pauses [`START_PAUSE`] just after its signals are watched and
    /// before its work, so that a test can signal it in its first moments
    /// (tests/cli/signals_early.rs).
    SlowStart,
}

/// How long `slow-start` pauses.
pub const START_PAUSE: std::time::Duration = std::time::Duration::from_millis(700);

/// How long `pause-mid-save` sleeps: far longer than a test needs to send SIGKILL.
pub const PAUSE: std::time::Duration = std::time::Duration::from_secs(30);

impl Fault {
    pub fn name(self) -> &'static str {
        match self {
            Fault::PanicInLoop => "panic-in-loop",
            Fault::PauseMidSave => "pause-mid-save",
            Fault::SlowWork => "slow-work",
            Fault::PanicInWorker => "panic-in-worker",
            Fault::SlowStart => "slow-start",
        }
    }

    /// Whether the environment switches this fault on (never, without `test-faults`).
    #[cfg(feature = "test-faults")]
    pub fn active(self) -> bool {
        std::env::var_os(ENV).is_some_and(|v| v == self.name())
    }

    /// Whether the environment switches this fault on (never, without `test-faults`).
    #[cfg(not(feature = "test-faults"))]
    pub const fn active(self) -> bool {
        false
    }
}
