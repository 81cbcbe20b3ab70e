//! The real explorer under a pseudo-terminal, ended from outside: each of SIGTERM, SIGHUP,
//! SIGINT and SIGQUIT gives the terminal back as it was (cooked mode, the main screen, the
//! cursor shown) and exits with 128 + the signal's number; and a start-up clears the
//! temporary files a killed save left in the presets folder.
#![cfg(unix)]

mod pty;

use pty::{Explorer, HIDE_CURSOR, assert_restored, modes, signal};
use rustix::process::Signal;
use std::fs;

#[test]
fn each_signal_restores_the_terminal_and_exits_128_plus_n() {
    for (sig, n) in [
        (Signal::TERM, 15),
        (Signal::HUP, 1),
        (Signal::INT, 2),
        (Signal::QUIT, 3),
    ] {
        let home = tempfile::tempdir().unwrap();
        let mut x = Explorer::spawn(home.path(), None, &[]);
        let before = modes(&x.before);
        x.wait_for_first_draw();
        x.wait_for(HIDE_CURSOR); // the end of the first frame
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
