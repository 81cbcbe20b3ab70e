//! `--mass` and `--radius` on every command that takes a ball (issue 27 item 8): they replace
//! the preset's measured m and R, the ball its parameter set is derived from
//! (src/api/entry.rs; docs/presets.md, "Mass and radius").

use crate::common;

use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};
use common::{argv, argv_with, bad, f, json, ok_calibrated};

/// The superball's adopted set (docs/model.md §7) at another mass, run by the library directly.
fn superball_at(mass: f64) -> ImpactParams {
    ImpactParams {
        mass,
        k_p: 5.45e4,
        damping: 140.0,
        k_r: 7.08e4,
        z_p: 4e-3,
        k_h: ImpactParams::k_h_matching(5.45e4, 4e-3),
        v0: 3.12,
    }
}

/// With the adopted set m is the model's mass and nothing else moves: `run --mass` is the
/// library's impact with that mass (λ the same, ζ = √(m K_p)/(2c) moved).
#[test]
fn mass_is_the_model_mass() {
    let v = json(&argv("run --preset superball --mass 0.05 --format json"));
    let r = simulate(
        &superball_at(0.05),
        ContactLaw::Linear,
        &SolveOptions::default(),
    )
    .unwrap();
    assert_eq!(f(&v, "mass"), 0.05);
    assert!(
        (f(&v, "cor") - r.cor).abs() < 1e-12,
        "{} vs {}",
        f(&v, "cor"),
        r.cor
    );
    assert!((f(&v, "max_force") - r.max_force).abs() < 1e-9 * r.max_force);
    let zeta = (0.05f64 * 5.45e4).sqrt() / (2.0 * 140.0);
    assert!((f(&v, "zeta") - zeta).abs() < 1e-12);
    // and it is not the preset's mass's answer
    let plain = json(&["run", "--preset", "superball", "--format", "json"]);
    assert!((f(&plain, "cor") - f(&v, "cor")).abs() > 1e-3);
}

/// With the adopted set R enters no parameter (K_h is Eq. 16's), so `run` is unchanged; with
/// the materials set K_h = (4/3) E* √R (Eq. 8) scales as √R.
#[test]
fn radius_moves_only_what_reads_it() {
    let at = |extra: &[&str]| {
        let mut a = vec!["run", "--preset", "superball", "--format", "json"];
        a.extend_from_slice(extra);
        json(&a)
    };
    let (plain, wide) = (at(&[]), at(&["--radius", "0.04"]));
    for key in ["cor", "max_force", "k_h", "k_p"] {
        assert_eq!(f(&plain, key), f(&wide, key), "{key}");
    }
    let m1 = at(&["--params", "materials"]);
    let m2 = at(&["--params", "materials", "--radius", "0.0431"]);
    let ratio = f(&m2, "k_h") / f(&m1, "k_h");
    assert!(
        (ratio - (0.0431f64 / 0.02155).sqrt()).abs() < 1e-12,
        "{ratio}"
    );
}

/// The drop's drag and the peers' exported radius follow `--radius`.
#[test]
fn drop_and_peers_take_the_radius() {
    let drop = |r: &str| {
        let v = json(&argv_with(
            "drop --preset tennis --radius {} --format json",
            &[r],
        ));
        f(&v["bounces"][0], "v_in")
    };
    // a bigger ball meets more air on the way down
    assert!(drop("0.05") < drop("0.03"));
    let s = ok_calibrated(&argv("peers --preset golf --radius 0.03 --export mujoco"));
    assert!(
        s.contains("R = 0.03 m") && s.contains("size=\"0.03\""),
        "{s}"
    );
}

/// Every command that takes a ball takes both.
#[test]
fn every_ball_command_takes_them() {
    for args in [
        &["run"][..],
        &["sweep", "velocity", "--points", "3"],
        &["drop"],
        &["peers"],
        &["map", "--lambda", "0.1:1:2", "--zeta", "0.1:1:2"],
        &["fit", "--cor", "0.7"],
    ] {
        let mut a = args.to_vec();
        a.extend(argv("--preset superball --mass 0.04 --radius 0.022"));
        ok_calibrated(&a);
    }
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("f.svg");
    let out = out.to_str().unwrap();
    ok_calibrated(&argv_with(
        "figure cor-velocity --mass 0.04 --radius 0.022 --out {}",
        &[out],
    ));
}

#[test]
fn bad_sizes_are_named() {
    bad(&["run", "--mass", "-1"], &["invalid mass: -1"]);
    bad(&["run", "--radius", "0"], &["invalid radius: 0"]);
    bad(&["drop", "--radius", "1e300"], &["invalid radius"]);
    bad(&["peers", "--mass", "nan"], &["mass"]);
    bad(&["run", "--normalized", "--mass", "2"], &["--mass"]);
    let axes = ["--lambda", "0.1:1:2", "--zeta", "0.1:1:2"];
    let mut map = vec!["map", "--normalized", "--radius", "2"];
    map.extend(axes);
    bad(&map, &["--radius"]);
}
