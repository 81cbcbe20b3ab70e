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
