//! `bouncelab collide`, `bat` and the bat standard in `standards` (issue 33, docs/targets.md):
//! the wall is today's `run`, the JSON keys are there and hold the kinematics of
//! docs/targets.md §3, bad input is one line naming the field, exit 2.

use crate::common;
use common::{argv, argv_with, bad, bad_each, f, json, ok, ok_calibrated};

/// M = ∞, v_t = 0, no K_s: `collide` is today's `run`, for every law.
#[test]
fn collide_on_the_wall_is_run() {
    for (preset, law, v0) in [
        ("superball", "linear", "3.12"),
        ("golf", "elastic-plastic", "6"),
        ("baseball", "hertz", "2"),
    ] {
        let common = argv_with(
            "--preset {} --law {} --v0 {} --format json",
            &[preset, law, v0],
        );
        let run = json(&[&["run"][..], &common].concat());
        let c = json(&[&["collide", "--target-mass", "inf"][..], &common].concat());
        for key in ["cor", "max_force", "contact_time", "max_indentation"] {
            let (a, b) = (f(&c, key), f(&run, key));
            assert!((a - b).abs() <= 1e-12 * b.abs(), "{preset} {key}: {a} {b}");
        }
        let v: f64 = v0.parse().unwrap();
        assert!((f(&c, "ball_speed_out") - f(&run, "cor") * v).abs() <= 1e-12 * v);
        assert_eq!(f(&c, "target_speed_out"), 0.0);
        assert_eq!(f(&c, "apparent_cor"), f(&c, "cor"));
        assert_eq!(f(&c, "reduced_mass"), f(&run, "mass"));
    }
}

/// The keys of the issue, and momentum and the separation speed from them.
#[test]
fn collide_json_holds_the_kinematics() {
    let (m_t, v_b, v_t) = (0.8, 40.0, 30.0);
    let c = json(&argv(
        "collide --preset baseball --v0 40 --target-mass 0.8 --target-speed 30 --format json",
    ));
    let m = f(&c, "ball_mass");
    let (out_b, out_t, e) = (
        f(&c, "ball_speed_out"),
        f(&c, "target_speed_out"),
        f(&c, "cor"),
    );
    let before = m * v_b - m_t * v_t;
    let after = -m * out_b - m_t * out_t;
    assert!((after - before).abs() <= 1e-12 * (m * v_b + m_t * v_t));
    assert!((out_b - out_t - e * (v_b + v_t)).abs() <= 1e-12 * (v_b + v_t));
    assert!((f(&c, "reduced_mass") - m * m_t / (m + m_t)).abs() <= 1e-15);
    for key in ["apparent_cor", "max_force", "contact_time"] {
        assert!(f(&c, key).is_finite(), "{key}");
    }
    // a compliant target: the peak deflection is reported, the exact solver ran it
    let s = json(&argv(
        "collide --preset superball --target-mass 0.3 --target-stiffness 2e4 --target-damping 3 \
            --format json",
    ));
    assert_eq!(s["method"], "exact");
    assert!(f(&s, "max_target_deflection") > 0.0);
    // ball on ball: m_eff and R_eff; equal balls leave at the same speed
    let g = json(&argv(
        "collide --preset golf --target-preset golf --target-speed 1.47 --format json",
    ));
    assert!((f(&g, "effective_mass") - 0.0228).abs() < 1e-15);
    assert!((f(&g, "effective_radius") - 0.020_75 / 2.0).abs() < 1e-15);
    assert!((f(&g, "ball_speed_out") + f(&g, "target_speed_out")).abs() < 1e-12);
}

