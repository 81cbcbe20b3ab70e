//! `bouncelab batch` through the binary: each ball's fit and verdict against `fit` and `drop`
//! run on their own, the summary against its balls, the files against the report, balls
//! without an answer, bad input and the thread count (docs/batch.md).

use crate::common;

use common::{argv, argv_with, assert_bad, bl_at, f, json, ok_at, parse_svg};
use serde_json::Value;
use std::path::Path;

/// Forty tennis balls, each dropped once from the ITF's 2.54 m (A7 twice), rebounds spread
/// over 1.335 … 1.505 m so that some fail either bound (and all are in the reach of K_r).
fn lot() -> String {
    let mut s = String::from("# lot 7, ITF rebound test\nid,drop_height_m,rebound_height_m\n");
    for i in 0..40 {
        let r = 1.335 + 0.17 * ((i * 17) % 40) as f64 / 39.0;
        s.push_str(&format!("A{i},2.54,{r:.4}\n"));
        if i == 7 {
            s.push_str(&format!("A{i},2.54,{:.4}\n", r + 0.01));
        }
    }
    s
}

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

fn report(dir: &Path, extra: &[&str]) -> Value {
    let mut args = vec!["batch", "lot.csv", "--preset", "tennis", "--format", "json"];
    args.extend(extra);
    serde_json::from_str(&ok_at(dir, &args)).unwrap()
}

/// In vacuum a one-drop fit of K_r reproduces its rebound exactly, so each ball's verdict is
/// its measured rebound against [1.35, 1.47]; the summary's statistics, failures and Cpk are
/// those of the balls' values, recomputed here.
#[test]
fn the_summary_is_that_of_its_balls() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lot.csv", &lot());
    let r = report(dir.path(), &[]);
    let balls = r["balls"].as_array().unwrap();
    assert_eq!(balls.len(), 40);
    let mut values = Vec::new();
    for (i, b) in balls.iter().enumerate() {
        let given = 1.335 + 0.17 * ((i * 17) % 40) as f64 / 39.0;
        let given = (given * 1e4).round() / 1e4;
        let m = f(b, "measured");
        if i != 7 {
            assert!((m - given).abs() < 1e-6, "{i}: {m} vs {given}");
        }
        let pass = (1.35..=1.47).contains(&m);
        assert_eq!(b["verdict"], if pass { "PASS" } else { "FAIL" }, "{b}");
        let margin = (m - 1.35).min(1.47 - m);
        assert!((f(b, "margin") - margin).abs() < 1e-12, "{b}");
        values.push(m);
    }
    let s = &r["summary"];
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let fails = values
        .iter()
        .filter(|v| !(1.35..=1.47).contains(*v))
        .count();
    assert_eq!(s["n"], 40);
    assert_eq!(s["failures"].as_u64(), Some(fails as u64));
    assert!(fails > 0 && fails < 40);
    assert!((f(s, "mean") - mean).abs() < 1e-12 && (f(s, "sd") - sd).abs() < 1e-12);
    let cpk = (1.47 - mean).min(mean - 1.35) / (3.0 * sd);
    assert!((f(s, "cpk") - cpk).abs() < 1e-12, "{s}");
    assert_eq!(s["no_answer"], 0);
    assert_eq!(
        r["standard"]["name"], "itf",
        "the tennis preset's own standard"
    );
    // A7's two rows are one ball with two drops
    assert_eq!(balls[7]["points"], 2);
    assert_eq!(balls[8]["line"], 12);
}

