//! The command line is a contract: every existing command's output (stdout, stderr, exit code
//! and every file it writes) is compared byte for byte with the copy stored under
//! `tests/golden/`. A change of output is then a deliberate act: `BOUNCELAB_BLESS=1 cargo test
//! --test cli cli_golden::` rewrites the stored copies, and the diff is reviewed like a snapshot.

use crate::common;

/// One case: a name (the stored file's stem) and the arguments. `{dir}` in an argument stands
/// for the case's own scratch folder, so files written there are collected and compared too.
const CASES: &[(&str, &str)] = &[
    ("run-text-superball", "run"),
    ("run-json-golf", "run --preset golf --format json"),
    ("run-csv-baseball", "run --preset baseball --format csv"),
    (
        "run-json-history-ep",
        "run --law elastic-plastic --v0 6 --format json --history --samples 25",
    ),
    ("run-text-hertz", "run --law hertz --v0 2"),
    ("run-text-materials", "run --preset golf --params materials"),
    (
        "run-json-normalized",
        "run --normalized --lambda 0.4 --zeta 0.3 --zp-bar 0.5 --format json",
    ),
    (
        "run-text-lambda-zeta",
        "--preset golf run --lambda 2 --zeta 0.5",
    ),
    ("sweep-zeta-csv", "sweep zeta --points 9"),
    (
        "sweep-zeta-json-ep",
        "sweep zeta --lambda 0.2,3 --points 5 --law elastic-plastic --format json",
    ),
    ("sweep-velocity-csv", "sweep velocity --points 7"),
    (
        "sweep-velocity-json-golf",
        "sweep velocity --preset golf --points 4 --format json",
    ),
    ("fit-text", "fit --cor 0.7"),
    (
        "fit-json-baseball",
        "fit --preset baseball --cor 0.5 --v0 2 --format json",
    ),
    ("presets-text", "presets"),
    ("presets-json", "presets --format json"),
    (
        "figure-cor-zeta",
        "figure cor-zeta --out {dir}/f.svg --csv-out {dir}/f.csv",
    ),
    ("figure-force-zeta", "figure force-zeta --out {dir}/f.svg"),
    (
        "figure-cor-velocity",
        "figure cor-velocity --preset golf --out {dir}/f.svg --csv-out {dir}/f.csv",
    ),
    (
        "figure-force-time",
        "figure force-time --out {dir}/f.svg --csv-out {dir}/f.csv",
    ),
    (
        "figure-force-displacement",
        "figure force-displacement --preset baseball --law elastic-plastic --out {dir}/f.svg \
         --csv-out {dir}/f.csv",
    ),
    ("reproduce", "reproduce --out {dir}/paper"),
    ("bad-lambda", "run --lambda nan"),
    ("bad-preset", "run --preset no-such-ball"),
    ("bad-fit-reach", "fit --cor 0.01"),
    ("bad-flag", "run --no-such-flag"),
    (
        "bad-figure-data-renamed",
        "figure force-time --out {dir}/f.svg --data {dir}/f.csv",
    ),
    ("bad-explorer-no-terminal", ""),
    (
        "drop-text-tennis-itf",
        "drop --preset tennis --standard itf",
    ),
    (
        "drop-json-basketball-fiba",
        "drop --preset basketball --standard fiba --bounces 2 --format json",
    ),
    ("standards-text", "standards"),
    ("bad-standard", "drop --standard wimbledon"),
    (
        "mc-text-golf",
        "mc --preset golf --vary k_p=5%,c=5%,k_r=5% --samples 200 --seed 7",
    ),
    (
        "mc-json-uniform-csv",
        "mc --preset tennis --vary k_r=10%,v0=0.02 --dist uniform --samples 12 --seed 3 \
         --format json --csv-out {dir}/samples.csv",
    ),
    ("bad-mc-vary", "mc --vary k_q=5%"),
];

#[test]
fn every_command_prints_what_it_printed_before() {
    common::golden::check_lines(CASES);
}
