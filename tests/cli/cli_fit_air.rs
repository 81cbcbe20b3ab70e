//! A drop fit states the air it took the drops in (src/cli/fit/report.rs, `air_line`): in
//! vacuum by default, while `bouncelab drop` falls through air unless `--no-drag` — so a ball
//! fitted in vacuum and dropped in air misses its own data. The report says so, and its advice
//! holds: the same air on both sides gives back the readings.

use crate::common;

use common::{argv, argv_with, bl_in, f};
use serde_json::Value;

/// Four rebounds from the ITF's own 2.54 m (mean 1.4625 m).
const DROPS: &str = "drop_height_m,rebound_height_m\n2.54,1.44\n2.54,1.46\n2.54,1.48\n2.54,1.47\n";

fn run(dir: &std::path::Path, args: &[&str]) -> String {
    let o = bl_in(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    o.stdout
}

/// The ITF's predicted rebound of preset `name`, with `extra` arguments to `drop`.
fn itf_rebound(dir: &std::path::Path, name: &str, extra: &[&str]) -> f64 {
    let mut args = argv_with("drop --preset {} --standard itf --format json", &[name]);
    args.extend(extra);
    let v: Value = serde_json::from_str(&run(dir, &args)).unwrap();
    f(&v["standard"], "measured")
}

/// A temporary config folder holding [`DROPS`] as `drops.csv`, and that file's path.
fn with_drops() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("drops.csv");
    std::fs::write(&file, DROPS).unwrap();
    let file = file.to_str().unwrap().to_string();
    (dir, file)
}

/// `fit` of the tennis ball's K_r to the drops of `file`.
fn fit_of(file: &str) -> [&str; 7] {
    [
        "fit",
        "--preset",
        "tennis",
        "--drop-test",
        file,
        "--free",
        "k_r",
    ]
}

#[test]
fn a_drop_fit_states_its_air_and_the_same_air_gives_back_the_readings() {
    let (dir, file) = with_drops();
    let fit = fit_of(&file);

    // vacuum, the default: said in the text, `air: null` in the JSON
    let text = run(dir.path(), &fit);
    assert!(
        text.contains("drops taken in vacuum: no drag correction"),
        "{text}"
    );
    let v: Value = serde_json::from_str(&run(
        dir.path(),
        &[&fit[..], &["--format", "json"]].concat(),
    ))
    .unwrap();
    assert!(v["air"].is_null() && v.get("air").is_some(), "{v}");
    // with drag: its coefficient and density
    let drag = [&fit[..], &["--drag-coefficient", "0.47"]].concat();
    assert!(run(dir.path(), &drag).contains("drops corrected for air drag: C_d 0.47"));
    let v: Value = serde_json::from_str(&run(
        dir.path(),
        &[&drag[..], &["--format", "json"]].concat(),
    ))
    .unwrap();
    assert_eq!(
        (
            f(&v["air"], "drag_coefficient"),
            f(&v["air"], "air_density")
        ),
        (0.47, 1.204)
    );
    // a COR has no drops, and no air
    let v: Value = serde_json::from_str(&run(
        dir.path(),
        &argv("fit --preset tennis --cor 0.75 --format json"),
    ))
    .unwrap();
    assert!(v.get("air").is_none(), "{v}");

    // what the line warns of, and its advice: fitted in vacuum, the ball dropped through air
    // rebounds some 6 % lower than its own readings; in the same air on both sides the
    // readings' mean comes back (to the fit's averaging of CORs: 1e-3 m)
    run(dir.path(), &[&fit[..], &["--save", "in-vacuum"]].concat());
    run(dir.path(), &[&drag[..], &["--save", "in-air"]].concat());
    let mean = 1.4625;
    let vacuum_in_air = itf_rebound(dir.path(), "in-vacuum", &[]);
    assert!(mean - vacuum_in_air > 0.05, "{vacuum_in_air}");
    for (name, extra) in [("in-vacuum", &["--no-drag"][..]), ("in-air", &[][..])] {
        let back = itf_rebound(dir.path(), name, extra);
        assert!((back - mean).abs() < 1e-3, "{name} {extra:?}: {back}");
    }
}

