//! Issue 52's new-user trial, second round: `court` answering for the superball, the bat and
//! court standards "unknown" to `drop`, messages naming a field the user never gave or
//! writing 17 digits, counts in scientific notation refused as "invalid digit found in
//! string", `mc`'s "fewer points or values", `standards`' "23 ± 0 °C". Each fails on the old
//! code.

use crate::common;
use common::{argv, bad, bad_each, bl, json, named, ok};

/// `court` without `--preset` fires the ITF court pace test's ball, `tennis` (as `bat` fires
/// its standard's): it answered for the superball, with an outside-calibration warning.
#[test]
fn court_fires_the_standards_ball() {
    let o = bl(&argv("court --surface clay --friction 0.6"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stderr.is_empty(), "no warning: {}", o.stderr);
    let tennis = ok(&argv("court --preset tennis --surface clay --friction 0.6"));
    assert_eq!(o.stdout, tennis);
    let v = json(&argv("court --friction 0.6 --format json"));
    assert_eq!(v["preset"], "tennis");
    assert_eq!(v["ball"]["name"], "tennis", "{}", v["ball"]);
    assert_eq!(v["standard"], "itf-court-pace");
    // the ball `standards` names for it
    let standards = json(&argv("standards --format json"));
    let court = named(&standards, "itf-court-pace");
    assert_eq!(court["balls"][0], "tennis", "{court}");
}

/// `drop --standard ncaa-bbcor` said "unknown standard" though `standards` lists it: it names
/// the command that judges it (exit 2 still).
#[test]
fn drop_names_the_command_of_a_bat_or_court_standard() {
    bad_each(&[
        (
            "drop --standard ncaa-bbcor",
            &["standard 'ncaa-bbcor'", "judged by `bouncelab bat`"],
        ),
        (
            "drop --standard itf-court-pace",
            &["standard 'itf-court-pace'", "judged by `bouncelab court`"],
        ),
        ("drop --standard nope", &["unknown standard 'nope'"]),
    ]);
    let o = bl(&argv("drop --standard ncaa-bbcor"));
    assert!(!o.stderr.contains("unknown"), "{}", o.stderr);
}

/// Each refusal names the option the user gave, and what else is needed: `--temperature 30`
/// on the tennis ball said "invalid inflated-at: 30"; `--pressure 1e308` said "invalid k_p:
/// 2.1048670779051614e307"; `--damping 1e-5` wrote ζ to 17 digits.
#[test]
fn messages_name_the_option_given() {
    bad_each(&[
        (
            "run --preset tennis --temperature 30",
            &["invalid temperature: 30", "give --inflated-at too"],
        ),
        (
            "run --preset tennis --pressure 1e308",
            &["invalid pressure: 1e308", "gives k_p = 2.105e307"],
        ),
        (
            "run --preset tennis --damping 1e-5",
            &["invalid damping: 1e-5", "gives zeta = 2.670e6"],
        ),
    ]);
    let o = bl(&argv("run --preset tennis --temperature 30"));
    assert!(!o.stderr.contains("inflated-at:"), "{}", o.stderr);
    // the temperature with the temperature it was inflated at runs
    let o = bl(&argv(
        "run --preset tennis --temperature 30 --inflated-at 20",
    ));
    assert_eq!(o.code, 0, "{}", o.stderr);
}

/// A count is a whole number, typed plainly or in scientific notation (docs/guarantees.md runs
/// `mc --samples 1e7`): `--samples 1e2` and `-inf` said "invalid digit found in string".
#[test]
fn counts_take_scientific_notation_and_say_what_they_take() {
    let plain = ok(&argv("run --history --samples 100 --format csv"));
    let scientific = ok(&argv("run --history --samples 1e2 --format csv"));
    assert_eq!(plain, scientific);
    assert_eq!(plain.lines().count(), 101, "a header and 100 samples");
    let mc = |n: &str| json(&argv_mc(n))["samples"].clone();
    assert_eq!(mc("2e2"), mc("200"));
    for n in ["-inf", "1.5e0", "-1", "ten"] {
        bad(
            &["run", "--history", "--samples", n],
            &["--samples", "a whole number ≥ 0"],
        );
    }
    // beyond mc's work limit: refused, saying what to change
    bad(
        &argv("mc --vary k_p=5% --samples 1e8"),
        &["too much work", "ask for fewer samples"],
    );
}

fn argv_mc(n: &str) -> Vec<&str> {
    let mut v = argv("mc --vary k_p=5% --seed 1 --format json --samples");
    v.push(n);
    v
}

/// `standards` printed "23 ± 0 °C" where the source states no tolerance.
#[test]
fn standards_print_no_tolerance_where_none_is_stated() {
    let text = ok(&["standards"]);
    assert!(!text.contains("± 0 °C"), "{text}");
    assert!(text.contains("wsf-23: 23 °C, no pressure stated"), "{text}");
    assert!(text.contains("itf: 20 ± 2 °C"), "{text}");
}
