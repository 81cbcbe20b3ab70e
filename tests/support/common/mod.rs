//! Helpers for the tests that run the `bouncelab` binary.
#![allow(dead_code)]

pub mod golden;
pub mod room;

use serde_json::Value;
use std::ffi::OsStr;
use std::path::Path;
use std::process::{Command, Stdio};

pub const SUPERBALL: &str = include_str!("../../../presets/superball.toml");

/// The balls that came with the drop tests (docs/drop.md), each fitted to the middle of its
/// standard's window (or 0.015 under a one-sided limit): one list for the tests that run each.
pub fn drop_test_balls() -> Vec<&'static str> {
    argv("tennis football basketball table-tennis softball baseball-mlb softball-44")
}

/// The embedded preset `name`.
pub fn embedded(name: &str) -> bouncelab::preset::Preset {
    bouncelab::preset::Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("no embedded preset {name}"))
}

pub struct Out {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

impl Out {
    /// Run `cmd` to its exit (not killed), its output UTF-8.
    pub fn of(mut cmd: Command) -> Out {
        let o = cmd.output().expect("the binary runs");
        Out {
            code: o.status.code().expect("exited, not killed"),
            stdout: String::from_utf8(o.stdout).expect("UTF-8 stdout"),
            stderr: String::from_utf8(o.stderr).expect("UTF-8 stderr"),
        }
    }
}

/// `bouncelab ARGS` with `config` as XDG_CONFIG_HOME (and HOME), so the user's own presets
/// never leak into a test, and stdin closed; the caller sets the rest and runs it.
pub fn command<S: AsRef<OsStr>>(config: &Path, args: impl IntoIterator<Item = S>) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_bouncelab"));
    cmd.args(args)
        .env("XDG_CONFIG_HOME", config)
        .env("HOME", config)
        .stdin(Stdio::null());
    cmd
}

/// [`command`] run in `dir`, which is its config folder too.
pub fn command_in<S: AsRef<OsStr>>(dir: &Path, args: impl IntoIterator<Item = S>) -> Command {
    let mut cmd = command(dir, args);
    cmd.current_dir(dir);
    cmd
}

/// Run the binary with `config` as XDG_CONFIG_HOME (and HOME), so the user's own presets never
/// leak into a test.
pub fn bl_in(config: &Path, args: &[&str]) -> Out {
    Out::of(command(config, args))
}

