//! Issue 54, "Done when": hostile generators. Every flag of every subcommand, read from the
//! binary's own `--help` (so a new flag is covered the day it is added), is given hostile
//! values, and every flag that takes a file hostile files, through the real binary. Each run
//! must end by itself within `LIMIT` with 0, 1 or 2 — never 101 (a panic), 134 (an abort) or
//! a signal; exit 2 says why in one `bouncelab: error:` line (warnings beside it only); stdout
//! is valid JSON when `--format json` asked for it and the run answered.
//!
//! Each flag meets one value a run, chosen by a seed (`BOUNCELAB_HOSTILE_SEED`, default 54):
//! every flag is run every time, and the values rotate with the seed; every file flag meets
//! every kind of hostile file. Runs go four at a time in their own empty folder.

use crate::hostile;
use hostile::*;

fn long_text() -> String {
    "9".repeat(4096) + "x"
}

/// The hostile values: empty, zeros, not numbers, infinities, the extremes, an underflow, text,
/// unicode (a combining mark, a filler, an emoji), a long string.
fn values() -> Vec<String> {
    [
        "",
        "0",
        "-0",
        "NaN",
        "inf",
        "-inf",
        "1e308",
        "-1e308",
        "1e-308",
        "1e-400",
        "text",
        "g\u{115F}ölf\u{301} ⚽",
        "-",
    ]
    .iter()
    .map(|s| s.to_string())
    .chain([long_text()])
    .collect()
}

fn seed() -> usize {
    std::env::var("BOUNCELAB_HOSTILE_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(54)
}

#[test]
fn every_flag_takes_every_hostile_value_and_answers_0_1_or_2() {
    let values = values();
    let surface = surface();
    assert!(
        surface.len() >= 15,
        "{} commands read from --help",
        surface.len()
    );
    let examples = examples(&surface);
    let mut runs = Vec::new();
    let mut k = seed();
    for (path, flags) in &surface {
        for flag in flags {
            let mut args = base(path, flags, flag, &examples);
            args.push(flag.long.clone());
            if flag.value.is_some() {
                k += 1;
                // `--flag=value`, so that `-inf` or `-` is the flag's value, not a flag
                let last = args.pop().unwrap();
                args.push(format!("{last}={}", values[k % values.len()]));
            }
            runs.push(args);
        }
    }
    assert!(runs.len() >= 200, "{} flags", runs.len());
    // the bases alone answer, so that a refusal is the hostile value's
    let bases: Vec<Vec<String>> = examples
        .iter()
        .map(|(path, _)| {
            let flags = &surface.iter().find(|(p, _)| p == path).unwrap().1;
            let none = Flag {
                long: "--none".into(),
                value: None,
            };
            base(path, flags, &none, &examples)
        })
        .collect();
    assert!(
        bases.len() >= 12,
        "{} commands with a docs example",
        bases.len()
    );
    let (failures, codes) = run_all(bases.clone(), &|_| {});
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert_eq!(codes[0], bases.len(), "bases that do not answer: {bases:?}");
    let (failures, codes) = run_all(runs, &|_| {});
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // some hostile values are taken (a switch, a 0 that means none, …)
    assert!(codes[0] >= 10, "only {} runs answered", codes[0]);
}

const FILE_KINDS: [&str; 10] = [
    "missing",
    "directory",
    "fifo",
    "device",
    "unreadable",
    "bom",
    "crlf",
    "quoted",
    "columns",
    "huge",
];

#[test]
fn every_file_flag_takes_every_hostile_file_and_answers_0_1_or_2() {
    let surface = surface();
    let examples = examples(&surface);
    let mut runs = Vec::new();
    for (path, flags) in &surface {
        for flag in flags.iter().filter(|f| takes_file(f)) {
            for kind in FILE_KINDS.iter().chain(&["binary"]) {
                if *kind == "device" && writes(flag) {
                    continue;
                }
                let mut args = base(path, flags, flag, &examples);
                // the file's path is relative: each run's folder holds its own
                let name = match *kind {
                    "device" => "/dev/zero".to_string(),
                    k => format!("in-{k}.csv"),
                };
                args.push(format!("{}={name}", flag.long));
                runs.push(args);
            }
        }
    }
    assert!(runs.len() >= 50, "{} file runs", runs.len());
    let (failures, _) = run_all(runs, &|dir| {
        for kind in FILE_KINDS.iter().chain(&["binary"]) {
            if *kind != "device" {
                hostile_file(kind, dir);
            }
        }
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
