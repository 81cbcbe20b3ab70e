//! `court` on an embedded court whose normal give no one has published (docs/surfaces.md §5)
//! says that it assumed it rigid, and how to give the court's own e: a new user found every
//! embedded court rated by μ alone (`court --surface clay --friction 0.6` gives the rigid
//! plate's e_y 0.76098, on every court) without a word. And μ from the command line is
//! listed among the surface's overrides, where the surface gives none too.

use crate::common;

use common::*;
use serde_json::Value;

const ASSUMED: &str = "its normal give is ASSUMED rigid";

fn warned(v: &Value) -> bool {
    warnings(v).iter().any(|w| w.contains(ASSUMED))
}

/// Every embedded surface: warned exactly when its file says its rigidity is ASSUMED (every
/// court but hard-court, whose rigidity is published), never on the rigid plate or concrete,
/// whose rigidity is their definition.
#[test]
fn an_assumed_rigid_court_says_so() {
    let all = json(&argv("surfaces --format json"));
    let plate = json(&argv("court --preset tennis --friction 0.6 --format json"));
    let mut assumed = 0;
    for s in all.as_array().unwrap() {
        let name = s["name"].as_str().unwrap();
        let says = s["sources"].as_array().unwrap().iter().any(|q| {
            q["quantity"] == "model" && q["source"].as_str().unwrap().contains("ASSUMED rigid")
        });
        let v = json(&argv_with(
            "court --preset tennis --surface {} --friction 0.6 --format json",
            &[name],
        ));
        assert_eq!(warned(&v), says && s["stiffness"].is_null(), "{name}: {v}");
        if says {
            assumed += 1;
            // the symptom: the rigid plate's e_y, whatever the court
            assert_eq!(f(&v, "cor_normal"), f(&plate, "cor_normal"), "{name}");
        }
    }
    assert!(
        assumed >= 5,
        "the five embedded courts but hard-court: {assumed}"
    );
    let text = ok_calibrated(&argv("court --preset tennis --surface clay --friction 0.6"));
    let line = text
        .lines()
        .find(|l| l.contains(ASSUMED))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(line.starts_with("warning: surface clay:"), "{line}");
    assert!(line.contains("--surface-cor E or --fit FILE"), "{line}");
}

/// The court's own e given (calibrated) or its K_s given: nothing assumed, no warning.
#[test]
fn a_court_given_its_give_is_not_warned() {
    for line in [
        "court --preset tennis --surface clay --friction 0.6 --surface-cor 0.7 --format json",
        "court --preset tennis --surface clay --friction 0.6 --surface-stiffness 1e6 --format json",
    ] {
        let v = json(&argv(line));
        assert!(!warned(&v), "{line}: {v}");
    }
}

/// μ from the command line is an override, where the surface gives none (clay) as where it
/// does not.
#[test]
fn friction_given_is_listed_among_the_overrides() {
    let v = json(&argv(
        "court --preset tennis --surface clay --friction 0.8 --format json",
    ));
    assert_eq!(v["surface"]["overrides"], serde_json::json!(["friction"]));
    assert_eq!(f(&v["surface"], "friction"), 0.8);
}

/// `hard-court` is rigid as published (docs/surfaces.md §2, §5: Haake et al. 2000, an acrylic
/// court rigid next to the ball, a rigid-court model matching the measured bounce): its file
/// cites that, not an assumption, so `court` on it does not warn, and its e_y is the rigid
/// plate's because the court is rigid. It gives no μ: `--friction` is still required.
#[test]
fn the_hard_court_is_rigid_as_published() {
    let all = json(&argv("surfaces --format json"));
    let hard = named(&all, "hard-court");
    let model = hard["sources"]
        .as_array()
        .unwrap()
        .iter()
        .find(|q| q["quantity"] == "model")
        .unwrap()["source"]
        .as_str()
        .unwrap();
    assert!(
        model.contains("Haake") && !model.contains("ASSUMED"),
        "{model}"
    );
    assert!(
        hard["stiffness"].is_null() && hard["friction"].is_null(),
        "{hard}"
    );
    let v = json(&argv(
        "court --preset tennis --surface hard-court --friction 0.6 --format json",
    ));
    let plate = json(&argv("court --preset tennis --friction 0.6 --format json"));
    assert!(!warned(&v), "{v}");
    assert_eq!(f(&v, "cor_normal"), f(&plate, "cor_normal"));
    let o = bl(&argv(
        "court --preset tennis --surface hard-court --format json",
    ));
    assert_eq!(o.code, 2, "no μ: {}", o.stderr);
    assert!(o.stderr.contains("friction"), "{}", o.stderr);
}
