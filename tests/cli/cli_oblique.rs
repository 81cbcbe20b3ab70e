//! `bouncelab oblique` and `court` through the binary: the JSON keys of the issue (a
//! contract), agreement with the library, the court pace formula, bad input.

use crate::common;
use common::{argv, bad, f, json, names, ok};

#[test]
fn oblique_json_has_the_issues_keys() {
    let v = json(&argv(
        "oblique --preset tennis --v0 25 --angle 16 --spin 300 --friction 0.6 --format json",
    ));
    let keys = "v_in angle_in_deg spin_in vx_in vy_in v_out angle_out_deg spin_out vx_out vy_out \
                cor_normal cor_tangential apparent_friction slid_throughout grip_time contact_time \
                max_normal_force max_friction_force energy";
    for key in argv(keys) {
        assert!(v.get(key).is_some(), "{key} missing: {v}");
    }
    assert!((f(&v, "v_in") - 25.0).abs() < 1e-12);
    assert!((f(&v, "cor_normal") - f(&v, "vy_out") / f(&v, "vy_in")).abs() < 1e-12);
    let mu_app = (f(&v, "vx_in") - f(&v, "vx_out")).abs() / (f(&v, "vy_in") + f(&v, "vy_out"));
    assert!((f(&v, "apparent_friction") - mu_app).abs() < 1e-12);
    assert!(v["energy"]["residual"].as_f64().unwrap() < 1e-12);
    assert!(v.get("t").is_none(), "no history unless asked");
}

#[test]
fn history_adds_the_forces_slip_and_spin() {
    let v = json(&argv(
        "oblique --preset tennis --angle 20 --friction 0.5 --format json --history --samples 50",
    ));
    for key in [
        "t",
        "normal_force",
        "friction_force",
        "slip_velocity",
        "spin",
    ] {
        assert_eq!(v[key].as_array().map(Vec::len), Some(50), "{key}");
    }
    let spin = v["spin"].as_array().unwrap();
    assert!((spin[49].as_f64().unwrap() - f(&v, "spin_out")).abs() < 1e-9);
}

#[test]
fn arriving_without_slip_has_no_tangential_cor() {
    // straight down without spin: v_c,in = 0, e_x = −v_c,out/v_c,in undefined → null
    let v = json(&argv(
        "oblique --preset tennis --angle 90 --friction 0.5 --format json",
    ));
    assert!(v["cor_tangential"].is_null(), "{v}");
    let run = json(&["run", "--preset", "tennis", "--format", "json"]);
    assert!((f(&v, "cor_normal") - f(&run, "cor")).abs() < 1e-12);
    assert_eq!(f(&v, "vx_out"), 0.0);
}

#[test]
fn court_pace_follows_the_itf_formula() {
    let v = json(&argv("court --preset tennis --friction 0.6 --format json"));
    let cpr = 100.0 * (1.0 - f(&v, "apparent_friction")) + 150.0 * (0.81 - f(&v, "cor_normal"));
    assert!((f(&v, "cpr") - cpr).abs() < 1e-12);
    let c = v["category"].as_u64().unwrap();
    assert!((1..=5).contains(&c));
    // the same impact as oblique at 30 m/s, 16°, no spin
    let o = json(&argv(
        "oblique --preset tennis --v0 30 --angle 16 --friction 0.6 --format json",
    ));
    assert_eq!(f(&v, "apparent_friction"), f(&o, "apparent_friction"));
    assert_eq!(f(&v, "cor_normal"), f(&o, "cor_normal"));
    // more friction, a slower court
    let slow = json(&argv("court --preset tennis --friction 0.9 --format json"));
    assert!(f(&slow, "cpr") < f(&v, "cpr"));
}

#[test]
fn standards_lists_the_court_pace() {
    assert!(ok(&["standards"]).contains("itf-court-pace"));
    let v = json(&["standards", "--format", "json"]);
    let listed = names(&v);
    assert!(listed.contains(&"itf-court-pace"), "{listed:?}");
}

