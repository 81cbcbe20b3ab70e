//! User presets through the binary: the config home, `--config`, and the duplicate-name rule.

use crate::common;

use common::*;
use serde_json::Value;
use std::process::Command;

#[test]
fn user_presets_from_the_config_home() {
    let home = config_home(&[("soft.toml", &renamed("soft", "3.0e4")), ("notes.txt", "x")]);
    let o = bl_in(home.path(), &["presets"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let line = o
        .stdout
        .lines()
        .find(|l| l.starts_with("soft "))
        .expect(&o.stdout);
    assert!(
        line.contains("soft.toml") && line.contains("0.550"),
        "{line}"
    );
    let o = bl_in(
        home.path(),
        &["run", "--preset", "soft", "--format", "json"],
    );
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(f(&v, "k_r"), 3.0e4);
    let origin = v["origin"].as_str().unwrap().to_string();
    assert!(origin.ends_with("soft.toml"));
    // the same file given with --config is not a duplicate of itself
    let o = bl_in(
        home.path(),
        &["run", "--config", &origin, "--format", "csv"],
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.lines().nth(1).unwrap().starts_with("soft,"));
    // without XDG_CONFIG_HOME, ~/.config is read
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join(".config/bouncelab/presets");
    std::fs::create_dir_all(&presets).unwrap();
    std::fs::write(presets.join("h.toml"), renamed("fromhome", "1e4")).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_bouncelab"))
        .args(["presets"])
        .env_remove("XDG_CONFIG_HOME")
        .env("HOME", dir.path())
        .output()
        .unwrap();
    assert!(String::from_utf8_lossy(&o.stdout).contains("fromhome"));
    // --config adds one file, listed and runnable
    let (_d, path) = file_with(renamed("extra", "5e4").as_bytes());
    let s = ok(&["presets", "--config", &path]);
    assert!(s.contains("extra") && s.contains(&path), "{s}");
    let v = json(&["run", "--config", &path, "--format", "json"]);
    assert_eq!((v["preset"].as_str(), f(&v, "k_r")), (Some("extra"), 5e4));
    let v = json(&["--config", &path, "fit", "--cor", "0.7", "--format", "json"]);
    assert_eq!(v["preset"], "extra");
}

#[test]
fn duplicate_preset_names_are_errors_naming_both() {
    let home = config_home(&[("mine.toml", SUPERBALL)]);
    let o = bl_in(home.path(), &["presets"]);
    assert_bad(
        &o,
        &argv("duplicate 'superball' mine.toml embedded:superball"),
    );
    let home = config_home(&[
        ("a.toml", &renamed("twin", "1e4")),
        ("b.toml", &renamed("twin", "2e4")),
    ]);
    let o = bl_in(home.path(), &["run", "--preset", "twin"]);
    assert_bad(&o, &["duplicate", "'twin'", "a.toml", "b.toml"]);
    let (_d, path) = file_with(SUPERBALL.as_bytes());
    bad(
        &["run", "--config", &path],
        &["duplicate", &path, "embedded:superball"],
    );
}

/// A new user's copy of golf.toml named "golf\u115F" stopped every command (`run --preset
/// tennis`, an embedded ball, and `presets` exited 2 with the file's error): a bad file in the
/// presets folder is skipped with one warning naming file:line:column and why, and is the
/// error (exit 2) only of a command asking for it, by its `name` or its file name.
#[test]
fn a_bad_user_preset_is_skipped_unless_asked_for() {
    let golf = include_str!("../../presets/golf.toml");
    let invisible = golf.replace("name = \"golf\"", "name = \"golf\\u115F\"");
    let line = golf.lines().position(|l| l.starts_with("name = ")).unwrap() + 1;
    let fit = baseball_with_fit("wide", |_, _| "[[1e290, 0.0], [0.0, 1e-6]]".into(), 6);
    let wide = std::fs::read_to_string(fit.path().join("wide.toml")).unwrap();
    let home = config_home(&[
        ("broken.toml", "name = \"x\"\n[measured\n"),
        ("golfx.toml", &invisible),
        ("soft.toml", &renamed("soft", "3.0e4")),
        ("wide.toml", &wide),
    ]);
    for args in [&["run", "--preset", "tennis"][..], &["presets"]] {
        let o = bl_in(home.path(), args);
        assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
        let lines: Vec<&str> = o.stderr.lines().collect();
        assert_eq!(lines.len(), 3, "{args:?}: {}", o.stderr);
        assert!(lines.iter().all(|l| l.starts_with("bouncelab: warning: ")));
        assert!(lines[0].contains("broken.toml:2:10:"), "{}", lines[0]);
        let name = format!("golfx.toml:{line}:1: name: holds an invisible character, U+115F");
        assert!(lines[1].contains(&name), "{}", lines[1]);
        assert!(lines[2].contains("wide.toml:") && lines[2].contains("covariance"));
    }
    let listed = bl_in(home.path(), &["presets"]).stdout;
    assert!(
        listed.contains("soft") && !listed.contains("golfx"),
        "{listed}"
    );
    // asked for: its error, the two other bad files warned of before it
    let asked = |name: &str, needles: &[&str]| {
        let o = bl_in(home.path(), &["run", "--preset", name]);
        assert_eq!(o.code, 2, "{name}: {}", o.stderr);
        let lines: Vec<&str> = o.stderr.lines().collect();
        assert_eq!(lines.len(), 3, "{name}: {}", o.stderr);
        let warnings = lines[..2]
            .iter()
            .filter(|l| l.contains("warning: "))
            .count();
        assert_eq!(warnings, 2, "{name}: {}", o.stderr);
        assert!(lines[2].starts_with("bouncelab: error: "), "{}", lines[2]);
        assert!(needles.iter().all(|n| lines[2].contains(n)), "{}", lines[2]);
        assert!(
            !lines[..2]
                .iter()
                .any(|l| l.contains(&format!("{name}.toml")))
        );
    };
    asked("broken", &["broken.toml:2:10:"]);
    asked("wide", &["wide.toml:", "covariance"]);
    let invisible = format!("golfx.toml:{line}:1: name: holds an invisible");
    asked("golfx", &[&invisible]);
}

/// `fit --save NAME` beside a bad file of the presets folder: refused (nothing written) when the
/// file may hold NAME — its name cannot be read, or is NAME — since the save could make a
/// second preset of that name once the file is mended; saved, with the file warned of, when
/// the bad file's name is readable and another.
#[test]
fn a_save_beside_a_bad_file_that_may_hold_its_name_is_refused() {
    let home = config_home(&[("broken.toml", "name = \n")]);
    let o = bl_in(home.path(), &argv("fit --cor 0.8 --save mine"));
    assert_bad(&o, &["broken.toml:1:"]);
    let presets = home.path().join("bouncelab").join("presets");
    assert!(!presets.join("mine.toml").exists());
    let golf = include_str!("../../presets/golf.toml");
    let invisible = golf.replace("name = \"golf\"", "name = \"golf\\u115F\"");
    let home = config_home(&[("golfx.toml", &invisible)]);
    let o = bl_in(home.path(), &argv("fit --cor 0.8 --save mine"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stderr.contains("golfx.toml:"), "{}", o.stderr);
    let presets = home.path().join("bouncelab").join("presets");
    assert!(presets.join("mine.toml").exists());
}
