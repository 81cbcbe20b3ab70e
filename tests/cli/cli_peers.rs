//! `bouncelab peers` through the binary: the JSON of issue 19, CSV, text, exports, and bad
//! input as one line with exit 2 (src/cli/peers.rs).

use crate::common;
use common::{argv, assert_bad, bl, f, json, ok};

const MODELS: [&str; 5] = [
    "kelvin-voigt",
    "kelvin-voigt-no-tension",
    "tsuji",
    "hunt-crossley",
    "christoforou-yigit",
];

/// Without --cor: the preset's measured COR at its measured v0; every model has an `exact`
/// row at that COR, the Hunt–Crossley family every published rule, and each row the keys of
/// the issue.
#[test]
fn json_lists_every_model_and_rule() {
    let v = json(&["peers", "--preset", "golf", "--format", "json"]);
    assert_eq!(f(&v, "mass"), 0.0456);
    assert_eq!(f(&v, "v0"), 1.47);
    assert_eq!(f(&v, "target_cor"), 0.84);
    let rows = v["models"].as_array().unwrap();
    for m in MODELS {
        let exact = rows
            .iter()
            .find(|r| r["model"] == m && r["rule"] == "exact")
            .unwrap_or_else(|| panic!("{m}: {v}"));
        assert!((f(exact, "cor") - 0.84).abs() < 1e-9, "{m}");
    }
    for rule in ["hunt-crossley", "lankarani-nikravesh", "flores", "gonthier"] {
        assert!(
            rows.iter()
                .any(|r| r["model"] == "hunt-crossley" && r["rule"] == rule)
        );
    }
    assert!(
        rows.iter()
            .any(|r| r["model"] == "kelvin-voigt" && r["rule"] == "log-decrement")
    );
    for r in rows {
        for key in argv("model rule stiffness damping cor max_force contact_time") {
            assert!(!r[key].is_null(), "{key} in {r}");
        }
    }
}

/// --cor and --v0: the target and the speed move; the peers' exact COR follows the target and
/// their damping does not depend on v0 (Kelvin–Voigt, Tsuji) or is χ (Hunt–Crossley).
#[test]
fn cor_and_v0_set_the_target_and_speed() {
    let a = json(&argv("peers --preset superball --cor 0.5 --format json"));
    let b = json(&argv(
        "peers --preset superball --cor 0.5 --v0 6 --format json",
    ));
    assert_eq!(f(&b, "v0"), 6.0);
    for (ra, rb) in a["models"]
        .as_array()
        .unwrap()
        .iter()
        .zip(b["models"].as_array().unwrap())
        .filter(|(r, _)| r["model"] != "christoforou-yigit")
    {
        assert!((f(ra, "cor") - f(rb, "cor")).abs() < 1e-9, "{ra} {rb}");
        assert!((f(ra, "damping") - f(rb, "damping")).abs() < 1e-7 * f(ra, "damping"));
    }
}

#[test]
fn csv_and_text() {
    let csv = ok(&["peers", "--preset", "baseball", "--format", "csv"]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "model,rule,stiffness,damping,cor,max_force,contact_time,k_r"
    );
    assert_eq!(lines.count(), 12);
    let text = ok(&["peers", "--preset", "baseball"]);
    for m in MODELS {
        assert!(text.contains(m), "{m}: {text}");
    }
    assert!(text.contains("target COR 0.49 (measured)"), "{text}");
}

#[test]
fn exports_for_every_code() {
    for (code, needle) in [
        ("lammps", "wall/gran granular hooke"),
        ("liggghts", "pair_style gran model hertz"),
        ("chrono", "ContactForceModel::Flores"),
        ("yade", "ViscElMat(kn="),
        ("mujoco", "solref=\"-"),
        ("json", "\"hunt_crossley_chi\""),
    ] {
        let s = ok(&["peers", "--preset", "superball", "--export", code]);
        assert!(s.contains(needle), "{code}: {s}");
        assert!(s.contains("0.75"), "{code} names the target: {s}");
    }
}

#[test]
fn christoforou_yigit_targets() {
    let v = json(&argv(
        "peers --preset superball --target christoforou-yigit --format json",
    ));
    let cy = v["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["model"] == "christoforou-yigit")
        .unwrap()
        .clone();
    assert!((f(&cy, "cor") - f(&v, "target_cor")).abs() < 1e-9);
    let curve = json(&argv(
        "peers --preset superball --target christoforou-yigit-curve --format json",
    ));
    assert_eq!(curve["target_source"], "christoforou-yigit-curve");
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    assert_bad(
        &bl(&["peers", "--preset", "golf", "--cor", "1.5"]),
        &["cor"],
    );
    assert_bad(
        &bl(&["peers", "--preset", "golf", "--cor", "nan"]),
        &["cor"],
    );
    assert_bad(&bl(&["peers", "--preset", "golf", "--v0", "-3"]), &["v0"]);
    assert_bad(
        &bl(&argv("peers --preset golf --cor 0 --format json")),
        &["cor", "out of reach"],
    );
    assert_bad(&bl(&["peers", "--preset", "nosuchball"]), &["nosuchball"]);
    assert_bad(
        &bl(&["peers", "--cor", "0.5", "--target", "christoforou-yigit"]),
        &["--cor"],
    );
}

/// A ball the conditions or an override changed is not the ball whose COR was measured: the
/// default target is then the Christoforou–Yigit model's COR for the ball as run, as an
/// export's is (`peers --preset football --pressure 0.6bar` targeted the measured 0.8806 at
/// 80 kPa and refitted K_r to reach it, while `run` there gives 0.8658 and the LAMMPS export
/// 0.865808); `--target measured` keeps the measured COR, saying whose it is.
#[test]
fn a_changed_ball_is_calibrated_to_its_own_cor() {
    for changed in [
        "peers --preset football --pressure 0.6bar --format json",
        "peers --preset tennis --k-p 60000 --format json",
    ] {
        let v = json(&argv(changed));
        let run = json(&argv(&changed.replacen("peers", "run", 1)));
        assert_eq!(v["target_source"], "christoforou-yigit", "{changed}");
        assert!(
            (f(&v, "target_cor") - f(&run, "cor")).abs() < 1e-9,
            "{changed}"
        );
        let cy = v["models"].as_array().unwrap().iter();
        let cy = cy
            .clone()
            .find(|r| r["model"] == "christoforou-yigit")
            .unwrap();
        // the model's own COR needs no refit: K_r stays the ball's
        assert!((f(cy, "k_r") - f(&run["ball"], "k_r")).abs() < 1e-6 * f(cy, "k_r"));
    }
    let asked = json(&argv(
        "peers --preset football --pressure 0.6bar --target measured --format json",
    ));
    assert_eq!(asked["target_source"], "measured");
    let warned = asked["warnings"].as_array().unwrap().iter();
    assert!(
        warned
            .clone()
            .any(|w| w.as_str().unwrap().contains("record's conditions")),
        "{}",
        asked["warnings"]
    );
    // the recorded ball at its record: the measured COR, as before
    let own = json(&argv("peers --preset football --format json"));
    assert_eq!(own["target_source"], "measured");
}
