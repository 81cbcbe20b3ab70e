//! Every format names the ball, its surface and conditions and warns outside them (docs/
//! guarantees.md; docs/cli.md "Conditions", "The ball object"): the formats a newcomer's trial
//! found losing a warning or a name. A batch's CSV lost the lot's warning; `figure` never
//! warned and subtitled a changed ball as the preset's; `fit`'s text showed no conditions,
//! called K_r at other conditions the preset's, and held the record's parameters at any speed
//! without a word; the SVGs of `map`, `mc` and `shot` named no override, condition or surface.
//! (A shot's trajectory CSV: tests/cli/cli_shot_net.rs.)

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

/// `fit`'s text shows the conditions as `run`'s header does (a single COR, drop tests, a COR
/// table; given or recorded), names the K_r it started from for what it is (41 402 N/m is
/// the football's at 0.6 bar, its preset's 55 202 at 0.8 bar), and warns of the record
/// its held parameters come from as `run` warns of the ball.
#[test]
fn a_fit_shows_its_conditions_and_the_k_r_it_started_from() {
    let dir = tempfile::tempdir().unwrap();
    let drops = dir.path().join("d.csv");
    std::fs::write(&drops, "drop_height_m,rebound_height_m\n2,1.5\n").unwrap();
    let table = dir.path().join("t.csv");
    std::fs::write(&table, "v0,cor\n5,0.87\n6,0.86\n7,0.85\n").unwrap();
    let (drops, table) = (drops.display().to_string(), table.display().to_string());
    let ball = "--preset football --pressure 0.6bar";
    let header = "conditions: 20 °C, gauge 60 kPa (0.6 bar, 8.702 psi), atmosphere 101.3 kPa";
    let run = common::ok_calibrated(&argv(&format!("run {ball}")));
    assert!(run.lines().any(|l| l == header));
    for (data, path) in [
        ("--cor 0.85", ""),
        ("--drop-test {}", &*drops),
        ("--cor-table {}", &*table),
    ] {
        let line = format!("fit {ball} {data}");
        let values: Vec<&str> = [path].into_iter().filter(|p| !p.is_empty()).collect();
        let o = bl(&argv_with(&line, &values));
        assert_eq!(o.code, 0, "{line}: {}", o.stderr);
        // the header: the ball, its surface (the rigid plate the data are read on), then
        // the conditions (output::ball_lines)
        let lines: Vec<&str> = o.stdout.lines().take(3).collect();
        assert!(
            lines[1].starts_with("surface steel-plate"),
            "{line}: {}",
            o.stdout
        );
        assert_eq!(lines[2], header, "{line}: {}", o.stdout);
        let warned = o.stdout.lines().filter(|l| {
            l.starts_with("warning: outside calibration: the ball at 20 °C, 60 kPa gauge")
        });
        assert_eq!(warned.count(), 1, "{line}: {}", o.stdout);
    }
    let text = common::ok_calibrated(&argv(&format!("fit {ball} --cor 0.85")));
    let row = |label: &str| {
        text.lines()
            .find_map(|l| l.trim().strip_prefix(label).map(str::trim))
            .unwrap_or_else(|| panic!("no {label}: {text}"))
            .to_string()
    };
    assert_eq!(row("K_r at these conditions"), "41402 N/m (λ = 1.0000)");
    assert_eq!(
        row("preset's K_r at its record's conditions"),
        "55202 N/m (λ = 1.0000)"
    );
    assert!(!text.contains("preset's K_r  "), "{text}");
    let squash = common::ok_calibrated(&argv("fit --preset squash --cor 0.4 --temperature 23"));
    assert_eq!(
        squash.lines().nth(2),
        Some("conditions: 23 °C, solid ball, atmosphere 101.3 kPa")
    );
}

/// `fit --cor 0.6 --v0 60` holds K_p, c and z_p from a record taken at 6.906 m/s: `run`'s
/// warning at 60 m/s, after the fitted ball's radius warning (it gave the radius alone).
#[test]
fn a_fit_at_another_speed_warns_of_the_record_it_holds() {
    let line = "fit --preset tennis --cor 0.6 --v0 60 --format json";
    let v = common::json(&argv(line));
    let want = run_calibration("run --preset tennis --v0 60");
    let got: Vec<&str> = common::outside_calibration(&v);
    assert_eq!(got, want.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(
        common::warnings(&v)[0].starts_with("the fitted ball at v0 = 60 m/s: peak indentation")
    );
    // a table at other speeds, with K_p and c held: the same, over its speeds
    let dir = tempfile::tempdir().unwrap();
    let table = dir.path().join("t.csv");
    std::fs::write(&table, "v0,cor\n10,0.7\n20,0.65\n30,0.6\n").unwrap();
    let path = table.display().to_string();
    let o = bl(&argv_with(
        "fit --preset tennis --cor-table {} --format json",
        &[&path],
    ));
    let v: serde_json::Value = serde_json::from_str(&o.stdout).unwrap();
    let tennis = bouncelab::Ball::from_preset("tennis").unwrap();
    assert_eq!(
        common::outside_calibration(&v),
        [tennis.speeds_warning(10.0, 30.0).unwrap().as_str()]
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
