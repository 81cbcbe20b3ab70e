//! A figure of an impact past the ball's radius says so on the figure, as `run` warns of it
//! (tests/cli/answer_reach.rs): its peak indentation z_m, or its centre's peak displacement
//! α_max, past R is a note line of the subtitle (`figure::history::push_radius_note`), in
//! `figure force-time`/`force-displacement`, a figure of several balls (named) and
//! `fit --plot`. Such figures once drew the impact with no word of it.

use crate::common;

use common::room::collisions;
use common::*;
use std::path::Path;

fn svg(dir: &Path, args: &[&str]) -> String {
    let mut all = args.to_vec();
    all.extend(["--out", "f.svg", "--force"]);
    // a figure past the radius is past its ball's record too: its warning on stderr
    ok_at_calibrated(dir, &all);
    let text = std::fs::read_to_string(dir.join("f.svg")).unwrap();
    let found = collisions(&text);
    assert!(found.is_empty(), "{args:?}: {found:?}");
    text
}

/// The figure's subtitle lines as drawn (and its `<desc>`), `>` escaped.
const PAST_Z: &str = "outside the model's range: z_m 31.05 mm &gt; radius 21.55 mm";
const PAST_ALPHA: &str =
    "outside the model&apos;s range: centre&apos;s α_max 34.97 mm &gt; radius 21.55 mm";

/// `figure NAME --preset superball` (within the radius) draws no note; with golf beside it
/// and `past_flags` (what takes the superball past its radius), the note is the superball's,
/// named, `past` after its name. The figure of the two balls.
fn assert_no_note_within_and_named_past(
    dir: &Path,
    name: &str,
    past_flags: &str,
    past: &str,
) -> String {
    let s = svg(dir, &["figure", name, "--preset", "superball"]);
    assert!(!s.contains("outside the model"), "{name}: {s}");
    let line = format!("figure {name} --preset superball --preset golf {past_flags}");
    let s = svg(dir, &argv(&line));
    assert!(s.contains(&format!("superball {past}")), "{line}: {s}");
    s
}

#[test]
fn a_figure_of_an_impact_past_the_radius_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // z_m 31.05 mm at 45 m/s, as `run --v0 45` warns
    let fast = ["--preset", "superball", "--v0", "45"];
    for name in ["force-time", "force-displacement"] {
        let s = svg(d, &[&["figure", name][..], &fast].concat());
        assert!(s.contains(PAST_Z), "{name}: {s}");
    }
    // the centre's 34.97 mm, the contact's 0.13 mm
    let soft = ["--preset", "superball", "--lambda", "0.001", "--zeta", "10"];
    let s = svg(d, &[&["figure", "force-displacement"][..], &soft].concat());
    assert!(s.contains(PAST_ALPHA), "{s}");
    let s = assert_no_note_within_and_named_past(d, "force-time", "--v0 45", PAST_Z);
    assert!(!s.contains("golf outside"), "{s}");
}

/// `fit --plot` of a ball fitted at 40 and 45 m/s: the fitted superball presses 32.84 mm at
/// the fastest, as the report's warning says.
#[test]
fn a_fit_plot_past_the_radius_says_so() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("c.csv"), "v0,cor\n40,0.62\n45,0.6\n").unwrap();
    let args = argv("fit --preset superball --cor-table c.csv --free k_r");
    let report = ok_at(dir.path(), &args);
    assert!(
        report.contains(
            "the fitted ball at v0 = 45 m/s (the fastest of the data): peak indentation 32.84 mm"
        ),
        "{report}"
    );
    ok_at(dir.path(), &[&args[..], &["--plot", "p.svg"]].concat());
    let s = std::fs::read_to_string(dir.path().join("p.svg")).unwrap();
    assert!(
        s.contains("outside the model's range at v0 = 45 m/s: z_m 32.84 mm &gt; radius 21.55 mm"),
        "{s}"
    );
    // the residuals' axis description clear of their tick labels ("-0.0005")
    assert!(collisions(&s).is_empty(), "{:?}", collisions(&s));
}

/// `figure cor-velocity` up to 45 m/s: the superball's centre passes its radius from
/// 24.56 m/s (the first of the curve's speeds past it), before its indentation does, as
/// `sweep velocity` warns of each row; the default range (to z_m = 3 z_p) stays within. With
/// several balls, the note is named.
#[test]
fn a_speed_figure_past_the_radius_says_from_where() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let past = "outside the model&apos;s range from v0 = 24.56 m/s: centre&apos;s α_max 21.66 mm \
                &gt; radius 21.55 mm";
    let s = svg(d, &argv("figure cor-velocity --preset superball --to 45"));
    assert!(s.contains(past), "{s}");
    assert_no_note_within_and_named_past(d, "cor-velocity", "--to 45", past);
}
