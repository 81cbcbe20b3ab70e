//! What an answer's `surface` is called once numbers are given over the surface's own
//! (docs/surfaces.md §1, "The name"): one rule for every command. A newcomer found `run
//! --surface-stiffness 3e4` answering on `"name": "steel-plate"` with a stiffness of 30 kN/m,
//! while `court --surface-cor` renamed the surface it calibrated because "it is no longer the
//! surface it started from". Now every command names a surface whose numbers differ from its
//! own for what it is: `given-surface` from the default plate, `NAME-modified` from a named
//! one, its `origin` saying which surface it started from and `overrides` what was given.

use crate::common;
use common::{argv, json, ok};
use serde_json::Value;

/// Every command that takes the surface options, each with one normal number given.
const GIVEN: [&str; 6] = [
    "run --preset tennis --surface-stiffness 3e4 --format json",
    "drop --preset tennis --bounces 1 --surface-stiffness 3e4 --format json",
    "oblique --preset tennis --angle 30 --friction 0.5 --surface-stiffness 3e4 --format json",
    "court --preset tennis --friction 0.5 --surface-stiffness 3e4 --format json",
    "shot --preset tennis --height 1 --speed 10 --elevation -10 --friction 0.5 --surface-stiffness 3e4 --format json",
    "collide --preset tennis --target-mass 0.3 --format json",
];

fn surface(line: &str) -> Value {
    json(&argv(line))["surface"].clone()
}

/// The defect: each of these kept `"name": "steel-plate"` (`run --surface-stiffness 3e4`:
/// K_s 30000 N/m on a "steel plate"). Fails on the old code at the first line.
#[test]
fn a_surface_given_other_numbers_is_named_for_what_it_is() {
    for line in GIVEN {
        let s = surface(line);
        assert_eq!(s["name"], "given-surface", "{line}: {s}");
        assert_eq!(
            s["origin"], "given over steel-plate (embedded)",
            "{line}: {s}"
        );
        assert!(
            !s["overrides"].as_array().unwrap().is_empty(),
            "{line}: {s}"
        );
    }
    // a named surface keeps its name, marked
    let s = surface("run --preset tennis --surface clay --surface-stiffness 3e4 --format json");
    assert_eq!(s["name"], "clay-modified", "{s}");
    assert_eq!(s["origin"], "given over clay (embedded)", "{s}");
    assert_eq!(s["overrides"], serde_json::json!(["stiffness"]));
    // the text's surface line names it so too
    let text = ok(&argv(
        "run --preset tennis --surface clay --surface-stiffness 3e4",
    ));
    assert!(
        text.contains(
            "surface clay-modified (K_s 30000 N/m, c_s 0 kg/s, immovable; given: stiffness)"
        ),
        "{text}"
    );
}

/// A number given equal to the surface's own changes nothing: the name stays (the override is
/// still listed); μ given where the surface has none fills a gap, it replaces nothing
/// (`court --surface clay --friction 0.6`: clay gives no μ).
#[test]
fn a_number_that_changes_nothing_keeps_the_name() {
    let s = surface("run --preset tennis --surface-stiffness inf --format json");
    assert_eq!(s["name"], "steel-plate", "{s}");
    assert_eq!(s["overrides"], serde_json::json!(["stiffness"]));
    let s = surface("court --preset tennis --surface clay --friction 0.6 --format json");
    assert_eq!(s["name"], "clay", "{s}");
    assert_eq!(s["origin"], "embedded", "{s}");
}

/// A court calibrated from a surface given its K_s is named for the calibration, from the
/// surface it started from (not `clay-modified-calibrated`).
#[test]
fn a_calibrated_court_given_its_stiffness_names_the_surface_it_started_from() {
    let s = surface(
        "court --preset tennis --surface clay --friction 0.6 --surface-stiffness 1e6 --surface-cor 0.75 --format json",
    );
    assert_eq!(s["name"], "clay-calibrated", "{s}");
    let origin = s["origin"].as_str().unwrap();
    assert!(origin.ends_with("from clay (embedded)"), "{origin}");
}
