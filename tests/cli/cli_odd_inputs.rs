//! Odd but legal inputs at the command line, as a new user gives them: what they print must
//! not read as another number.

use crate::common;

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

/// `fit --cor 1` said "cor 1 is out of reach …: the model spans 0.5985 (λ = 0) to 1.0000
/// (λ → ∞)", a span that holds 1 as printed. Its end is printed with the digits that keep it
/// below the COR asked for, and the COR as typed (it read "cor 1" for 0.999999999999); ends
/// far from it keep four.
#[test]
fn an_unreachable_cor_is_not_inside_the_span_shown() {
    for cor in ["1", "0.999999999999"] {
        let o = bl(&["fit", "--cor", cor]);
        assert_bad(
            &o,
            &[&format!("cor {cor} is out of reach"), "0.5985 (λ = 0)"],
        );
        let high: f64 = o
            .stderr
            .split(" to ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(high < cor.parse::<f64>().unwrap(), "{}", o.stderr);
    }
    bad(
        &["fit", "--cor", "0.01"],
        &["the model spans 0.5985 (λ = 0) to 1.0000 (λ → ∞)"],
    );
}

/// `fit --cor 0.99999999999` answered with "target COR 1": the COR typed, rounded to six
/// digits, read as another. It is shown as typed (as `peers` shows a typed target).
#[test]
fn a_typed_cor_is_shown_as_typed() {
    let text = ok(&["fit", "--cor", "0.99999999999"]);
    let line = text.lines().find(|l| l.contains("target COR")).unwrap();
    assert_eq!(
        line.split_whitespace().last(),
        Some("0.99999999999"),
        "{text}"
    );
    let text = ok(&["fit", "--cor", "0.75"]);
    assert!(text.contains("  target COR            0.75\n"), "{text}");
}
