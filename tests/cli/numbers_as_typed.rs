//! Issue 54 item 7: numbers are read as typed or refused naming the flag. `mc --vary
//! k_p=1e-400` ran with a spread of 0 (its own reader, not the command line's); 1e-320, a
//! subnormal held to fewer digits than typed, was accepted by `--spin`, `--friction`,
//! `--target-speed`, `--drag-coefficient`, which have no lower bound to catch it.

use crate::common;
use common::{argv, assert_bad, bl};

#[test]
fn a_spread_that_underflows_is_refused_naming_it() {
    for spread in ["1e-400", "1e-400%", "1e-320", "1e-307%"] {
        let vary = format!("k_p={spread}");
        let o = bl(&["mc", "--vary", &vary, "--samples", "10"]);
        assert_bad(&o, &["invalid vary k_p", "too small"]);
    }
    // a correlation of 1e-400 is no 0 either
    let o = bl(&argv(
        "mc --vary k_p=5%,c=5% --correlate k_p:c=1e-400 --samples 10",
    ));
    assert_bad(&o, &["invalid correlate", "k_p:c=1e-400"]);
    // what is typed still reads: 0 and the smallest normal spreads
    for ok in ["k_p=0,c=5%", "k_p=2.3e-308,c=5%"] {
        let o = bl(&["mc", "--vary", ok, "--samples", "3", "--format", "json"]);
        assert_eq!(o.code, 0, "{ok}: {}", o.stderr);
    }
}

#[test]
fn subnormals_are_refused_by_every_flag_naming_it() {
    let cases: [(&[&str], &str); 5] = [
        (
            &argv("oblique --preset tennis --angle 30 --friction 1e-320"),
            "--friction",
        ),
        (
            &argv("oblique --preset tennis --angle 30 --friction 0.5 --spin 1e-320"),
            "--spin",
        ),
        (
            &argv("collide --preset tennis --target-mass 1 --target-speed -1e-320"),
            "--target-speed",
        ),
        (
            &["drop", "--preset", "tennis", "--drag-coefficient", "1e-320"],
            "--drag-coefficient",
        ),
        (&["run", "--preset", "golf", "--v0", "4e-310"], "--v0"),
    ];
    for (args, flag) in cases {
        assert_bad(&bl(args), &[flag, "too small"]);
    }
}

#[test]
fn samples_that_are_not_a_count_name_the_flag() {
    // item 9: `--samples -inf` was "unexpected argument '-i'"
    for n in ["-inf", "-1", "nan"] {
        assert_bad(
            &bl(&["mc", "--vary", "k_p=5%", "--samples", n]),
            &["--samples"],
        );
    }
}
