//! The real explorer under a pseudo-terminal, ended from outside: each of SIGTERM, SIGHUP,
//! SIGINT and SIGQUIT gives the terminal back as it was (cooked mode, the main screen, the
//! cursor shown) and exits with 128 + the signal's number; and a start-up clears the
//! temporary files a killed save left in the presets folder.
#![cfg(unix)]

use crate::pty;

use pty::{Explorer, HIDE_CURSOR, assert_restored, modes, signal};
use rustix::process::Signal;
use std::fs;
use std::path::Path;

/// The explorer with no ball, its first frame drawn (up to the cursor hidden at its end), and
/// the terminal's modes before it started.
fn started(home: &Path) -> (Explorer, String) {
    let (mut x, before) = Explorer::started(home, None, &[]);
    x.wait_for(HIDE_CURSOR);
    (x, before)
}

/// `trials` times: the explorer [`started`], `act` on it (ending in its quit), and it exits
/// with 0, the terminal as it was; a failure names the trial.
fn each_trial_quits_restored(trials: usize, act: impl Fn(&mut Explorer)) {
    for trial in 0..trials {
        let home = tempfile::tempdir().unwrap();
        let (mut x, before) = started(home.path());
        act(&mut x);
        let (status, after, out) = x.finish();
        assert_eq!(status.code(), Some(0), "trial {trial}: {status:?}");
        assert_restored(&before, &after, &out);
    }
}

/// The explorer, sent `sig` (number `n`) after its first frame, gives the terminal back as it
/// was and exits with 128 + n.
fn assert_signal_ends_it_restored(sig: Signal, n: i32) {
    let home = tempfile::tempdir().unwrap();
    let (x, before) = started(home.path());
    x.signal(sig);
    let (status, after, out) = x.finish();
    assert_eq!(
        status.code(),
        Some(128 + n),
        "signal {n}: {status:?}, killed by {:?}",
        signal(&status)
    );
    assert_restored(&before, &after, &out);
}

#[test]
fn each_signal_restores_the_terminal_and_exits_128_plus_n() {
    for (sig, n) in [
        (Signal::TERM, 15),
        (Signal::HUP, 1),
        (Signal::INT, 2),
        (Signal::QUIT, 3),
    ] {
        assert_signal_ends_it_restored(sig, n);
    }
}

#[test]
fn the_debris_of_a_killed_save_is_removed_at_start() {
    let home = tempfile::tempdir().unwrap();
    let dir = home.path().join("bouncelab").join("presets");
    fs::create_dir_all(&dir).unwrap();
    // the name catalog::write gives a save's temporary, of a process that has exited
    let mut gone = std::process::Command::new("true").spawn().unwrap();
    let pid = gone.id();
    gone.wait().unwrap();
    let debris = dir.join(format!(".golf2.toml.{pid}-123456789.tmp"));
    let other = dir.join("notes.tmp");
    fs::write(&debris, "name = \"go").unwrap();
    fs::write(&other, "mine").unwrap();
    let mut x = Explorer::spawn(home.path(), None, &[]);
    x.wait_for_first_draw();
    x.send(b"q");
    let (status, _, out) = x.finish();
    assert!(status.success(), "{status:?}\n{}", out.escape_debug());
    assert!(!debris.exists(), "the dead save's temporary is removed");
    assert!(other.exists(), "a file of another kind is left alone");
}

#[test]
fn other_terminating_signals_restore_the_terminal_too() {
    for (sig, n) in [
        (Signal::USR1, 10),
        (Signal::USR2, 12),
        (Signal::ALARM, 14),
        (Signal::VTALARM, 26),
        // issue 54 item 6: these two left the terminal raw
        (Signal::XCPU, 24),
        (Signal::ABORT, 6),
    ] {
        assert_signal_ends_it_restored(sig, n);
    }
}

/// The state letter of process `pid` (`T` when stopped), from /proc.
fn state(pid: u32) -> char {
    let stat = fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    // "pid (comm) S …": the state follows the command's closing parenthesis
    stat.rsplit_once(") ")
        .and_then(|(_, rest)| rest.chars().next())
        .unwrap_or('?')
}

#[test]
fn ctrl_z_and_sigtstp_suspend_with_the_terminal_restored_and_sigcont_redraws() {
    use rustix::termios::LocalModes;
    for how in ["ctrl-z", "sigtstp"] {
        let home = tempfile::tempdir().unwrap();
        let (mut x, before) = started(home.path());
        match how {
            "ctrl-z" => x.send(b"\x1a"),
            _ => x.signal(Signal::TSTP),
        }
        let pid = x.pid();
        x.wait_until("the explorer stopped", || state(pid) == 'T');
        // stopped with the terminal as it was: cooked mode, the main screen, the cursor shown
        let now = x.termios_now();
        assert!(
            now.local_modes
                .contains(LocalModes::ICANON | LocalModes::ECHO),
            "{how}: raw mode left on while stopped"
        );
        assert_eq!(modes(&now), before, "{how}");
        // (what it wrote before it stopped may still be on its way through the pty)
        x.wait_for(pty::LEAVE_ALT_SCREEN);
        x.wait_for(pty::SHOW_CURSOR);
        let out = x.output();
        assert!(out.rfind(pty::LEAVE_ALT_SCREEN) > out.rfind(pty::ENTER_ALT_SCREEN));
        assert!(out.rfind(pty::SHOW_CURSOR) > out.rfind(HIDE_CURSOR));
        // continued: back on the alternate screen, drawn whole again, and it still takes keys
        x.signal(Signal::CONT);
        x.wait_for(pty::ENTER_ALT_SCREEN);
        x.wait_for("bouncelab");
        assert_ne!(state(pid), 'T');
        x.send(b"q");
        let (status, after, out) = x.finish();
        assert_eq!(
            status.code(),
            Some(0),
            "{how}: {status:?}\n{}",
            out.escape_debug()
        );
        assert_restored(&before, &after, &out);
    }
}

#[test]
// issue 28 ("after a burst of 20 resizes the next key is lost"): it lost the `q` in one trial
// of three under CI load; the cause and its test that fails every time are below
fn a_key_after_a_burst_of_resizes_is_not_lost() {
    each_trial_quits_restored(3, |x| {
        // the burst and the key come while the explorer reads nothing (stopped, as when it is
        // busy or its output is blocked): on waking it finds both the resizes and the key
        x.signal(Signal::STOP);
        let pid = x.pid();
        x.wait_until("the explorer stopped", || state(pid) == 'T');
        for i in 0..20u16 {
            x.resize(100 + i, 30 + i % 7);
        }
        x.send(b"q");
        x.signal(Signal::CONT);
    });
}

#[test]
fn a_key_typed_while_the_explorer_draws_a_resize_is_not_lost() {
    // crossterm's reader, woken with a resize and a key ready together, returned the resize
    // and never read the key (src/tui/event.rs, `rearm_input`). Made to happen: a resize to a
    // large screen keeps the explorer drawing, and meanwhile a second resize then a key
    // arrive, in that order. Before the fix 7 of 10 trials lost the `q` (the explorer sat
    // until the next key); a trial that loses it fails at `finish`'s timeout
    each_trial_quits_restored(10, |x| {
        x.resize(400, 150);
        std::thread::sleep(std::time::Duration::from_millis(30));
        x.resize(401, 150);
        std::thread::sleep(std::time::Duration::from_millis(5));
        x.send(b"q");
    });
}
