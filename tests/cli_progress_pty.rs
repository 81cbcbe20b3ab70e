//! Long work allowed by the work limit, on a terminal: a progress bar on stderr, and Ctrl-C
//! (SIGINT) or SIGTERM ends the command with exit 130 before any file is written.
#![cfg(unix)]

mod pty;

use pty::Explorer;
use rustix::process::Signal;

#[test]
fn long_work_shows_progress_and_a_signal_stops_it_writing_nothing() {
    for sig in [Signal::INT, Signal::TERM] {
        let home = tempfile::tempdir().unwrap();
        let out = home.path().join("slow.svg");
        let args = [
            "figure",
            "cor-zeta",
            "--law",
            "hertz",
            "--points",
            "2000",
            "--out",
            out.to_str().unwrap(),
        ];
        let mut x = Explorer::spawn(home.path(), None, &args);
        x.wait_for("/6000 impacts"); // the bar
        x.signal(sig);
        let (status, _, text) = x.finish();
        assert_eq!(
            status.code(),
            Some(130),
            "{status:?}\n{}",
            text.escape_debug()
        );
        assert!(text.contains("interrupted"), "{}", text.escape_debug());
        let left: Vec<_> = std::fs::read_dir(home.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert!(left.is_empty(), "{left:?}");
    }
}
