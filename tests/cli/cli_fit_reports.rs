//! What a fit's report says of its uncertainty: residuals all zero leave no scatter to
//! estimate an interval from (not "± 0"), and `fit --plot`'s subtitle gives each fitted value
//! with its interval, as the text report does.

use crate::common;

use common::*;
use serde_json::Value;
use std::path::Path;

fn json_at(dir: &Path, args: &[&str]) -> Value {
    serde_json::from_str(&ok_at(dir, args)).unwrap()
}

/// Two equal CORs fitted with K_r: the model (no flattening at these speeds) meets both to
/// the last bit, s² = 0, and the report said `± 0` with an interval `70448 … 70448`.
#[test]
fn equal_cors_leave_no_scatter_to_estimate_from() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("eq.csv"), "v0,cor\n2,0.75\n4,0.75\n").unwrap();
    let args = ["fit", "--preset", "superball", "--cor-table", "eq.csv"];
    let v = json_at(dir.path(), &[&args[..], &["--format", "json"]].concat());
    assert_eq!(f(&v, "rms_residual"), 0.0);
    assert!(v["fitted"]["k_r"]["std_error"].is_null(), "{v}");
    assert!(v["fitted"]["k_r"]["ci95"][0].is_null(), "{v}");
    assert!(v["fitted"]["k_r"]["ci95"][1].is_null(), "{v}");
    assert_eq!(v["exact"], true, "{v}");
    assert_eq!(v["identified"], true, "the value is determined: {v}");
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter()
            .any(|w| w.as_str().unwrap().contains("no scatter to estimate")),
        "{w:?}"
    );
    let text = ok_at(dir.path(), &args);
    assert!(
        text.contains("exact: no scatter to estimate it from"),
        "{text}"
    );
    assert!(
        text.contains("warning: the residuals are all zero"),
        "{text}"
    );
    assert!(!text.contains("70448 … 70448"), "{text}");
    // saved, it says so, and carries no [fit] table to draw intervals from
    ok_at(dir.path(), &[&args[..], &["--save", "eq"]].concat());
    let saved = std::fs::read_to_string(dir.path().join("bouncelab/presets/eq.toml")).unwrap();
    assert!(saved.contains("exact: no scatter"), "{saved}");
    assert!(!saved.contains("[fit]"), "{saved}");
    // a scatter of 1e-4 gives its interval as before
    std::fs::write(dir.path().join("ne.csv"), "v0,cor\n2,0.75\n4,0.7501\n").unwrap();
    let v = json_at(
        dir.path(),
        &["fit", "--cor-table", "ne.csv", "--format", "json"],
    );
    assert!(v.get("exact").is_none(), "{v}");
    assert!(f(&v["fitted"]["k_r"], "std_error") > 0.0, "{v}");
}

/// The subtitle lines of the first figure of `fit --plot`'s SVG (font size 60 in drawing
/// units: the subtitle's 15 px).
fn subtitle(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("font-size") == Some("60.00000000000001"))
        .filter_map(|n| n.text())
        .map(|t| t.trim().to_string())
        .take_while(|t| !t.starts_with("rms "))
        .filter(|t| t.contains("superball") || t.contains(" = "))
        .collect()
}

/// The subtitle printed `fitted k_r = 7.048e4` where the report gives `70479 … ± (95 %:
/// 70086 … 70874)`; three values with their intervals take three lines, each within the
/// picture's 800 px (15 px text, about 0.52 em a character: 98 characters).
#[test]
fn the_plot_subtitle_gives_each_value_with_its_interval() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("ne.csv"), "v0,cor\n2,0.75\n4,0.7501\n").unwrap();
    ok_at(d, &["fit", "--cor-table", "ne.csv", "--plot", "c.svg"]);
    let lines = subtitle(&std::fs::read_to_string(d.join("c.svg")).unwrap());
    assert_eq!(
        lines,
        ["superball, linear law; fitted k_r = 70479 N/m (95 %: 70086 … 70874)"]
    );
    // a trace fitted with three parameters
    let csv = ok(&argv(
        "run --preset superball --history --samples 300 --format csv",
    ));
    let mut trace = String::from("time_ms,force_N\n");
    for (i, row) in csv.lines().skip(1).enumerate() {
        let (t, force) = row.split_once(',').unwrap();
        let force: f64 = force.split(',').next().unwrap().parse().unwrap();
        let t: f64 = t.parse().unwrap();
        let wobble = 1.0 + 0.01 * (1.7 * (i + 2) as f64).sin();
        trace.push_str(&format!("{},{}\n", t * 1e3, force * wobble));
    }
    std::fs::write(d.join("trace.csv"), trace).unwrap();
    let args = argv("fit --v0 3.12 --force-time trace.csv --free k_p,c,k_r --plot t.svg");
    let text = ok_at(d, &args);
    let lines = subtitle(&std::fs::read_to_string(d.join("t.svg")).unwrap());
    assert_eq!(lines.len(), 3, "{lines:?}");
    for line in &lines {
        assert!(line.chars().count() <= 98, "{line}");
    }
    let all = lines.join("; ");
    for (name, row) in ["k_p", "c", "k_r"].iter().map(|n| {
        let row = text
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{n} ")))
            .unwrap();
        (n, row.split_whitespace().collect::<Vec<_>>())
    }) {
        // `k_p  54500  291  53930 … 55076  N/m`: value, error, lo, …, hi, unit
        let shown = format!(
            "{name} = {} {} (95 %: {} … {})",
            row[1], row[6], row[3], row[5]
        );
        assert!(all.contains(&shown), "{shown} not in {all}");
    }
}

/// A fit answered with a ball that, at the data's speed, presses past its radius, and said
/// nothing: `fit --cor 0.6 --v0 45` (K_r 187687 N/m, z_m 32.8 mm, R 21.55 mm), and a COR
/// table up to 45 m/s. The single fit's JSON had no `warnings` key at all.
#[test]
fn a_fitted_ball_past_its_radius_is_warned_of() {
    let args = ["fit", "--preset", "superball", "--cor", "0.6", "--v0", "45"];
    let v = json(&[&args[..], &["--format", "json"]].concat());
    let w = warnings(&v);
    let radius = "the fitted ball at v0 = 45 m/s: peak indentation 32.81 mm exceeds";
    assert!(w[0].starts_with(radius), "{w:?}");
    // then the record's of the K_p, c, z_p held, as `run --v0 45` warns
    // (tests/cli/cli_formats_name.rs)
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(
        w[1].starts_with("outside calibration: impact speed 45 m/s"),
        "{w:?}"
    );
    let text = ok(&args);
    assert!(
        w.iter().all(|w| text.contains(&format!("warning: {w}"))),
        "{text}"
    );
    let calm = json(&argv("fit --preset superball --cor 0.75 --format json"));
    assert_eq!(calm["warnings"], serde_json::json!([]));
    // a table: at its fastest row, named
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("fast.csv"),
        "v0,cor\n30,0.62\n45,0.58\n40,0.6\n",
    )
    .unwrap();
    let o = bl_at(
        dir.path(),
        &argv("fit --cor-table fast.csv --free k_r --format json"),
    );
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    let fastest = "the fitted ball at v0 = 45 m/s (the fastest of the data): peak indentation";
    assert!(warnings(&v).iter().any(|w| w.starts_with(fastest)), "{v}");
}
