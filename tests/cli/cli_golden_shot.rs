//! `bouncelab shot`'s golden cases (issue 57), in tests/cli/cli_golden.rs's manner: stdout,
//! stderr and exit code byte for byte against `tests/golden/shot-*.txt` and
//! `bad-shot-*.txt`. `BOUNCELAB_BLESS=1 cargo test --test cli cli_golden_shot::` rewrites them.

use crate::common;

const SERVE: &str =
    "shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 --friction 0.6";

const CASES: &[(&str, &str)] = &[
    ("shot-text-serve", SERVE),
    // a steep landing that grips (not slid throughout): the tangential dashpot changes the
    // bounce (the flag was taken and ignored before: the answer was the undamped one,
    // end x = 7.205 m)
    (
        "shot-text-grip-damped",
        "shot --preset tennis --height 2 --speed 15 --elevation -40 --friction 0.9 \
            --tangential-damping 5",
    ),
    (
        "shot-json-serve",
        "shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 --friction 0.6 \
            --format json --samples 3",
    ),
    (
        "shot-csv-baseball-bounces",
        "shot --preset baseball --height 1 --speed 40 --elevation 20 --spin -200 --friction 0.5 \
            --bounces 2 --format csv",
    ),
    (
        "shot-csv-trajectory",
        "shot --preset golf --height 0.03 --speed 60 --elevation 12 --spin -300 --friction 0.4 \
            --format csv --samples 5 --distance 150",
    ),
    (
        "bad-shot-height",
        "shot --preset tennis --height 0.01 --speed 50 --friction 0.6",
    ),
    (
        "bad-shot-drag",
        "shot --preset tennis --height 2 --speed 50 --friction 0.6 --drag-coefficient -1",
    ),
    (
        "bad-shot-time",
        "shot --preset tennis --height 2 --speed 50 --friction 0.6 --time 0",
    ),
    (
        "shot-mc-serve",
        "mc --shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 \
            --friction 0.6 --vary speed=2%,spin=30 --samples 200",
    ),
    (
        "bad-shot-mc-vary",
        "mc --shot --preset tennis --height 2.8 --speed 50 --friction 0.6 --vary k_p=5%",
    ),
    // the net (docs/flight.md §6): the serve meets it; at −5° it clears it
    (
        "shot-text-net",
        "shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 --friction 0.6 --net 11.89",
    ),
    (
        "shot-json-net",
        "shot --preset tennis --height 2.8 --speed 50 --elevation -5 --spin 200 --friction 0.6 \
            --net 11.89 --format json",
    ),
    (
        "shot-mc-net-after-bounce",
        "mc --shot --preset tennis --height 2.8 --speed 50 --elevation -5.5 --spin 200 \
            --friction 0.6 --net 11.89 --after-bounce 1 --vary speed=2%,elevation=0.5 --samples 200",
    ),
    (
        "bad-shot-endless",
        "shot --preset tennis --height 1 --speed 10 --friction 0.5 --lift-coefficient 5 \
            --drag-coefficient 0 --spin -100",
    ),
];

#[test]
fn shot_prints_what_it_printed_before() {
    common::golden::check_lines(CASES);
}

/// `--svg-out` writes the side view (valid SVG naming the path, the surface and the bounce),
/// refuses an existing file without `--force` and writes nothing then.
#[test]
fn svg_out_draws_the_side_view_once() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("serve.svg");
    let run = |extra: &[&str]| {
        let mut args = common::argv(SERVE);
        args.extend(["--svg-out", svg.to_str().unwrap()]);
        args.extend(extra);
        std::process::Command::new(env!("CARGO_BIN_EXE_bouncelab"))
            .args(&args)
            .output()
            .unwrap()
    };
    let first = run(&[]);
    assert!(first.status.success(), "{first:?}");
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    assert!(
        text.contains("path (model); bounce (model)"),
        "the legend names the series"
    );
    let again = run(&[]);
    assert_eq!(again.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&again.stderr).contains("exists (use --force"));
    assert!(again.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&svg).unwrap(), text);
    assert!(run(&["--force"]).status.success());
}

/// The defect: `shot --format json` named neither its ball nor its surface as every other
/// command on a ball and a surface does (`oblique`'s `ball` and `surface` objects; issue 57),
/// and its text did not say what it bounced on. Fails on the old code (no `ball`, no
/// `surface`, no `surface …` line).
#[test]
fn shot_names_its_ball_surface_and_conditions() {
    let mut args = common::argv(SERVE);
    args.extend(["--tangential-damping", "5", "--format", "json"]);
    let j = json_calibrated(&args);
    let ball = &j["ball"];
    assert_eq!(ball["name"], "tennis");
    assert_eq!(ball["mass"], 0.0577);
    assert_eq!(ball["radius"], j["radius"]);
    let s = &j["surface"];
    assert_eq!(s["name"], "steel-plate");
    assert!(s["stiffness"].is_null() && s["mass"].is_null());
    assert_eq!(s["friction"], 0.6);
    assert_eq!(s["tangential_damping"], 5.0);
    assert_eq!(j["conditions"]["atmosphere_pa"], 101_325.0);
    // the same objects as `oblique` gives for the first bounce's ball and surface
    let o = json_calibrated(&common::argv(
        "oblique --preset tennis --v0 30 --angle 16 --friction 0.6 --tangential-damping 5 \
         --format json",
    ));
    assert_eq!(o["ball"], j["ball"]);
    assert_eq!(o["surface"], j["surface"]);
    let text = common::ok_calibrated(&common::argv(SERVE));
    assert_eq!(
        text.lines().nth(1),
        Some("surface steel-plate (rigid, immovable, μ 0.6000)")
    );
}