/// A command line as typed, split at its spaces: `argv("drop --preset golf --bounces 1")`
/// (for arguments that hold no space themselves).
pub fn argv(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

/// [`argv`] with each `{}` word replaced by the next of `values`, which are passed whole (a
/// path may hold a space): `argv_with("fit --drop-test {} --free k_r", &[&path])`.
pub fn argv_with<'a>(line: &'a str, values: &[&'a str]) -> Vec<&'a str> {
    let mut values = values.iter();
    let words: Vec<&str> = argv(line)
        .into_iter()
        .map(|w| match w {
            "{}" => values.next().expect("a value for every {}"),
            w => w,
        })
        .collect();
    assert!(values.next().is_none(), "more values than {{}} in {line:?}");
    words
}

pub fn bl(args: &[&str]) -> Out {
    let dir = tempfile::tempdir().unwrap();
    bl_in(dir.path(), args)
}

/// Success, nothing on stderr; stdout.
pub fn ok(args: &[&str]) -> String {
    let o = bl(args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    assert!(o.stderr.is_empty(), "{args:?}: {}", o.stderr);
    o.stdout
}

/// Success, stdout; on stderr nothing but `outside calibration:` warnings (a ball the command
/// line changed, or run away from the speed its preset was fitted at: tests/cli/calibration.rs).
pub fn ok_calibrated(args: &[&str]) -> String {
    let o = bl(args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    let calibration = |l: &str| l.starts_with("bouncelab: warning: outside calibration:");
    assert!(o.stderr.lines().all(calibration), "{args:?}: {}", o.stderr);
    o.stdout
}

/// [`ok_calibrated`] run in `dir` ([`bl_at`]).
pub fn ok_at_calibrated(dir: &Path, args: &[&str]) -> String {
    let o = bl_at(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    let calibration = |l: &str| l.starts_with("bouncelab: warning: outside calibration:");
    assert!(o.stderr.lines().all(calibration), "{args:?}: {}", o.stderr);
    o.stdout
}

pub fn json(args: &[&str]) -> Value {
    let s = ok(args);
    assert_eq!(s.lines().count(), 1, "one JSON document on one line");
    serde_json::from_str(&s).unwrap_or_else(|e| panic!("{args:?}: {e}: {s}"))
}

pub fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} is not a number: {}", v[key]))
}

/// The warnings of a JSON answer, in its order: `warnings` must be a list of strings.
pub fn warnings(v: &Value) -> Vec<&str> {
    v["warnings"]
        .as_array()
        .unwrap_or_else(|| panic!("no warnings array: {v}"))
        .iter()
        .map(|w| {
            w.as_str()
                .unwrap_or_else(|| panic!("a warning not a string: {w}"))
        })
        .collect()
}

/// The warnings of a JSON answer that begin with `outside calibration:`.
pub fn outside_calibration(v: &Value) -> Vec<&str> {
    let mut w = warnings(v);
    w.retain(|w| w.starts_with("outside calibration:"));
    w
}

/// The `name` of each entry of a JSON list (`presets`, `surfaces`, `standards`), in its order.
pub fn names(list: &Value) -> Vec<&str> {
    entries(list)
        .iter()
        .map(|e| e["name"].as_str().unwrap_or_else(|| panic!("no name: {e}")))
        .collect()
}

/// The entry of a JSON list whose `name` is `name`.
pub fn named<'a>(list: &'a Value, name: &str) -> &'a Value {
    entries(list)
        .iter()
        .find(|e| e["name"] == name)
        .unwrap_or_else(|| panic!("{name} not listed: {list}"))
}

fn entries(list: &Value) -> &Vec<Value> {
    list.as_array()
        .unwrap_or_else(|| panic!("not a list: {list}"))
}

/// Exit code 2, stdout empty, stderr exactly one line `bouncelab: error: …` holding `needles`.
pub fn assert_bad(o: &Out, needles: &[&str]) {
    assert_bad_of(o, needles, "");
}

/// [`assert_bad`], each failure's message starting with `case` (the command that ran).
fn assert_bad_of(o: &Out, needles: &[&str], case: &str) {
    assert_eq!(o.code, 2, "{case}stderr: {}", o.stderr);
    assert!(o.stdout.is_empty(), "{case}stdout: {}", o.stdout);
    assert_eq!(
        o.stderr.lines().count(),
        1,
        "{case}one line: {:?}",
        o.stderr
    );
    assert!(o.stderr.ends_with('\n'), "{case}{:?}", o.stderr);
    assert!(
        o.stderr.starts_with("bouncelab: error: "),
        "{case}{}",
        o.stderr
    );
    assert!(!o.stderr.contains("panicked"), "{case}{}", o.stderr);
    for n in needles {
        assert!(o.stderr.contains(n), "{case}{n:?} not in {:?}", o.stderr);
    }
}

pub fn bad(args: &[&str], needles: &[&str]) {
    assert_bad_of(&bl(args), needles, &format!("{args:?}: "));
}

/// [`bad`] over a table: each command line (split at its spaces, as [`argv`]) refused, its
/// error holding its needles; a failure names the line.
pub fn bad_each(cases: &[(&str, &[&str])]) {
    for (line, needles) in cases {
        assert_bad_of(&bl(&argv(line)), needles, &format!("`{line}`: "));
    }
}

/// Each `{prefix} {words}` (split at its spaces, as [`argv`]) exits 2 with `says` on stderr
/// and nothing on stdout; a failure names the line. Looser than [`bad_each`]: stderr may hold
/// more than the one error line (a shot's calibration warning before it).
pub fn refused_each(prefix: &str, cases: &[(&str, &str)]) {
    for (words, says) in cases {
        let line = format!("{prefix} {words}");
        let o = bl(&argv(&line));
        assert_eq!(o.code, 2, "{line}: {}", o.stderr);
        assert!(o.stderr.contains(says), "{line}: {}", o.stderr);
        assert!(o.stdout.is_empty(), "{line}: {}", o.stdout);
    }
}

/// `args` with `--format json` give one warning, starting with `starts`, and the text answer
/// (`args` alone) says the same as `warning: …`.
pub fn assert_warns_once_in_json_and_text(args: &[&str], starts: &str) {
    let v = json(&[args, &["--format", "json"][..]].concat());
    let w = v["warnings"].as_array().expect("a warnings array");
    assert_eq!(w.len(), 1, "{w:?}");
    let said = w[0].as_str().unwrap();
    assert!(said.starts_with(starts), "{said}");
    assert!(ok(args).contains(&format!("warning: {said}")));
}

/// A temp folder holding one file written from bytes; returns (folder, path as text).
pub fn file_with(bytes: &[u8]) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("ball.toml");
    std::fs::write(&path, bytes).unwrap();
    let p = path.to_str().unwrap().to_string();
    (dir, p)
}

