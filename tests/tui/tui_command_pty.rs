//! `y` in the real explorer under a pseudo-terminal (issue 29 item 2): the box shows the
//! explorer's line; on `xterm-256color` (not known to take OSC 52) no OSC 52 goes out; and
//! when the explorer ends, the last line `y` showed is printed on the main screen, after the
//! alternate screen is left — one line the scrollback keeps whole.
#![cfg(unix)]

use crate::pty;

use pty::Explorer;

#[test]
fn the_last_y_line_is_printed_on_the_main_screen_at_exit() {
    let home = tempfile::tempdir().unwrap();
    let (mut x, before) = Explorer::started(home.path(), None, &["--preset", "golf", "--v0", "3"]);
    x.send(b"y");
    x.wait_for("reopens");
    // q closes the box (Esc then q would read as Alt+q), a second q quits
    x.send(b"q");
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.send(b"q");
    let out = x.finish_restored(&before);
    assert!(
        !out.contains("\x1b]52;"),
        "no OSC 52 on an unknown terminal"
    );
    let left = out.rfind("\x1b[?1049l").expect("the alternate screen left");
    let tail = &out[left..];
    assert!(
        tail.contains("bouncelab --preset golf --v0 3\r\n")
            || tail.contains("bouncelab --preset golf --v0 3\n"),
        "{}",
        tail.escape_debug()
    );
}
