//! A lot's mean COR has its 95 % interval inside [0, 1] (src/analysis/batch_stats.rs,
//! docs/batch.md): two balls leave Student's t with one degree of freedom (t = 12.71), whose
//! interval about 0.525 reached −0.43 … 1.48; it is clipped to where a COR lies, and says so.

use crate::common;

use common::{f, ok_at};
use serde_json::Value;

/// Two baseballs, each its COR at the MLB test's 85 ft/s: 0.45 and 0.60.
fn lot(dir: &std::path::Path) {
    std::fs::write(
        dir.join("lot.csv"),
        "id,v0,cor\nS1,25.908,0.45\nS2,25.908,0.60\n",
    )
    .unwrap();
}

fn end(summary: &Value, i: usize) -> f64 {
    summary["mean_ci"][i].as_f64().unwrap()
}

const ARGS: [&str; 6] = [
    "batch",
    "lot.csv",
    "--preset",
    "baseball",
    "--standard",
    "mlb",
];

#[test]
fn a_two_ball_lot_mean_cor_interval_stays_in_zero_one() {
    let dir = tempfile::tempdir().unwrap();
    lot(dir.path());
    let mut args = ARGS.to_vec();
    args.extend(["--format", "json"]);
    let r: Value = serde_json::from_str(&ok_at(dir.path(), &args)).unwrap();
    let s = &r["summary"];
    let ci = [end(s, 0), end(s, 1)];
    assert!((f(s, "mean") - 0.525).abs() < 1e-9, "{s}");
    assert_eq!(ci, [0.0, 1.0], "Student's 0.525 ± 0.953, clipped: {s}");
    assert_eq!(s["mean_ci_clipped"], true, "{s}");
    let text = ok_at(dir.path(), &ARGS);
    assert!(
        text.contains(
            "mean 0.52500 (95 % 0 … 1.0000; Student's t clipped to 0 … 1, where a COR lies)"
        ),
        "{text}"
    );
}

/// A lot whose interval is inside [0, 1] keeps Student's interval and no note.
#[test]
fn an_interval_inside_zero_one_is_left_alone() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("lot.csv"),
        "id,v0,cor\nS1,25.908,0.52\nS2,25.908,0.58\n",
    )
    .unwrap();
    let mut args = ARGS.to_vec();
    args.extend(["--format", "json"]);
    let r: Value = serde_json::from_str(&ok_at(dir.path(), &args)).unwrap();
    let s = &r["summary"];
    let half = 12.706204736 * f(s, "sd") / 2f64.sqrt();
    assert!((end(s, 0) - (f(s, "mean") - half)).abs() < 1e-6, "{s}");
    assert_eq!(s["mean_ci_clipped"], false, "{s}");
    assert!(!ok_at(dir.path(), &ARGS).contains("clipped"));
}
