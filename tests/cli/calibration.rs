//! Issue 52: every preset carries its calibration record, every answer outside it says so,
//! and every JSON answer names the ball it ran (docs/presets.md, "The calibration record";
//! docs/cli.md, "The ball object").

use crate::common;
use crate::fit_common;

use bouncelab::preset::Preset;
use common::*;
use serde_json::Value;

#[test]
fn every_embedded_preset_has_a_record_that_holds_at_its_own_speed() {
    for p in Preset::embedded_all() {
        let c = p
            .calibration
            .as_ref()
            .unwrap_or_else(|| panic!("{} has no [calibration]", p.name));
        assert!(c.holds_at(p.measured.v0), "{}: {c:?}", p.name);
        assert!(!c.data.is_empty() && c.data.iter().all(|d| !d.source.is_empty()));
        // and it reads back exactly from its TOML
        let back = Preset::parse(&p.to_toml(&[]), "x.toml").unwrap();
        assert_eq!(back.calibration, p.calibration);
    }
}

#[test]
fn a_bad_record_is_named_with_file_line_and_column() {
    let text = SUPERBALL.replace("speed_max = 3.12 ", "speed_max = 1.0  ");
    let err = Preset::parse(&text, "b.toml").unwrap_err().to_string();
    let line = text
        .lines()
        .position(|l| l.starts_with("speed_max"))
        .unwrap()
        + 1;
    assert_eq!(
        err,
        format!("b.toml:{line}:1: calibration.speed_max: 1 is below speed_min 3.12")
    );
    let text = SUPERBALL.replace("speeds = [3.12]", "speeds = [-3.12]");
    let err = Preset::parse(&text, "b.toml").unwrap_err().to_string();
    assert!(
        err.contains(": calibration.data.speeds: must be a positive finite number, got -3.12"),
        "{err}"
    );
    let text = SUPERBALL.replace("source = \"Cross", "sauce = \"Cross");
    let err = Preset::parse(&text, "b.toml").unwrap_err().to_string();
    assert!(err.contains("unknown field `sauce`"), "{err}");
}

#[test]
fn presets_shows_the_records() {
    let v = json(&["presets", "--format", "json"]);
    let golf = named(&v, "golf");
    assert_eq!(f(&golf["calibration"], "speed_min"), 1.47);
    assert_eq!(f(&golf["calibration"], "speed_max"), 1.47);
    let text = ok(&["presets"]);
    assert!(text.contains("  golf: 1.47 m/s only\n"), "{text}");
    assert!(
        text.contains("  football: 6.111 m/s only, 20 °C, 80 kPa gauge\n"),
        "{text}"
    );
}

/// The paper's baseball at the MLB test speed, 85 ft/s = 25.908 m/s: outside its record.
#[test]
fn the_papers_baseball_at_the_mlb_speed_is_outside_calibration() {
    let v = json(&argv("run --preset baseball --v0 25.908 --format json"));
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 1, "{v}");
    assert!(
        w[0].starts_with(
            "outside calibration: impact speed 25.91 m/s, the ball was fitted at 1.25 m/s only"
        ),
        "{}",
        w[0]
    );
    // at its own speed: none
    let v = json(&["run", "--preset", "baseball", "--format", "json"]);
    assert!(outside_calibration(&v).is_empty(), "{v}");
    // text: a warning line
    let text = ok(&["run", "--preset", "golf", "--v0", "40"]);
    assert!(
        text.contains("warning: outside calibration: impact speed 40 m/s"),
        "{text}"
    );
}

#[test]
fn an_override_is_listed_what_was_kept_too_and_the_comparison_is_withheld() {
    let v = json(&argv("run --preset tennis --k-p 30000 --format json"));
    let ball = &v["ball"];
    assert_eq!(ball["name"], "tennis");
    assert_eq!(ball["overrides"], serde_json::json!(["k_p"]));
    assert_eq!(f(ball, "k_p"), 30000.0);
    assert_eq!(f(ball, "inertia_factor"), 0.6105);
    assert!(
        v["comparison_withheld"]
            .as_str()
            .unwrap()
            .contains("k_p changed this ball"),
        "{v}"
    );
    let w = outside_calibration(&v);
    assert!(
        w[0].starts_with("outside calibration: k_p changed the ball"),
        "{w:?}"
    );
    let text = ok(&["run", "--preset", "tennis", "--k-p", "30000"]);
    assert!(
        text.contains("overrides: k_p; kept from the preset: mass, radius, c, k_r, z_p\n"),
        "{text}"
    );
    assert!(text.contains("(measured values not compared:"), "{text}");
    // no override: an empty list, the comparison made
    let v = json(&["run", "--preset", "tennis", "--format", "json"]);
    assert_eq!(v["ball"]["overrides"], serde_json::json!([]));
    assert!(v["comparison_withheld"].is_null());
}

