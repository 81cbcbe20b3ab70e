//! `bouncelab map` as a user runs it: cells equal to `bouncelab run` at the same (λ, ζ), the
//! CSV columns of the issue, JSON, an SVG that parses, `--out` written whole, and bad input
//! refused with exit 2 naming the flag.

use crate::common;

use common::{argv, argv_with, bad, bl, bl_at, json, ok, ok_calibrated, parse_svg, warnings};

/// (λ, ζ, cor, force, time) of each CSV row.
fn rows(csv: &str) -> Vec<Vec<String>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').map(String::from).collect())
        .collect()
}

#[test]
fn csv_cells_are_what_run_prints() {
    let o = bl(&argv(
        "map --preset golf --v0 30 --lambda 0.2:5:3 --zeta 0.05:2:2",
    ));
    // golf's record is 1.47 m/s: the grid at 30 m/s says so once, on stderr (issue 52), and
    // that its cells are the ball at other λ and ζ (the 2026-12-07 trial)
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_eq!(o.stderr.lines().count(), 2, "{}", o.stderr);
    assert!(
        o.stderr
            .starts_with("bouncelab: warning: outside calibration: impact speed 30 m/s"),
        "{}",
        o.stderr
    );
    assert!(
        o.stderr
            .contains("the map's cells are this ball at other λ and ζ"),
        "{}",
        o.stderr
    );
    let csv = o.stdout;
    assert_eq!(
        csv.lines().next(),
        Some("lambda,zeta,cor,max_force,contact_time")
    );
    let cells = rows(&csv);
    assert_eq!(cells.len(), 6);
    for r in &cells {
        let v = json(&argv_with(
            "run --preset golf --v0 30 --lambda {} --zeta {} --format json",
            &[&r[0], &r[1]],
        ));
        for (k, key) in [(2, "cor"), (3, "max_force"), (4, "contact_time")] {
            let want = v[key].as_f64().unwrap();
            let got: f64 = r[k].parse().unwrap();
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "{key} at {r:?}: {got} vs {want}"
            );
        }
    }
    let n = ok(&argv(
        "map --normalized --zp-bar 0.5 --lambda 0.4:0.4:1 --zeta 0.3:0.3:1 --where cor>=0.5",
    ));
    assert_eq!(
        n.lines().next(),
        Some("lambda,zeta,cor,max_force_normalized,contact_time_normalized,feasible")
    );
    let r = &rows(&n)[0];
    let v = json(&argv(
        "run --normalized --zp-bar 0.5 --lambda 0.4 --zeta 0.3 --format json",
    ));
    // the map promises run's values to 1e-12 (docs/map.md), as the golf rows above: this
    // ball flattens (F̄_m = 0.70 > z̄_p), and its cell comes from the flattening closed form
    let (got, want) = (r[2].parse::<f64>().unwrap(), v["cor"].as_f64().unwrap());
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
    assert_eq!(
        r[5],
        if v["cor"].as_f64().unwrap() >= 0.5 {
            "true"
        } else {
            "false"
        }
    );
}

#[test]
fn json_and_svg() {
    let v = json(&argv(
        "map --normalized --lambda 0.1:10:5 --zeta 0.01:10:6 --where cor>=0.8 --format json",
    ));
    assert_eq!(v["rows"].as_array().unwrap().len(), 30);
    assert_eq!(v["columns"][5], "feasible");
    assert_eq!(v["iso_cor"][0]["level"], 0.8);
    assert!(!v["iso_cor"][0]["lines"].as_array().unwrap().is_empty());
    let svg = ok_calibrated(&argv(
        "map --preset superball --lambda 0.1:10:12 --zeta 0.02:2:16 --where cor>=0.7 --format svg",
    ));
    let s = parse_svg(&svg);
    for layer in [
        "cor (model)",
        "iso-lines (model)",
        "target-cor (reference)",
        "feasible-outline (reference)",
        "ball (model)",
    ] {
        assert!(
            s.series.iter().any(|x| x == layer),
            "{layer}: {:?}",
            s.series
        );
    }
    assert!(s.texts.iter().any(|t| t == "e (COR)"), "colour bar label");
    assert!(
        s.texts.iter().any(|t| t == "0.8"),
        "a numbered iso-line or bar tick"
    );
}

#[test]
fn out_is_written_whole_and_not_overwritten_without_force() {
    let dir = tempfile::tempdir().unwrap();
    let args = argv("map --normalized --lambda 1:2:2 --zeta 0.1:1:2 --out m.csv");
    assert_eq!(bl_at(dir.path(), &args).code, 0);
    let text = std::fs::read_to_string(dir.path().join("m.csv")).unwrap();
    assert_eq!(text.lines().count(), 5);
    let again = bl_at(dir.path(), &args);
    assert_eq!(again.code, 2);
    assert!(
        again.stderr.contains("exists (use --force"),
        "{}",
        again.stderr
    );
    let mut forced = args.to_vec();
    forced.push("--force");
    assert_eq!(bl_at(dir.path(), &forced).code, 0);
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "no temporary left: {names:?}");
}

