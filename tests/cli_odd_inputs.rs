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
