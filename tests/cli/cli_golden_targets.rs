//! `bouncelab collide` and `bat`'s golden cases (issue 33), in tests/cli/cli_golden.rs's manner:
//! stdout, stderr and exit code byte for byte against `tests/golden/collide-*.txt`,
//! `bat-*.txt` and `bad-collide-*.txt`. `BOUNCELAB_BLESS=1 cargo test --test
//! cli_golden_targets` rewrites them.

use crate::common;

const CASES: &[(&str, &str)] = &[
    (
        "collide-text-bat",
        "collide --preset baseball --v0 40 --target-mass 0.8 --target-speed 30",
    ),
    (
        "collide-json-compliant",
        "collide --preset superball --target-mass 0.3 --target-stiffness 2e4 --target-damping 3 \
            --format json",
    ),
    (
        "collide-text-ball-on-ball",
        "collide --preset golf --target-preset golf --target-speed 1.47",
    ),
    ("bat-text", "bat --preset baseball --bat-mass 0.8"),
    (
        "bat-json",
        "bat --bat-mass 0.6 --ball-speed 35 --bat-speed 25 --format json",
    ),
    ("peers-text-pair", "peers --preset golf --pair golf"),
    (
        "bad-collide-never-meet",
        "collide --target-mass 1 --target-speed -5",
    ),
];

#[test]
fn every_command_prints_what_it_printed_before() {
    common::golden::check_lines(CASES);
}
