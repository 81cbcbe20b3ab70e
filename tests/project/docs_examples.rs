//! The docs' command examples stay true: every fenced block of `docs/*.md` and `README.md`
//! that shows `$ COMMAND` lines is run, command by command, through `sh` with the real
//! binary first on `PATH`, and its output (stdout then stderr, as `2>&1` interleaves them) is
//! compared with the lines under the command. `BOUNCELAB_BLESS=1` rewrites the blocks that
//! differ with the real output (as the goldens are blessed; put any elision back by hand).
//!
//! The comparison is exact but for these rules, which leave every shown number checked:
//! - a line that is only `…` stands for lines left out (any number of them);
//! - `…` inside a line stands for text left out of that line, and what it shows must match
//!   around it (the output's own `…`, as in `1.35 … 1.47 m`, matches itself);
//! - trailing blank lines are dropped on both sides (the blank line before the next `$`);
//! - `/tmp/doccfg` in a command is a fresh folder of the same length (so table columns keep
//!   their width), holding `bouncelab/presets/soft.toml` (tests/docs/soft.toml), and that
//!   folder reads back as `/tmp/doccfg` in the output.
//!
//! Each page runs in one scratch folder, in page order (a later command may read an earlier
//! one's file), holding `lot7.csv` (tests/golden/batch-lot7.csv). A command continues on the
//! next line after a trailing `\`. The exit code is not compared (cli_golden.rs holds them).
//! A `$ ` line anywhere else (an indented block, or indented inside a fence) is refused: such
//! an example would not be run, and would go stale unseen.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// One `$ …` example: its command and the page lines [from, to) of its shown output.
struct Example {
    command: String,
    from: usize,
    to: usize,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The examples of one page, in order: inside each fenced block, a `$ ` line (and its `\`
/// continuations) is a command, the lines up to the next `$ ` or the fence its output.
fn examples(lines: &[&str]) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    let (mut fenced, mut i) = (false, 0);
    while i < lines.len() {
        let line = lines[i];
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            if !fenced {
                close(&mut out, i, lines);
            }
        } else if fenced && line.starts_with("$ ") {
            close(&mut out, i, lines);
            let mut command = line[2..].to_string();
            while command.ends_with('\\') && i + 1 < lines.len() {
                command.pop();
                i += 1;
                command.push_str(lines[i].trim_start());
            }
            out.push(Example {
                command,
                from: i + 1,
                to: usize::MAX,
            });
        }
        i += 1;
    }
    out
}

/// The lines (1-based) showing a `$ ` command that `examples` does not run: one in an
/// indented block, or indented inside a fence. Such an example would go stale unchecked.
fn unchecked_commands(lines: &[&str]) -> Vec<usize> {
    let mut fenced = false;
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if line.trim_start().starts_with("$ ") && !(fenced && line.starts_with("$ ")) {
            out.push(i + 1);
        }
    }
    out
}

/// Ends the open example (if any) at line `end`, less its trailing blank lines.
fn close(out: &mut [Example], end: usize, lines: &[&str]) {
    if let Some(e) = out.last_mut().filter(|e| e.to == usize::MAX) {
        let mut to = end;
        while to > e.from && lines[to - 1].trim().is_empty() {
            to -= 1;
        }
        e.to = to;
    }
}

/// A scratch folder under /tmp whose path is as long as `/tmp/doccfg`, with the user preset.
fn config_dir() -> tempfile::TempDir {
    let dir = tempfile::Builder::new()
        .prefix("doc")
        .rand_bytes(3)
        .tempdir_in("/tmp")
        .unwrap();
    assert_eq!(dir.path().as_os_str().len(), "/tmp/doccfg".len());
    let presets = dir.path().join("bouncelab/presets");
    std::fs::create_dir_all(&presets).unwrap();
    std::fs::copy(
        root().join("tests/docs/soft.toml"),
        presets.join("soft.toml"),
    )
    .unwrap();
    dir
}

/// Runs one command in `work` and returns its output as the page would show it.
fn run(command: &str, work: &Path, config: &Path, bin: &Path) -> String {
    let cfg = config.to_str().unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "{{ {} ; }} 2>&1",
            command.replace("/tmp/doccfg", cfg)
        ))
        .current_dir(work)
        .env("PATH", path)
        .env("XDG_CONFIG_HOME", work.join("no-user-presets"))
        .env_remove("NO_COLOR")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let text = String::from_utf8(o.stdout).expect("UTF-8 output");
    text.replace(cfg, "/tmp/doccfg").trim_end().to_string()
}

/// Whether a shown line matches an output line: equal, or equal around its `…`s.
fn line_matches(shown: &str, got: &str) -> bool {
    if shown == got {
        return true;
    }
    let parts: Vec<&str> = shown.split('…').collect();
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if parts.len() < 2 || !got.starts_with(first) || !got[first.len()..].ends_with(last) {
        return false;
    }
    let mut rest = &got[first.len()..got.len() - last.len()];
    for part in &parts[1..parts.len() - 1] {
        match rest.find(part) {
            Some(at) => rest = &rest[at + part.len()..],
            None => return false,
        }
    }
    true
}

/// Whether the shown lines match the output's, a line of only `…` standing for any lines.
fn block_matches(shown: &[&str], got: &[&str]) -> bool {
    match shown.split_first() {
        None => got.is_empty(),
        Some((s, rest)) if s.trim() == "…" => {
            (0..=got.len()).any(|k| block_matches(rest, &got[k..]))
        }
        Some((s, rest)) => {
            !got.is_empty() && line_matches(s, got[0]) && block_matches(rest, &got[1..])
        }
    }
}

/// Checks one page; returns what differs, and with `bless` rewrites the page.
fn check_page(page: &Path, bin: &Path, bless: bool) -> Vec<String> {
    let text = std::fs::read_to_string(page).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let found = examples(&lines);
    if found.is_empty() {
        return Vec::new();
    }
    let (work, config) = (tempfile::tempdir().unwrap(), config_dir());
    std::fs::copy(
        root().join("tests/golden/batch-lot7.csv"),
        work.path().join("lot7.csv"),
    )
    .unwrap();
    let name = page.strip_prefix(root()).unwrap().display().to_string();
    let (mut differ, mut rewritten, mut copied) = (Vec::new(), Vec::<String>::new(), 0);
    for e in &found {
        let got = run(&e.command, work.path(), config.path(), bin);
        let got_lines: Vec<&str> = got.lines().collect();
        let shown = &lines[e.from..e.to];
        rewritten.extend(lines[copied..e.from].iter().map(|l| l.to_string()));
        if block_matches(shown, &got_lines) {
            rewritten.extend(shown.iter().map(|l| l.to_string()));
        } else {
            differ.push(format!(
                "{name}:{}: $ {}\n--- shown\n{}\n--- got\n{got}",
                e.from,
                e.command,
                shown.join("\n")
            ));
            rewritten.extend(got_lines.iter().map(|l| l.to_string()));
        }
        copied = e.to;
    }
    if bless && !differ.is_empty() {
        rewritten.extend(lines[copied..].iter().map(|l| l.to_string()));
        std::fs::write(page, rewritten.join("\n") + "\n").unwrap();
    }
    differ
}

/// The binary's own folder holds more than `bouncelab`: put a link to it alone on PATH.
fn bin_dir(scratch: &Path) -> PathBuf {
    let bin = scratch.join("bin");
    std::fs::create_dir(&bin).unwrap();
    std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_bouncelab"), bin.join("bouncelab")).unwrap();
    bin
}

#[test]
fn every_docs_example_prints_what_the_binary_prints() {
    let bless = std::env::var_os("BOUNCELAB_BLESS").is_some();
    let scratch = tempfile::tempdir().unwrap();
    let bin = bin_dir(scratch.path());
    let differ: Vec<String> = super::speed_figures::doc_pages()
        .iter()
        .flat_map(|p| check_page(p, &bin, bless))
        .collect();
    assert!(
        differ.is_empty() || bless,
        "{} docs examples differ from the binary (BOUNCELAB_BLESS=1 rewrites them):\n\n{}",
        differ.len(),
        differ.join("\n\n")
    );
}

#[test]
fn every_shown_command_is_in_a_checked_block() {
    let unchecked: Vec<String> = super::speed_figures::doc_pages()
        .iter()
        .flat_map(|page| {
            let text = std::fs::read_to_string(page).unwrap();
            let name = page.strip_prefix(root()).unwrap().display().to_string();
            let lines: Vec<&str> = text.lines().collect();
            unchecked_commands(&lines)
                .into_iter()
                .map(move |n| format!("{name}:{n}"))
                .collect::<Vec<_>>()
        })
        .collect();
    assert!(
        unchecked.is_empty(),
        "a `$ ` command outside a fenced block, or indented in one, is not run against the \
         binary: put it in a ``` block at the line's start ({})",
        unchecked.join(", ")
    );
}