/// A ball's fit is `bouncelab fit` on its rows, and its verdict `bouncelab drop --standard`
/// of the fitted ball, each run on its own.
#[test]
fn a_ball_is_fit_and_drop_run_on_their_own() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lot.csv", &lot());
    let r = report(dir.path(), &[]);
    let b = &r["balls"][7];
    // ball A7's two drops as a file of its own
    let mut text = String::from("drop_height_m,rebound_height_m\n");
    for row in lot().lines().filter(|l| l.starts_with("A7,")) {
        text.push_str(&row[3..]);
        text.push('\n');
    }
    write(dir.path(), "a7.csv", &text);
    let args = argv("fit --preset tennis --drop-test a7.csv --format json");
    let fit: Value = serde_json::from_str(&ok_at(dir.path(), &args)).unwrap();
    assert_eq!(f(b, "k_r"), f(&fit, "k_r"), "the same fit");
    let k_r = format!("{}", f(&fit, "k_r"));
    let drop = json(&argv_with(
        "drop --preset tennis --k-r {} --standard itf --no-drag --format json",
        &[&k_r],
    ));
    let v = &drop["standard"];
    // the fitted ball's value (the verdict itself is on A7's readings at 2.54 m:
    // tests/cli/cli_batch_readings.rs)
    assert!(
        (f(v, "measured") - f(b, "model_measured")).abs() < 1e-9,
        "{v} vs {b}"
    );
    assert_eq!(v["verdict"] == "pass", b["verdict"] == "PASS");
    // the COR at the standard's speed is the first bounce's
    assert!(
        (f(&drop["bounces"][0], "cor") - f(b, "cor")).abs() < 1e-9,
        "{drop}"
    );
}

/// The per-ball CSV holds the JSON's balls; the SVG is a histogram with the window's two
/// bounds; an existing file is not replaced without --force, and then nothing is written.
#[test]
fn the_files_hold_the_report() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lot.csv", &lot());
    let r = report(
        dir.path(),
        &["--csv-out", "balls.csv", "--svg-out", "h.svg"],
    );
    let csv = std::fs::read_to_string(dir.path().join("balls.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[0], "id");
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 40);
    for (row, b) in rows.iter().zip(r["balls"].as_array().unwrap()) {
        assert_eq!(row[col("id")], b["id"]);
        assert_eq!(row[col("verdict")], b["verdict"]);
        // serde_json reads a float to within an ulp (no float_roundtrip feature), Rust exactly
        let same = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
        for key in ["cor", "margin", "k_r"] {
            assert!(
                same(row[col(key)].parse().unwrap(), f(b, key)),
                "{key}: {row:?} vs {b}"
            );
        }
    }
    // the free-text columns close the original sixteen; columns added later follow them, so
    // that every earlier column keeps its place
    assert_eq!(&header[14..16], ["error", "warnings"]);
    assert_eq!(&header[16..18], ["measured_ci95_lo", "measured_ci95_hi"]);
    assert_eq!(
        &header[18..23],
        [
            "verdict_from",
            "readings",
            "model_measured",
            "fit_error",
            "lot_warnings"
        ]
    );
    // then the ball, the plate and the conditions, as `sweep velocity`'s CSV ends
    assert!(header.ends_with(&["temperature_c", "pressure_gauge_pa", "atmosphere_pa"]));
    let svg = parse_svg(&std::fs::read_to_string(dir.path().join("h.svg")).unwrap());
    assert_eq!(
        svg.series,
        ["histogram (model)", "lo (reference)", "hi (reference)"]
    );
    assert!(
        svg.texts.iter().any(|t| t == "window low"),
        "{:?}",
        svg.texts
    );
    // the CSV exists: refused, and the SVG (removed) is not written either
    std::fs::remove_file(dir.path().join("h.svg")).unwrap();
    let o = bl_at(
        dir.path(),
        &argv("batch lot.csv --preset tennis --csv-out balls.csv --svg-out h.svg"),
    );
    assert_bad(&o, &["balls.csv", "--force"]);
    assert!(!dir.path().join("h.svg").exists());
}

