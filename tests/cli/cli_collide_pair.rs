//! `collide --target-preset` names the ball it met (docs/targets.md §3, §8). A newcomer found
//! `collide --preset tennis --target-preset golf --format json` answering on
//! `"surface":{"name":"steel-plate",…}` with `"target":{…,"stiffness":null}` — a rigid steel
//! plate — and "golf" only inside a warning; the partner's ball and conditions nowhere, where
//! `peers --pair golf` said `surface: null` with a `surface_note` and `pair.preset`. Now the
//! answer names the partner as it names its own ball, says it met no surface, and says the
//! target is not rigid.

use crate::common;
use common::{argv, json, ok_calibrated};
use serde_json::Value;

fn pair() -> Value {
    json(&argv(
        "collide --preset tennis --target-preset golf --format json",
    ))
}

/// The JSON: no surface (with the note saying what was met), the partner by its preset, its
/// ball object and conditions written as `run --preset golf` writes its own, and a target
/// that is not rigid. Fails on the old code (`surface.name` steel-plate, no `pair`).
#[test]
fn collide_with_a_ball_names_the_partner_and_no_plate() {
    let v = pair();
    assert!(v["surface"].is_null(), "{}", v["surface"]);
    let note = v["surface_note"].as_str().unwrap_or_else(|| panic!("{v}"));
    assert!(
        note.contains("golf") && note.contains("no surface"),
        "{note}"
    );
    let p = &v["pair"];
    assert_eq!(p["preset"], "golf", "{v}");
    let golf = json(&argv("run --preset golf --format json"));
    assert_eq!(
        p["ball"], golf["ball"],
        "the ball object, as every answer writes it"
    );
    assert_eq!(p["conditions"], golf["conditions"]);
    assert_eq!(p["effective_mass"], v["effective_mass"]);
    assert_eq!(p["effective_radius"], v["effective_radius"]);
    // the partner deforms: not rigid, though it has no surface spring of its own
    let t = &v["target"];
    assert_eq!(t["rigid"], false, "{t}");
    assert!(t["stiffness"].is_null(), "{t}");
    // the keys kept (add, don't rename): the answer's own ball, the target's numbers
    assert_eq!(v["ball"], "tennis");
    assert_eq!(v["ball_record"]["name"], "tennis");
    assert_eq!(t["mass"], 0.0456);
}

/// A rigid target says so; a target behind a given surface is not rigid; a ball partner
/// behind a given surface (`--target-stiffness`) ran on that surface, which the answer
/// names, and still names the partner.
#[test]
fn the_target_says_whether_it_is_rigid() {
    let wall = json(&argv(
        "collide --preset tennis --target-mass 0.3 --format json",
    ));
    assert_eq!(wall["target"]["rigid"], true);
    assert!(wall.get("pair").is_none(), "{wall}");
    let soft = json(&argv(
        "collide --preset tennis --target-mass 0.3 --target-stiffness 4e4 --format json",
    ));
    assert_eq!(soft["target"]["rigid"], false);
    let behind = json(&argv(
        "collide --preset tennis --target-preset golf --target-stiffness 1e5 --format json",
    ));
    assert_eq!(behind["surface"]["stiffness"], 1e5, "{behind}");
    assert_eq!(behind["pair"]["preset"], "golf");
    assert_eq!(behind["target"]["rigid"], false);
}

/// The text names the partner with its origin and conditions, and claims no plate.
#[test]
fn collide_text_names_the_partner() {
    let text = ok_calibrated(&argv("collide --preset tennis --target-preset football"));
    assert!(
        text.contains("partner: football (embedded, adopted parameters)"),
        "{text}"
    );
    assert!(text.contains("partner conditions: "), "{text}");
    assert!(!text.contains("steel-plate"), "{text}");
    assert!(text.contains("surface none: "), "{text}");
}

/// `peers --pair` names its partner the same way (its `pair` gains the ball and conditions).
#[test]
fn peers_pair_names_the_partner_as_collide_does() {
    let peers = json(&argv("peers --preset tennis --pair golf --format json"));
    let collide = pair();
    for key in [
        "preset",
        "ball",
        "conditions",
        "effective_mass",
        "effective_radius",
    ] {
        assert_eq!(peers["pair"][key], collide["pair"][key], "{key}");
    }
}