/// The text's speeds out say the way each body goes, as the JSON's signs do: a target
/// knocked back, a receding target the ball catches, a light target the ball follows. The
/// text once printed `-1.292 m/s (in its original direction)` for a golf ball knocked back
/// by another, and `-2.479 m/s (away from the target)` for a ball that follows the target.
#[test]
fn collide_text_says_the_way_each_speed_goes() {
    let cases: [&[&str]; 3] = [
        &argv("--preset golf --target-preset golf --target-speed 1.47"),
        &argv("--preset baseball --v0 40 --target-mass 0.8 --target-speed -10"),
        &argv("--preset baseball --v0 10 --target-mass 0.05"),
    ];
    for args in cases {
        let c = json(&[&["collide"][..], args, &["--format", "json"]].concat());
        let text = ok(&[&["collide"][..], args].concat());
        let line = |label: &str| {
            let l = text.lines().find(|l| l.trim_start().starts_with(label));
            l.unwrap_or_else(|| panic!("{args:?}: no {label} line in\n{text}"))
                .to_string()
        };
        let said = [
            (
                "ball speed out",
                "ball_speed_out",
                "away from the target",
                "toward the target",
            ),
            (
                "target speed out",
                "target_speed_out",
                "toward the ball",
                "away from the ball",
            ),
        ];
        for (label, key, positive, negative) in said {
            let (l, v) = (line(label), f(&c, key));
            let way = if v < 0.0 { negative } else { positive };
            assert!(l.contains(way), "{args:?}: {key} = {v}, text {l:?}");
            let size = l.trim_start()[label.len()..].split_whitespace().next();
            let size: f64 = size.unwrap().parse().unwrap();
            assert!(
                (size - v.abs()).abs() <= 5e-4 * v.abs(),
                "{args:?}: {l:?} against {v}"
            );
        }
        let target = line("target  ");
        let toward = c["target"]["speed"].as_f64().unwrap() >= 0.0;
        let way = if toward {
            "toward the ball"
        } else {
            "away from the ball"
        };
        assert!(target.contains(way), "{args:?}: {target:?}");
    }
}

#[test]
fn bat_reports_bbs_and_the_bbcor_verdict() {
    let b = json(&["bat", "--bat-mass", "0.8", "--format", "json"]);
    // the BBCOR standard's ball (tests/cli/issue52_trial.rs, `bat_names_the_standards_ball`)
    assert_eq!(b["ball"], "baseball-mlb");
    let e_a = f(&b, "apparent_cor");
    assert!((f(&b, "bbs") - (e_a * 40.0 + (1.0 + e_a) * 30.0)).abs() < 1e-12);
    // BBCOR is the pair's COR of `collide` at 136 mph onto the bat at rest
    let c = json(&argv(
        "collide --preset baseball-mlb --v0 60.79744 --target-mass 0.8 --format json",
    ));
    assert_eq!(f(&b, "bbcor"), f(&c, "cor"));
    let pass = f(&b, "bbcor") <= 0.5;
    assert_eq!(b["verdict"], if pass { "PASS" } else { "FAIL" });
    assert!(ok(&["bat", "--bat-mass", "0.8"]).contains(if pass { "PASS" } else { "FAIL" }));
}

#[test]
fn standards_lists_the_bat_standard() {
    assert!(ok(&["standards"]).contains("ncaa-bbcor"));
    let v = json(&["standards", "--format", "json"]);
    // after the ball standards (the court pace, tests/cli/cli_oblique.rs, comes after it)
    let list = v.as_array().unwrap();
    let last = list[bouncelab::drop::standards::STANDARDS.len()].clone();
    assert_eq!(last["name"], "ncaa-bbcor");
    assert_eq!(last["test"]["kind"], "bbcor");
    assert_eq!(last["test"]["speed"], 60.79744);
    assert_eq!(last["window"], serde_json::json!([null, 0.5]));
}

#[test]
fn bad_targets_are_one_line_and_exit_2() {
    fn c<'a>(more: &[&'a str]) -> Vec<&'a str> {
        [&["collide", "--preset", "golf", "--v0", "3"][..], more].concat()
    }
    bad(&c(&["--target-mass", "0"]), &["invalid target_mass: 0"]);
    bad(&c(&["--target-mass", "-1"]), &["invalid target_mass: -1"]);
    bad(&c(&["--target-mass", "nan"]), &["invalid target_mass: NaN"]);
    bad(
        &c(&["--target-mass", "1", "--target-stiffness", "0"]),
        &["invalid target_stiffness: 0"],
    );
    bad(
        &c(&argv(
            "--target-mass 1 --target-stiffness 1e4 --target-damping -2",
        )),
        &["invalid target_damping: -2"],
    );
    bad(
        &c(&["--target-mass", "1", "--target-speed", "-3"]),
        &["invalid target_speed: -3", "never meet"],
    );
    bad(
        &c(&["--target-mass", "1", "--target-speed", "nan"]),
        &["target_speed"],
    );
    bad(&c(&[]), &["--target-mass"]);
}

