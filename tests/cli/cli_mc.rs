//! `bouncelab mc` through the binary: its files against its report, a sample against `run`,
//! the thread count, bad input and existing files (docs/scale.md).

use crate::common;

use common::{Out, argv, argv_with, assert_bad, bl, bl_at, f, json, ok, ok_at, parse_svg};
use serde_json::Value;
use std::process::Command;

const VARY: &str = "k_p=5%,c=5%,k_r=5%";

/// Type-7 quantile of sorted values.
fn quantile(sorted: &[f64], p: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * p / 100.0;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

/// The CSV's samples give the JSON's statistics; the SVG is a figure with the histogram and
/// the two marks.
#[test]
fn the_files_hold_the_samples_the_report_sums_up() {
    let dir = tempfile::tempdir().unwrap();
    let line = format!(
        "mc --preset golf --vary {VARY} --samples 301 --seed 11 --format json --csv-out s.csv \
            --svg-out h.svg"
    );
    let args = argv(&line);
    let report: Value = serde_json::from_str(&ok_at(dir.path(), &args)).unwrap();
    assert_eq!(
        (report["samples"].as_u64(), report["seed"].as_u64()),
        (Some(301), Some(11))
    );
    let csv = std::fs::read_to_string(dir.path().join("s.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("index,k_p,c,k_r,cor,max_force,contact_time")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 301);
    for (k, key) in [(4, "cor"), (5, "max_force"), (6, "contact_time")] {
        let mut v: Vec<f64> = rows.iter().map(|r| r[k]).collect();
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        v.sort_by(f64::total_cmp);
        let st = &report["stats"][key];
        assert!((f(st, "mean") / mean - 1.0).abs() < 1e-13, "{key}");
        // serde_json's default float parsing may be an ulp off: compare to a few ulps
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs();
        assert!(
            near(f(st, "min"), v[0]) && near(f(st, "max"), v[300]),
            "{key}"
        );
        for p in ["1", "2.5", "5", "25", "50", "75", "95", "97.5", "99"] {
            let q = quantile(&v, p.parse().unwrap());
            assert!(near(f(&st["q"], p), q), "{key} {p}");
        }
    }
    let svg = parse_svg(&std::fs::read_to_string(dir.path().join("h.svg")).unwrap());
    assert!(
        svg.series.iter().any(|s| s == "histogram (model)"),
        "{:?}",
        svg.series
    );
    assert!(
        svg.series.iter().any(|s| s == "q97.5 (reference)"),
        "{:?}",
        svg.series
    );
    // an existing file is refused before any work, and kept
    let again = bl_at(dir.path(), &args);
    assert_bad(&again, &["s.csv exists (use --force to overwrite it)"]);
    assert_eq!(
        std::fs::read_to_string(dir.path().join("s.csv")).unwrap(),
        csv
    );
}

/// A sample's parameters, given to `run`, give the sample's impact.
#[test]
fn a_sample_is_the_impact_run_gives_for_its_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let line = format!("mc --preset golf --vary {VARY} --samples 3 --seed 5 --csv-out s.csv");
    let args = argv(&line);
    ok_at(dir.path(), &args);
    let csv = std::fs::read_to_string(dir.path().join("s.csv")).unwrap();
    let row: Vec<&str> = csv.lines().nth(3).unwrap().split(',').collect();
    let r = json(&argv_with(
        "run --preset golf --k-p {} --damping {} --k-r {} --format json",
        &[row[1], row[2], row[3]],
    ));
    let cor: f64 = row[4].parse().unwrap();
    let force: f64 = row[5].parse().unwrap();
    assert!(
        (f(&r, "cor") - cor).abs() < 1e-12,
        "{} vs {cor}",
        f(&r, "cor")
    );
    assert!((f(&r, "max_force") / force - 1.0).abs() < 1e-12);
}

#[test]
fn the_same_seed_gives_the_same_report_on_one_thread_and_two() {
    let on = |threads: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_bouncelab"))
            .args(argv(&format!(
                "mc --preset golf --vary {VARY} --samples 40000 --seed 9 --format json"
            )))
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .unwrap();
        assert!(o.status.success());
        String::from_utf8(o.stdout).unwrap()
    };
    assert_eq!(on("1"), on("2"));
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    let cases: [(&[&str], &str); 6] = [
        (
            &["--vary", "spin=5%"],
            "invalid vary: unknown parameter 'spin'",
        ),
        (&["--vary", "k_p=-1%"], "invalid vary k_p: -0.01"),
        (
            &["--vary", "k_p=5%", "--samples", "0"],
            "invalid samples: 0",
        ),
        (
            &["--vary", "k_p=5%,k_p=1%"],
            "invalid vary: k_p given twice",
        ),
        (
            &["--vary", "k_p=120%", "--dist", "uniform"],
            "a uniform spread must be below 1",
        ),
        (
            &["--vary", "k_p=1%", "--samples", "10000001"],
            "too much work: 10000001 samples",
        ),
    ];
    for (extra, needle) in cases {
        let mut args = vec!["mc", "--preset", "golf"];
        args.extend(extra);
        assert_bad(&bl(&args), &[needle]);
    }
    // a normal spread wide enough to cross 0 names the sample and the parameter
    let o = bl(&argv("mc --preset golf --vary k_r=300% --samples 100"));
    assert_bad(&o, &["invalid vary: sample ", "k_r", "--dist lognormal"]);
}

/// `o`, a JSON answer of `mc --samples 30000`, ran them all (`case` names it).
fn assert_ran_30000(o: &Out, case: &str) {
    assert_eq!(o.code, 0, "{case}: {}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["samples"], 30000, "{case}: {}", o.stdout);
}

/// Under Hertz the work limit counts a sample of a ball the Hertz table answers as 1/40 of an
/// impact (`work::check_samples_by`, `Nominal::Table`): golf's 30 000 samples run, its
/// 1 000 001 are refused; a ball whose Hertz cell the table leaves to the Taylor steps
/// (baseball's K_r × 10⁶: λ̂ past the grid) counts a whole impact a sample, so its 30 000 (more than 25 000) are refused.
#[test]
fn hertz_samples_of_a_tabulated_ball_count_as_cheap_ones() {
    let base = ["mc", "--law", "hertz", "--vary", "k_p=5%,c=5%"];
    let run = |preset: &str, samples: &str| {
        let mut args = base.to_vec();
        args.extend(["--preset", preset, "--samples", samples, "--format", "json"]);
        bl(&args)
    };
    assert_ran_30000(&run("golf", "30000"), "golf");
    assert_bad(
        &run("golf", "1000001"),
        &["too much work: 1000001 samples (40 Hertz-law samples of a ball the Hertz table"],
    );
    let mut off_table = base.to_vec();
    off_table.extend(argv("--preset baseball --k-r 4.2e11 --samples 30000"));
    assert_bad(
        &bl(&off_table),
        &["too much work: 30000 samples is 30000 hertz-law impacts"],
    );
    assert_eq!(run("baseball", "30000").code, 0);
}

/// Under the elastic–plastic law the work limit counts a sample by its nominal ball's path
/// (`Ball::check_samples`, `work::check_samples_by`): the superball at its own speed stays
/// below yield, where the Hertz table answers (1/40 of an impact a sample: 30 000 run,
/// 1 000 001 refused); at 9.4 m/s it yields and the Taylor steps answer (1/20 a sample:
/// 30 000 run, 500 001 refused).
#[test]
fn elastic_plastic_samples_count_by_their_path() {
    let base = ["mc", "--preset", "superball", "--law", "elastic-plastic"];
    let run = |v0: &str, samples: &str| {
        let mut args = base.to_vec();
        args.extend(["--vary", VARY, "--v0", v0, "--samples", samples]);
        args.extend(["--format", "json"]);
        bl(&args)
    };
    for v0 in ["3.12", "9.4"] {
        assert_ran_30000(&run(v0, "30000"), v0);
    }
    assert_bad(
        &run("3.12", "1000001"),
        &["too much work: 1000001 samples (40 elastic-plastic-law samples of a ball the Hertz"],
    );
    assert_bad(
        &run("9.4", "500001"),
        &["too much work: 500001 samples (20 elastic-plastic-law samples past yield"],
    );
}

/// `mc --samples 1` printed `sd 0`, a spread of nothing where one draw says nothing of the
/// spread, and "1 samples". Its sd is now unknown (text `–`, JSON null), as its mean's
/// interval was.
#[test]
fn one_sample_has_no_spread_to_estimate() {
    let args = ["mc", "--vary", "k_p=5%", "--samples", "1"];
    let text = ok(&args);
    assert!(text.contains("\n1 sample, seed 0"), "{text}");
    let sd = text
        .lines()
        .find(|l| l.trim_start().starts_with("sd "))
        .unwrap();
    assert_eq!(
        sd.split_whitespace().collect::<Vec<_>>(),
        ["sd", "–", "–", "–"]
    );
    assert!(text.contains("warning: 1 sample is too few"), "{text}");
    let v = json(&[&args[..], &["--format", "json"]].concat());
    for q in ["cor", "max_force", "contact_time"] {
        assert!(v["stats"][q]["sd"].is_null(), "{q}: {}", v["stats"][q]);
        assert!(v["stats"][q]["mean"].is_number());
    }
    // two samples: a spread
    let v = json(&argv("mc --vary k_p=5% --samples 2 --format json"));
    assert!(f(&v["stats"]["cor"], "sd") > 0.0);
}
