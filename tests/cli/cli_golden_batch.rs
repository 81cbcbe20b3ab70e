//! `bouncelab batch`'s output is a contract like every command's (tests/cli/cli_golden.rs): its
//! text, JSON and files byte for byte against `tests/golden/`; `BOUNCELAB_BLESS=1` rewrites
//! them. The batch read is `tests/golden/batch-lot7.csv` (T06 out of the model's reach).

use crate::common;

const CASES: &[(&str, &str)] = &[
    (
        "batch-text-tennis-itf",
        "batch tests/golden/batch-lot7.csv --preset tennis",
    ),
    (
        "batch-json-files",
        "batch tests/golden/batch-lot7.csv --preset tennis --format json \
         --csv-out {dir}/balls.csv --svg-out {dir}/rebound.svg",
    ),
];

#[test]
fn batch_outputs_match_their_golden_copies() {
    common::golden::check_lines(CASES);
}
