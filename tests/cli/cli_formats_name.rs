//! Every format names the ball, its surface and conditions and warns outside them (docs/
//! guarantees.md; docs/cli.md "Conditions", "The ball object"): the formats a newcomer's trial
//! found losing a warning or a name. A batch's CSV lost the lot's warning; `figure` never
//! warned and subtitled a changed ball as the preset's; the SVGs of `map`, `mc` and `shot`
//! named no override, condition or surface. (A shot's trajectory CSV:
//! tests/cli/cli_shot_net.rs.)

use crate::common;

use common::{argv, argv_with, bl, parse_svg};

const LOT: &str = "tests/golden/batch-lot7.csv";

/// The `bouncelab: warning: …` lines of stderr, without their prefix.
fn stderr_warnings(stderr: &str) -> Vec<&str> {
    stderr
        .lines()
        .filter_map(|l| l.strip_prefix("bouncelab: warning: "))
        .collect()
}

/// Every text of an SVG, "; " between them: a subtitle the SVG broke after a "; " reads as
/// the figure wrote it.
fn svg_text(path: &std::path::Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    parse_svg(&text).texts.join("; ")
}

/// `batch --format csv` and `--csv-out`: the lot's warning (the JSON's top-level `warnings`,
/// which belongs to no ball) on every row in `lot_warnings`, and the ball the fits start from,
/// the plate and the conditions after it, as `sweep velocity`'s CSV ends.
#[test]
fn a_batch_csv_carries_the_lot_s_warning_and_names_its_ball() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("balls.csv");
    let json = common::json(&argv_with(
        "batch {} --preset tennis --pressure 10psi --format json",
        &[LOT],
    ));
    let lot = common::warnings(&json);
    assert!(
        lot[0].starts_with(
            "outside calibration: the ball at an unrecorded temperature, 68.95 kPa gauge"
        ),
        "{lot:?}"
    );
    let line = "batch {} --preset tennis --pressure 10psi --format csv --csv-out {}";
    let path = file.display().to_string();
    let o = bl(&argv_with(line, &[LOT, &path]));
    assert_eq!(o.code, 0, "{}", o.stderr);
    for csv in [o.stdout.clone(), std::fs::read_to_string(&file).unwrap()] {
        let mut rows = csv::Reader::from_reader(csv.as_bytes());
        let head = rows.headers().unwrap().clone();
        let at = |name: &str| head.iter().position(|h| h == name).unwrap();
        assert!(head.iter().collect::<Vec<_>>().ends_with(&[
            "fit_error",
            "lot_warnings",
            "preset",
            "origin",
            "parameters",
            "law",
            "surface",
            "surface_stiffness",
            "surface_damping",
            "surface_mass",
            "temperature_c",
            "pressure_gauge_pa",
            "atmosphere_pa"
        ]));
        for row in rows.records() {
            let row = row.unwrap();
            assert_eq!(&row[at("lot_warnings")], lot.join("; "));
            assert_eq!(&row[at("preset")], "tennis");
            assert_eq!(&row[at("surface")], "steel-plate");
            let p: f64 = row[at("pressure_gauge_pa")].parse().unwrap();
            assert!((p - 68947.57).abs() < 0.01, "{p}");
        }
    }
}

/// The `outside calibration:` warnings of `run`'s JSON for the same ball and speed.
fn run_calibration(line: &str) -> Vec<String> {
    let o = bl(&argv(&format!("{line} --format json")));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    common::outside_calibration(&v)
        .into_iter()
        .map(String::from)
        .collect()
}

/// `figure force-time` of a changed golf ball at 40 m/s: `run`'s warning for that ball on
/// stderr, and a subtitle that names the K_p override, the other law and the speed against
/// the record (it read "adopted parameters, hertz law, v0 = 40 m/s" and stderr was empty).
#[test]
fn a_figure_warns_as_run_and_its_subtitle_names_what_moved() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("g1.svg");
    let ball = "--preset golf --v0 40 --k-p 1e6 --law hertz";
    let path = svg.display().to_string();
    let o = bl(&argv_with(
        &format!("figure force-time {ball} --out {{}}"),
        &[&path],
    ));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let want = run_calibration(&format!("run {ball}"));
    assert!(!want.is_empty());
    assert_eq!(stderr_warnings(&o.stderr), want);
    let text = svg_text(&svg);
    for part in [
        "adopted parameters, hertz law, v0 = 40 m/s",
        "overrides: k_p",
        "the hertz law, not the record's",
        "outside calibration: impact speed 40 m/s, the ball was fitted at 1.47 m/s only",
    ] {
        assert!(text.contains(part), "{part}: {text}");
    }
}

