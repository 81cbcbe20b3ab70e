//! The 2026-12-07 newcomer trial's defects in `run`'s outputs and their neighbours, each
//! failing on the old code: a text comparison the JSON withheld, a CSV without a fitted
//! preset's intervals or without the surface and conditions it ran on, `static --k-r 0`
//! refused, a map silent of its cells' other λ and ζ, `fit --cor-temperature` JSON without
//! its ball, conditions and warnings, and an export's normal speed labelled v0.

use crate::common;
use common::{argv, argv_with, bl, bl_at, json, ok_calibrated, outside_calibration};
use serde_json::Value;

/// The CSV `text` (a header and rows, no quoted comma but in the last columns' cells read
/// here by name) as maps from column to cell.
fn csv_rows(text: &str) -> Vec<std::collections::HashMap<String, String>> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let head: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            head.iter()
                .cloned()
                .zip(r.iter().map(String::from))
                .collect()
        })
        .collect()
}

/// A number cell against the JSON's value (`null`: an empty cell), to 1e-15: serde_json
/// reads a number to within an ulp of the shortest text the binary wrote.
fn same(cell: &str, v: &Value) {
    match v.as_f64() {
        None => assert_eq!(cell, "", "{v}"),
        Some(x) => {
            let c: f64 = cell.parse().unwrap();
            assert!((c - x).abs() <= 1e-15 * x.abs(), "{cell} against {v}");
        }
    }
}

/// Each of the trial's runs away from the record's conditions: the JSON withholds the
/// comparison, and the text, which printed the measured column and the difference above its
/// own "not compared" line, now shows the model's column alone (one rule for both).
#[test]
fn text_withholds_the_comparison_whenever_the_json_does() {
    for args in [
        "run --preset squash --temperature 23",
        "run --preset football --temperature 5",
        "run --preset football --after 72h",
        "run --preset tennis --pressure 70kPa",
        "run --preset football --pressure 1e9",
    ] {
        let v = json(&argv(&format!("{args} --format json")));
        let why = v["comparison_withheld"].as_str().expect("withheld");
        let text = ok_calibrated(&argv(args));
        // the table's head: `model` alone, or `model  measured  difference`
        let compared = |l: &str| l.trim_start().starts_with("model") && l.contains("measured");
        assert!(!text.lines().any(compared), "{args}: {text}");
        assert!(
            !text.contains("difference"),
            "{args}: the comparison printed: {text}"
        );
        let said = format!("(measured values not compared: {why})");
        assert!(text.contains(&said), "{args}: {text}");
    }
    // at the record's own conditions both compare
    let v = json(&argv("run --preset squash --format json"));
    assert_eq!(v["comparison_withheld"], Value::Null);
    let text = ok_calibrated(&argv("run --preset squash"));
    assert!(text.contains("measured  difference"), "{text}");
}

