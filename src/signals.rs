//! Signals that end, suspend or resume the program while it owns the terminal.
//!
//! The explorer puts the terminal in raw mode, on the alternate screen, with the cursor
//! hidden. While a [`TerminalGuard`] lives, a thread waits for signals:
//!
//! - the catchable ones whose default is to end the process ([`SIGNALS`]: SIGTERM, SIGHUP,
//!   SIGINT, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGXCPU, SIGABRT) would end it
//!   without undoing that (the shell after it then echoes nothing): the thread takes the stdout lock (so no frame
//!   is drawn after it), restores the terminal, and exits with the conventional 128 + the
//!   signal's number (tests/tui/tui_exit_pty.rs, `each_signal_restores_the_terminal_and_exits_128_plus_n`,
//!   `other_terminating_signals_restore_the_terminal_too`). SIGPIPE is ignored by Rust's
//!   runtime (a write to a closed terminal fails instead);
//! - SIGTSTP (and Ctrl-Z, which raw mode delivers as a key: the event loop calls [`suspend`])
//!   restores the terminal and stops the process, as vim and htop do; on SIGCONT the terminal
//!   is set up again and the event loop redraws the whole screen ([`take_redraw`];
//!   `ctrl_z_and_sigtstp_suspend_with_the_terminal_restored_and_sigcont_redraws`).

use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

/// Restores the terminal and exits on a terminating signal, suspends on SIGTSTP, while it lives.
pub struct TerminalGuard {
    #[cfg(unix)]
    handle: signal_hook::iterator::Handle,
    #[cfg(unix)]
    thread: Option<std::thread::JoinHandle<()>>,
}

/// The terminating signals handled, with the exit code they give (128 + n).
#[cfg(unix)]
/// SIGXCPU (a CPU-time limit, `ulimit -t`) and SIGABRT sent from outside end it too (issue 54
/// item 6: they left the terminal raw); an abort from within (`abort()` re-raises SIGABRT with
/// its default action once the handler returns) is not held by this.
pub const SIGNALS: [i32; 10] = {
    use signal_hook::consts::signal::{
        SIGABRT, SIGALRM, SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGVTALRM, SIGXCPU,
    };
    [
        SIGTERM, SIGHUP, SIGINT, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGXCPU, SIGABRT,
    ]
};

/// Set when the terminal was set up again after a suspension: the screen must be redrawn
/// whole.
static REDRAW: AtomicBool = AtomicBool::new(false);

/// Whether the screen must be redrawn whole (once: the flag is cleared).
pub fn take_redraw() -> bool {
    REDRAW.swap(false, Ordering::Relaxed)
}

/// Suspend as SIGTSTP does (Ctrl-Z in raw mode arrives as a key): the guard's thread restores
/// the terminal and stops the process. Without a guard, SIGTSTP's default stops it.
pub fn suspend() {
    #[cfg(unix)]
    let _ = signal_hook::low_level::raise(signal_hook::consts::SIGTSTP);
}

impl TerminalGuard {
    /// Start watching; `restore` puts the terminal back (raw mode off, main screen, cursor),
    /// `resume` sets it up again after a suspension.
    pub fn new(restore: fn(), resume: fn()) -> io::Result<TerminalGuard> {
        #[cfg(unix)]
        {
            use signal_hook::consts::{SIGCONT, SIGTSTP};
            let mut all = SIGNALS.to_vec();
            all.extend([SIGTSTP, SIGCONT]);
            let mut signals = signal_hook::iterator::Signals::new(all)?;
            let handle = signals.handle();
            let thread = std::thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    for sig in signals.forever() {
                        match sig {
                            SIGTSTP => stop(restore, resume),
                            // resumed by a SIGSTOP's SIGCONT (which no handler sees): the
                            // terminal as the shell left it, so set it up and redraw
                            SIGCONT => {
                                let _lock = io::stdout().lock();
                                let _ = std::panic::catch_unwind(resume);
                                REDRAW.store(true, Ordering::Relaxed);
                            }
                            _ => end(sig, restore),
                        }
                    }
                })?;
            Ok(TerminalGuard {
                handle,
                thread: Some(thread),
            })
        }
        #[cfg(not(unix))]
        {
            let _ = (restore, resume);
            Ok(TerminalGuard {})
        }
    }
}

/// Restore the terminal and exit 128 + `sig`.
#[cfg(unix)]
fn end(sig: i32, restore: fn()) -> ! {
    // held until the exit: the event loop cannot draw over the restored terminal (the lock
    // is reentrant, so `restore` may take it again)
    let stdout = io::stdout();
    let mut lock = stdout.lock();
    // a terminal that hung up fails every write: exit whatever happens
    let _ = std::panic::catch_unwind(restore);
    let _ = lock.flush();
    std::process::exit(128 + sig);
}

/// Restore the terminal, stop (SIGSTOP, which cannot be caught), and on SIGCONT set the
/// terminal up again and ask for a whole redraw; no frame is drawn in between (the stdout
/// lock is held).
#[cfg(unix)]
fn stop(restore: fn(), resume: fn()) {
    let stdout = io::stdout();
    let mut lock = stdout.lock();
    let _ = std::panic::catch_unwind(restore);
    let _ = lock.flush();
    let _ = signal_hook::low_level::raise(signal_hook::consts::SIGSTOP);
    let _ = std::panic::catch_unwind(resume);
    let _ = lock.flush();
    REDRAW.store(true, Ordering::Relaxed);
}

impl Drop for TerminalGuard {
    fn drop(&mut self) {
        #[cfg(unix)]
        {
            self.handle.close();
            if let Some(t) = self.thread.take() {
                let _ = t.join();
            }
        }
    }
}