/// `figure cor-velocity`'s default range runs far past a record of one speed: the library's
/// warning over the speeds drawn ([`bouncelab::Ball::speeds_warning`], as `sweep velocity`
/// warns of each row), each ball's after its name when there are several; the subtitle says
/// it too.
#[test]
fn a_speed_figure_warns_over_the_speeds_it_draws() {
    let dir = tempfile::tempdir().unwrap();
    let (svg, csv) = (dir.path().join("t.svg"), dir.path().join("t.csv"));
    let (svg, csv) = (svg.display().to_string(), csv.display().to_string());
    let line = "figure cor-velocity --preset tennis --out {} --csv-out {}";
    let o = bl(&argv_with(line, &[&svg, &csv]));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let speeds: Vec<f64> = std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .filter(|l| l.starts_with("model,"))
        .map(|l| l.split(',').nth(2).unwrap().parse().unwrap())
        .collect();
    let (lo, hi) = (speeds[0], speeds[speeds.len() - 1]);
    let tennis = bouncelab::Ball::from_preset("tennis").unwrap();
    let want = tennis.speeds_warning(lo, hi).unwrap();
    assert_eq!(stderr_warnings(&o.stderr), [want.as_str()]);
    let text = svg_text(std::path::Path::new(&svg));
    assert!(
        text.contains("outside calibration: impact speeds 0.6906–"),
        "{text}"
    );
    // two balls: each one's warning, named
    let line = "figure cor-velocity --preset tennis --preset golf --out {} --force";
    let o = bl(&argv_with(line, &[&svg]));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let said = stderr_warnings(&o.stderr);
    assert_eq!(said.len(), 2, "{said:?}");
    assert!(said[0].starts_with("outside calibration: tennis: impact speeds 0.6906–"));
    assert!(said[1].starts_with("outside calibration: golf: impact speeds 0.147–"));
    // the subtitle has room for their names only (a note each overran the plot)
    let text = svg_text(std::path::Path::new(&svg));
    assert!(
        text.contains("; outside calibration: tennis, golf"),
        "{text}"
    );
}

/// The SVGs of `map`, `mc` and `shot` name what moved from the preset, its record and the
/// plate: an override, conditions, a surface (the map read "golf at v0 = 1.47 m/s").
#[test]
fn the_svgs_name_overrides_conditions_and_surface() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("f.svg");
    let path = svg.display().to_string();
    let moved = "the ball at 20 °C, 60 kPa gauge; its record at 20 °C, 80 kPa gauge";
    let axes = "--lambda 0.1:1:3 --zeta 0.1:1:3 --format svg";
    let cases: [(&str, &[&str]); 5] = [
        (
            "map --preset golf --mass 0.1 {axes}",
            &["golf at v0 = 1.47 m/s, linear law; overrides: mass"],
        ),
        ("map --preset football --pressure 0.6bar {axes}", &[moved]),
        (
            "mc --preset football --pressure 0.6bar --samples 50 --vary k_r=5%",
            &[moved],
        ),
        (
            "shot --preset tennis --height 1 --speed 20 --surface clay --friction 0.6",
            &["tennis (embedded, adopted parameters); surface clay ("],
        ),
        (
            "shot --preset football --pressure 0.6bar --mass 0.5 --height 1 --speed 20 --friction 0.5",
            &["overrides: mass", moved],
        ),
    ];
    for (line, parts) in cases {
        let line = line.replace("{axes}", axes);
        let out = if line.starts_with("map") {
            "--out"
        } else {
            "--svg-out"
        };
        let o = bl(&argv_with(&format!("{line} {out} {{}} --force"), &[&path]));
        assert_eq!(o.code, 0, "{line}: {}", o.stderr);
        let text = svg_text(&svg);
        for part in parts {
            assert!(text.contains(part), "{line}: {part}: {text}");
        }
    }
}
