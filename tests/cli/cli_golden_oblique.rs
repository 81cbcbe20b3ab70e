//! `bouncelab oblique` and `court`'s golden cases (issue 31), in tests/cli/cli_golden.rs's manner:
//! stdout, stderr and exit code byte for byte against `tests/golden/oblique-*.txt`,
//! `court-*.txt` and `bad-oblique-*.txt`. `BOUNCELAB_BLESS=1 cargo test --test
//! cli_golden_oblique` rewrites them.

use crate::common;

const CASES: &[(&str, &str)] = &[
    (
        "oblique-text-tennis",
        "oblique --preset tennis --v0 25 --angle 16 --spin 300 --friction 0.6",
    ),
    (
        "oblique-json-superball",
        "oblique --angle 45 --spin -50 --friction 0.3 --format json",
    ),
    (
        "oblique-csv-golf",
        "oblique --preset golf --angle 30 --friction 0.2 --format csv",
    ),
    (
        "oblique-csv-history",
        "oblique --preset tennis --angle 20 --friction 0.5 --format csv --history --samples 5",
    ),
    (
        "court-json-tennis",
        "court --preset tennis --friction 0.6 --format json",
    ),
    ("court-text-tennis", "court --preset tennis --friction 0.35"),
    ("bad-oblique-angle", "oblique --angle 0 --friction 0.5"),
];

#[test]
fn oblique_and_court_print_what_they_printed_before() {
    common::golden::check_lines(CASES);
}
