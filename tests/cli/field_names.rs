//! Issue 54 item 9: the small defects — each message names what the user gave, each option
//! given is used or refused.

use crate::common;
use common::{
    argv, argv_with, assert_bad, assert_name_refused_as_invisible, bad, bad_each,
    baseball_with_fit, bl, bl_at,
};

#[test]
fn a_preset_name_with_a_filler_or_ignorable_character_is_refused() {
    // `golf` + U+115F (a Hangul filler, a letter that prints as nothing) listed as a second
    // `golf`; so would the other default-ignorable code points and fillers
    for c in [
        '\u{115F}', '\u{1160}', '\u{3164}', '\u{FFA0}', '\u{034F}', '\u{FE0F}', '\u{2800}',
    ] {
        assert_name_refused_as_invisible(c);
    }
}

#[test]
fn peers_friction_without_export_is_refused() {
    // `--format json --friction 0.5` printed the comparison and ignored the friction
    for format in ["json", "text", "csv"] {
        bad(
            &argv_with(
                "peers --preset tennis --format {} --friction 0.5",
                &[format],
            ),
            &["--friction", "--export"],
        );
    }
}

#[test]
fn a_derived_group_out_of_range_names_the_option_given() {
    // `--damping 1e-5` said "invalid zeta: 1888081…"
    bad_each(&[
        (
            "run --preset tennis --damping 1e-5",
            &["invalid damping: 1e-5", "gives zeta = "],
        ),
        (
            "run --preset tennis --k-r 1e12",
            &["invalid k_r: 1e12", "gives lambda = "],
        ),
        // the mass and K_p move ζ and K_h too: they said "invalid zeta: 2.6365755464702502e7",
        // "invalid k_h: 1.0540925533894598e16"
        (
            "run --mass 1e15",
            &["invalid mass: 1e15", "gives zeta = 2.637e7"],
        ),
        (
            "run --k-p 1e15 --v0 200",
            &["invalid k_p: 1e15", "gives k_h = 1.054e16"],
        ),
    ]);
    // `oblique --angle 1e-15` said "invalid v0: 1.2e-16"
    bad(
        &argv("oblique --preset tennis --angle 1e-15 --friction 0.5"),
        &["invalid angle: 1e-15", "normal speed"],
    );
}

#[test]
fn an_oblique_row_no_impact_runs_at_is_exit_2_at_its_cell() {
    // a v0 out of range (or a normal speed v0 sin θ below 1e-15) exited 1, "no starting
    // point gave parameters the solver answers for"
    let d = tempfile::tempdir().unwrap();
    let head = "v0,angle_deg,spin_in,vx_out,vy_out\n20,30,0,15,7\n";
    for (row, at) in [
        ("1e-20,30,0,15,7", "ob.csv:3:1: v0 1e-20"),
        ("20,1e-16,0,15,7", "ob.csv:3:4: angle_deg 1e-16"),
    ] {
        std::fs::write(
            d.path().join("ob.csv"),
            format!("{head}{row}\n25,40,0,17,10\n"),
        )
        .unwrap();
        let o = bl_at(
            d.path(),
            &["fit", "--preset", "tennis", "--oblique", "ob.csv"],
        );
        assert_bad(&o, &[at]);
    }
    // the rows themselves still fit
    let o = bl(&["run", "--preset", "tennis"]);
    assert_eq!(o.code, 0);
}

#[test]
fn vary_fit_names_the_fit_not_an_option_never_given() {
    // a [fit] covariance whose correlations no normal distribution has (ρ = 1 exactly, which
    // the table's check allows) said "invalid correlate: … weaken the correlations" to a user
    // who gave no --correlate
    let d = baseball_with_fit("mine", |_, _| "[[4e6, 2.0], [2.0, 1e-6]]".into(), 6);
    let o = bl_at(
        d.path(),
        &argv("mc --config mine.toml --vary fit --samples 10"),
    );
    assert_bad(&o, &["invalid vary fit", "[fit] covariance", "refit"]);
    assert!(!o.stderr.contains("correlate"), "{}", o.stderr);
}
