//! A preset names its ball's published flight model (`aerodynamics`, docs/presets.md,
//! docs/flight.md §2), not its name: a copy under another name keeps the model, a bad value
//! is refused at its file:line:column, and `fit --save` writes the model it flew on.

use crate::common;

use common::*;
use serde_json::Value;
use std::path::Path;

const GOLF: &str = include_str!("../../presets/golf.toml");

/// The average tour drive of docs/flight.md §4 by `preset`, to its landing, as JSON.
fn drive(config: &Path, preset: &str) -> Value {
    let args = argv_with(
        "shot --preset {} --height 0.05 --speed 74.97 --elevation 10.8 --spin -272.2 \
         --friction 0.4 --bounces 0 --format json",
        &[preset],
    );
    let o = bl_in(config, &args);
    assert_eq!(o.code, 0, "{preset}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

#[test]
fn a_copy_of_golf_under_another_name_flies_as_golf() {
    let line = GOLF
        .lines()
        .find(|l| l.starts_with("aerodynamics = "))
        .expect("golf names its model");
    let copy = GOLF.replace("name = \"golf\"", "name = \"my-golf\"");
    let bare = copy
        .replace(&format!("{line}\n"), "")
        .replace("my-golf", "bare-golf");
    let home = config_home(&[("my-golf.toml", &copy), ("bare-golf.toml", &bare)]);
    let (golf, mine) = (drive(home.path(), "golf"), drive(home.path(), "my-golf"));
    assert_eq!(mine["aero"], golf["aero"]);
    assert_eq!(mine["end"]["x"], golf["end"]["x"]);
    assert!(f(&golf["end"], "x") > 200.0, "{}", golf["end"]);
    // without the field, a name no model has: the smooth sphere, saying so and why
    let bare = drive(home.path(), "bare-golf");
    assert_eq!(bare["aero"]["assumed"], true);
    let source = bare["aero"]["source"].as_str().unwrap();
    assert!(source.contains("`aerodynamics`"), "{source}");
}

#[test]
fn the_driver_and_mlb_balls_fly_on_their_kinds_models() {
    let home = config_home(&[]);
    for (ball, kind) in [("golf-driver", "golf"), ("baseball-mlb", "baseball")] {
        let (own, model) = (drive(home.path(), ball), drive(home.path(), kind));
        assert_eq!(own["aero"], model["aero"], "{ball}");
    }
}

#[test]
fn a_bad_model_is_refused_at_its_place() {
    let dir = tempfile::tempdir().unwrap();
    let text = GOLF.replace("aerodynamics = \"golf\"", "aerodynamics = \"golfball\"");
    let row = text
        .lines()
        .position(|l| l.starts_with("aerodynamics"))
        .unwrap()
        + 1;
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, text.replace("name = \"golf\"", "name = \"bad\"")).unwrap();
    let o = bl_in(dir.path(), &["run", "--config", path.to_str().unwrap()]);
    let at = format!("bad.toml:{row}:16: aerodynamics: unknown variant `golfball`");
    assert_bad(&o, &[&at, "`tennis`, `baseball`, `golf`"]);
}

#[test]
fn fit_save_writes_the_model_the_ball_flew_on() {
    let dir = tempfile::tempdir().unwrap();
    ok_at(
        dir.path(),
        &[
            "fit",
            "--preset",
            "golf-driver",
            "--cor",
            "0.8",
            "--save",
            "my-driver",
        ],
    );
    let saved = dir.path().join("bouncelab/presets/my-driver.toml");
    let text = std::fs::read_to_string(saved).unwrap();
    assert!(text.contains("\naerodynamics = \"golf\""), "{text}");
    let (mine, golf) = (drive(dir.path(), "my-driver"), drive(dir.path(), "golf"));
    assert_eq!(mine["aero"], golf["aero"]);
}

/// `presets --format json` names the flight model each ball flies on (its `aerodynamics`, or
/// the model named like it, `null` for neither): golf-driver flies as golf although its name
/// is none of the models' (the list lacked the field).
#[test]
fn the_presets_list_names_each_ball_s_flight_model() {
    let copy = GOLF.replace("name = \"golf\"", "name = \"my-golf\"");
    let home = config_home(&[("my-golf.toml", &copy)]);
    let o = bl_in(home.path(), &["presets", "--format", "json"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let rows: Value = serde_json::from_str(&o.stdout).unwrap();
    let model = |name: &str| {
        let row = rows.as_array().unwrap().iter().find(|r| r["name"] == name);
        row.unwrap_or_else(|| panic!("{name} listed"))["aerodynamics"].clone()
    };
    for (ball, kind) in [
        ("golf-driver", "golf"),
        ("my-golf", "golf"),
        ("baseball-mlb", "baseball"),
        ("tennis", "tennis"),
    ] {
        assert_eq!(model(ball), kind, "{ball}");
    }
    assert_eq!(model("superball"), Value::Null);
}
