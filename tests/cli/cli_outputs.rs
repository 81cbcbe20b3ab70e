//! Every command's outputs are one transaction (src/cli/outputs.rs, docs/guarantees.md): the
//! targets checked before any work with one set of messages and exit codes, the files staged
//! and published together once the report is out, and none left when anything fails — a
//! preset folder that takes no file, a stdout that is full. One test per command that writes
//! files: figure, fit, map, mc, reproduce.

use crate::common;

use common::*;
use std::fs;
use std::path::Path;
use std::process::Stdio;

const COR: &str = "v0,cor\n2,0.8\n4,0.75\n6,0.7\n";

/// `bouncelab ARGS` in `dir` (also its config folder) with stdout on /dev/full.
fn to_full_stdout(dir: &Path, args: &[&str]) -> (i32, String) {
    let full = fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let o = command_in(dir, args)
        .stdout(Stdio::from(full))
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    (
        o.status.code().expect("exited"),
        String::from_utf8(o.stderr).unwrap(),
    )
}

fn presets(dir: &Path) -> std::path::PathBuf {
    dir.join("bouncelab").join("presets")
}

#[test]
fn fit_is_all_or_nothing() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    fs::write(d.join("cor.csv"), COR).unwrap();
    let fit = argv("fit --cor-table cor.csv --plot p.svg --save mine");
    // a presets folder that cannot be one (a file in its place): refused before the fit
    fs::create_dir(d.join("bouncelab")).unwrap();
    fs::write(presets(d), "").unwrap();
    let o = bl_at(d, &fit);
    assert_ne!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.is_empty(), "no report: {}", o.stdout);
    assert_eq!(folder_names(d), ["bouncelab", "cor.csv"], "{}", o.stderr);
    fs::remove_file(presets(d)).unwrap();
    // the preset cannot be published (a folder in its place): the replaced plot is put back
    fs::create_dir_all(presets(d).join("mine.toml").join("x")).unwrap();
    fs::write(d.join("p.svg"), "old").unwrap();
    let forced = [&fit[..], &["--force"]].concat();
    let o = bl_at(d, &forced);
    assert_eq!(o.code, 1, "{}", o.stderr);
    assert!(o.stderr.contains("cannot write"), "{}", o.stderr);
    assert_eq!(fs::read_to_string(d.join("p.svg")).unwrap(), "old");
    assert_eq!(folder_names(d), ["bouncelab", "cor.csv", "p.svg"]);
    fs::remove_dir_all(d.join("bouncelab")).unwrap();
    fs::remove_file(d.join("p.svg")).unwrap();
    // a report that cannot be written: neither the plot nor the preset (nor its folder)
    for args in [
        &fit[..],
        &["fit", "--cor", "0.8", "--plot", "p.svg", "--save", "one"],
    ] {
        let (code, err) = to_full_stdout(d, args);
        assert_eq!(code, 1, "{err}");
        assert!(err.contains("cannot write the report to stdout"), "{err}");
        assert_eq!(folder_names(d), ["cor.csv"], "{args:?}");
    }
    // and all of it when everything can be written
    let o = bl_at(d, &fit);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(d.join("p.svg").is_file() && presets(d).join("mine.toml").is_file());
}

/// The command, its stdout a full device, fails (exit 1) and leaves its folder empty.
fn writes_nothing_when_stdout_is_full(args: &[&str]) {
    let d = tempfile::tempdir().unwrap();
    let (code, err) = to_full_stdout(d.path(), args);
    assert_eq!(code, 1, "{err}");
    assert!(
        folder_names(d.path()).is_empty(),
        "{:?}",
        folder_names(d.path())
    );
}

#[test]
fn figure_writes_nothing_when_its_report_cannot_go_out() {
    writes_nothing_when_stdout_is_full(&argv("figure force-time --out a.svg --csv-out a.csv"));
}

#[test]
fn mc_writes_nothing_when_its_report_cannot_go_out() {
    writes_nothing_when_stdout_is_full(&argv("mc --vary k_p=5% --samples 20 --csv-out s.csv"));
}

