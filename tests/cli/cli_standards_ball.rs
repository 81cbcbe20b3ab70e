//! The newcomer trial of 2026-12-07, repeated: a standard judging another sport's ball (at
//! that standard's pressure, with no word), the batch summary's reasons and header, court's
//! measured-file errors, and small messages — each failed here on the old code.

use crate::common;
use common::{argv, bl, bl_in, config_home, json, ok, warnings};
use serde_json::Value;

/// The one warning `bat` gives (tests/cli/issue52_trial.rs), from `v`'s `warnings`.
fn not_standards(v: &Value) -> Option<String> {
    warnings(v)
        .into_iter()
        .find(|w| w.starts_with("not the standard's ball: "))
        .map(String::from)
}

/// A temp folder holding the file `name` with `text`, and the file's path.
fn file(name: &str, text: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    (dir, path.to_str().unwrap().to_string())
}

/// `v`'s `not the standard's ball` warning, which must begin with `starts`.
fn warns(v: &Value, starts: &str) -> String {
    let w = not_standards(v).unwrap_or_else(|| panic!("no warning: {v}"));
    assert!(w.starts_with(starts), "{w}");
    w
}

/// `drop --standard` of another sport's ball: judged, warned in `bat`'s words, and run at its
/// own pressure (the tennis ball was inflated to FIBA's 8 psi, 55.16 kPa, and FAILed with only
/// an `outside calibration` warning); the standard's own ball is neither warned nor changed.
#[test]
fn a_drop_standard_names_its_ball_and_keeps_another_sports_conditions() {
    let tennis = json(&argv(
        "drop --preset tennis --standard fiba --bounces 1 --format json",
    ));
    assert_eq!(
        tennis["conditions"]["pressure_gauge_pa"], 82737.09,
        "{tennis}"
    );
    let w = warns(
        &tennis,
        "not the standard's ball: the fiba test drops basketball; this is tennis: the verdict \
             judges another ball by this test, at its own conditions (an unrecorded temperature, \
             82.74 kPa gauge), not the test's",
    );
    let text = ok(&argv("drop --preset tennis --standard fiba --bounces 1"));
    assert!(text.contains("gauge 82.74 kPa"), "{text}");
    assert!(text.contains(&format!("warning: {w}")), "{text}");
    let basketball = json(&argv(
        "drop --preset basketball --standard itf --format json",
    ));
    warns(
        &basketball,
        "not the standard's ball: the itf test drops tennis; this is basketball",
    );
    let own = json(&argv(
        "drop --preset basketball --standard fiba --format json",
    ));
    assert_eq!(not_standards(&own), None, "{own}");
    // a static standard and a COR standard alike
    let squeezed = json(&argv(
        "drop --preset basketball --standard itf-deformation --format json",
    ));
    warns(
        &squeezed,
        "not the standard's ball: the itf-deformation test loads tennis; this is basketball",
    );
    let fired = json(&argv("drop --preset tennis --standard mlb --format json"));
    warns(
        &fired,
        "not the standard's ball: the mlb test fires baseball-mlb; this is tennis",
    );
}

