//! Ctrl-Z suspends command-line work (issue 54 item 6): SIGTSTP stops a command on a terminal
//! and SIGCONT lets it finish as if nothing happened. The command runs as the leader of its
//! own session in a pty, as in the review's terminal: there the kernel discards SIGTSTP's
//! default action (a process group none of whose parents is in its session), so the command
//! went on — the test fails on the old code at "stopped by SIGTSTP".
#![cfg(unix)]

use crate::pty;

use rustix::process::Signal;
use std::time::{Duration, Instant};

/// The state letter of process `pid` (`T`: stopped), from /proc.
fn state(pid: u32) -> char {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    stat.rsplit(')')
        .next()
        .and_then(|rest| rest.trim().chars().next())
        .unwrap_or('?')
}

#[test]
fn sigtstp_suspends_a_command_and_sigcont_lets_it_finish() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, out) = pty::slow_figure(home.path(), 200);
    x.wait_for("/600 impacts"); // the bar: the work is under way (some seconds of it)
    let pid = x.pid();
    x.signal(Signal::TSTP);
    x.wait_until("stopped by SIGTSTP", || state(pid) == 'T');
    // it stays stopped: no work, no exit
    let held = Instant::now();
    while held.elapsed() < Duration::from_millis(300) {
        assert_eq!(state(pid), 'T', "resumed by itself");
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(!out.exists(), "the figure was written while stopped");
    x.signal(Signal::CONT);
    let (status, _, text) = x.finish();
    assert_eq!(
        status.code(),
        Some(0),
        "{status:?}\n{}",
        text.escape_debug()
    );
    assert!(out.exists(), "no figure after SIGCONT");
}