/// Balls whose data cannot be fitted, and were not taken at the standard's condition (B2
/// was dropped from 1 m, not the ITF's 2.54 m: no reading of its own judges it), say why in
/// their row; the others are judged; the command ends with exit 1 after the whole report.
/// (A ball dropped from the standard's height keeps its verdict on its reading:
/// tests/cli/cli_batch_readings.rs.)
#[test]
fn a_ball_without_a_fit_says_why_and_the_batch_goes_on() {
    let dir = tempfile::tempdir().unwrap();
    let text = "id,drop_height_m,rebound_height_m\nB1,2.54,1.40\nB2,1.00,0.0004\nB3,2.54,1.45\n";
    write(dir.path(), "lot.csv", text);
    let o = bl_at(
        dir.path(),
        &["batch", "lot.csv", "--preset", "tennis", "--format", "json"],
    );
    assert_eq!(o.code, 1, "{}", o.stderr);
    assert_eq!(
        o.stderr,
        "bouncelab: error: 1 of 3 balls has no verdict: their rows say why\n"
    );
    let r: Value = serde_json::from_str(&o.stdout).unwrap();
    let b2 = &r["balls"][1];
    assert!(b2["verdict"].is_null() && b2["cor"].is_null());
    assert!(
        b2["error"].as_str().unwrap().contains("out of reach"),
        "{b2}"
    );
    assert_eq!(r["balls"][2]["verdict"], "PASS");
    assert_eq!(
        (
            r["summary"]["n"].as_u64(),
            r["summary"]["no_answer"].as_u64()
        ),
        (Some(2), Some(1))
    );
}

/// Each ball's own trace file, named relative to the batch: the model's own pulse gives the
/// preset's springs back, and a missing file is bad input naming the batch's cell.
#[test]
fn traces_by_file_path() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("traces")).unwrap();
    let pulse = common::ok(&argv(
        "run --preset baseball --history --samples 300 --format csv",
    ));
    let trace: String = pulse
        .lines()
        .map(|l| l.split(',').take(2).collect::<Vec<_>>().join(",") + "\n")
        .collect();
    write(&dir.path().join("traces"), "b1.csv", &trace);
    write(dir.path(), "lot.csv", "id,trace\nb1,b1.csv\n");
    let o = bl_at(
        dir.path().join("traces").parent().unwrap(),
        &argv("batch lot.csv --preset baseball --standard mlb"),
    );
    assert_bad(&o, &["lot.csv:2:4: trace of 'b1'", "no such file"]);
    write(dir.path(), "lot.csv", "id,trace\nb1,traces/b1.csv\n");
    let args = argv("batch lot.csv --preset baseball --standard mlb --format json");
    let r: Value = serde_json::from_str(&ok_at(dir.path(), &args)).unwrap();
    let b = &r["balls"][0];
    assert_eq!(b["data"], "force-time trace");
    let run = json(&argv_with(
        "run --preset baseball --v0 {} --format json",
        &[&format!("{}", 85.0 * 0.3048)],
    ));
    assert!((f(b, "k_r") / 420000.0 - 1.0).abs() < 1e-4, "{b}");
    assert!((f(b, "cor") - f(&run, "cor")).abs() < 1e-4, "{b} vs {run}");
}

#[test]
fn bad_batches_are_one_line_naming_the_place() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&str, &[&str]); 4] = [
        (
            "id,drop_height_m,rebound_height_m\nA,2.54,1.4\nB,2.54,1.4\nA,2.54,1.4\n",
            &["lot.csv:4:1: id 'A' again", "line 2"],
        ),
        (
            "drop_height_m,rebound_height_m\n2.54,1.4\n",
            &["lot.csv:1:1: no id column"],
        ),
        (
            "rebound_height_m,id,drop_height_m\n1.4,A,x\n",
            &["lot.csv:2:7:", "'x' is not a number"],
        ),
        (
            "id,drop_height_m,rebound_height_m\nA,2.54,3\n",
            &["lot.csv:2:8:", "rebound height 3 m"],
        ),
    ];
    for (text, needles) in cases {
        write(dir.path(), "lot.csv", text);
        assert_bad(
            &bl_at(dir.path(), &["batch", "lot.csv", "--preset", "tennis"]),
            needles,
        );
    }
    let o = bl_at(dir.path(), &["batch", "lot.csv", "--preset", "golf"]);
    assert_bad(&o, &["--standard is needed"]);
    let o = bl_at(dir.path(), &["batch", "lot.csv", "--standard", "wimbledon"]);
    assert_bad(&o, &["unknown standard 'wimbledon'"]);
}

