//! Odd but legal inputs at the command line, as a new user gives them: what they print must
//! not read as another number.

mod common;

use common::*;

/// `run --lambda 0 --zeta 1` (no rebound, the dashpot takes everything) closed its energy
/// balance exactly and printed the residual as Rust's `0.0e0`.
#[test]
fn an_exact_zero_residual_reads_0() {
    let text = ok(&["run", "--lambda", "0", "--zeta", "1"]);
    let line = text
        .lines()
        .find(|l| l.contains("balance residual"))
        .unwrap();
    assert_eq!(
        line.split_whitespace().collect::<Vec<_>>(),
        ["balance", "residual", "0", "of", "the", "initial"],
        "{text}"
    );
    // a residual that is not zero keeps its two digits
    let text = ok(&["run", "--preset", "superball"]);
    assert!(
        text.contains("balance residual           1.5e-16 of the initial"),
        "{text}"
    );
}

/// `peers --preset superball --v0 45` put its warning (a peak indentation of 31 mm on a ball
/// of 21.55 mm) in the JSON only: the text said nothing, nor the CSV or an export.
#[test]
fn peers_say_their_warning_in_every_format() {
    let base = ["peers", "--preset", "superball", "--v0", "45"];
    let said = "peak indentation 31.05 mm exceeds the ball's radius 21.55 mm";
    let text = ok(&base);
    assert!(text.contains(&format!("\nwarning: {said}")), "{text}");
    for extra in [
        &["--format", "csv"][..],
        &["--export", "lammps"],
        &["--export", "json"],
    ] {
        let o = bl(&[&base[..], extra].concat());
        assert_eq!(o.code, 0, "{extra:?}: {}", o.stderr);
        assert!(
            o.stderr.starts_with(&format!("bouncelab: warning: {said}")),
            "{extra:?}: {}",
            o.stderr
        );
    }
    // at the measured speed, nothing
    let o = bl(&["peers", "--preset", "superball", "--export", "lammps"]);
    assert!(o.stderr.is_empty(), "{}", o.stderr);
    assert!(!ok(&["peers", "--preset", "superball"]).contains("warning:"));
}
