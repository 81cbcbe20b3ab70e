//! Issue 52's new-user trial, repeated: the defects it found (the bat standard's ball, the
//! pair's calibration warnings, a drop on another surface than the standard's, the overrides
//! header of `oblique` and `peers`, raw floats in text) each fail here on the old code.

use crate::common;
use common::{argv, bl, json, named, ok, outside_calibration};
use serde_json::Value;

/// `bat` without `--preset` fires the BBCOR test's ball, `baseball-mlb` (the paper's
/// baseball, COR 0.485 at 85 ft/s, gave BBCOR 0.42 with any rigid bat: every bat PASSed), and
/// a trampoline bat fails with it; the paper's ball says it is not the standard's.
#[test]
fn bat_names_the_standards_ball() {
    let rigid = json(&argv("bat --bat-mass 0.6 --format json"));
    assert_eq!(rigid["ball"], "baseball-mlb");
    assert_eq!(rigid["verdict"], "PASS", "{rigid}");
    let standard = |w: &Value| w.to_string().contains("not the standard's ball");
    assert!(!standard(&rigid["warnings"]), "{}", rigid["warnings"]);
    let trampoline = json(&argv(
        "bat --bat-mass 0.9 --bat-stiffness 1e6 --format json",
    ));
    assert_eq!(trampoline["verdict"], "FAIL", "{trampoline}");
    let paper = json(&argv("bat --preset baseball --bat-mass 0.6 --format json"));
    assert!(standard(&paper["warnings"]), "{}", paper["warnings"]);
    let text = ok(&argv("bat --preset baseball --bat-mass 0.9"));
    assert!(
        text.contains("warning: not the standard's ball: the ncaa-bbcor test fires baseball-mlb; this is baseball"),
        "{text}"
    );
    let standards = json(&argv("standards --format json"));
    let bbcor = named(&standards, "ncaa-bbcor");
    assert_eq!(bbcor["balls"], serde_json::json!(["baseball-mlb"]));
}

/// The standard's ball is its preset as recorded: `baseball-mlb` with a parameter the command
/// line changed (or under another law) is another ball, and `bat` says so as for another name
/// (the name alone was checked: `--k-r 5e5` gave no warning).
#[test]
fn bat_names_the_standards_ball_unchanged() {
    let standard = |args: &str| {
        let o = bl(&argv(args));
        assert_eq!(o.code, 0, "{args}: {}", o.stderr);
        let v: Value = serde_json::from_str(&o.stdout).unwrap();
        let w = v["warnings"].as_array().expect("warnings").clone();
        w.into_iter()
            .map(|w| w.as_str().unwrap().to_string())
            .find(|w| w.starts_with("not the standard's ball"))
    };
    assert_eq!(standard("bat --bat-mass 0.6 --format json"), None);
    let stiffer = standard("bat --bat-mass 0.6 --k-r 5e5 --format json").expect("a warning");
    assert!(
        stiffer.contains("this is baseball-mlb with k_r changed"),
        "{stiffer}"
    );
    let hertz = standard("bat --bat-mass 0.6 --law hertz --format json").expect("a warning");
    assert!(
        hertz.contains("this is baseball-mlb under another law"),
        "{hertz}"
    );
}

/// `peers --pair` warns as `collide --target-preset` does: each ball at the speed it meets
/// the other (tennis 3.049 and golf 3.857 m/s at a closing speed of 6.906; 15 m/s each for
/// two tennis balls at 30), not the closing speed against one record.
#[test]
fn peers_pair_warns_as_collide_for_both_balls() {
    for (ball, partner, v0) in [("tennis", "golf", "6.906"), ("tennis", "tennis", "30")] {
        let peers = json(&[
            "peers", "--preset", ball, "--pair", partner, "--v0", v0, "--format", "json",
        ]);
        let collide = json(&[
            "collide",
            "--preset",
            ball,
            "--target-preset",
            partner,
            "--v0",
            v0,
            "--format",
            "json",
        ]);
        let expected = outside_calibration(&collide);
        assert!(!expected.is_empty(), "{ball}/{partner}: {collide}");
        assert_eq!(outside_calibration(&peers), expected, "{ball}/{partner}");
    }
    let equal = json(&argv(
        "peers --preset tennis --pair tennis --v0 30 --format json",
    ));
    let w = outside_calibration(&equal).join("\n");
    assert!(w.contains("impact speed 15 m/s"), "{w}");
    assert!(
        w.contains("the partner (tennis): impact speed 15 m/s"),
        "{w}"
    );
}

/// `oblique` and `peers` text name the overrides and what was kept from the preset, with the
/// line `run` and `drop` print.
#[test]
fn oblique_and_peers_list_the_overrides() {
    let line = "overrides: k_p; kept from the preset: mass, radius, c, k_r, z_p";
    let run = ok(&argv("run --preset tennis --k-p 60000"));
    assert!(run.contains(line), "{run}");
    for args in [
        "oblique --preset tennis --k-p 60000 --angle 30 --friction 0.5",
        "peers --preset tennis --k-p 60000",
    ] {
        let o = common::bl(&argv(args));
        assert_eq!(o.code, 0, "{args}: {}", o.stderr);
        assert!(o.stdout.contains(line), "{args}: {}", o.stdout);
    }
}