/// The two `outside calibration:` warnings of the golf ball's answer `v` at 40 m/s: the
/// speed's first (checked here), then the answer's own (the caller checks it).
fn speed_40_then_one(v: &Value) -> Vec<&str> {
    let w = outside_calibration(v);
    assert_eq!(w.len(), 2, "{v}");
    assert!(
        w[0].starts_with("outside calibration: impact speed 40 m/s"),
        "{}",
        w[0]
    );
    w
}

/// The warnings of every kind of answer, at a speed outside the ball's record: each begins
/// with "outside calibration:" and names the value and the range.
#[test]
fn every_answer_outside_the_record_says_so() {
    let golf_40: &[&[&str]] = &[
        &["run", "--preset", "golf", "--v0", "40"],
        &argv("oblique --preset golf --v0 40 --angle 90 --friction 0.5"),
        &argv("collide --preset golf --v0 40 --target-mass inf"),
        &argv("mc --preset golf --v0 40 --vary k_p=5% --samples 1000"),
    ];
    for args in golf_40 {
        let v = json(&[args, &["--format", "json"][..]].concat());
        let w = outside_calibration(&v);
        assert_eq!(w.len(), 1, "{args:?}: {v}");
        assert!(
            w[0].starts_with(
                "outside calibration: impact speed 40 m/s, the ball was fitted at 1.47 m/s only"
            ),
            "{args:?}: {}",
            w[0]
        );
    }
    // peers at 40 m/s: the speed, and the target COR measured at another one, both named
    let v = json(&argv("peers --preset golf --v0 40 --format json"));
    let w = speed_40_then_one(&v);
    assert_eq!(
        w[1],
        "outside calibration: the target COR 0.84 was measured at 1.47 m/s, and this \
         calibration is at impact speed 40 m/s (give --cor E for the COR at that speed)"
    );
    // a COR given is the user's, at the speed asked: no second warning
    let v = json(&argv("peers --preset golf --v0 40 --cor 0.7 --format json"));
    assert_eq!(outside_calibration(&v).len(), 1, "{v}");
    // sweep rows: each row its own
    let v = json(&argv(
        "sweep velocity --preset golf --from 1.47 --to 40 --points 2 --format json",
    ));
    let rows = v["rows"].as_array().unwrap();
    assert!(outside_calibration(&rows[0]).is_empty(), "{}", rows[0]);
    assert_eq!(outside_calibration(&rows[1]).len(), 1, "{}", rows[1]);
    // the map: once for the grid's speed, once for its cells' other λ and ζ
    let v = json(&argv(
        "map --preset golf --v0 40 --lambda 0.5:1:2 --zeta 0.05:0.1:2 --format json",
    ));
    let w = speed_40_then_one(&v);
    assert!(
        w[1].starts_with("outside calibration: lambda, zeta changed"),
        "{}",
        w[1]
    );
    assert_eq!(v["ball"]["name"], "golf");
    // a bat: the game's and the BBCOR test's closing speeds, one warning
    let v = json(&argv("bat --preset baseball --bat-mass 0.9 --format json"));
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 1, "{v}");
    assert!(
        w[0].starts_with("outside calibration: impact speeds "),
        "{}",
        w[0]
    );
    assert!(w[0].contains("fitted at 1.25 m/s only"), "{}", w[0]);
    // a drop is judged by its first impact: the ITF drop is the tennis ball's record; the
    // later bounces, slower, are named apart (cli_drop.rs)
    let v = json(&argv(
        "drop --preset tennis --height 2.54 --standard itf --format json",
    ));
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 1, "{v}");
    assert!(
        w[0].starts_with("outside calibration: bounces 2–10 of the drop"),
        "{}",
        w[0]
    );
    let o = bl(&argv("drop --preset golf --height 20 --format json"));
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    let w = outside_calibration(&v);
    assert_eq!(w.len(), 2, "{v}");
    assert!(
        w[0].starts_with("outside calibration: impact speed "),
        "{}",
        w[0]
    );
    assert!(
        w[1].starts_with("outside calibration: bounces 2–"),
        "{}",
        w[1]
    );
    // court: the normal speed of the ITF's 30 m/s at 16°
    let v = json(&argv("court --preset tennis --friction 0.6 --format json"));
    let w = outside_calibration(&v);
    assert!(
        w[0].starts_with("outside calibration: impact speed 8.269 m/s"),
        "{w:?}"
    );
}