#[test]
fn bad_input_is_exit_2_naming_the_flag() {
    let grid = ["--lambda", "0.1:1:3", "--zeta", "0.1:1:3"];
    let with = |extra: &[&'static str]| {
        let mut a = vec!["map", "--normalized"];
        a.extend_from_slice(&grid);
        a.extend_from_slice(extra);
        a
    };
    bad(
        &argv("map --normalized --lambda 0:1:3 --zeta 0.1:1:3"),
        &["invalid lambda: '0:1:3'", "above 0 on a log axis"],
    );
    bad(
        &argv("map --normalized --lambda 0.1:1:3 --zeta 1:0.1:3"),
        &["invalid zeta", "FROM must be below TO"],
    );
    bad(
        &argv("map --normalized --lambda 0.1:1:100000 --zeta 0.1:1:3"),
        &["invalid lambda", "N must lie in 1 … 4096"],
    );
    bad(
        &argv("map --normalized --lambda 0.1:1e9:3 --zeta 0.1:1:3"),
        &["invalid lambda", "0 … 1e6"],
    );
    bad(
        &argv("map --normalized --lambda nan:1:3 --zeta 0.1:1:3"),
        &["invalid lambda", "finite"],
    );
    bad(
        &argv("map --normalized --lambda 0.1:1 --zeta 0.1:1:3"),
        &["invalid lambda", "FROM:TO:N"],
    );
    bad(
        &argv("map --normalized --lambda 0.01:1:1000 --zeta 0.01:1:1001"),
        &["invalid grid: 1000 λ values × 1001 ζ values"],
    );
    bad(
        &argv("map --normalized --law hertz --lambda 0.01:1:200 --zeta 0.01:1:200"),
        &["too much work", "40000"],
    );
    bad(
        &with(&["--where", "cor>0.8"]),
        &["invalid where: 'cor>0.8'"],
    );
    bad(
        &with(&["--where", "cor>=0.8,speed<=3"]),
        &["invalid where: 'speed<=3'", "unknown quantity"],
    );
    bad(&with(&["--format", "png"]), &["png"]);
    bad(&with(&["--zp-bar", "-1"]), &["invalid zp_bar"]);
    bad(
        &argv("map --preset golf --normalized --lambda 1:2:2 --zeta 1:2:2"),
        &["--normalized"],
    );
    bad(
        &argv("map --zp-bar 0.5 --lambda 1:2:2 --zeta 1:2:2"),
        &["--normalized"],
    );
    bad(
        &argv("map --preset golf --v0 -3 --lambda 1:2:2 --zeta 1:2:2"),
        &["v0"],
    );
    bad(
        &argv("map --preset nope --lambda 1:2:2 --zeta 1:2:2"),
        &["nope"],
    );
    bad(&["map", "--lambda", "1:2:2"], &["--zeta"]);
}

/// A target no impact can meet (e ≤ 1, F_m > 0, t_f > 0) is bad input naming it: the map
/// once ran and marked every cell infeasible in silence.
#[test]
fn a_target_no_impact_meets_is_refused() {
    let grid = argv("map --normalized --lambda 0.1:1:3 --zeta 0.1:1:3");
    for (target, why) in [
        ("cor>=1.5", "the COR is at most 1"),
        ("cor<=-0.1", "the COR is at least 0"),
        ("max_force<=0", "the peak force is above 0"),
        ("cor>=0.5,contact_time<=-1", "the contact time is above 0"),
    ] {
        let args = [&grid[..], &["--where", target]].concat();
        bad(&args, &["invalid where", "no impact meets it", why]);
    }
    // the ends of the range are accepted (e = 1 where the dashpot is rigid, e = 0 where the
    // ball does not leave): a map may hold them, so this one is only warned of
    let o = bl(&[&grid[..], &["--where", "cor>=1,max_force>=0"]].concat());
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stderr.contains("warning: no cell meets"), "{}", o.stderr);
}

/// Targets no cell of the map meets are warned of — each constraint with the cells that meet
/// it alone and its quantity's span — in the JSON's `warnings` and beside the CSV on stderr;
/// a map with a feasible cell says nothing.
#[test]
fn targets_no_cell_meets_are_warned_of() {
    let grid = argv("map --preset tennis --lambda 0.1:10:6 --zeta 0.01:1:5");
    let unmet = [&grid[..], &["--where", "cor>=0.96,max_force<=250"]].concat();
    let o = bl(&unmet);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let line = "bouncelab: warning: no cell meets the targets 'cor>=0.96,max_force<=250': \
                cor>=0.96 in 9 of 30 cells (cor spans 0.2479 … 0.9883); max_force<=250 in 4 \
                of 30 cells (max_force spans 145.6 … 363.8)";
    // beside it, only the calibration's word on the cells' other λ and ζ (the trial of
    // 2026-12-07, tests/cli/cli_runout_trial.rs)
    let calibration = |w: &&str| w.contains("outside calibration:");
    let said: Vec<&str> = o.stderr.lines().filter(|w| !calibration(w)).collect();
    assert_eq!(said, [line], "{}", o.stderr);
    let doc = json(&[&unmet[..], &["--format", "json"]].concat());
    let mut said = warnings(&doc);
    said.retain(|w| !calibration(w));
    assert_eq!(said.len(), 1);
    assert_eq!(said[0], line.trim_start_matches("bouncelab: warning: "));
    assert!(
        doc["rows"]
            .as_array()
            .unwrap()
            .iter()
            .all(|r| r[5] == false)
    );
    // the numbers the warning gives are the map's own: its largest COR is the span's end
    let cor = |r: &serde_json::Value| r[2].as_f64().unwrap();
    let top = doc["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(cor)
        .fold(0.0, f64::max);
    assert_eq!(format!("{top:.4}"), "0.9883");
    // met somewhere: nothing to say
    let met = [&grid[..], &["--where", "cor>=0.9,max_force<=330"]].concat();
    let doc = json(&[&met[..], &["--format", "json"]].concat());
    let mut said = warnings(&doc);
    said.retain(|w| !calibration(w));
    assert!(said.is_empty(), "{said:?}");
}