/// A drop judged against a standard on a surface that gives is the ball's there, not the
/// standard's (the ITF test is on a rigid block): it says so, naming the surface as changed;
/// on the standard's rigid plate it does not.
#[test]
fn a_drop_on_another_surface_says_so() {
    let soft = "drop --preset tennis --standard itf --surface-stiffness 30000 --surface-damping 5";
    let v = json(&argv(&format!("{soft} --format json")));
    let w = v["warnings"].to_string();
    assert!(
        w.contains("standard itf: the standard's test is on a smooth, rigid, horizontal block"),
        "{w}"
    );
    assert!(
        w.contains("this drop is on surface given-surface (K_s 30000 N/m, c_s 5.000 kg/s, immovable; given: stiffness, damping)"),
        "{w}"
    );
    let text = common::bl(&argv(soft)).stdout;
    assert!(
        text.contains("warning: standard itf: the standard's test is on"),
        "{text}"
    );
    let rigid = json(&argv("drop --preset tennis --standard itf --format json"));
    assert!(
        !rigid["warnings"]
            .to_string()
            .contains("the standard's test is on")
    );
}

/// An export's comments give numbers as the text does (v0 = 15, not 14.999999999999998), the
/// lines the code reads keep every digit; the pair export's warnings are one plain sentence
/// each and read the reach against the ball's own radius (33.5 mm), not R_eff (16.75 mm).
#[test]
fn exports_comment_in_the_house_number_format() {
    let o = common::bl(&argv(
        "peers --preset tennis --export lammps --angle 30 --v0 30",
    ));
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(!o.stdout.contains("14.99999"), "{}", o.stdout);
    assert!(o.stdout.contains("v0 = 15 m/s"), "{}", o.stdout);
    assert!(o.stdout.contains("v·sinθ = 15 m/s"), "{}", o.stdout);
    let pair = common::bl(&argv("peers --preset tennis --pair golf --export lammps"));
    assert_eq!(pair.code, 0, "{}", pair.stderr);
    assert!(!pair.stdout.contains("0.028849999"), "{}", pair.stdout);
    assert!(
        pair.stderr.contains("the preset's v0: give --v0"),
        "{}",
        pair.stderr
    );
    assert!(!pair.stderr.contains("  "), "{}", pair.stderr);
    let fast = common::bl(&argv(
        "peers --preset tennis --pair tennis --export lammps --v0 60",
    ));
    assert!(!fast.stderr.contains("16.75 mm"), "{}", fast.stderr);
    assert!(fast.stderr.contains("radius 33.50 mm"), "{}", fast.stderr);
}

/// `fit --save` of a pressurised ball keeps its gauge pressure in the saved record.
#[test]
fn fit_save_keeps_the_balls_pressure() {
    let dir = tempfile::tempdir().unwrap();
    let drops = "drop_height_m,rebound_height_m\n1.0,0.56\n2.54,1.41\n";
    std::fs::write(dir.path().join("drops.csv"), drops).unwrap();
    let o = common::bl_at(
        dir.path(),
        &argv("fit --preset tennis --drop-test drops.csv --free k_r --save mine"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let saved = dir.path().join("bouncelab/presets/mine.toml");
    let text = std::fs::read_to_string(&saved).unwrap();
    let record = &text[text.find("[calibration]").expect("a record")..];
    assert!(record.contains("pressure = 82737.09"), "{record}");
}

/// A value of the wrong type in a user preset names its field, at its line and column.
#[test]
fn a_wrong_type_names_the_field() {
    let tennis = include_str!("../../presets/tennis.toml");
    let line = tennis
        .lines()
        .find(|l| l.starts_with("speed_max"))
        .expect("speed_max");
    let bad = tennis
        .replace(line, "speed_max = \"fast\"")
        .replace("name = \"tennis\"", "name = \"fast-tennis\"");
    let home = common::config_home(&[("fast-tennis.toml", &bad)]);
    let o = common::bl_in(home.path(), &argv("run --preset fast-tennis"));
    assert_eq!(o.code, 2, "{}", o.stderr);
    let at = bad
        .lines()
        .position(|l| l.starts_with("speed_max"))
        .unwrap()
        + 1;
    assert!(
        o.stderr.contains(&format!(
            "fast-tennis.toml:{at}:13: calibration.speed_max: invalid type: string \"fast\", expected f64"
        )),
        "{}",
        o.stderr
    );
}

/// JSON names what an override kept from the preset, as the text header does.
#[test]
fn json_ball_lists_what_was_kept() {
    let v = json(&argv("run --preset tennis --k-p 60000 --format json"));
    let kept = serde_json::json!(["mass", "radius", "c", "k_r", "z_p"]);
    assert_eq!(v["ball"]["kept"], kept, "{}", v["ball"]);
    let plain = json(&argv("run --preset tennis --format json"));
    assert!(plain["ball"].get("kept").is_none(), "{}", plain["ball"]);
}
