//! Issue 54 item 6 (the edges): a signal in a command's first moments. Ctrl-C in the first
//! half-second of `figure --measured`, `batch` or `fit --plot` was lost and everything written
//! (exit 0); SIGTERM there exited 143; SIGHUP and SIGQUIT let a command finish and write. Now
//! each stops it as Ctrl-C does: exit 130, nothing written. `slow-start` (src/fault.rs) holds
//! the command just after its signals are watched, so the signal lands in those moments.
#![cfg(unix)]

use crate::common::{argv, command_in};
use std::path::Path;
use std::process::Stdio;
use std::time::{Duration, Instant};

const COR: &str = "v0,cor\n2,0.8\n4,0.75\n6,0.7\n";
const LOT: &str = "id,drop_height_m,rebound_height_m\nA1,2.54,1.40\nA2,2.54,1.45\n";

/// `bouncelab ARGS` in `dir`, sent `signal` 250 ms after it started: its exit code (None:
/// ended by the signal itself).
fn signalled(dir: &Path, args: &[&str], signal: i32) -> Option<i32> {
    let mut child = command_in(dir, args)
        .env("BOUNCELAB_TEST_FAULT", "slow-start")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(250));
    let pid = rustix::process::Pid::from_child(&child);
    let sig = rustix::process::Signal::from_named_raw(signal).unwrap();
    rustix::process::kill_process(pid, sig).unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status.code();
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "{args:?} still runs"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Each command and the file it would write.
const COMMANDS: [(&str, &str); 3] = [
    ("figure force-time --measured cor2.csv --out f.svg", "f.svg"),
    ("fit --cor-table cor.csv --plot p.svg", "p.svg"),
    ("batch lot.csv --preset tennis --csv-out b.csv", "b.csv"),
];

#[test]
fn an_early_signal_stops_the_command_writing_nothing() {
    use rustix::process::Signal;
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    std::fs::write(d.join("cor.csv"), COR).unwrap();
    std::fs::write(d.join("lot.csv"), LOT).unwrap();
    // a force trace for figure --measured
    let mut trace = String::from("time_s,force_N\n");
    for i in 0..=100 {
        let t = i as f64 * 1e-5;
        trace.push_str(&format!(
            "{t},{}\n",
            500.0 * (t / 1e-3 * std::f64::consts::PI).sin()
        ));
    }
    std::fs::write(d.join("cor2.csv"), trace).unwrap();
    for signal in [Signal::INT, Signal::TERM, Signal::HUP, Signal::QUIT] {
        for (line, file) in COMMANDS {
            let args = argv(line);
            let code = signalled(d, &args, signal.as_raw());
            assert_eq!(code, Some(130), "{args:?} and {signal:?}");
            assert!(
                !d.join(file).exists(),
                "{args:?} and {signal:?} wrote {file}"
            );
        }
    }
}
