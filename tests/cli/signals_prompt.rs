//! Issue 54 item 6 (≤ 0.5 s): Ctrl-C or SIGTERM during `figure --measured` or `fit
//! --force-time --plot` on a large trace was obeyed only at the end — a release build with
//! 10⁶ rows took 2.84 s, and a signal 0.1 s in ended it 2.96 s later (a debug build: 42–56 s),
//! exit 130 and nothing written, but only after all the work: the file was parsed row by row
//! (twice, for `figure`) with no look at the stop flag. Now the reading looks at it every
//! 4096 rows and every 256 KiB scanned, and the commands between their phases.
//!
//! The bound is a part of the work itself, timed on this machine now, not an absolute time:
//! the same command is run once to its end (T), then signalled T/4 in, and must end within
//! 0.1 s + T/5 of the signal. A command that looks at the flag only at its end goes on for
//! some 3T/4, beyond the bound on a release build (T ≈ 0.5 s) and a debug one under load
//! (T ≈ 10 s) alike, since the load stretches T and the rest of the work together; one that
//! looks every few milliseconds of work ends well within it.
#![cfg(unix)]

use crate::common::{argv, command_in};
use std::path::Path;
use std::process::Stdio;
use std::time::{Duration, Instant};

/// A trace of `rows` samples 40 ns apart: a half-sine pulse of 3 ms a tennis ball at 6.906
/// m/s could give (impulse some 0.7 N s), a little noise on either side.
fn trace(rows: usize) -> String {
    let mut s = String::with_capacity(rows * 24);
    s.push_str("time_s,force_N\n");
    for i in 0..rows {
        let t = i as f64 * 4e-8;
        let u = (t - 4e-4) / 3e-3;
        let pulse = if (0.0..=1.0).contains(&u) {
            360.0 * (std::f64::consts::PI * u).sin()
        } else {
            0.0
        };
        let noise = if i % 2 == 0 { 0.05 } else { -0.05 };
        s.push_str(&format!("{t:.9e},{:.6}\n", pulse + noise));
    }
    s
}

/// `bouncelab ARGS` in `dir` to its end: its exit code and the seconds it took.
fn whole(dir: &Path, args: &[&str]) -> (Option<i32>, f64) {
    let start = Instant::now();
    let status = command_in(dir, args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .unwrap();
    (status.code(), start.elapsed().as_secs_f64())
}

/// `bouncelab ARGS` in `dir`, sent `signal` `after` s in: its exit code and the seconds from
/// the signal to its end.
fn signalled(
    dir: &Path,
    args: &[&str],
    signal: rustix::process::Signal,
    after: f64,
) -> (Option<i32>, f64) {
    let mut child = command_in(dir, args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_secs_f64(after));
    let pid = rustix::process::Pid::from_child(&child);
    rustix::process::kill_process(pid, signal).unwrap();
    let sent = Instant::now();
    let status = child.wait().unwrap();
    (status.code(), sent.elapsed().as_secs_f64())
}

#[test]
fn a_signal_during_a_large_trace_is_obeyed_promptly() {
    use rustix::process::Signal;
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    std::fs::write(d.join("big.csv"), trace(200_000)).unwrap();
    let cases = [
        (
            "figure force-time --measured big.csv --out fr.svg",
            "fr.svg",
            Signal::INT,
        ),
        (
            "figure force-time --measured big.csv --out fr.svg",
            "fr.svg",
            Signal::TERM,
        ),
        (
            "fit --preset tennis --force-time big.csv --v0 6.906 --free k_p --plot fp.svg",
            "fp.svg",
            Signal::INT,
        ),
    ];
    for (line, file, signal) in cases {
        let args = argv(line);
        let (code, t) = whole(d, &args);
        assert_eq!(code, Some(0), "{line}: the whole run");
        std::fs::remove_file(d.join(file)).unwrap();
        let (code, late) = signalled(d, &args, signal, t / 4.0);
        let bound = 0.1 + t / 5.0;
        eprintln!(
            "{line} ({signal:?}): whole {t:.2} s; ended {late:.3} s after the signal (bound {bound:.2} s)"
        );
        assert_eq!(
            code,
            Some(130),
            "{line} ({signal:?}): ended before the signal?"
        );
        assert!(!d.join(file).exists(), "{line} ({signal:?}) wrote {file}");
        assert!(
            late < bound,
            "{line} ({signal:?}): ended {late:.2} s after the signal; the whole run took {t:.2} s"
        );
    }
}
