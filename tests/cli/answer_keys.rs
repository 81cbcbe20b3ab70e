//! Every answer names its ball, its surface and its conditions (issues 52 and 53): each
//! JSON-answering subcommand's document has the keys `ball`, `surface` and `conditions`
//! (docs/cli.md, "The surface object"). A new user found `bat`, `peers`, `static`, `batch`,
//! `map` and `fit` without `surface`, and `fit` without `conditions`.

use crate::common;

use common::*;
use serde_json::Value;
use std::path::Path;

/// The JSON answer of a command that succeeds (warnings on stderr allowed: a ball away from
/// the speed its preset was fitted at).
fn answer(args: &[&str]) -> Value {
    let o = bl(args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap_or_else(|e| panic!("{args:?}: {e}"))
}

/// The data files the `fit` rows read, each from the model's own answers (exact data: the
/// keys are asked of, not the fit's quality): a COR table, oblique bounces, static
/// deflections.
fn data_files(dir: &Path) {
    let mut cors = String::from("v0,cor\n");
    let mut bounces = String::from("v0,angle_deg,spin_in,vx_out,vy_out\n");
    for (v0, angle) in [(2.0, 20.0), (5.0, 35.0), (10.0, 50.0), (20.0, 65.0)] {
        let v = answer(&argv_with(
            "run --preset tennis --v0 {} --format json",
            &[&v0.to_string()],
        ));
        cors += &format!("{v0},{}\n", f(&v, "cor"));
        let o = answer(&argv_with(
            "oblique --preset tennis --v0 {} --angle {} --friction 0.5 --format json",
            &[&v0.to_string(), &angle.to_string()],
        ));
        let (vx, vy) = (f(&o, "vx_out"), f(&o, "vy_out"));
        bounces += &format!("{v0},{angle},0,{vx},{vy}\n");
    }
    let mut statics = String::from("load_kg,deflection_m\n");
    for load in [2.0, 5.0, 8.165] {
        let s = answer(&argv_with(
            "static --preset tennis --load {} --format json",
            &[&load.to_string()],
        ));
        let d = s["forward"]["deflection_m"].as_f64().unwrap();
        statics += &format!("{load},{d}\n");
    }
    std::fs::write(dir.join("cor.csv"), cors).unwrap();
    std::fs::write(dir.join("bounces.csv"), bounces).unwrap();
    std::fs::write(dir.join("static.csv"), statics).unwrap();
}

/// Every subcommand that answers in JSON, once each way its JSON is written: `{dir}` is the
/// data files' folder. `surface: null` is allowed only with a `surface_note` saying what the
/// ball met instead (`peers --pair`, `collide --target-preset`).
const ANSWERS: [&str; 24] = [
    "run --preset golf --format json",
    "drop --preset basketball --standard fiba --format json",
    "oblique --angle 45 --friction 0.3 --format json",
    "court --preset tennis --friction 0.6 --format json",
    "collide --preset superball --target-mass 0.3 --format json",
    "collide --preset tennis --target-preset golf --format json",
    "shot --preset tennis --height 2.8 --speed 50 --elevation -6 --friction 0.6 --format json",
    "sweep velocity --preset golf --points 3 --format json",
    "sweep zeta --lambda 0.4 --points 3 --format json",
    "bat --preset baseball-mlb --bat-mass 0.6 --format json",
    "bat --bat-mass 0.6 --bat-stiffness 1e7 --bat-damping 5 --format json",
    "peers --preset tennis --format json",
    "peers --preset tennis --pair tennis --format json",
    "static --preset tennis --load 8.165 --format json",
    "batch tests/golden/batch-lot7.csv --preset tennis --format json",
    "map --lambda 0.1:2:3 --zeta 0.1:1:3 --format json",
    "map --normalized --zp-bar 0.5 --linear-axes --lambda 0:2:3 --zeta 0:1:3 --format json",
    "fit --preset baseball --cor 0.5 --v0 2 --format json",
    "fit --preset tennis --cor-table {dir}/cor.csv --format json",
    "fit --preset tennis --oblique {dir}/bounces.csv --format json",
    "fit --preset tennis --static {dir}/static.csv --cor-table {dir}/cor.csv --format json",
    "fit --drop-height 1 --rebound-height 0.49 --format json",
    "mc --preset golf --vary k_p=5% --samples 50 --seed 7 --format json",
    "mc --shot --preset tennis --height 2.8 --speed 50 --elevation -6 --friction 0.6 --vary speed=2% --samples 20 --format json",
];

#[test]
fn every_json_answer_names_its_ball_surface_and_conditions() {
    let dir = tempfile::tempdir().unwrap();
    data_files(dir.path());
    let folder = dir.path().display().to_string();
    let mut missing = Vec::new();
    for line in ANSWERS {
        let line = line.replace("{dir}", &folder);
        let v = answer(&argv(&line));
        for key in ["ball", "surface", "conditions"] {
            if v.get(key).is_none() {
                missing.push(format!("{line}: no `{key}`"));
            }
        }
        let surface = &v["surface"];
        let named = surface["name"].is_string() && surface["overrides"].is_array();
        let explained = surface.is_null() && v["surface_note"].is_string();
        if v.get("surface").is_some() && !(named || explained) {
            missing.push(format!("{line}: `surface` is {surface}"));
        }
        let conditions = &v["conditions"];
        if v.get("conditions").is_some() && !conditions["atmosphere_pa"].is_number() {
            missing.push(format!("{line}: `conditions` is {conditions}"));
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

/// The bat is what the ball met: its mass, its barrel's stiffness and damping, each given on
/// the command line listed as an override; rigid when no stiffness is given.
#[test]
fn bats_surface_is_the_bat_it_was_given() {
    let v = answer(&argv(
        "bat --bat-mass 0.6 --bat-stiffness 1e7 --bat-damping 5 --format json",
    ));
    let s = &v["surface"];
    assert_eq!(s["name"], "bat");
    assert_eq!(
        (f(s, "mass"), f(s, "stiffness"), f(s, "damping")),
        (0.6, 1e7, 5.0)
    );
    assert_eq!(
        s["overrides"],
        serde_json::json!(["stiffness", "damping", "mass"])
    );
    let v = answer(&argv("bat --bat-mass 0.6 --format json"));
    assert!(v["surface"]["stiffness"].is_null(), "rigid: {v}");
    assert_eq!(v["surface"]["overrides"], serde_json::json!(["mass"]));
}
