//! `fit` on several data sets at once through the binary (issue 52 item 5, docs/fitting.md
//! "Joint calibration"): the JSON's `data_sets`, the saved preset's record of every set, data
//! sets that contradict each other (exit 1, nothing saved), and the static file's bad input.

use crate::common;

use bouncelab::model::static_chain::plates_deflection;
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};
use common::*;
use serde_json::Value;
use std::path::Path;

/// The tennis preset's ball with its recoil spring at `k_r` (what the files are made from).
fn tennis(k_r: f64) -> ImpactParams {
    let v = json(&["run", "--preset", "tennis", "--format", "json"]);
    let b = &v["ball"];
    ImpactParams {
        mass: f(b, "mass"),
        k_p: f(b, "k_p"),
        damping: f(b, "c"),
        k_r,
        z_p: f(b, "z_p"),
        k_h: f(b, "k_h"),
        v0: 5.0,
    }
}

/// A COR table of `p` at 2 … 20 m/s and its deflections under 1 … 8 kg, each with a small
/// scatter of alternating sign (0.003 in COR, 0.5 % in deflection).
fn files(dir: &Path, p: &ImpactParams, q: &ImpactParams) {
    let mut cors = String::from("v0,cor\n");
    for (i, v0) in (1..=10).map(|i| 2.0 * i as f64).enumerate() {
        let e = simulate(
            &ImpactParams { v0, ..*p },
            ContactLaw::Linear,
            &SolveOptions::default(),
        )
        .unwrap()
        .cor;
        let noise = if i % 3 == 0 { 0.003 } else { -0.002 };
        cors.push_str(&format!("{v0},{}\n", e + noise));
    }
    let mut statics = String::from("load_kg,deflection_m\n");
    for i in 1..=8 {
        let d = plates_deflection(q, ContactLaw::Linear, i as f64);
        let noise = if i % 2 == 0 { 1.005 } else { 0.995 };
        statics.push_str(&format!("{i},{}\n", d * noise));
    }
    std::fs::write(dir.join("cors.csv"), cors).unwrap();
    std::fs::write(dir.join("static.csv"), statics).unwrap();
}

fn fit_in(dir: &Path, extra: &[&str]) -> Out {
    let cors = dir.join("cors.csv");
    let statics = dir.join("static.csv");
    let mut args = argv_with(
        "fit --preset tennis --cor-table {} --static {}",
        &[cors.to_str().unwrap(), statics.to_str().unwrap()],
    );
    args.extend(extra);
    bl_in(dir, &args)
}

#[test]
fn each_set_is_reported_and_the_saved_record_lists_them_all() {
    let dir = tempfile::tempdir().unwrap();
    let truth = tennis(30_000.0);
    files(dir.path(), &truth, &truth);
    let o = fit_in(dir.path(), &["--format", "json", "--save", "mine"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["data"], "data sets");
    assert_eq!(v["free"], serde_json::json!(["k_r", "z_p"]));
    let ci = &v["fitted"]["k_r"]["ci95"];
    let (lo, hi) = (ci[0].as_f64().unwrap(), ci[1].as_f64().unwrap());
    assert!(lo <= 30_000.0 && 30_000.0 <= hi, "{ci}");
    let sets = v["data_sets"].as_array().unwrap();
    assert_eq!(sets.len(), 2, "{v}");
    assert_eq!(sets[0]["kind"], "COR table");
    assert_eq!(sets[1]["kind"], "static deflection");
    assert_eq!(
        (sets[0]["points"].as_u64(), sets[1]["points"].as_u64()),
        (Some(10), Some(8))
    );
    assert_eq!(
        (sets[0]["unit"].as_str(), sets[1]["unit"].as_str()),
        (Some("COR"), Some("m"))
    );
    for s in sets {
        assert_eq!(s["sd_stated"], false, "{s}");
        assert!(
            f(s, "sd_estimated") > 0.0 && f(s, "rms_residual") > 0.0,
            "{s}"
        );
        assert_eq!(s["lack_of_fit"]["test"], "F", "{s}");
        assert!(f(&s["lack_of_fit"], "p_value") > 1e-3, "{s}");
    }
    assert_eq!(v["identified"], true);
    let text = std::fs::read_to_string(dir.path().join("bouncelab/presets/mine.toml")).unwrap();
    let p = bouncelab::preset::Preset::parse(&text, "mine.toml").unwrap();
    let c = p.calibration.expect("a [calibration] record");
    assert_eq!(c.data.len(), 2, "{c:?}");
    assert_eq!(c.data[0].quantities, "COR table");
    assert_eq!(c.data[0].speeds.len(), 10);
    assert_eq!(c.data[1].quantities, "static deflection under 8 loads");
    assert!(c.data[1].source.contains("static.csv"), "{:?}", c.data[1]);
    assert_eq!((c.speed_min, c.speed_max), (2.0, 20.0));
    // the text report: each set's line
    let o = fit_in(dir.path(), &[]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(
        o.stdout.contains("static deflection static.csv") || o.stdout.contains("static.csv  8"),
        "{}",
        o.stdout
    );
    assert!(o.stdout.contains("(estimated)"), "{}", o.stdout);
}

#[test]
fn contradicting_sets_exit_1_and_save_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // CORs of K_r = 30 000 N/m, deflections of a ball with 50 % more
    files(dir.path(), &tennis(30_000.0), &tennis(45_000.0));
    let o = fit_in(dir.path(), &["--save", "mine"]);
    assert_eq!(o.code, 1, "{}\n{}", o.stdout, o.stderr);
    assert!(o.stdout.contains("CONTRADICTS"), "{}", o.stdout);
    assert!(o.stderr.contains("contradict each other"), "{}", o.stderr);
    assert!(o.stderr.contains("--save not written"), "{}", o.stderr);
    assert!(!dir.path().join("bouncelab/presets/mine.toml").exists());
}

#[test]
fn static_input_is_checked() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("static.csv");
    let p = path.to_str().unwrap();
    std::fs::write(&path, "load_kg,deflection_m\n1,0.001\n2,abc\n").unwrap();
    let o = bl_in(dir.path(), &["fit", "--preset", "tennis", "--static", p]);
    assert_bad(&o, &["static.csv:3:3"]);
    std::fs::write(&path, "load_kg,deflection_m\n1,0.001\n2,0.002\n").unwrap();
    // deflections alone give no impact speed to record
    let o = bl_in(
        dir.path(),
        &["fit", "--preset", "tennis", "--static", p, "--save", "x"],
    );
    assert_bad(&o, &["--save", "impact speed"]);
    let o = bl_in(
        dir.path(),
        &argv_with("fit --preset tennis --static {} --plot x.svg", &[p]),
    );
    assert_bad(&o, &["--plot"]);
    let o = bl_in(
        dir.path(),
        &["fit", "--preset", "tennis", "--static", p, "--cor", "0.7"],
    );
    assert_bad(&o, &["--cor"]);
    // alone: K_r from the springs in series
    let o = bl_in(
        dir.path(),
        &argv_with("fit --preset tennis --static {} --format json", &[p]),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["free"], serde_json::json!(["k_r"]));
}
