//! The golden-output harness of tests/cli/cli_golden.rs and tests/cli/cli_golden_map.rs: each case's
//! stdout, stderr, exit code and written files, byte for byte against `tests/golden/NAME.txt`;
//! `BOUNCELAB_BLESS=1` rewrites the stored copies.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Everything a case produced, as one text: the exit code, stdout, stderr, then each file
/// written under the scratch folder (path relative to it, then its bytes).
fn transcript(args: &[&str]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let scratch = dir.path().join("out");
    std::fs::create_dir(&scratch).unwrap();
    let scratch_text = scratch.to_str().unwrap().to_string();
    let home_text = dir.path().to_str().unwrap().to_string();
    let args: Vec<String> = args
        .iter()
        .map(|a| a.replace("{dir}", &scratch_text))
        .collect();
    let argv: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = super::bl_in(dir.path(), &argv);
    let mut t = format!(
        "$ bouncelab {}\n== exit {}\n== stdout\n{}== stderr\n{}",
        args.join(" ").replace(&scratch_text, "{dir}"),
        o.code,
        o.stdout,
        o.stderr
    );
    for (name, bytes) in files_under(&scratch) {
        t.push_str(&format!("== file {name}\n"));
        t.push_str(&String::from_utf8(bytes).expect("UTF-8 output file"));
    }
    t.replace(&scratch_text, "{dir}")
        .replace(&home_text, "{home}")
}

fn files_under(root: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut files = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let p = entry.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p.strip_prefix(root).unwrap().to_str().unwrap().to_string();
                files.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    files
}

fn golden_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(format!("{name}.txt"))
}

/// Compare every case with its stored copy (or store it, with `BOUNCELAB_BLESS=1`); one
/// failure names every case whose output changed.
pub fn check(cases: &[(&str, &[&str])]) {
    let bless = std::env::var_os("BOUNCELAB_BLESS").is_some();
    let mut differ = Vec::new();
    for (name, args) in cases {
        let got = transcript(args);
        let path = golden_path(name);
        if bless {
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(&path, &got).unwrap();
            continue;
        }
        let want = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (BOUNCELAB_BLESS=1 writes it)", path.display()));
        if got != want {
            let line = got
                .lines()
                .zip(want.lines())
                .position(|(g, w)| g != w)
                .unwrap_or(got.lines().count().min(want.lines().count()));
            differ.push(format!("{name} (first difference at line {})", line + 1));
        }
    }
    assert!(
        differ.is_empty(),
        "output changed for: {differ:?}; review with BOUNCELAB_BLESS=1 and git diff tests/golden"
    );
}

/// `check` for cases written as command lines (`"map --normalized --lambda 1:2:2"`), split
/// at their spaces (`super::argv`).
pub fn check_lines(cases: &[(&str, &str)]) {
    let argvs: Vec<(&str, Vec<&str>)> = cases
        .iter()
        .map(|(name, line)| (*name, super::argv(line)))
        .collect();
    let cases: Vec<(&str, &[&str])> = argvs.iter().map(|(n, a)| (*n, a.as_slice())).collect();
    check(&cases);
}
