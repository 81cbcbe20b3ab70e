//! Every text answer names its surface in its header, as every JSON answer does (docs/cli.md,
//! "The surface object"). A newcomer found `oblique`, `court` and `shot` printing a `surface
//! …` line while `run`, `drop`, `static`, `collide`, `bat`, `peers`, `mc` and `fit` named
//! `steel-plate` only in JSON (and `run`, `collide` a surface only when `--surface` was given,
//! below the answer). Now one line, from one function (`output::surface_line`), in the header
//! of each.

use crate::common;
use common::{argv, bl};

/// Each command, and how its surface line begins.
const ANSWERS: [(&str, &str); 16] = [
    (
        "run --preset tennis",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "run --preset tennis --surface clay",
        "surface clay (rigid, immovable)",
    ),
    (
        "drop --preset tennis --standard itf",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "static --preset tennis --load 8.165",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "collide --preset tennis --target-mass 0.3",
        "surface given-surface (rigid, M 0.3000 kg; given: target_mass)",
    ),
    (
        "collide --preset tennis --target-preset golf",
        "surface none: the ball met golf",
    ),
    (
        "bat --preset baseball-mlb --bat-mass 0.8",
        "surface bat (rigid, M 0.8000 kg; given: mass)",
    ),
    (
        "peers --preset tennis",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "peers --preset golf --pair golf",
        "surface none: the ball met golf",
    ),
    (
        "mc --preset golf --vary k_p=5% --samples 20 --seed 1",
        "surface steel-plate (rigid, immovable)",
    ),
    ("fit --cor 0.7", "surface steel-plate (rigid, immovable)"),
    (
        "fit --preset baseball --drop-height 1 --rebound-height 0.2",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "batch tests/golden/batch-lot7.csv --preset tennis",
        "surface steel-plate (rigid, immovable)",
    ),
    (
        "oblique --preset tennis --angle 30 --friction 0.5",
        "surface steel-plate (rigid, immovable, μ 0.5000)",
    ),
    (
        "court --preset tennis --friction 0.5",
        "surface steel-plate (rigid, immovable, μ 0.5000)",
    ),
    (
        "shot --preset tennis --height 1 --speed 10 --elevation -10 --friction 0.5",
        "surface steel-plate (rigid, immovable, μ 0.5000)",
    ),
];

/// The header: the lines before the first blank one (at most the first six: `oblique` and
/// `court` go on to their table without one).
fn header(text: &str) -> Vec<&str> {
    text.lines().take_while(|l| !l.is_empty()).take(6).collect()
}

/// Fails on the old code at `run --preset tennis` (no surface line) and at `run --surface
/// clay` (its line below the answer).
#[test]
fn every_text_answer_names_its_surface_in_its_header() {
    let mut missing = Vec::new();
    for (line, starts) in ANSWERS {
        let o = bl(&argv(line));
        assert!(
            o.code == 0 || line.starts_with("batch"),
            "{line}: {}",
            o.stderr
        );
        let said: Vec<&str> = (o.stdout.lines())
            .filter(|l| l.starts_with("surface "))
            .collect();
        let in_header = header(&o.stdout).iter().any(|l| l.starts_with(starts));
        if said.len() != 1 || !in_header {
            missing.push(format!("{line}: {said:?}\n{}", o.stdout));
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n\n"));
}
