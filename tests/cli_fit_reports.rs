//! What a fit's report says of its uncertainty: residuals all zero leave no scatter to
//! estimate an interval from (not "± 0"), and `fit --plot`'s subtitle gives each fitted value
//! with its interval, as the text report does.

mod common;

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
