//! The command line is a contract: every existing command's output (stdout, stderr, exit code
//! and every file it writes) is compared byte for byte with the copy stored under
//! `tests/golden/`. A change of output is then a deliberate act: `BOUNCELAB_BLESS=1 cargo test
//! --test cli_golden` rewrites the stored copies, and the diff is reviewed like a snapshot.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One case: a name (the stored file's stem) and the arguments. `{dir}` in an argument stands
/// for the case's own scratch folder, so files written there are collected and compared too.
const CASES: &[(&str, &[&str])] = &[
    ("run-text-superball", &["run"]),
    (
        "run-json-golf",
        &["run", "--preset", "golf", "--format", "json"],
    ),
    (
        "run-csv-baseball",
        &["run", "--preset", "baseball", "--format", "csv"],
    ),
    (
        "run-json-history-ep",
        &[
            "run",
            "--law",
            "elastic-plastic",
            "--v0",
            "6",
            "--format",
            "json",
            "--history",
            "--samples",
            "25",
        ],
    ),
    ("run-text-hertz", &["run", "--law", "hertz", "--v0", "2"]),
    (
        "run-text-materials",
        &["run", "--preset", "golf", "--params", "materials"],
    ),
    (
        "run-json-normalized",
        &[
            "run",
            "--normalized",
            "--lambda",
            "0.4",
            "--zeta",
            "0.3",
            "--zp-bar",
            "0.5",
            "--format",
            "json",
        ],
    ),
    (
        "run-text-lambda-zeta",
        &["--preset", "golf", "run", "--lambda", "2", "--zeta", "0.5"],
    ),
    ("sweep-zeta-csv", &["sweep", "zeta", "--points", "9"]),
    (
        "sweep-zeta-json-ep",
        &[
            "sweep",
            "zeta",
            "--lambda",
            "0.2,3",
            "--points",
            "5",
            "--law",
            "elastic-plastic",
            "--format",
            "json",
        ],
    ),
    (
        "sweep-velocity-csv",
        &["sweep", "velocity", "--points", "7"],
    ),
    (
        "sweep-velocity-json-golf",
        &[
            "sweep", "velocity", "--preset", "golf", "--points", "4", "--format", "json",
        ],
    ),
    ("fit-text", &["fit", "--cor", "0.7"]),
    (
        "fit-json-baseball",
        &[
            "fit", "--preset", "baseball", "--cor", "0.5", "--v0", "2", "--format", "json",
        ],
    ),
    ("presets-text", &["presets"]),
    ("presets-json", &["presets", "--format", "json"]),
    (
        "figure-cor-zeta",
        &[
            "figure",
            "cor-zeta",
            "--out",
            "{dir}/f.svg",
            "--csv-out",
            "{dir}/f.csv",
        ],
    ),
    (
        "figure-force-zeta",
        &["figure", "force-zeta", "--out", "{dir}/f.svg"],
    ),
    (
        "figure-cor-velocity",
        &[
            "figure",
            "cor-velocity",
            "--preset",
            "golf",
            "--out",
            "{dir}/f.svg",
            "--csv-out",
            "{dir}/f.csv",
        ],
    ),
    (
        "figure-force-time",
        &[
            "figure",
            "force-time",
            "--out",
            "{dir}/f.svg",
            "--csv-out",
            "{dir}/f.csv",
        ],
    ),
    (
        "figure-force-displacement",
        &[
            "figure",
            "force-displacement",
            "--preset",
            "baseball",
            "--law",
            "elastic-plastic",
            "--out",
            "{dir}/f.svg",
            "--csv-out",
            "{dir}/f.csv",
        ],
    ),
    ("reproduce", &["reproduce", "--out", "{dir}/paper"]),
    ("bad-lambda", &["run", "--lambda", "nan"]),
    ("bad-preset", &["run", "--preset", "no-such-ball"]),
    ("bad-fit-reach", &["fit", "--cor", "0.01"]),
    ("bad-flag", &["run", "--no-such-flag"]),
    (
        "bad-figure-data-renamed",
        &[
            "figure",
            "force-time",
            "--out",
            "{dir}/f.svg",
            "--data",
            "{dir}/f.csv",
        ],
    ),
    ("bad-explorer-no-terminal", &[]),
    (
        "drop-text-tennis-itf",
        &["drop", "--preset", "tennis", "--standard", "itf"],
    ),
    (
        "drop-json-basketball-fiba",
        &[
            "drop",
            "--preset",
            "basketball",
            "--standard",
            "fiba",
            "--bounces",
            "2",
            "--format",
            "json",
        ],
    ),
    ("standards-text", &["standards"]),
    ("bad-standard", &["drop", "--standard", "wimbledon"]),
];

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
    let o = common::bl_in(dir.path(), &argv);
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

#[test]
fn every_command_prints_what_it_printed_before() {
    let bless = std::env::var_os("BOUNCELAB_BLESS").is_some();
    let mut differ = Vec::new();
    for (name, args) in CASES {
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