/// `drop --standard mlb` with the paper's baseball: the verdict is the model's at 85 ft/s,
/// 20 times the speed the ball was fitted at, and says so; the JSON names the ball dropped.
#[test]
fn the_mlb_verdict_on_the_papers_baseball_warns_and_the_drop_names_its_ball() {
    let o = bl(&argv("drop --preset baseball --standard mlb --format json"));
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(v["standard"]["verdict"], "fail");
    let w = outside_calibration(&v);
    assert!(
        w.iter().any(|w| w.starts_with(
            "outside calibration: impact speed 25.91 m/s, the ball was fitted at 1.25 m/s only"
        )),
        "{w:?}"
    );
    assert_eq!(v["ball"]["name"], "baseball");
    assert_eq!(f(&v["ball"], "k_p"), 1.05e6);
    let v = json(&argv(
        "drop --preset tennis --height 2.54 --k-r 20000 --format json",
    ));
    assert_eq!(v["ball"]["overrides"], serde_json::json!(["k_r"]));
    assert!(outside_calibration(&v)[0].starts_with("outside calibration: k_r changed the ball"));
    let text = bl(&["drop", "--preset", "tennis", "--k-r", "20000"]).stdout;
    assert!(
        text.contains("\noverrides: k_r; kept from the preset: mass, radius, k_p, c, z_p\n"),
        "{text}"
    );
}

