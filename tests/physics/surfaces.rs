//! Surfaces (issue 53 items 1–3; docs/surfaces.md, docs/oblique.md §6 and §11): the presets and
//! `bouncelab surfaces`, `--surface*` on oblique, court and collide, court pace from both μ
//! and e, and its calibration to a measured (μ, e).

use crate::common;
use common::{argv, argv_with, assert_bad, bl, bl_in, f, json, names};

/// The ITF formula (ITF CS 01/02).
fn cpr(mu: f64, e: f64) -> f64 {
    100.0 * (1.0 - mu) + 150.0 * (0.81 - e)
}

/// The defect: `court` took e from the rigid plate for every court, so that its rating was
/// 100(1 − μ) + 9 whatever the court (issue 53). A court of the same μ with its own measured
/// e = 0.81 (the formula's reference) now rates by both: 100(1 − 0.6) + 0 = 40, not the
/// rigid plate's 49.2. On the old code `--surface-cor` did not exist (exit 2).
#[test]
fn court_pace_is_rated_by_the_courts_own_e() {
    let rigid = json(&argv("court --preset tennis --friction 0.6 --format json"));
    let court = json(&argv(
        "court --preset tennis --friction 0.6 --surface-cor 0.81 --format json",
    ));
    let e = f(&court, "cor_normal");
    assert!((e - 0.81).abs() < 0.002, "e {e}");
    let mu = f(&court, "apparent_friction");
    assert!((f(&court, "cpr") - cpr(mu, e)).abs() < 1e-9);
    assert!(
        (f(&court, "cpr") - 40.0).abs() < 0.5,
        "{}",
        f(&court, "cpr")
    );
    assert!((f(&rigid, "cpr") - f(&court, "cpr")).abs() > 5.0);
    // what it was computed on: the calibrated surface, named in the answer
    let s = &court["surface"];
    assert_eq!(s["overrides"][0], "calibrated");
    assert!(f(s, "damping") > 0.0 && f(s, "stiffness").is_finite());
    assert!(
        court["computed_on"]
            .as_str()
            .unwrap()
            .contains("30 m/s and 16°")
    );
    // the rigid plate, the default, names itself and moves nothing
    assert_eq!(rigid["surface"]["name"], "steel-plate");
    assert!(rigid["surface"]["stiffness"].is_null());
}

/// The defect: a court calibrated to a measured e (`--surface-cor`, `--fit`) kept the name of
/// the surface it started from, the rigid "steel-plate" it is not, in the JSON `surface`, the
/// text's surface line and `computed_on` (issue 53). Fails on the old code.
#[test]
fn a_calibrated_court_is_named_for_what_it_is() {
    let args = argv("court --preset tennis --friction 0.6 --surface-cor 0.81");
    let mut with_json = args.to_vec();
    with_json.extend(["--format", "json"]);
    let court = json(&with_json);
    let s = &court["surface"];
    assert_eq!(s["name"], "calibrated-court");
    let origin = s["origin"].as_str().unwrap();
    assert!(
        origin.contains("--surface-cor") && origin.contains("from steel-plate (embedded)"),
        "{origin}"
    );
    let on = court["computed_on"].as_str().unwrap();
    assert!(
        on.contains("surface calibrated-court (") && !on.contains("steel-plate ("),
        "{on}"
    );
    let out = common::ok(&args);
    assert!(out.contains("surface calibrated-court ("), "{out}");
    assert!(!out.contains("surface steel-plate"), "{out}");
    // a named surface calibrated keeps its name, marked
    let mut named = with_json.clone();
    named.extend(["--surface", "clay"]);
    assert_eq!(json(&named)["surface"]["name"], "clay-calibrated");
}

#[test]
fn a_calibrated_court_returns_its_e_at_every_reachable_value() {
    for (mu, e) in [(0.5, 0.6), (0.75, 0.78), (0.3, 0.84)] {
        let (mu_s, e_s) = (mu.to_string(), e.to_string());
        let c = json(&argv_with(
            "court --preset tennis --friction {} --surface-cor {} --format json",
            &[&mu_s, &e_s],
        ));
        let got = f(&c, "cor_normal");
        assert!((got - e).abs() < 0.002, "({mu}, {e}): e {got}");
        let cal = &c["calibration"];
        assert!((f(cal, "cor") - got).abs() < 1e-12);
        assert!((f(&c, "cpr") - cpr(f(&c, "apparent_friction"), got)).abs() < 1e-9);
    }
    // a court that moves (0.5 kg under the ball) is calibrated as it moves: it carries energy
    // off, so its reach is lower (0.394–0.671 at K_s = K_p)
    let c = json(&argv(
        "court --preset tennis --friction 0.6 --surface-mass 0.5 --surface-cor 0.6 --format json",
    ));
    assert!(
        (f(&c, "cor_normal") - 0.6).abs() < 0.002,
        "{}",
        f(&c, "cor_normal")
    );
    assert_eq!(f(&c["surface"], "mass"), 0.5);
}