/// `bat`'s errors name its own flags: they once named the library's target (`invalid
/// target_mass: 0` for `--bat-mass 0`), and a pitch away from the bat blamed the bat's speed
/// and `v0` (`invalid target_speed: 30 (… v0 + target_speed must be positive)`).
#[test]
fn bat_errors_name_its_flags() {
    fn b<'a>(more: &[&'a str]) -> Vec<&'a str> {
        [&["bat", "--bat-mass", "0.8"][..], more].concat()
    }
    bad_each(&[
        ("bat --bat-mass 0", &["invalid bat_mass: 0"]),
        ("bat --bat-mass -1", &["invalid bat_mass: -1"]),
    ]);
    let never = "never meet: ball_speed + bat_speed must be positive";
    bad(
        &b(&["--bat-speed", "-50"]),
        &["invalid bat_speed: -50", never],
    );
    bad(
        &b(&["--ball-speed", "-50"]),
        &["invalid ball_speed: -50", never],
    );
    bad(&b(&["--bat-speed", "nan"]), &["invalid bat_speed: NaN"]);
    bad(&b(&["--ball-speed", "inf"]), &["invalid ball_speed: inf"]);
    bad(&b(&["--bat-stiffness", "0"]), &["invalid bat_stiffness: 0"]);
    let damped = ["--bat-stiffness", "1e6", "--bat-damping", "-2"];
    bad(&b(&damped), &["invalid bat_damping: -2"]);
    // a bat swung away from the pitch: the game line says so, not "toward each other"
    let away = ok(&b(&["--bat-speed", "-5"]));
    let game = away.lines().find(|l| l.starts_with("game:")).unwrap();
    assert_eq!(
        game,
        "game: ball at 40.00 m/s toward the bat, bat at 5.000 m/s away from the ball"
    );
}

/// `peers --pair PRESET` calibrates for the pair: the reduced ball of `collide
/// --target-preset` (m_eff, R_eff, the partner at rest), and its COR as the target.
#[test]
fn peers_pair_calibrates_for_the_pair() {
    let p = json(&argv("peers --preset golf --pair tennis --format json"));
    let c = json(&argv(
        "collide --preset golf --target-preset tennis --format json",
    ));
    assert_eq!(f(&p, "mass"), f(&c, "effective_mass"));
    assert_eq!(f(&p, "radius"), f(&c, "effective_radius"));
    assert_eq!(p["pair"]["preset"], "tennis");
    assert_eq!(p["target_source"], "christoforou-yigit");
    let (e_pair, e_model) = (f(&p, "target_cor"), f(&c, "cor"));
    assert!((e_pair - e_model).abs() <= 1e-12, "{e_pair} {e_model}");
    // every exact row reaches it
    for row in p["models"].as_array().unwrap() {
        if row["rule"] == "exact" {
            assert!((f(row, "cor") - e_pair).abs() < 1e-9, "{row}");
        }
    }
    // without --pair, no pair key: the output is as before
    let alone = json(&["peers", "--preset", "golf", "--format", "json"]);
    assert!(alone.get("pair").is_none());
    bad(
        &["peers", "--preset", "golf", "--pair", "cricket"],
        &["unknown preset 'cricket'"],
    );
}

/// `peers --target PRESET` (issue 33's name) is `--pair PRESET`, output for output; the COR
/// sources keep their names under `--target`, and two different partners are refused.
#[test]
fn peers_target_preset_is_the_pair() {
    // golf meets tennis at 0.82 m/s, tennis golf at 0.65: both below their records, each
    // warned of (as `collide --target-preset`)
    for format in ["json", "text", "csv"] {
        let by_pair = ok_calibrated(&argv(&format!(
            "peers --preset golf --pair tennis --format {format}"
        )));
        let by_target = ok_calibrated(&argv(&format!(
            "peers --preset golf --target tennis --format {format}"
        )));
        assert_eq!(by_pair, by_target, "{format}");
    }
    // (the closing speed given: without it a pair export warns that it holds at the preset's
    // v0, tests/cli/cli_peers_case.rs)
    let lammps = ok_calibrated(&argv(
        "peers --preset golf --pair tennis --export lammps --v0 1.47",
    ));
    let by_target = ok_calibrated(&argv(
        "peers --preset golf --target tennis --export lammps --v0 1.47",
    ));
    assert_eq!(lammps, by_target);
    let cy = json(&argv(
        "peers --preset golf --target christoforou-yigit --format json",
    ));
    assert!(cy.get("pair").is_none());
    assert_eq!(cy["target_source"], "christoforou-yigit");
    bad(
        &argv("peers --preset golf --target tennis --pair golf"),
        &["target", "two partners"],
    );
    bad(
        &["peers", "--preset", "golf", "--target", "cricket"],
        &["unknown preset 'cricket'"],
    );
}