/// `fit --force-time` without `--v0` held the preset's speed: a superball trace made at twice
/// it (6.24 m/s) with K_r = 90 000 N/m gave K_r 43 k with a tight interval. Now the speed is
/// fitted too, the report says so, and the truth lies inside every interval.
#[test]
fn a_trace_without_v0_fits_its_speed() {
    use bouncelab::{Ball, SolveOptions, simulate};
    let ball = Ball::from_preset("superball").unwrap();
    let truth = bouncelab::ImpactParams {
        v0: 2.0 * ball.params.v0,
        k_r: 9e4,
        ..ball.params
    };
    let r = simulate(
        &truth,
        ball.law,
        &SolveOptions::default().with_samples(4_001),
    )
    .unwrap();
    let (h, tf) = (&r.history, r.contact_time.unwrap());
    let mut rng = fit_common::Rng::new(52);
    let mut text = String::from("time_s,force_N\n");
    let dt = 1e-5;
    for i in 0..600 {
        let t = -5e-4 + i as f64 * dt;
        let force = fit_common::force_at(h, tf, t);
        text.push_str(&format!("{t},{}\n", force + 0.5 * rng.normal()));
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("trace.csv");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let v = json(&argv_with(
        "fit --preset superball --force-time {} --format json",
        &[p],
    ));
    let inside = |name: &str, want: f64| {
        let ci = &v["fitted"][name]["ci95"];
        let (lo, hi) = (ci[0].as_f64().unwrap(), ci[1].as_f64().unwrap());
        assert!(
            lo < want && want < hi,
            "{name}: {want} not in [{lo}, {hi}]: {v}"
        );
    };
    inside("v0", truth.v0);
    inside("k_r", truth.k_r);
    inside("k_p", truth.k_p);
    inside("c", truth.damping);
    let said = v["warnings"].as_array().unwrap()[0].as_str().unwrap();
    assert!(
        said.starts_with("no --v0 given: the trace's impact speed was fitted (as --free v0)"),
        "{said}"
    );
    // with --v0 the speed is held, as before
    let v = json(&argv_with(
        "fit --preset superball --force-time {} --v0 6.24 --format json",
        &[p],
    ));
    assert!(v["fitted"]["v0"].is_null(), "{v}");
    inside_of(&v, "k_r", truth.k_r);
}

fn inside_of(v: &Value, name: &str, want: f64) {
    let ci = &v["fitted"][name]["ci95"];
    let (lo, hi) = (ci[0].as_f64().unwrap(), ci[1].as_f64().unwrap());
    assert!(lo < want && want < hi, "{name}: {want} not in [{lo}, {hi}]");
}

/// The ball object, beside the keys they had, in every JSON answer that carries it.
#[test]
fn json_answers_name_their_ball() {
    let cases: &[&[&str]] = &[
        &["run", "--preset", "golf", "--k-r", "5e5"],
        &["drop", "--preset", "golf", "--k-r", "5e5"],
        &argv("sweep velocity --preset golf --k-r 5e5 --points 2"),
        &argv("oblique --preset golf --k-r 5e5 --angle 40 --friction 0.3"),
        &["peers", "--preset", "golf", "--k-r", "5e5"],
    ];
    for args in cases {
        let v = json(&[args, &["--format", "json"][..]].concat());
        let ball = &v["ball"];
        assert_eq!(ball["name"], "golf", "{args:?}: {v}");
        assert_eq!(f(ball, "k_r"), 5e5, "{args:?}");
        assert_eq!(f(ball, "k_p"), 5.6e5, "{args:?}");
        assert_eq!(ball["overrides"], serde_json::json!(["k_r"]), "{args:?}");
        assert_eq!(ball["law"], "linear", "{args:?}");
        assert!(f(ball, "inertia_factor") == 0.4, "{args:?}");
    }
}

/// `fit --save` writes the record of the data it fitted: their speeds, heights and source,
/// and the saved ball warns outside them.
#[test]
fn fit_save_writes_the_record_of_its_data() {
    let home = tempfile::tempdir().unwrap();
    let o = bl_in(
        home.path(),
        &argv("fit --preset tennis --drop-height 2.54 --rebound-height 1.41 --save mine"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let path = home.path().join("bouncelab/presets/mine.toml");
    let p = Preset::parse(&std::fs::read_to_string(&path).unwrap(), "mine.toml").unwrap();
    let c = p.calibration.expect("a [calibration] record");
    assert_eq!(c.data.len(), 1);
    assert_eq!(c.data[0].heights, [2.54]);
    assert_eq!(c.data[0].quantities, "drop test");
    assert!(
        c.data[0].source.contains("given on the command line"),
        "{:?}",
        c.data[0]
    );
    // in vacuum (the fit's default) a 2.54 m drop meets the plate at √(2 g h)
    let v = (2.0 * 9.80665 * 2.54f64).sqrt();
    assert!(
        (c.speed_min - v).abs() < 1e-9 && c.speed_max == c.speed_min,
        "{c:?}"
    );
    assert_eq!(p.measured.v0, c.speed_min);
    let o = bl_in(
        home.path(),
        &["run", "--preset", "mine", "--format", "json"],
    );
    let run: Value = serde_json::from_str(&o.stdout).unwrap();
    assert!(outside_calibration(&run).is_empty(), "{run}");
    let o = bl_in(
        home.path(),
        &["run", "--preset", "mine", "--v0", "20", "--format", "json"],
    );
    let run: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(outside_calibration(&run).len(), 1, "{run}");
}

/// Issue 52 item 3, the rest: `collide`, `bat` (as `ball_record`: their `ball` is the preset's
/// name, a string, kept), `court`, `mc`, `fit` and `static` name their ball too, and their
/// text headers list the overrides.
#[test]
fn the_other_answers_name_their_ball_too() {
    let check = |args: &[&str], key: &str| {
        let v = json(&[args, &["--format", "json"][..]].concat());
        let ball = &v[key];
        assert_eq!(ball["name"], "golf", "{args:?}: {v}");
        assert_eq!(f(ball, "c"), 1000.0, "{args:?}");
        assert_eq!(f(ball, "k_p"), 5.6e5, "{args:?}");
        assert_eq!(ball["overrides"], serde_json::json!(["c"]), "{args:?}");
        v
    };
    let golf = ["--preset", "golf", "--damping", "1000"];
    let collide = [&["collide"][..], &golf, &["--target-mass", "0.2"]].concat();
    assert_eq!(check(&collide, "ball_record")["ball"], "golf");
    let bat = [&["bat"][..], &golf, &["--bat-mass", "0.6"]].concat();
    assert_eq!(check(&bat, "ball_record")["ball"], "golf");
    let court = [&["court"][..], &golf, &["--friction", "0.3"]].concat();
    check(&court, "ball");
    let mc = [
        &["mc"][..],
        &golf,
        &["--vary", "k_p=5%", "--samples", "20", "--seed", "1"],
    ]
    .concat();
    check(&mc, "ball");
    let fit = [&["fit"][..], &golf, &["--cor", "0.8"]].concat();
    check(&fit, "ball");
    let stat = [&["static"][..], &golf, &["--load", "1"]].concat();
    check(&stat, "ball");
    for args in [&collide, &bat, &court, &mc, &fit, &stat] {
        let text = ok_calibrated(args);
        assert!(
            text.contains("overrides: c; kept from the preset"),
            "{args:?}: {text}"
        );
    }
}