/// The balls run in parallel: one thread or four, the same bytes.
#[test]
fn the_same_answer_on_any_number_of_threads() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "lot.csv", &lot());
    let run = |threads: &str| {
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_bouncelab"))
            .args(["batch", "lot.csv", "--preset", "tennis", "--format", "json"])
            .current_dir(dir.path())
            .env("RAYON_NUM_THREADS", threads)
            .env("XDG_CONFIG_HOME", dir.path())
            .output()
            .unwrap();
        assert!(o.status.success());
        o.stdout
    };
    assert_eq!(run("1"), run("4"));
}

/// A batch of one ball is spoken of as one: the report once said "1 balls from …" and the
/// error "1 of 1 balls have no verdict".
#[test]
fn a_batch_of_one_ball_reads_as_one() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "one.csv",
        "id,drop_height_m,rebound_height_m\nB1,2.54,1.40\n",
    );
    let text = ok_at(dir.path(), &["batch", "one.csv", "--preset", "tennis"]);
    assert!(
        text.contains("\n1 ball from one.csv, fitted one by one"),
        "{text}"
    );
    write(
        dir.path(),
        "bad.csv",
        "id,drop_height_m,rebound_height_m\nB1,1.00,0.0004\n",
    );
    let o = bl_at(dir.path(), &["batch", "bad.csv", "--preset", "tennis"]);
    assert_eq!(o.code, 1, "{}", o.stderr);
    assert_eq!(
        o.stderr,
        "bouncelab: error: the ball has no verdict: its row says why\n"
    );
}

/// A ball's fit warns in a batch as `bouncelab fit` warns of it: the fitted superball that
/// gives e = 0.6 at 45 m/s presses 33 mm into a ball of radius 21.55 mm at that speed
/// (`Ball::fitted_warnings`), and the batch once left that out of the ball's warnings.
#[test]
fn a_ball_s_warnings_hold_its_fitted_ball_past_the_radius() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "lot.csv",
        "id,v0,cor\nS1,45,0.6\nS2,3,0.73\nS2,3.12,0.7302\n",
    );
    write(dir.path(), "s1.csv", "v0,cor\n45,0.6\n");
    let batch = argv("batch lot.csv --preset superball --standard mlb");
    let free = ["--free", "k_r"];
    let args = |tail: &[&'static str]| -> Vec<&'static str> {
        batch.iter().chain(&free).chain(tail).copied().collect()
    };
    let r: Value = serde_json::from_str(&ok_at(dir.path(), &args(&["--format", "json"]))).unwrap();
    let fit: Value = serde_json::from_str(&ok_at(
        dir.path(),
        &argv("fit --preset superball --cor-table s1.csv --format json"),
    ))
    .unwrap();
    let past = fit["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| {
            w.as_str()
                .unwrap()
                .starts_with("the fitted ball at v0 = 45 m/s: peak indentation")
        })
        .expect("fit warns of the indentation");
    assert!(
        r["balls"][0]["warnings"].as_array().unwrap().contains(past),
        "{}",
        r["balls"][0]
    );
    assert_eq!(r["balls"][1]["warnings"], serde_json::json!([]));
    let text = ok_at(dir.path(), &args(&[]));
    assert!(text.contains("\nballs whose fit warns: 1 ("), "{text}");
    assert!(!text.contains("1 balls"), "{text}");
    let csv = ok_at(dir.path(), &args(&["--format", "csv"]));
    assert!(csv.contains(past.as_str().unwrap()), "{csv}");
}
