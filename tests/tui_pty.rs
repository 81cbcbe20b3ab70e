//! The real explorer under a pseudo-terminal: whether it quits normally or panics inside its
//! event loop (the test-only fault `BOUNCELAB_TEST_FAULT=panic-in-loop`, a panic at the first
//! key press), the terminal is given back as it was — cooked mode (line editing and echo on),
//! the main screen, a visible cursor — and a panic's message reaches the user.
#![cfg(unix)]

mod pty;

use pty::{Explorer, HIDE_CURSOR, LEAVE_ALT_SCREEN, SHOW_CURSOR, modes, signal};
use rustix::termios::LocalModes;

/// What every exit must leave: the settings from before the start, in cooked mode, the
/// alternate screen left, the cursor shown after it was last hidden.
fn assert_restored(x_before: &str, after: &rustix::termios::Termios, out: &str) {
    let cooked = LocalModes::ICANON | LocalModes::ECHO;
    assert!(
        after.local_modes.contains(cooked),
        "not back in cooked mode: {:?}",
        after.local_modes
    );
    assert_eq!(modes(after), x_before, "the terminal's settings changed");
    assert!(
        out.contains(LEAVE_ALT_SCREEN),
        "never left the alternate screen"
    );
    let hidden = out
        .rfind(HIDE_CURSOR)
        .expect("the explorer hides the cursor");
    let shown = out.rfind(SHOW_CURSOR).expect("the cursor is shown again");
    assert!(shown > hidden, "the cursor was last hidden, not shown");
}

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
    x.wait_for("Backspace"); // the help is up: keys are read and the screen redrawn
    x.send(b"q");
    let (status, after, out) = x.finish();
    assert!(status.success(), "{status:?}\n{}", out.escape_debug());
    assert_restored(&before, &after, &out);
}

#[test]
fn a_panic_in_the_event_loop_restores_the_terminal_and_reports() {
    let home = tempfile::tempdir().unwrap();
    let mut x = Explorer::spawn(home.path(), Some("panic-in-loop"), &[]);
    let before = modes(&x.before);
    x.wait_for_first_draw();
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
