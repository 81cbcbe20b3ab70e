//! Issue 54 item 8: a fitted preset's 95 % intervals stay where physics allows. The delta
//! method's y ± t√Var knows no bounds: three drops of a table-tennis ball gave a COR interval
//! up to 1.0018 and a rebound above its drop height; a huge but valid `[fit]` covariance gave
//! a COR of ±7e144 and negative contact times. Now a COR lies in [0, 1], forces and times are
//! not negative, a rebound is no higher than the drop, the nominal value inside each.

use crate::common;
use common::{argv, bl_at};
use serde_json::Value;

/// A folder holding `wide.toml`: the baseball with a `[fit]` table of a huge, valid
/// covariance (symmetric, non-negative variances).
fn wide_preset() -> tempfile::TempDir {
    let variances = |k_r: f64, z_p: f64| {
        let (var_k, var_z) = ((10.0 * k_r).powi(2), (10.0 * z_p).powi(2));
        format!("[[{var_k:?}, 0.0], [0.0, {var_z:?}]]")
    };
    common::baseball_with_fit("wide", variances, 2)
}

fn json_of(dir: &std::path::Path, args: &[&str]) -> Value {
    let o = bl_at(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

fn band(v: &Value, key: &str) -> [f64; 2] {
    let b = v[key].as_array().unwrap_or_else(|| panic!("{key}: {v}"));
    [b[0].as_f64().unwrap(), b[1].as_f64().unwrap()]
}

fn inside(b: [f64; 2], lo: f64, hi: f64, nominal: f64, what: &str) {
    assert!(
        lo <= b[0] && b[0] <= nominal && nominal <= b[1] && b[1] <= hi,
        "{what}: {b:?} around {nominal}, allowed {lo} … {hi}"
    );
}

#[test]
fn a_runs_intervals_stay_physical() {
    let d = wide_preset();
    let v = json_of(
        d.path(),
        &["run", "--config", "wide.toml", "--format", "json"],
    );
    let f = |k: &str| v[k].as_f64().unwrap();
    inside(band(&v, "cor_ci95"), 0.0, 1.0, f("cor"), "cor");
    let inf = f64::INFINITY;
    inside(
        band(&v, "max_force_ci95"),
        0.0,
        inf,
        f("max_force"),
        "max_force",
    );
    let t = f("contact_time");
    inside(band(&v, "contact_time_ci95"), 0.0, inf, t, "contact_time");
}

#[test]
fn a_drops_intervals_stay_physical() {
    let d = wide_preset();
    let v = json_of(
        d.path(),
        &argv("drop --config wide.toml --height 1.5 --format json"),
    );
    let bounces = v["bounces"].as_array().unwrap();
    assert!(!bounces.is_empty());
    for (i, b) in bounces.iter().enumerate() {
        let f = |k: &str| b[k].as_f64().unwrap();
        let what = |k: &str| format!("bounce {}: {k}", i + 1);
        inside(band(b, "cor_ci95"), 0.0, 1.0, f("cor"), &what("cor"));
        let h = f("rebound_height");
        inside(
            band(b, "rebound_height_ci95"),
            0.0,
            1.5,
            h,
            &what("rebound"),
        );
        let ct = f("contact_time");
        inside(
            band(b, "contact_time_ci95"),
            0.0,
            f64::INFINITY,
            ct,
            &what("time"),
        );
    }
}

#[test]
fn a_covariance_too_wide_to_mean_anything_is_refused_when_loaded() {
    // the same table with a standard deviation 1000 times k_r: refused at its line, naming it
    let d = wide_preset();
    let path = d.path().join("wide.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let k_r = bouncelab::preset::Preset::parse(&text, "wide.toml")
        .unwrap()
        .adopted
        .k_r;
    let from = format!("[[{:?}, 0.0]", (10.0 * k_r).powi(2));
    let to = format!("[[{:?}, 0.0]", (1000.0 * k_r).powi(2));
    assert!(text.contains(&from), "{text}");
    let bad = text.replace(&from, &to);
    let e = bouncelab::preset::Preset::parse(&bad, "wide.toml")
        .unwrap_err()
        .to_string();
    let line = bad[..bad.find("covariance").unwrap()].matches('\n').count() + 1;
    let at = format!("wide.toml:{line}:1: fit.covariance: diagonal 1");
    assert!(
        e.starts_with(&at) && e.contains("more than 100 times"),
        "{e}"
    );
    std::fs::write(&path, bad).unwrap();
    let o = bl_at(d.path(), &["run", "--config", "wide.toml"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
}
