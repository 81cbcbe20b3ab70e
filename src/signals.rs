//! Signals that end the program while it owns the terminal.
//!
//! The explorer puts the terminal in raw mode, on the alternate screen, with the cursor
//! hidden. SIGTERM, SIGHUP, SIGINT and SIGQUIT would end the process without undoing that (the
//! shell after it then echoes nothing). While a [`TerminalGuard`] lives, a thread waits for
//! those four; on one it takes the stdout lock (so no frame is drawn after it), restores the
//! terminal, and exits with the conventional code 128 + the signal's number.
//! (tests/tui_exit_pty.rs, `each_signal_restores_the_terminal_and_exits_128_plus_n`.)

use std::io::{self, Write};

/// Restores the terminal and exits on a terminating signal, while it lives.
pub struct TerminalGuard {
    #[cfg(unix)]
    handle: signal_hook::iterator::Handle,
    #[cfg(unix)]
    thread: Option<std::thread::JoinHandle<()>>,
}

/// The signals handled, with the exit code they give.
#[cfg(unix)]
pub const SIGNALS: [i32; 4] = {
    use signal_hook::consts::signal::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
    [SIGTERM, SIGHUP, SIGINT, SIGQUIT]
};

impl TerminalGuard {
    /// Start watching; `restore` puts the terminal back (raw mode off, main screen, cursor).
    pub fn new(restore: fn()) -> io::Result<TerminalGuard> {
        #[cfg(unix)]
        {
            let mut signals = signal_hook::iterator::Signals::new(SIGNALS)?;
            let handle = signals.handle();
            let thread = std::thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    if let Some(sig) = signals.forever().next() {
                        // held until the exit: the event loop cannot draw over the restored
                        // terminal (the lock is reentrant, so `restore` may take it again)
                        let stdout = io::stdout();
                        let mut lock = stdout.lock();
                        // a terminal that hung up fails every write: exit whatever happens
                        let _ = std::panic::catch_unwind(restore);
                        let _ = lock.flush();
                        std::process::exit(128 + sig);
                    }
                })?;
            Ok(TerminalGuard {
                handle,
                thread: Some(thread),
            })
        }
        #[cfg(not(unix))]
        {
            let _ = restore;
            Ok(TerminalGuard {})
        }
    }
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
