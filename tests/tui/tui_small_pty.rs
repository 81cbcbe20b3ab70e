//! The real explorer below its minimum size (issue 18, defect 5): keys typed while it asks for
//! a larger terminal change nothing; after the resize the next key acts as usual.
#![cfg(unix)]

use crate::pty;

use pty::Explorer;

#[test]
fn keys_below_the_minimum_size_do_nothing_unseen() {
    let home = tempfile::tempdir().unwrap();
    let mut x = Explorer::spawn(home.path(), None, &[]);
    x.wait_for_first_draw();
    // crossterm listens for SIGWINCH from its first read of an event on
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.resize(40, 12);
    x.wait_for("enlarge");
    // v would change v0 unseen, ? would open an invisible help that swallows the next keys
    x.send(b"vvv?");
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.resize(120, 40);
    x.wait_for("Force");
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.send(b"c"); // acts ("contact law: …"), so no help is in the way
    x.wait_for("law:");
    // the law changed: q asks first (issue 51), q again quits
    x.send(b"q");
    x.wait_for("Quit");
    x.send(b"q");
    let (status, _, out) = x.finish();
    assert!(status.success(), "{status:?}");
    assert!(!out.contains("Esc or ? closes"), "the help opened");
    assert!(
        !out.contains("3.42"),
        "v0 changed while the screen was too small"
    );
}
