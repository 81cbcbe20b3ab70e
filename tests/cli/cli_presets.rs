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

#[test]
fn a_broken_user_preset_is_reported_not_skipped() {
    let home = config_home(&[("broken.toml", "name = \"x\"\n[measured\n")]);
    let o = bl_in(home.path(), &["run", "--preset", "superball"]);
    assert_bad(&o, &["broken.toml:2:10:"]);
}