fn json_calibrated(args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&common::ok_calibrated(args)).expect("one JSON object")
}

/// The defect: `mc --shot` answered without the `ball`, `surface` (and the air) every other
/// answer names (issue 52 item 3, issue 53), and its text said neither what it bounced on nor
/// the conditions. Its objects are now `shot`'s for the same flags. Fails on the old code.
#[test]
fn mc_shot_names_its_ball_surface_and_conditions() {
    let launch = "--preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 \
                  --friction 0.6 --tangential-damping 5";
    let mc = json_calibrated(&common::argv(&format!(
        "mc --shot {launch} --vary speed=2% --samples 20 --format json"
    )));
    let shot = json_calibrated(&common::argv(&format!("shot {launch} --format json")));
    for key in ["ball", "surface", "conditions", "aero"] {
        assert!(mc[key].is_object(), "{key}: {mc}");
        assert_eq!(mc[key], shot[key], "{key}");
    }
    assert_eq!(mc["surface"]["tangential_damping"], 5.0);
    assert_eq!(mc["warnings"], shot["bounces"][0]["warnings"]);
    let text = common::ok_calibrated(&common::argv(&format!(
        "mc --shot {launch} --vary speed=2% --samples 20"
    )));
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[1], "surface steel-plate (rigid, immovable, μ 0.6000)");
    assert!(lines[2].starts_with("conditions: "), "{text}");
    assert!(lines[3].starts_with("air: ρ = 1.204 kg/m³; C_D "), "{text}");
    assert!(
        text.lines()
            .last()
            .unwrap()
            .starts_with("warning: outside calibration:"),
        "{text}"
    );
}

/// `--after-bounce D` ends the shot D m past its last bounce: the coach's "where is it a
/// metre later" in one command (issue 57). The same answer, byte for byte, as `--distance`
/// at the bounce's x + D found by hand; refused by name where it means nothing. Fails on the
/// old code (no such flag).
#[test]
fn after_bounce_is_the_distance_past_the_bounce() {
    for (launch, bounces) in [(SERVE, "1"), (SERVE, "2")] {
        let mut args = common::argv(launch);
        args.extend(["--bounces", bounces, "--format", "json"]);
        let plain = json_calibrated(&args);
        let n: usize = bounces.parse().unwrap();
        let x = plain["bounces"][n - 1]["x"].as_f64().unwrap() + 1.0;
        let mut after = args.clone();
        after.extend(["--after-bounce", "1"]);
        let after = common::ok_calibrated(&after);
        let j: serde_json::Value = serde_json::from_str(&after).unwrap();
        assert_eq!(j["end"]["reason"], "distance");
        assert_eq!(j["end"]["x"].as_f64().unwrap(), x);
        assert_eq!(j["bounces"].as_array().unwrap().len(), n);
        let x = x.to_string();
        let mut by_hand = args.clone();
        by_hand.extend(["--distance", &x]);
        assert_eq!(after, common::ok_calibrated(&by_hand));
    }
    common::refused_each(
        SERVE,
        &[
            (
                "--after-bounce 1 --bounces 0",
                "invalid --after-bounce: the shot makes no bounce",
            ),
            (
                "--after-bounce 0",
                "invalid --after-bounce: 0 (must be positive)",
            ),
            ("--after-bounce 1 --time 0.2", "before its bounce 1"),
            ("--after-bounce 1 --distance 20", "cannot be used with"),
        ],
    );
}

/// The text's end line says why the shot ended as it was asked to: `--after-bounce D` ends D m
/// past the last bounce (no distance was given), `--distance` where x reaches it. Fails on the
/// old code: "end (reaches the distance)" for both.
#[test]
fn the_end_line_names_the_after_bounce() {
    let end = |extra: &str| {
        let mut args = common::argv(SERVE);
        args.extend(common::argv(extra));
        let text = common::ok_calibrated(&args);
        let line = text
            .lines()
            .find(|l| l.starts_with("end ("))
            .map(str::to_string);
        line.unwrap_or_else(|| panic!("{extra}: no end line in {text}"))
    };
    let once = end("--after-bounce 1");
    assert!(once.starts_with("end (1 m past bounce 1): "), "{once}");
    let twice = end("--bounces 2 --after-bounce 0.5");
    assert!(twice.starts_with("end (0.5 m past bounce 2): "), "{twice}");
    let at = end("--distance 20");
    assert!(at.starts_with("end (reaches the distance): "), "{at}");
}
