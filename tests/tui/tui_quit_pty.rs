//! The real explorer under a pseudo-terminal (issue 29 item 1): with a pin, Esc twice leaves
//! it running and says that q quits, `q` asks "Quit and lose 1 pin?", a second `q` quits and
//! the terminal is given back.
#![cfg(unix)]

use crate::pty;

use pty::Explorer;

#[test]
fn esc_keeps_the_pins_and_q_asks_before_losing_them() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, before) = Explorer::started(home.path(), None, &[]);
    x.send(b"p");
    x.wait_for("pinned");
    x.send(b"\x1b");
    // the screen is written word by word (the cursor moved between): wait for one word
    x.wait_for("never");
    x.send(b"\x1b");
    x.send(b"q");
    x.wait_for("Quit");
    x.send(b"q");
    x.finish_restored(&before);
}

/// `q` after an edit of the ball (no pin) asks too, naming the changes (issue 51 item 2); a
/// second `q` quits and the terminal is given back.
#[test]
fn q_asks_before_losing_an_edit() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, before) = Explorer::started(home.path(), None, &[]);
    x.send(b"c");
    x.wait_for("law:");
    x.send(b"q");
    x.wait_for("Quit");
    x.wait_for("changes");
    x.send(b"q");
    x.finish_restored(&before);
}