#[test]
fn the_matching_rules_leave_shown_numbers_checked() {
    assert!(line_matches("COR 0.75 … 0.80", "COR 0.75 … 0.80"));
    assert!(line_matches(r#"{"a":1,…,"c":3}"#, r#"{"a":1,"b":2,"c":3}"#));
    assert!(!line_matches(
        r#"{"a":1,…,"c":3}"#,
        r#"{"a":1,"b":2,"c":4}"#
    ));
    assert!(!line_matches("COR 0.75", "COR 0.76"));
    assert!(block_matches(&["a", "…", "d"], &["a", "b", "c", "d"]));
    assert!(!block_matches(&["a", "…", "d"], &["a", "b", "c", "e"]));
    assert!(!block_matches(&["a", "b"], &["a", "b", "c"]));
    let page = ["```", "$ one \\", "  two", "x", "", "$ three", "```"];
    let found = examples(&page);
    assert_eq!(found.len(), 2);
    assert_eq!(
        (found[0].command.as_str(), found[0].from, found[0].to),
        ("one two", 3, 4)
    );
    assert_eq!((found[1].from, found[1].to), (6, 6));
    let indented = [
        "    $ one",
        "```",
        "  $ two",
        "$ three",
        "```",
        "text $ four",
    ];
    assert_eq!(unchecked_commands(&indented), [1, 3]);
}