/// `map --out` is checked before the grid with `figure`'s own check: the same message and exit
/// code for a directory, a missing folder, an existing file and a dangling link.
#[test]
fn map_checks_its_target_as_figure_does() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    fs::create_dir(d.join("folder")).unwrap();
    fs::write(d.join("old.svg"), "old").unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink("nowhere/x", d.join("dangling.svg")).unwrap();
    let map = |out: &str| {
        bl_at(
            d,
            &argv_with("map --lambda 0.1:10:4 --zeta 0.1:10:4 --out {}", &[out]),
        )
    };
    let figure = |out: &str| bl_at(d, &["figure", "force-time", "--out", out]);
    for (out, needle) in [
        ("folder", "folder is a directory, not a file"),
        (
            "nowhere/m.svg",
            "cannot write nowhere/m.svg: no such directory nowhere",
        ),
        ("old.svg", "old.svg exists (use --force to overwrite it)"),
        #[cfg(unix)]
        (
            "dangling.svg",
            "dangling.svg exists (use --force to overwrite it)",
        ),
    ] {
        let (m, f) = (map(out), figure(out));
        assert_bad(&m, &[needle]);
        assert_eq!(m.stderr, f.stderr, "{out}");
    }
    assert_eq!(fs::read_to_string(d.join("old.svg")).unwrap(), "old");
}

/// `reproduce --out` onto a symbolic link that leads nowhere: refused naming it (exit 2), never
/// "File exists" from making the folder; and nothing when its report cannot go out.
#[cfg(unix)]
#[test]
fn reproduce_refuses_a_dangling_link() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    std::os::unix::fs::symlink("gone", d.join("figs")).unwrap();
    for force in [false, true] {
        let mut args = vec!["reproduce", "--out", "figs"];
        args.extend(force.then_some("--force"));
        let o = bl_at(d, &args);
        assert_bad(&o, &["--out figs is a symbolic link to gone"]);
        assert!(!o.stderr.contains("File exists"), "{}", o.stderr);
    }
    let (code, err) = to_full_stdout(d, &["reproduce", "--out", "out"]);
    assert_eq!(code, 1, "{err}");
    assert_eq!(folder_names(d), ["figs"]);
}

/// 20 real processes saving one preset name at once, in one config folder: their exit codes and
/// stderr lines.
fn save_race(dir: &Path, name: &str, force: bool) -> Vec<(i32, String)> {
    let children: Vec<_> = (0..20)
        .map(|_| {
            let mut args = vec!["fit", "--cor", "0.8", "--save", name];
            args.extend(force.then_some("--force"));
            command(dir, &args)
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    children
        .into_iter()
        .map(|c| {
            let o = c.wait_with_output().unwrap();
            let err = String::from_utf8(o.stderr).unwrap();
            (o.status.code().expect("exited"), err)
        })
        .collect()
}

/// With `--force` every one of 20 concurrent saves of one name succeeds (the last wins); without
/// it one succeeds and the others exit 2 because the preset exists, never 1 "File exists".
#[test]
fn concurrent_saves_of_one_name() {
    let d = tempfile::tempdir().unwrap();
    for (code, err) in save_race(d.path(), "readers", true) {
        assert_eq!(code, 0, "{err}");
    }
    let folder = presets(d.path());
    assert_eq!(
        folder_names(&folder),
        ["readers.toml"],
        "one preset, no temporary"
    );
    let results = save_race(d.path(), "racers", false);
    let won = results.iter().filter(|r| r.0 == 0).count();
    assert_eq!(won, 1, "{results:?}");
    for (code, err) in results.iter().filter(|r| r.0 != 0) {
        assert_eq!(*code, 2, "{err}");
        assert!(err.contains("exists") && err.contains("--force"), "{err}");
        assert!(!err.contains("os error"), "{err}");
    }
    assert_eq!(folder_names(&folder), ["racers.toml", "readers.toml"]);
}

/// A reader that went away (`… | head`) is no failure: the files are published and the command
/// exits 0, as for any closed pipe.
#[test]
fn a_closed_stdout_still_publishes() {
    let d = tempfile::tempdir().unwrap();
    fs::write(d.path().join("cor.csv"), COR).unwrap();
    for args in [
        &["figure", "force-time", "--out", "a.svg"][..],
        &["fit", "--cor-table", "cor.csv", "--plot", "p.svg"],
    ] {
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let o = command_in(d.path(), args)
            .stdout(Stdio::from(writer))
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
    }
    assert_eq!(folder_names(d.path()), ["a.svg", "cor.csv", "p.svg"]);
}