#[test]
fn bad_input_is_one_line_exit_2() {
    let t = ["oblique", "--preset", "tennis"];
    let with = |extra: &[&'static str]| [&t[..], extra].concat();
    bad(
        &with(&["--angle", "0", "--friction", "0.5"]),
        &["angle", "0"],
    );
    bad(
        &with(&["--angle", "91", "--friction", "0.5"]),
        &["angle", "91"],
    );
    bad(
        &with(&["--angle", "30", "--friction", "-0.1"]),
        &["friction"],
    );
    bad(
        &with(&argv("--angle 30 --friction 0.5 --tangential-stiffness 0")),
        &["tangential_stiffness"],
    );
    bad(
        &with(&argv("--angle 30 --friction 0.5 --inertia-factor 0")),
        &["inertia_factor"],
    );
    bad(
        &with(&argv("--angle 30 --friction 0.5 --inertia-factor 1.01")),
        &["inertia_factor"],
    );
    bad(
        &["court", "--preset", "tennis", "--friction", "-1"],
        &["friction"],
    );
}

#[test]
fn every_law_answers_and_angle_90_is_runs_cor() {
    for law in ["linear", "hertz", "elastic-plastic"] {
        let o = json(&argv(&format!(
            "oblique --preset tennis --angle 90 --friction 0.5 --law {law} --format json"
        )));
        let r = json(&argv(&format!(
            "run --preset tennis --law {law} --format json"
        )));
        assert_eq!(o["law"], law);
        assert!((f(&o, "cor_normal") - f(&r, "cor")).abs() <= 1e-12, "{law}");
        assert!(f(&o, "vx_out").abs() <= 1e-12 && f(&o, "spin_out").abs() <= 1e-12);
        let oblique = json(&argv(&format!(
            "oblique --preset tennis --angle 30 --spin -200 --friction 0.5 --law {law} --format json"
        )));
        // backspin: the contact point slides forward and friction slows the ball
        assert!(f(&oblique, "vx_out") < f(&oblique, "vx_in"), "{law}");
    }
    let text = ok(&argv(
        "oblique --preset tennis --angle 30 --friction 0.5 --law hertz",
    ));
    assert!(
        text.starts_with("tennis (embedded, adopted parameters), hertz law: μ = 0.5"),
        "{text}"
    );
}

#[test]
fn peers_exports_add_the_tangential_model_with_friction() {
    let plain = ok(&["peers", "--preset", "tennis", "--export", "lammps"]);
    let with = ok(&argv(
        "peers --preset tennis --export lammps --friction 0.6 --tangential-stiffness 15000",
    ));
    // the normal lines unchanged, the tangential fix after them
    assert!(with.starts_with(&plain), "{with}");
    let fix = with
        .lines()
        .find(|l| l.starts_with("fix kvclipt"))
        .expect("the tangential fix");
    assert!(
        fix.contains("tangential linear_history 15000 0.0 0.6 damping velocity limit_damping"),
        "{fix}"
    );
    // its normal model is the clipped Kelvin-Voigt line's
    let clip = plain
        .lines()
        .find(|l| l.starts_with("fix kvclip "))
        .unwrap();
    let normal = |l: &str| {
        l.split_whitespace()
            .skip(5)
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    };
    assert_eq!(normal(fix), normal(clip));
    let mujoco = ok(&argv(
        "peers --preset tennis --export mujoco --friction 0.6",
    ));
    assert!(
        mujoco.contains("condim=\"3\" friction=\"0.6 0 0\""),
        "{mujoco}"
    );
    assert!(mujoco.contains("no tangential spring"), "{mujoco}");
    let v = json(&argv("peers --preset tennis --export json --friction 0.6"));
    assert!((v["tangential"]["friction"].as_f64().unwrap() - 0.6).abs() < 1e-15);
    let k_t = json(&argv(
        "oblique --preset tennis --angle 30 --friction 0.6 --format json",
    ));
    assert_eq!(
        v["tangential"]["tangential_stiffness"],
        k_t["tangential_stiffness"]
    );
    bad(
        &argv("peers --preset tennis --export lammps --friction -1"),
        &["friction"],
    );
    bad(
        &argv("peers --preset tennis --export yade --friction 0.5"),
        &["--friction"],
    );
    bad(
        &["peers", "--preset", "tennis", "--friction", "0.5"],
        &["--export"],
    );
}