/// A preset saved by `fit --save` carries 95 % intervals: `run --format csv` gave text and
/// JSON's `cor_ci95` but no `…_ci95_lo/hi` columns; they come after every other column, and
/// hold the JSON's numbers.
#[test]
fn run_csv_carries_a_fitted_presets_intervals() {
    let dir = tempfile::tempdir().unwrap();
    let table = "v0,cor\n1.0,0.62\n1.25,0.60\n1.5,0.585\n2.0,0.57\n2.5,0.55\n";
    std::fs::write(dir.path().join("bb.csv"), table).unwrap();
    let o = bl_at(
        dir.path(),
        &argv("fit --preset baseball --cor-table bb.csv --save my-baseball"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let run = |format: &str| {
        let o = bl_at(
            dir.path(),
            &argv_with("run --preset my-baseball --v0 45 --format {}", &[format]),
        );
        assert_eq!(o.code, 0, "{}", o.stderr);
        o.stdout
    };
    let v: Value = serde_json::from_str(&run("json")).unwrap();
    let csv = run("csv");
    let head = csv.lines().next().unwrap();
    assert!(
        head.ends_with(
            ",cor_ci95_lo,cor_ci95_hi,max_force_ci95_lo,max_force_ci95_hi,\
             contact_time_ci95_lo,contact_time_ci95_hi"
        ),
        "{head}"
    );
    let row = &csv_rows(&csv)[0];
    for key in ["cor", "max_force", "contact_time"] {
        let ci = &v[format!("{key}_ci95")];
        same(&row[&format!("{key}_ci95_lo")], &ci[0]);
        same(&row[&format!("{key}_ci95_hi")], &ci[1]);
    }
    // the embedded ball has no fit: no interval columns
    let plain = ok_calibrated(&argv("run --preset baseball --format csv"));
    assert!(!plain.contains("ci95"), "{plain}");
}

const GYM: &str = r#"name = "gym"
description = "Our gym floor, measured"

[normal]
stiffness = 3e5
damping = 40.0

[tangential]
friction = 0.55

[[sources]]
quantity = "stiffness"
source = "our drop tests of 2026-11-02, K_s fitted"
[[sources]]
quantity = "damping"
source = "the same fit"
[[sources]]
quantity = "friction"
source = "our sled test"
"#;

/// The surface and conditions columns of `csv` (its first row) against the JSON `v` of the
/// same answer, and the ball's `preset` against the JSON's `ball.name`.
fn states_as_json(csv: &str, v: &Value) {
    let rows = csv_rows(csv);
    assert!(!rows.is_empty(), "{csv}");
    let head = csv.lines().next().unwrap();
    assert!(
        head.ends_with(
            "preset,origin,parameters,law,surface,surface_stiffness,surface_damping,\
             surface_mass,temperature_c,pressure_gauge_pa,atmosphere_pa"
        ) || head.contains(
            ",warnings,surface,surface_stiffness,surface_damping,surface_mass,temperature_c,\
             pressure_gauge_pa,atmosphere_pa"
        ),
        "{head}"
    );
    for row in &rows {
        assert_eq!(row["preset"], v["ball"]["name"].as_str().unwrap(), "{csv}");
        assert_eq!(row["surface"], v["surface"]["name"].as_str().unwrap());
        let inf = |x: &Value| x.as_f64().map_or("inf".to_string(), |x| x.to_string());
        assert_eq!(row["surface_stiffness"], inf(&v["surface"]["stiffness"]));
        assert_eq!(row["surface_mass"], inf(&v["surface"]["mass"]));
        same(&row["surface_damping"], &v["surface"]["damping"]);
        for key in ["temperature_c", "pressure_gauge_pa", "atmosphere_pa"] {
            same(&row[key], &v["conditions"][key]);
        }
    }
}

/// `run --format csv` named neither the surface (the basketball on the gym floor gave COR
/// 0.8001 against the plate's 0.7902 with no column saying so) nor the conditions (the
/// football at 6 psi said them only inside a warning); `drop`, `sweep velocity` and
/// `oblique` named no ball either. Each CSV now ends with what its JSON states.
#[test]
fn every_csv_names_its_ball_surface_and_conditions() {
    let home = tempfile::tempdir().unwrap();
    let surfaces = home.path().join("bouncelab").join("surfaces");
    std::fs::create_dir_all(&surfaces).unwrap();
    std::fs::write(surfaces.join("gym.toml"), GYM).unwrap();
    let pair = |args: &str| {
        let run = |format: &str| {
            let o = bl_at(
                home.path(),
                &argv_with(&format!("{args} --format {{}}"), &[format]),
            );
            assert_eq!(o.code, 0, "{args}: {}", o.stderr);
            o.stdout
        };
        let v: Value = serde_json::from_str(&run("json")).unwrap();
        (run("csv"), v)
    };
    for args in [
        "run --preset basketball --surface gym",
        "run --preset football --pressure 6psi",
        "run --preset squash --temperature 23",
        "drop --preset basketball --surface gym --bounces 2",
        "drop --preset football --pressure 6psi --bounces 1",
        "sweep velocity --preset football --pressure 6psi --points 3",
        "oblique --preset tennis --angle 30 --friction 0.5 --surface gym",
        "oblique --preset football --pressure 6psi --angle 30 --friction 0.5",
    ] {
        let (csv, v) = pair(args);
        states_as_json(&csv, &v);
    }
    let (csv, _) = pair("run --preset basketball --surface gym");
    let row = &csv_rows(&csv)[0];
    assert_eq!(row["surface"], "gym");
    assert_eq!(row["surface_stiffness"], "300000");
    // no energy audit of the chain on a surface that gives (docs/surfaces.md §5)
    assert_eq!(row["energy_initial"], "");
}

/// `static --k-r 0` was refused ("invalid k_r: 0 (must be positive)") though documented,
/// and a preset file with k_r = 0 answered: the ball with no recoil spring creeps, each
/// reading `null` with its reason. `run --k-r 0` is `run --lambda 0`, as λ = 0 is taken.
#[test]
fn k_r_0_is_the_ball_without_a_recoil_spring() {
    let v = json(&argv(
        "static --preset tennis --load 8.165 --k-r 0 --format json",
    ));
    for reading in ["forward", "return"] {
        assert_eq!(v[reading]["deflection_m"], Value::Null, "{v}");
        let why = v[reading]["reason"].as_str().unwrap();
        assert!(why.contains("no recoil spring"), "{why}");
    }
    let by_k_r = json(&argv("run --preset tennis --k-r 0 --format json"));
    let by_lambda = json(&argv("run --preset tennis --lambda 0 --format json"));
    assert_eq!(by_k_r["cor"], by_lambda["cor"]);
    assert_eq!(by_k_r["k_r"], 0.0);
    // below zero is still refused
    let o = bl(&argv("static --preset tennis --load 8.165 --k-r -1"));
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("invalid k_r: -1"), "{}", o.stderr);
}

/// `map` gave `warnings: []` though each cell but the ball's own changes λ and ζ, for which
/// `run --lambda --zeta` warns; it now warns once, in run's words.
#[test]
fn a_map_warns_that_its_cells_are_other_balls() {
    let v = json(&argv(
        "map --preset tennis --lambda 0.1:10:3 --zeta 0.01:1:3 --format json",
    ));
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 1, "{v}");
    let run = json(&argv(
        "run --preset tennis --lambda 0.1 --zeta 0.01 --format json",
    ));
    let said = outside_calibration(&run)[0];
    assert!(w[0].starts_with(said), "{} against {said}", w[0]);
    assert!(
        w[0].contains("the map's cells are this ball at other λ and ζ; only its own point"),
        "{}",
        w[0]
    );
}

