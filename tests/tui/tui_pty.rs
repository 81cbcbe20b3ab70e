//! The real explorer under a pseudo-terminal: whether it quits normally or panics inside its
//! event loop (the test-only fault `BOUNCELAB_TEST_FAULT=panic-in-loop`, a panic at the first
//! key press), the terminal is given back as it was — cooked mode (line editing and echo on),
//! the main screen, a visible cursor — and a panic's message reaches the user.
#![cfg(unix)]

use crate::pty;

use pty::{Explorer, LEAVE_ALT_SCREEN, assert_restored, modes, signal};
use rustix::termios::LocalModes;

#[test]
fn q_quits_with_the_terminal_restored() {
    let home = tempfile::tempdir().unwrap();
    let mut x = Explorer::spawn(home.path(), None, &[]);
    let before = modes(&x.before);
    assert!(
        x.before
            .local_modes
            .contains(LocalModes::ICANON | LocalModes::ECHO),
        "a new pty starts cooked"
    );
    x.wait_for_first_draw();
    x.send(b"?");
    x.wait_for("Keys · Esc or ? closes"); // the help is up: keys are read and the screen redrawn
    x.send(b"qq"); // the first q closes the help, the second quits
    x.finish_restored(&before);
}

#[test]
fn a_panic_in_the_event_loop_restores_the_terminal_and_reports() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, before) = Explorer::started(home.path(), Some("panic-in-loop"), &[]);
    x.send(b"l");
    let (status, after, out) = x.finish();
    assert!(!status.success(), "a panic must not exit 0");
    assert_eq!(
        status.code(),
        Some(101),
        "{status:?}, signal {:?}",
        signal(&status)
    );
    assert_restored(&before, &after, &out);
    let msg = out
        .find("panic-in-loop: test fault injected at a key press")
        .unwrap_or_else(|| panic!("no panic message in:\n{}", out.escape_debug()));
    assert!(out[..msg].contains("panicked at"), "{}", out.escape_debug());
    // printed on the main screen, after leaving the alternate one: it stays visible
    let left = out.find(LEAVE_ALT_SCREEN).unwrap();
    assert!(
        left < msg,
        "the message went to the alternate screen and is lost"
    );
}