/// A fitted preset keeps its drops' air (`[measured.drops]`), and `drop` warns when it falls
/// through another — naming the flags that drop it as the fit did — in text and JSON, and
/// says nothing when the airs agree; a ball fitted exactly to one drop (no `[fit]` table)
/// too.
#[test]
fn drop_warns_when_it_falls_through_another_air_than_the_fits() {
    let (dir, file) = with_drops();
    let fit = fit_of(&file);
    run(dir.path(), &[&fit[..], &["--save", "in-vacuum"]].concat());
    let in_air = [
        &fit[..],
        &["--drag-coefficient", "0.47", "--save", "in-air"],
    ]
    .concat();
    run(dir.path(), &in_air);
    let saved = std::fs::read_to_string(dir.path().join("bouncelab/presets/in-vacuum.toml"));
    let saved = saved.unwrap();
    assert!(
        saved.contains("[measured.drops]\ndrag_coefficient = 0.0 "),
        "{saved}"
    );

    let warned = |name: &str, extra: &[&str]| -> Vec<String> {
        let mut args = vec!["drop", "--preset", name, "--format", "json"];
        args.extend(extra);
        let v: Value = serde_json::from_str(&run(dir.path(), &args)).unwrap();
        let w = v["warnings"].as_array().unwrap();
        w.iter()
            .map(|x| x.as_str().unwrap().to_string())
            .filter(|x| x.contains("fitted to drops"))
            .collect()
    };
    let w = warned("in-vacuum", &[]);
    let says = |w: &[String], what: &str| w.len() == 1 && w[0].contains(what);
    assert!(
        says(&w, "taken in vacuum") && w[0].contains("--no-drag drops it"),
        "{w:?}"
    );
    let w = warned("in-air", &["--no-drag"]);
    assert!(
        says(&w, "--drag-coefficient 0.47 --air-density 1.204"),
        "{w:?}"
    );
    assert!(warned("in-vacuum", &["--no-drag"]).is_empty());
    assert!(warned("in-air", &[]).is_empty());
    let text = run(dir.path(), &["drop", "--preset", "in-vacuum"]);
    let line = "warning: this ball was fitted to drops taken in vacuum";
    assert!(text.contains(line), "{text}");
    // one drop: an exact solve, no [fit] table, the air kept all the same
    let one = argv("fit --preset tennis --drop-height 2.54 --rebound-height 1.46");
    run(dir.path(), &[&one[..], &["--save", "one-drop"]].concat());
    assert!(says(&warned("one-drop", &[]), "taken in vacuum"));
    assert!(warned("one-drop", &["--no-drag"]).is_empty());
}

/// `[measured.drops]` reads back as written, and a density that is no density is refused
/// naming the table and key (a preset file is checked where it is read).
#[test]
fn the_measured_drops_table_round_trips_and_is_checked() {
    use bouncelab::preset::Preset;
    let (dir, file) = with_drops();
    let fit = fit_of(&file);
    run(
        dir.path(),
        &[
            &fit[..],
            &["--drag-coefficient", "0.47", "--save", "in-air"],
        ]
        .concat(),
    );
    let path = dir.path().join("bouncelab/presets/in-air.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let p = Preset::parse(&text, "in-air.toml").unwrap();
    let air = p.measured.drops.unwrap();
    assert_eq!((air.drag_coefficient, air.air_density), (0.47, 1.204));
    assert_eq!(Preset::parse(&p.to_toml(&[]), "x.toml").unwrap(), p);
    let bad = text.replacen("air_density = 1.204", "air_density = -1", 1);
    let e = Preset::parse(&bad, "x.toml").unwrap_err().to_string();
    assert!(
        e.contains("measured.drops.air_density") && e.contains("positive"),
        "{e}"
    );
}