#[test]
fn an_e_out_of_reach_says_the_range() {
    let o = bl(&argv(
        "court --preset tennis --friction 0.6 --surface-cor 0.95",
    ));
    assert_bad(&o, &["invalid surface_cor: 0.95", "reaches 0.55", "0.848"]);
    let o = bl(&["court", "--preset", "tennis", "--surface", "clay"]);
    assert_bad(&o, &["the surface clay gives no μ", "--friction"]);
}

/// Bounces the model makes on a known court (K_s = K_p, c_s = 20 kg/s, μ = 0.55), read back by
/// `court --fit`: the calibration recovers c_s and e.
#[test]
fn court_fit_recovers_a_known_court_from_its_bounces() {
    let dir = tempfile::tempdir().unwrap();
    // the calibration holds K_s at the ball's K_p (docs/surfaces.md §4): the court is made so
    let ball = json(&["run", "--preset", "tennis", "--format", "json"]);
    let k_s = format!("{}", f(&ball["ball"], "k_p"));
    let mut csv = String::from("v_in,angle_in,v_out,angle_out\n");
    for (v, a) in [(29.0, 15.0), (30.0, 16.0), (31.0, 17.0)] {
        let (v_s, a_s) = (format!("{v}"), format!("{a}"));
        let r = json(&argv_with(
            "oblique --preset tennis --v0 {} --angle {} --friction 0.55 --surface-stiffness {} \
             --surface-damping 20 --format json",
            &[&v_s, &a_s, &k_s],
        ));
        csv.push_str(&format!(
            "{v},{a},{},{}\n",
            f(&r, "v_out"),
            f(&r, "angle_out_deg")
        ));
    }
    let file = dir.path().join("itf.csv");
    std::fs::write(&file, csv).unwrap();
    let c = json(&argv_with(
        "court --preset tennis --fit {} --format json",
        &[file.to_str().unwrap()],
    ));
    let m = &c["measured"];
    assert_eq!(m["bounces"], 3);
    assert!((f(m, "apparent_friction") - 0.55).abs() < 1e-6, "{m}");
    assert!((f(&c, "cor_normal") - f(m, "cor_normal")).abs() < 0.002);
    // the middle bounce is the ITF test itself: its e is the court's, so c_s comes back
    assert!(
        (f(&c["calibration"], "damping") - 20.0).abs() < 1.0,
        "{}",
        c["calibration"]
    );
    assert!((f(m, "cpr") - cpr(f(m, "apparent_friction"), f(m, "cor_normal"))).abs() < 1e-9);
}

/// A gripping tennis bounce with the damped tangential spring on a surface preset reaches the
/// published e_x of 0.1–0.2 over 30–75° (issue 53). c_t = 27 kg/s: the tangential dashpot's
/// critical value √(K_t m κ/(1 + κ)) is 26.8 kg/s for the tennis ball's K_t (docs/oblique.md).
#[test]
fn a_gripping_bounce_on_a_hard_court_reaches_published_e_x() {
    for angle in ["30", "45", "60", "75"] {
        let r = json(&argv_with(
            "oblique --preset tennis --surface hard-court --friction 0.6 --tangential-damping 27 \
             --angle {} --v0 25 --format json",
            &[angle],
        ));
        let ex = f(&r, "cor_tangential");
        assert!((0.1..=0.2).contains(&ex), "{angle}°: e_x {ex}");
        assert_eq!(r["surface"]["name"], "hard-court");
        assert_eq!(r["surface"]["tangential_damping"], 27.0);
    }
}

#[test]
fn oblique_at_90_degrees_is_collide_on_the_same_surface() {
    let o = json(&argv(
        "oblique --preset tennis --angle 90 --v0 20 --friction 0.6 --surface-stiffness 3e4 \
            --surface-damping 40 --format json",
    ));
    let c = json(&argv(
        "collide --preset tennis --v0 20 --target-mass inf --target-stiffness 3e4 \
            --target-damping 40 --format json",
    ));
    assert_eq!(f(&o, "cor_normal"), f(&c, "cor"));
    assert!((f(&o, "v_out") - f(&c, "ball_speed_out")).abs() < 1e-12 * 20.0);
    let s = json(&argv(
        "collide --preset tennis --v0 20 --surface-stiffness 3e4 --surface-damping 40 \
            --surface-mass inf --format json",
    ));
    assert_eq!(f(&s, "cor"), f(&c, "cor"));
}

