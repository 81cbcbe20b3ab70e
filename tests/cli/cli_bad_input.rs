//! Bad input through the binary: exit code 2, exactly one line on stderr naming the field
//! (and file:line:column for a preset file), never a panic; a closed stdout is quiet.

use crate::common;

use common::*;
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

#[test]
fn fit_out_of_reach_and_bad_target() {
    // at the superball's ζ ≈ 0.16, λ = 0 already gives e ≈ 0.60
    bad_each(&[
        ("fit --cor 0.2", &["out of reach", "0.2"]),
        ("fit --cor 1.5", &["invalid cor: 1.5"]),
        ("fit --cor NaN", &["invalid cor: NaN"]),
        ("fit", &["--cor"]),
    ]);
}

#[test]
fn bad_numbers_name_the_field() {
    bad_each(&[
        ("run --zeta NaN", &["invalid zeta: NaN (not a number)"]),
        ("run --normalized --zeta nan", &["invalid zeta: NaN"]),
        ("run --lambda inf", &["invalid lambda: inf"]),
        ("run --lambda -1", &["invalid lambda: -1", "negative"]),
        ("run --v0 -3", &["invalid v0: -3", "negative"]),
        ("run --v0 0", &["invalid v0: 0", "positive"]),
        ("run --v0 1e300", &["invalid v0: 1e300"]),
        ("run --v0 abc", &["--v0", "abc"]),
        ("run --zeta 1e-300", &["invalid zeta: 1e-300"]),
        ("run --zeta 1e8", &["invalid zeta: 1e8", "above 1e6"]),
        ("run --lambda 1e14", &["invalid lambda: 1e14", "above 1e6"]),
        ("run --zeta 1e-14", &["invalid zeta: 1e-14", "c = "]),
        ("run --normalized --zp-bar 0", &["invalid zp_bar: 0"]),
        ("run --history --samples 1", &["invalid samples: 1"]),
        // `--history --samples 0` wrote no history and exit 0 from `oblique`, where 1 was refused
        (
            "run --history --samples 0",
            &["invalid samples: 0", "2 … 100000"],
        ),
    ]);
    let oblique = ["oblique", "--angle", "30", "--friction", "0.5", "--history"];
    for n in ["0", "1", "100001"] {
        let args: Vec<&str> = oblique.iter().copied().chain(["--samples", n]).collect();
        bad(&args, &[&format!("invalid samples: {n}"), "2 … 100000"]);
    }
    bad_each(&[
        ("fit --cor 0.5 --v0 inf", &["invalid v0: inf"]),
        ("sweep zeta --points 0", &["invalid points: 0"]),
        (
            "sweep zeta --points 100001",
            &["invalid points: 100001", "100000"],
        ),
        ("sweep zeta --points -5", &["--points", "-5"]),
        ("sweep zeta --from 0", &["invalid from: 0"]),
        ("sweep zeta --to inf", &["invalid to: inf"]),
        ("sweep zeta --lambda 0.4,NaN", &["invalid lambda: NaN"]),
        ("sweep velocity --from -1", &["invalid from: -1"]),
        ("sweep velocity --points 0", &["invalid points: 0"]),
    ]);
}

#[test]
fn bad_presets_and_files() {
    bad_each(&[
        (
            "run --preset nope",
            &["unknown preset 'nope'", "superball, golf, baseball"],
        ),
        ("sweep velocity --preset nope", &["unknown preset"]),
    ]);
    let (_d, p) = file_with(b"name = \"x\"\n[measured\nmass = 1\n");
    bad(&["run", "--config", &p], &[&format!("{p}:2:10:")]);
    let neg = SUPERBALL.replace("mass = 0.0374 ", "mass = -1 ");
    let (_d, p) = file_with(neg.as_bytes());
    bad(
        &["run", "--config", &p],
        &[&format!("{p}:9:1:"), "measured.mass"],
    );
    let unknown = SUPERBALL.replace("[adopted]", "[adopted]\nspring = 3");
    let (_d, p) = file_with(unknown.as_bytes());
    bad(&["run", "--config", &p], &[&format!("{p}:22:1:"), "spring"]);
    let (_d, p) = file_with(b"name = \"x\"\ndescription = \"caf\xe9\"\n");
    bad(&["run", "--config", &p], &[&format!("{p}:2:19:"), "UTF-8"]);
    bad(
        &["run", "--config", "/nonexistent/ball.toml"],
        &["/nonexistent/ball.toml", "no such file"],
    );
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().to_str().unwrap();
    bad(&["run", "--config", d], &[d, "directory"]);
    bad(&["presets", "--config", "/dev/null/x"], &["/dev/null/x"]);
}

#[test]
fn usage_errors_exit_2_on_one_line() {
    bad_each(&[
        ("run --format xml", &["xml", "text, json, csv"]),
        ("run --bogus", &["--bogus"]),
        (
            "run --normalized --preset golf",
            &["--normalized", "--preset"],
        ),
        ("frobnicate", &["frobnicate"]),
        ("--preset golf sweep zeta", &["sweep zeta"]),
    ]);
}

#[test]
fn no_subcommand_without_a_terminal_points_at_run() {
    // stdout is a pipe here
    let o = bl(&[]);
    assert_bad(&o, &["terminal", "bouncelab run"]);
    let o = bl(&["--preset", "golf"]);
    assert_bad(&o, &["terminal"]);
}

#[test]
fn a_closed_stdout_is_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_bouncelab"))
        .args(["run", "--history", "--samples", "100000", "--format", "csv"])
        .env("XDG_CONFIG_HOME", dir.path())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert_eq!(first, "t,force,indentation,displacement\n");
    // the reader is dropped: the pipe is closed with most of the output unwritten
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}
