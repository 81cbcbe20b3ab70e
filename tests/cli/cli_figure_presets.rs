//! `figure --preset A --preset B …`: several balls on one figure, each labelled by its name in
//! the SVG's legend and the CSV's `series` column. Only `figure` takes `--preset` twice.
//!
//! The CSV of one case is kept under `tests/golden/` like the command line's other outputs;
//! `BOUNCELAB_BLESS=1 cargo test --test cli cli_figure_presets::` rewrites it (review the diff).

use crate::common;

use common::*;
use std::path::Path;

fn figure_in(dir: &Path, name: &str, presets: &[&str], extra: &[&str]) -> (String, String) {
    let mut args = vec!["figure", name];
    for p in presets {
        args.extend(["--preset", p]);
    }
    args.extend(["--out", "f.svg", "--csv-out", "f.csv", "--force"]);
    args.extend(extra);
    ok_at_calibrated(dir, &args);
    (
        std::fs::read_to_string(dir.join("f.svg")).unwrap(),
        std::fs::read_to_string(dir.join("f.csv")).unwrap(),
    )
}

/// The CSV rows of `csv` (header left out).
fn rows(csv: &str) -> Vec<&str> {
    csv.lines().skip(1).collect()
}

#[test]
fn golden_force_time_of_two_balls() {
    let dir = tempfile::tempdir().unwrap();
    let (_, csv) = figure_in(
        dir.path(),
        "force-time",
        &["golf", "baseball"],
        &["--points", "12"],
    );
    let golden =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden/figure-force-time-presets.csv");
    if std::env::var_os("BOUNCELAB_BLESS").is_some() {
        std::fs::write(&golden, &csv).unwrap();
    }
    assert_eq!(csv, std::fs::read_to_string(&golden).unwrap());
}

/// Each ball's series are its one-ball figure's, named after it: two paths, one answer.
#[test]
fn each_ball_is_its_own_figure_labelled_by_name() {
    for name in ["force-time", "force-displacement", "cor-velocity"] {
        let dir = tempfile::tempdir().unwrap();
        let extra = ["--points", "20"];
        let (svg, csv) = figure_in(dir.path(), name, &["golf", "baseball", "superball"], &extra);
        let svg = parse_svg(&svg);
        for ball in ["golf", "baseball", "superball"] {
            let (_, one) = figure_in(dir.path(), name, &[ball], &extra);
            let prefix = format!("{ball} ");
            let mine: Vec<String> = rows(&csv)
                .into_iter()
                .filter_map(|r| r.strip_prefix(&prefix).map(String::from))
                .collect();
            assert_eq!(mine, rows(&one), "{name} {ball}");
            assert!(
                svg.texts
                    .iter()
                    .any(|t| t.starts_with(&format!("{ball}: "))),
                "{name}: the legend names {ball}: {:?}",
                svg.texts
            );
        }
        // the title names no single ball
        assert!(!svg.texts[0].ends_with(": golf"), "{}", svg.texts[0]);
    }
}

#[test]
fn a_user_preset_joins_and_its_measurements_carry_its_file_name() {
    let home = config_home(&[("mine.toml", &renamed("mine", "9e4"))]);
    let o = bl_at(
        home.path(),
        &argv("figure cor-velocity --preset golf --preset mine --out f.svg --csv-out f.csv"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let csv = std::fs::read_to_string(home.path().join("f.csv")).unwrap();
    assert!(csv.lines().any(|l| l.starts_with("golf model,")));
    assert!(csv.lines().any(|l| l.starts_with("mine model,")));
    let svg = parse_svg(&std::fs::read_to_string(home.path().join("f.svg")).unwrap());
    assert!(
        svg.texts.iter().any(|t| t == "mine: measured (mine.toml)"),
        "{:?}",
        svg.texts
    );
    assert!(svg.texts.iter().any(|t| t == "golf: measured (Cross 1999)"));
    // on the ζ figures a user's balls join the paper's three as markers
    let o = bl_at(
        home.path(),
        &argv("figure cor-zeta --preset mine --preset golf --out z.svg --csv-out z.csv --points 5"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let csv = std::fs::read_to_string(home.path().join("z.csv")).unwrap();
    for ball in ["superball", "golf", "baseball", "mine"] {
        let id = format!("measured {ball},");
        assert!(csv.lines().any(|l| l.starts_with(&id)), "{ball}\n{csv}");
    }
}

#[test]
fn repeats_are_refused_where_they_mean_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = |args: &[&str]| bl_at(dir.path(), args);
    assert_bad(
        &out(&argv(
            "figure force-time --preset golf --preset golf --out f.svg",
        )),
        &["--preset golf is given twice"],
    );
    assert_bad(
        &out(&argv(
            "figure peers-force-time --preset golf --preset baseball --out f.svg",
        )),
        &["a second --preset does not apply to peers-force-time"],
    );
    assert_bad(
        &out(&argv(
            "figure force-time --preset golf --config x.toml --out f.svg",
        )),
        &["cannot be used with"],
    );
    // before the subcommand, as for one --preset
    assert_bad(
        &out(&argv(
            "--preset golf figure force-time --preset baseball --out f.svg",
        )),
        &["--preset/--config given both before and after the subcommand"],
    );
    // the other subcommands keep one --preset
    for cmd in [
        &["run"][..],
        &["sweep", "velocity"],
        &["fit", "--cor", "0.7"],
    ] {
        let mut args = cmd.to_vec();
        args.extend(["--preset", "golf", "--preset", "baseball"]);
        assert_bad(
            &out(&args),
            &["'--preset <NAME>' cannot be used multiple times"],
        );
    }
    assert!(!dir.path().join("f.svg").exists(), "nothing written");
}

/// A preset before a subcommand that runs no chosen ball is refused, each with its reason:
/// `--normalized` (run, map) is a ball of its own, and sweep zeta, standards and surfaces take
/// no ball.
#[test]
fn a_preset_before_a_subcommand_without_a_ball_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = |args: &[&str]| bl_at(dir.path(), args);
    let normalized = "--normalized cannot be used with --preset or --config";
    for line in [
        "--preset golf run --normalized",
        "--preset golf map --normalized --lambda 0.1:1:3 --zeta 0.1:1:3",
    ] {
        assert_bad(&out(&argv(line)), &[normalized]);
    }
    for (line, why) in [
        (
            "--preset golf sweep zeta",
            "sweep zeta runs the normalized ball",
        ),
        ("--preset golf standards", "standards lists the standards"),
        ("--preset golf surfaces", "surfaces lists the surfaces"),
    ] {
        assert_bad(&out(&argv(line)), &[why]);
    }
}