/// `fit --cor-temperature`'s JSON had no `ball`, `conditions` or `warnings` (every other
/// answer has them) and no word that its data's speed is not the ball's record's.
#[test]
fn fit_cor_temperature_names_its_ball_conditions_and_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let rows = "temperature_c,v0,cor\n0,2,0.850724\n10,2,0.780748\n23,2,0.727505\n\
                35,2,0.758775\n45,2,0.815560\n";
    std::fs::write(dir.path().join("warm.csv"), rows).unwrap();
    let o = bl_at(
        dir.path(),
        &argv("fit --preset superball --cor-temperature warm.csv --temperature 23 --format json"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["ball"]["name"], "superball");
    assert_eq!(v["conditions"]["temperature_c"], 23.0);
    assert_eq!(v["conditions"]["atmosphere_pa"], 101325.0);
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 1, "{v}");
    assert!(
        w[0].starts_with("outside calibration: impact speed 2 m/s"),
        "{}",
        w[0]
    );
    let text = bl_at(
        dir.path(),
        &argv("fit --preset superball --cor-temperature warm.csv --temperature 23"),
    );
    assert!(
        text.stdout.contains(&format!("warning: {}", w[0])),
        "{}",
        text.stdout
    );
}

/// `peers --export mujoco --angle 30`'s header said `v0 = 0.735 m/s`, the normal speed of
/// the 1.47 m/s bounce, as if it were the ball's speed.
#[test]
fn an_export_at_an_angle_labels_its_normal_speed() {
    let o = bl(&argv("peers --preset golf --export mujoco --angle 30"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let first = o.stdout.lines().next().unwrap();
    assert!(
        first.contains("v0 = 0.735 m/s (the normal speed v·sinθ)"),
        "{first}"
    );
    let head_on = bl(&argv("peers --preset golf --export mujoco"));
    let first = head_on.stdout.lines().next().unwrap();
    assert!(first.contains("v0 = 1.47 m/s, target COR"), "{first}");
}
