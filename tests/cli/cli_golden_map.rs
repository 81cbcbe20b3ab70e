//! `bouncelab map`'s golden cases (issue 21), in tests/cli/cli_golden.rs's manner: stdout,
//! stderr, exit code and every file written, byte for byte against `tests/golden/map-*.txt`
//! and `bad-map-*.txt`. `BOUNCELAB_BLESS=1 cargo test --test cli cli_golden_map::` rewrites them.

use crate::common;

const CASES: &[(&str, &str)] = &[
    (
        "map-csv-normalized",
        "map --normalized --lambda 0.01:100:3 --zeta 0.01:100:4",
    ),
    (
        "map-csv-golf-where",
        "map --preset golf --v0 30 --lambda 0.1:10:3 --zeta 0.01:1:3 \
            --where cor>=0.8,max_force<=9000,contact_time>=0.0004",
    ),
    (
        "map-json-linear-axes",
        "map --normalized --zp-bar 0.5 --linear-axes --lambda 0:2:3 --zeta 0:1:3 --where cor>=0.5 \
            --format json",
    ),
    (
        "map-out-ep",
        "--preset superball map --law elastic-plastic --lambda 1:2:2 --zeta 0.1:1:2 \
            --out {dir}/m.csv",
    ),
    (
        "bad-map-axis",
        "map --normalized --lambda 0:1:3 --zeta 0.1:1:3",
    ),
    (
        "bad-map-where",
        "map --normalized --lambda 1:2:2 --zeta 1:2:2 --where cor>=0.8,force<=2",
    ),
];

#[test]
fn map_prints_what_it_printed_before() {
    common::golden::check_lines(CASES);
}
