//! Long work allowed by the work limit, on a terminal: a progress bar on stderr, and Ctrl-C
//! (SIGINT) or SIGTERM ends the command with exit 130 before any file is written.
#![cfg(unix)]

use crate::common::argv;
use crate::pty;

use pty::Explorer;
use rustix::process::Signal;

#[test]
fn long_work_shows_progress_and_a_signal_stops_it_writing_nothing() {
    for sig in [Signal::INT, Signal::TERM] {
        let home = tempfile::tempdir().unwrap();
        let (mut x, _) = pty::slow_figure(home.path(), 2000);
        x.wait_for("/6000 impacts"); // the bar
        x.signal(sig);
        stopped_writing_nothing(x, home.path(), &format!("{sig:?}"));
    }
}

/// The files left in `dir`, by name.
fn left(dir: &std::path::Path) -> Vec<std::ffi::OsString> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect()
}

/// The command `x` ran in `home` ended on its signal: exit 130, "interrupted", no file left
/// in `home`; its output. `what` names the case in a failure.
fn stopped_writing_nothing(x: Explorer, home: &std::path::Path, what: &str) -> String {
    let (status, _, text) = x.finish();
    assert_eq!(
        status.code(),
        Some(130),
        "{what}: {status:?}\n{}",
        text.escape_debug()
    );
    assert!(text.contains("interrupted"), "{}", text.escape_debug());
    assert!(left(home).is_empty(), "{:?}", left(home));
    text
}

/// A 999 999-row force trace (the most a file may hold): a half-sine pulse of 60 N over
/// 3 ms from 2 ms, on 10 ms, with a little alternating noise.
fn dense_trace(path: &std::path::Path) {
    use std::fmt::Write as _;
    let rows = 999_999;
    let mut text = String::with_capacity(rows * 24);
    text.push_str("time_s,force_N\n");
    for i in 0..rows {
        let t = i as f64 * 1e-8;
        let s = (t - 2e-3) / 3e-3;
        let pulse = if (0.0..1.0).contains(&s) {
            60.0 * (std::f64::consts::PI * s).sin()
        } else {
            0.0
        };
        let noise = if i % 2 == 0 { 0.1 } else { -0.1 };
        writeln!(text, "{t:e},{:.4}", pulse + noise).unwrap();
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn a_dense_trace_fit_shows_progress_and_a_signal_stops_it_writing_nothing() {
    let data = tempfile::tempdir().unwrap();
    let trace = data.path().join("dense.csv");
    dense_trace(&trace);
    for sig in [Signal::INT, Signal::TERM] {
        let home = tempfile::tempdir().unwrap();
        let plot = home.path().join("fit.svg");
        let mut args = argv("fit --preset tennis --free k_p,c,k_r,v0 --force-time");
        args.extend([trace.to_str().unwrap(), "--plot", plot.to_str().unwrap()]);
        // each model run slowed to 20 ms: the fit is still running when the signal comes
        let mut x = Explorer::spawn(home.path(), Some("slow-work"), &args);
        // the counter, after the 999 999 rows are read: about 25 s in a debug build at a load
        // average of 9 (the two runs took 51 s), beyond the usual 30 s wait at a load of 20
        x.wait_for_within("model runs,", std::time::Duration::from_secs(120));
        x.signal(sig);
        stopped_writing_nothing(x, home.path(), &format!("{sig:?}"));
    }
}

#[test]
fn a_signal_mid_write_leaves_no_temporary_file() {
    for sig in [Signal::INT, Signal::TERM] {
        let home = tempfile::tempdir().unwrap();
        let out = home.path().join("m.svg");
        let mut args =
            argv("map --normalized --lambda 0.1:10:40 --zeta 0.1:10:40 --format svg --out");
        args.push(out.to_str().unwrap());
        // the write stops halfway (30 s) with its temporary file on disk
        let mut x = Explorer::spawn(home.path(), Some("pause-mid-save"), &args);
        let dir = home.path().to_path_buf();
        x.wait_until("the temporary file", || {
            left(&dir)
                .iter()
                .any(|n| n.to_string_lossy().starts_with(".m.svg."))
        });
        x.signal(sig);
        stopped_writing_nothing(x, home.path(), &format!("{sig:?}"));
    }
}

#[test]
fn cor_table_and_drop_test_fits_stop_on_a_signal_writing_nothing() {
    // issue 28: the COR-table and drop-test fits look at the watch before every model run and
    // every 64 impacts within one (src/analysis/fit/cor.rs), as the trace fit does
    let data = tempfile::tempdir().unwrap();
    let table = data.path().join("cor.csv");
    let mut text = String::from("v0,cor\n");
    for i in 0..200 {
        let v0 = 1.0 + 0.1 * i as f64;
        text.push_str(&format!("{v0},{}\n", 0.85 - 0.005 * v0));
    }
    std::fs::write(&table, text).unwrap();
    let drops = "--drop-height 1 --rebound-height 0.7 --drop-height 2 --rebound-height 1.3 \
                 --drop-height 3 --rebound-height 1.8";
    let cases: [Vec<&str>; 2] = [vec!["--cor-table", table.to_str().unwrap()], argv(drops)];
    for (case, sig) in cases.iter().zip([Signal::INT, Signal::TERM]) {
        let home = tempfile::tempdir().unwrap();
        let plot = home.path().join("fit.svg");
        let mut args = argv("fit --preset tennis --plot");
        args.push(plot.to_str().unwrap());
        args.extend(case.iter().copied());
        // each look of the watch slowed to 20 ms: the fit is still running at the signal
        let mut x = Explorer::spawn(home.path(), Some("slow-work"), &args);
        x.wait_for("model runs,"); // the counter
        x.signal(sig);
        stopped_writing_nothing(x, home.path(), &format!("{case:?}"));
    }
}

#[test]
fn a_drop_stops_on_a_signal_printing_nothing() {
    // `drop` looks at the watch before every bounce, as do the drops of a fitted preset's
    // intervals (issue 28): a signal stops it before its table is printed
    let home = tempfile::tempdir().unwrap();
    let args = argv("drop --preset superball --law hertz --bounces 1000 --min-rebound 1e-9");
    // 593 bounces, each slowed to 20 ms: the drop is still running at the signal
    let mut x = Explorer::spawn(home.path(), Some("slow-work"), &args);
    x.wait_for("bounces,"); // the counter
    x.signal(Signal::INT);
    let text = stopped_writing_nothing(x, home.path(), "drop");
    assert!(!text.contains("rebound"), "{}", text.escape_debug());
}

#[test]
fn a_shot_monte_carlo_shows_progress_and_a_signal_stops_it() {
    // `mc --shot` runs its shots in blocks of 1024 with the bar and the Ctrl-C check between
    // them (issue 57 item 5): 2·10⁶ shots are still running at the signal
    for sig in [Signal::INT, Signal::TERM] {
        let home = tempfile::tempdir().unwrap();
        let args = argv(
            "mc --shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 \
             --friction 0.6 --vary speed=2%,spin=30 --samples 2000000",
        );
        let mut x = Explorer::spawn(home.path(), None, &args);
        x.wait_for("/2000000 shots"); // the bar
        let sent = std::time::Instant::now();
        x.signal(sig);
        let text = stopped_writing_nothing(x, home.path(), &format!("mc --shot, {sig:?}"));
        // measured, not asserted (speed is the benchmarks'): the issue asks for 0.5 s
        eprintln!("mc --shot stopped {:?} after {sig:?}", sent.elapsed());
        assert!(!text.contains("landing x"), "{}", text.escape_debug());
    }
}