/// A user preset copied from the standard's ball under another name is another ball, as in
/// `bat`: warned, and kept at its own conditions.
#[test]
fn a_user_copy_of_the_standards_ball_is_another_ball() {
    let tennis =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/tennis.toml"))
            .unwrap()
            .replace("name = \"tennis\"", "name = \"lot-tennis\"");
    let home = config_home(&[("lot-tennis.toml", &tennis)]);
    let o = bl_in(
        home.path(),
        &argv("drop --preset lot-tennis --standard itf --format json"),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    warns(
        &v,
        "not the standard's ball: the itf test drops tennis; this is lot-tennis",
    );
}

/// `batch --standard` judges another sport's balls with the warning; the standard's own ball
/// has none.
#[test]
fn a_batch_standard_names_its_ball() {
    let (_dir, lot) = file(
        "lot7.csv",
        "id,drop_height_m,rebound_height_m\nT01,2.54,1.41\nT02,2.54,1.43\n",
    );
    let lot = lot.as_str();
    let args = [
        "batch",
        lot,
        "--preset",
        "tennis",
        "--standard",
        "softball-47",
    ];
    let other = json(&[&args[..], &["--format", "json"]].concat());
    let w = not_standards(&other).expect("warned");
    assert_eq!(
        w,
        "not the standard's ball: the softball-47 test fires softball; this is tennis: the \
         verdict judges another ball by this test"
    );
    let text = ok(&args);
    assert!(text.contains(&format!("warning: {w}")), "{text}");
    let own = json(&["batch", lot, "--preset", "tennis", "--format", "json"]);
    assert_eq!(not_standards(&own), None, "{own}");
}

/// `court` rates a surface with the ITF's tennis ball: another ball is warned of.
#[test]
fn court_names_its_ball() {
    let other = json(&argv(
        "court --preset basketball --friction 0.5 --format json",
    ));
    let w = not_standards(&other).expect("warned");
    assert_eq!(
        w,
        "not the standard's ball: the itf-court-pace test fires tennis; this is basketball: the \
         rating judges the court with another ball"
    );
    let own = json(&argv("court --friction 0.5 --format json"));
    assert_eq!(not_standards(&own), None, "{own}");
}

/// A lot of COR tables at several speeds, two balls with too few points for `--free k_r,z_p`:
/// the summary gives their reason (not "the model cannot follow them"), the header what each
/// ball was fitted on, and no air (a COR lot has no flight).
#[test]
fn the_batch_summary_says_why_and_what_was_fitted() {
    let (_dir, cannon) = file(
        "cannon.csv",
        "id,v0,cor\nS01,15,0.52\nS01,20,0.49\nS01,26.8,0.46\nS02,15,0.51\nS02,20,0.48\n\
         S02,26.8,0.45\nS03,26.8,0.44\nS04,26.8,0.45\n",
    );
    let o = bl(&[
        "batch",
        &cannon,
        "--preset",
        "softball",
        "--standard",
        "softball-47",
        "--free",
        "k_r,z_p",
    ]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(
        o.stdout.contains(
            "4 balls from cannon.csv, fitted one by one (k_r, z_p: 2 balls; 2 without a \
             fit); judged against softball-47"
        ),
        "{}",
        o.stdout
    );
    assert!(!o.stdout.contains("in vacuum"), "{}", o.stdout);
    assert!(
        o.stdout.contains(
            "judged on their readings without a fit: 2 (fewer data points than the parameters \
             fitted; their rows say why)"
        ),
        "{}",
        o.stdout
    );
    assert!(
        o.stdout
            .contains("1 data point, fewer than the 2 parameters fitted")
    );
}

/// A measured court bounce that leaves faster than it came is refused at its file, line and
/// column, saying why (it named `--surface-cor`, a flag never given, with no place).
#[test]
fn court_fit_refuses_a_faster_rebound_at_its_row() {
    let (_dir, cbad) = file("cbad.csv", "v_in,angle_in,v_out,angle_out\n30,16,40,17.5\n");
    let o = bl(&["court", "--preset", "tennis", "--fit", &cbad]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(
        o.stderr.contains(
            "cbad.csv:2:7: the rebound is faster than the arrival: v_out sin(angle_out) = 12.03 \
             m/s up against v_in sin(angle_in) = 8.269 m/s down (e = 1.455)"
        ),
        "{}",
        o.stderr
    );
    assert!(!o.stderr.contains("surface_cor"), "{}", o.stderr);
}

/// `fit`'s refusal of data given together lists only what excludes what: a COR table and
/// drop tests fit jointly.
#[test]
fn fit_says_what_excludes_what() {
    let (_dir, table) = file("a.csv", "v0,cor\n10,0.5\n20,0.45\n");
    let table = table.as_str();
    let o = bl(&["fit", "--cor-table", table, "--cor", "0.5"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(
        o.stderr
            .contains("--cor fits alone, without --cor-table: a joint fit takes --drop-test"),
        "{}",
        o.stderr
    );
    assert!(!o.stderr.contains("exclude each other"), "{}", o.stderr);
    let o = bl(&[
        "fit",
        "--drop-test",
        table,
        "--drop-height",
        "2",
        "--rebound-height",
        "1",
    ]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(o.stderr.contains("give drop tests once"), "{}", o.stderr);
}

/// Singular where one; `bat`'s verdict names its limit as a limit.
#[test]
fn small_messages_read_right() {
    let one = ok(&argv("drop --preset tennis --bounces 1"));
    assert!(one.contains("ended: after 1 bounce (--bounces)"), "{one}");
    let fail = ok(&argv("bat --bat-mass 0.9 --bat-stiffness 1e6"));
    assert!(
        fail.contains("FAIL (BBCOR 0.6682 over the limit 0.50)"),
        "{fail}"
    );
    let pass = ok(&argv("bat --bat-mass 0.9"));
    assert!(
        pass.contains("PASS (BBCOR 0.4721 within the limit 0.50)"),
        "{pass}"
    );
}

/// A user surface reusing an embedded surface's name is called a surface.
#[test]
fn a_duplicate_surface_is_called_a_surface() {
    let home = config_home(&[]);
    let folder = home.path().join("bouncelab/surfaces");
    std::fs::create_dir_all(&folder).unwrap();
    let clay = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/presets/surfaces/clay.toml"
    ))
    .unwrap();
    std::fs::write(folder.join("g2.toml"), clay).unwrap();
    let o = bl_in(home.path(), &["surfaces"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(
        o.stderr.contains("duplicate surface name 'clay': ")
            && o.stderr
                .contains("g2.toml and the embedded surface (embedded:clay)"),
        "{}",
        o.stderr
    );
}