/// The names in `dir` (hidden temporaries too), sorted.
pub fn folder_names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// A config home whose presets folder holds `files` (name, contents).
pub fn config_home(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("bouncelab").join("presets");
    std::fs::create_dir_all(&presets).unwrap();
    for (name, text) in files {
        std::fs::write(presets.join(name), text).unwrap();
    }
    dir
}

pub fn renamed(name: &str, k_r: &str) -> String {
    SUPERBALL
        .replace("name = \"superball\"", &format!("name = \"{name}\""))
        .replace("k_r = 7.08e4", &format!("k_r = {k_r}"))
}

/// A preset named `golf` + `c` (a character that prints as nothing) is refused at load, at
/// the name's file:line:column, the character named by its code point: asked for (by its file
/// name), the error; otherwise skipped with that as a warning (`presets` lists the others).
pub fn assert_name_refused_as_invisible(c: char) {
    let text = renamed(&format!("golf{c}"), "7.08e4");
    let line = text[..text.find("name = ").unwrap()].matches('\n').count() + 1;
    let home = config_home(&[("golf2.toml", &text)]);
    let why = [
        &format!("golf2.toml:{line}:1: name: holds an invisible character")[..],
        &format!("U+{:04X}", c as u32),
    ];
    assert_bad(&bl_in(home.path(), &["run", "--preset", "golf2"]), &why);
    let o = bl_in(home.path(), &["presets"]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(o.stdout.contains("superball"), "{}", o.stdout);
    let warning = o.stderr.trim_end();
    assert!(!warning.contains('\n'), "one line: {warning}");
    assert!(warning.starts_with("bouncelab: warning: "), "{warning}");
    assert!(why.iter().all(|w| warning.contains(w)), "{warning}");
}

/// A folder holding `NAME.toml`: the baseball preset renamed `name`, with a `[fit]` table
/// freeing K_r and z_p at their adopted values, its `covariance` made by `covariance(k_r,
/// z_p)` (a TOML array of arrays), `dof` degrees of freedom, a residual sd of 0.01.
pub fn baseball_with_fit(
    name: &str,
    covariance: impl Fn(f64, f64) -> String,
    dof: u32,
) -> tempfile::TempDir {
    let base = embedded("baseball");
    let text = base
        .to_toml(&[])
        .replace("name = \"baseball\"", &format!("name = \"{name}\""));
    let (k_r, z_p) = (base.adopted.k_r, base.adopted.z_p.unwrap());
    let fit = format!(
        "\n[fit]\nfree = [\"k_r\", \"z_p\"]\nvalues = [{k_r:?}, {z_p:?}]\n\
         covariance = {}\ndof = {dof}\nresidual_sd = 0.01\n",
        covariance(k_r, z_p)
    );
    let d = tempfile::tempdir().unwrap();
    std::fs::write(
        d.path().join(format!("{name}.toml")),
        format!("{text}{fit}"),
    )
    .unwrap();
    d
}

/// Run with `dir` as working folder (and config home): paths in `args` are relative to it.
pub fn bl_at(dir: &Path, args: &[&str]) -> Out {
    Out::of(command_in(dir, args))
}

pub fn ok_at(dir: &Path, args: &[&str]) -> String {
    let o = bl_at(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    assert!(o.stderr.is_empty(), "{args:?}: {}", o.stderr);
    o.stdout
}

/// What a figure holds, read from its SVG as an XML document.
pub struct Svg {
    /// Every `<text>` content, trimmed.
    pub texts: Vec<String>,
    /// Series named in `<desc>`.
    pub series: Vec<String>,
    pub polylines: usize,
}

pub fn parse_svg(text: &str) -> Svg {
    let doc = roxmltree::Document::parse(text).unwrap_or_else(|e| panic!("not XML: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some("800"));
    assert_eq!(root.attribute("height"), Some("560"));
    assert!(root.attribute("viewBox").is_some());
    let title = root.children().find(|n| n.has_tag_name("title"));
    assert!(
        title.and_then(|t| t.text()).is_some_and(|t| !t.is_empty()),
        "a <title>"
    );
    let desc = root
        .children()
        .find(|n| n.has_tag_name("desc"))
        .and_then(|d| d.text());
    let series = desc
        .and_then(|d| d.split("Series: ").nth(1))
        .map(|s| {
            s.trim_end_matches('.')
                .split("; ")
                .map(String::from)
                .collect()
        })
        .unwrap_or_default();
    let texts = root
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(|t| t.trim().to_string()))
        .collect();
    let polylines = root
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .count();
    Svg {
        texts,
        series,
        polylines,
    }
}