#[test]
fn surfaces_lists_every_surface_with_its_sources() {
    let all = json(&["surfaces", "--format", "json"]);
    assert_eq!(
        names(&all),
        [
            "steel-plate",
            "concrete",
            "hard-court",
            "clay",
            "grass",
            "carpet",
            "hardwood",
            "turf"
        ]
    );
    for s in all.as_array().unwrap() {
        assert!(!s["sources"].as_array().unwrap().is_empty(), "{s}");
    }
    assert_eq!(all[0]["default"], true);
}

#[test]
fn user_surfaces_are_read_beside_user_presets_and_checked() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("bouncelab/surfaces");
    std::fs::create_dir_all(&folder).unwrap();
    std::fs::write(
        folder.join("gym.toml"),
        "name = \"gym\"\ndescription = \"a test floor\"\n[normal]\nstiffness = 3e4\n\
         damping = 40.0\n[[sources]]\nquantity = \"stiffness\"\nsource = \"a test\"\n\
         [[sources]]\nquantity = \"damping\"\nsource = \"a test\"\n",
    )
    .unwrap();
    let o = bl_in(
        dir.path(),
        &argv("collide --preset tennis --v0 20 --surface gym --format json"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["surface"]["name"], "gym");
    assert_eq!(v["target"]["stiffness"], 3e4);
    std::fs::write(
        folder.join("bad.toml"),
        "name = \"bad\"\ndescription = \"d\"\n[tangential]\nfriction = 0.4\n",
    )
    .unwrap();
    let o = bl_in(dir.path(), &["surfaces"]);
    assert_bad(&o, &["bad.toml:4:12: tangential.friction: no source"]);
    // a broken surface file stops every command that reads the surfaces, as a preset does
    std::fs::remove_file(folder.join("bad.toml")).unwrap();
    let o = bl_in(
        dir.path(),
        &argv("court --preset tennis --friction 0.5 --surface nope"),
    );
    assert_bad(&o, &["unknown surface 'nope'"]);
}

/// `run` on a surface that gives is the ball against it at rest (`collide`'s COR, peak force
/// and contact time); on the rigid plate it is today's run with the surface named.
#[test]
fn run_on_a_surface_is_collide_against_it_at_rest() {
    let r = json(&argv(
        "run --preset tennis --surface-stiffness 24713 --surface-damping 50 --format json",
    ));
    let c = json(&argv(
        "collide --preset tennis --target-mass inf --target-stiffness 24713 --target-damping 50 \
            --format json",
    ));
    for (a, b) in [
        ("cor", "cor"),
        ("max_force", "max_force"),
        ("contact_time", "contact_time"),
    ] {
        assert_eq!(f(&r, a), f(&c, b), "{a}");
    }
    assert!(
        r["comparison_withheld"]
            .as_str()
            .unwrap()
            .contains("rigid plate")
    );
    assert_eq!(
        r["surface"]["overrides"],
        serde_json::json!(["stiffness", "damping"])
    );
    let plate = json(&["run", "--preset", "tennis", "--format", "json"]);
    let concrete = json(&argv(
        "run --preset tennis --surface concrete --format json",
    ));
    assert_eq!(f(&plate, "cor"), f(&concrete, "cor"));
    assert_eq!(concrete["surface"]["name"], "concrete");
    let o = bl(&["run", "--preset", "tennis", "--surface-stiffness", "-1"]);
    assert_bad(&o, &["surface_stiffness"]);
}

/// `drop` (and its standard) on a surface that gives: each bounce is the ball against it at
/// rest; on the rigid plate nothing moves.
#[test]
fn drop_bounces_on_its_surface() {
    let give = argv("--surface-stiffness 2e5 --surface-damping 100 --format json");
    let base = ["drop", "--preset", "basketball", "--standard", "fiba"];
    let d = json(&[&base[..], &give[..]].concat());
    let plate = json(&[&base[..], &["--format", "json"][..]].concat());
    let first = &d["bounces"][0];
    let v_in = f(first, "v_in").to_string();
    let c = json(&argv_with(
        "collide --preset basketball --v0 {} --target-mass inf --target-stiffness 2e5 \
         --target-damping 100 --format json",
        &[&v_in],
    ));
    assert_eq!(f(first, "cor"), f(&c, "apparent_cor"));
    assert_eq!(f(first, "max_force"), f(&c, "max_force"));
    assert!(f(first, "cor") < f(&plate["bounces"][0], "cor"));
    // the standard judged on the same floor
    assert!(f(&d["standard"], "measured") < f(&plate["standard"], "measured"));
    assert_eq!(plate["surface"]["name"], "steel-plate");
    let concrete = json(
        &[
            &base[..],
            &["--surface", "concrete", "--format", "json"][..],
        ]
        .concat(),
    );
    assert_eq!(concrete["bounces"], plate["bounces"]);
}
