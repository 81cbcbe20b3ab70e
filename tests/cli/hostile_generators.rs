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

use crate::common::command_in;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A run that has not ended by then is a failure (it is killed): the debug binary on a loaded
/// machine; a refusal takes milliseconds, the work limit bounds the rest (docs/guarantees.md).
const LIMIT: Duration = Duration::from_secs(60);

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

fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_bouncelab")
}

fn help(args: &[&str]) -> String {
    let o = Command::new(bin())
        .args(args)
        .arg("--help")
        .output()
        .unwrap();
    String::from_utf8(o.stdout).unwrap()
}

/// The names listed under `Commands:` in a help text (but `help`).
fn commands(help: &str) -> Vec<String> {
    section(help, "Commands:")
        .iter()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_string)
        .collect()
}

/// The lines of one section of a help text (`Commands:`, `Options:`), each an entry's first.
fn section<'a>(help: &'a str, title: &str) -> Vec<&'a str> {
    help.lines()
        .skip_while(|l| l.trim() != title)
        .skip(1)
        .take_while(|l| !l.trim().is_empty() && l.starts_with(' '))
        .filter(|l| {
            let t = l.trim_start();
            l.len() - t.len() <= 6 && !t.is_empty()
        })
        .collect()
}

/// A flag: its long name and its value's name (`None` for a switch).
#[derive(Debug, Clone)]
struct Flag {
    long: String,
    value: Option<String>,
}

fn flags(help: &str) -> Vec<Flag> {
    section(help, "Options:")
        .iter()
        .filter_map(|l| {
            let l = l.trim_start();
            let at = l.find("--")?;
            let mut words = l[at..].split_whitespace();
            let long = words.next()?.trim_end_matches(',').to_string();
            let value = words
                .next()
                .filter(|w| w.starts_with('<') || w.starts_with('['))
                .map(str::to_string);
            (long != "--help" && long != "--version").then_some(Flag { long, value })
        })
        .collect()
}

/// Every subcommand path (`["run"]`, `["sweep", "zeta"]`, …) with its flags.
fn surface() -> Vec<(Vec<String>, Vec<Flag>)> {
    let mut out = Vec::new();
    for c in commands(&help(&[])) {
        let h = help(&[&c]);
        let subs = commands(&h);
        if subs.is_empty() {
            out.push((vec![c.clone()], flags(&h)));
        }
        for s in subs {
            let h = help(&[&c, &s]);
            out.push((vec![c.clone(), s], flags(&h)));
        }
    }
    out
}

/// A flag that names a file the command writes (these get no device: `--force` over a
/// device is refused, but a test must never risk `/dev/null`).
fn writes(f: &Flag) -> bool {
    ["out", "plot", "save", "export", "dir"]
        .iter()
        .any(|w| f.long.contains(w))
}

/// A flag whose value is a path.
fn takes_file(f: &Flag) -> bool {
    f.value.as_deref().is_some_and(|v| {
        let v = v.to_ascii_uppercase();
        v.contains("FILE") || v.contains("PATH") || v.contains("DIR")
    })
}

/// One run's verdict: `Err` with what was wrong.
fn run(args: &[String], dir: &Path) -> Result<i32, String> {
    run_command(command_in(dir, args), args).map(|(code, _)| code)
}

/// The verdict of `cmd`, a run of `args`: its exit code and stderr, `Err` with what was wrong.
fn run_command(mut cmd: Command, args: &[String]) -> Result<(i32, String), String> {
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let (out, err) = (child.stdout.take().unwrap(), child.stderr.take().unwrap());
    let read = |mut r: Box<dyn std::io::Read + Send>| {
        std::thread::spawn(move || {
            let mut v = Vec::new();
            let _ = r.read_to_end(&mut v);
            v
        })
    };
    let (out, err) = (read(Box::new(out)), read(Box::new(err)));
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().map_err(|e| e.to_string())? {
            break s;
        }
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("still running after {LIMIT:?}: killed"));
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let (stdout, stderr) = (out.join().unwrap(), err.join().unwrap());
    let stderr = String::from_utf8_lossy(&stderr);
    let code = status
        .code()
        .ok_or_else(|| format!("ended by a signal: {status:?}; {stderr}"))?;
    if !(0..=2).contains(&code) {
        return Err(format!("exit {code}: {stderr}"));
    }
    if code == 2 {
        let errors = stderr
            .lines()
            .filter(|l| l.starts_with("bouncelab: error: "))
            .count();
        let others = stderr
            .lines()
            .filter(|l| !l.starts_with("bouncelab: error: "))
            .filter(|l| !l.starts_with("bouncelab: warning: "))
            .count();
        if errors != 1 || others != 0 {
            return Err(format!("exit 2 without one error line: {stderr:?}"));
        }
    }
    let json = args
        .windows(2)
        .any(|w| w[0] == "--format" && w[1] == "json");
    if code == 0 && json {
        let text = String::from_utf8_lossy(&stdout);
        serde_json::from_str::<serde_json::Value>(&text)
            .map_err(|e| format!("stdout is not JSON ({e}): {text:.200}"))?;
    }
    Ok((code, stderr.into_owned()))
}

/// The runs, four at a time, each in its own folder made by `prepare`: the failures, and how
/// many runs ended with 0, 1 and 2.
fn run_all(runs: Vec<Vec<String>>, prepare: &(dyn Fn(&Path) + Sync)) -> (Vec<String>, [usize; 3]) {
    let queue = Mutex::new(runs);
    let failures = Mutex::new(Vec::new());
    let codes = Mutex::new([0; 3]);
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| {
                while let Some(args) = queue.lock().unwrap().pop() {
                    let dir = tempfile::tempdir().unwrap();
                    prepare(dir.path());
                    match run(&args, dir.path()) {
                        Ok(code) => codes.lock().unwrap()[code as usize] += 1,
                        Err(e) => failures.lock().unwrap().push(format!("{args:.300?}: {e}")),
                    }
                }
            });
        }
    });
    let codes = codes.into_inner().unwrap();
    eprintln!(
        "runs ended 0: {}, 1: {}, 2: {}",
        codes[0], codes[1], codes[2]
    );
    (failures.into_inner().unwrap(), codes)
}

fn seed() -> usize {
    std::env::var("BOUNCELAB_HOSTILE_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(54)
}

/// The docs' `$ bouncelab …` examples (tests/project/docs_examples.rs runs them: they answer), plain
/// words only (no pipe, redirection or quote), a file they name made absolute: the first of
/// each command path is that command's base, so the flag under test meets a command that
/// otherwise answers.
fn examples(surface: &[(Vec<String>, Vec<Flag>)]) -> Vec<(Vec<String>, Vec<String>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out: Vec<(Vec<String>, Vec<String>)> = Vec::new();
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    for page in pages {
        let text = std::fs::read_to_string(page).unwrap();
        for line in text.lines().map(str::trim) {
            let Some(rest) = line.strip_prefix("$ bouncelab ") else {
                continue;
            };
            if rest.contains(['|', '>', '<', '\'', '"', '$', '&', ';', '\\']) {
                continue;
            }
            // a data file the page made beforehand (not in the repository)
            let missing = rest
                .split_whitespace()
                .any(|w| !w.starts_with('-') && w.ends_with(".csv") && !root.join(w).is_file());
            if missing && !rest.contains("-out") {
                continue;
            }
            let words: Vec<String> = rest
                .split_whitespace()
                .map(|w| {
                    let file = root.join(w);
                    if !w.starts_with('-') && w.contains('.') && file.is_file() {
                        file.to_string_lossy().into_owned()
                    } else {
                        w.to_string()
                    }
                })
                .collect();
            let path = surface
                .iter()
                .map(|(p, _)| p)
                .filter(|p| words.starts_with(p))
                .max_by_key(|p| p.len());
            if let Some(path) = path
                && !out.iter().any(|(p, _)| p == path)
            {
                out.push((path.clone(), words));
            }
        }
    }
    out
}

/// The base of a run of `flag`: the command's docs example (else the preset where it takes
/// one), asking for JSON where it speaks it.
fn base(
    path: &[String],
    flags: &[Flag],
    flag: &Flag,
    examples: &[(Vec<String>, Vec<String>)],
) -> Vec<String> {
    let has = |name: &str| flags.iter().any(|f| f.long == name) && flag.long != name;
    let mut args = match examples.iter().find(|(p, _)| p == path) {
        Some((_, words)) => words.clone(),
        None if has("--preset") => {
            let mut a = path.to_vec();
            a.extend(["--preset".into(), "tennis".into()]);
            a
        }
        None => path.to_vec(),
    };
    if has("--format") {
        args = without(&args, "--format", true);
        args.extend(["--format".into(), "json".into()]);
    }
    without(&args, &flag.long, flag.value.is_some())
}

/// `args` without `flag` (and its value, when it takes one): the run gives it its own.
fn without(args: &[String], flag: &str, valued: bool) -> Vec<String> {
    let mut out = Vec::new();
    let mut skip = false;
    for a in args {
        if skip {
            skip = false;
            continue;
        }
        if a == flag {
            skip = valued;
            continue;
        }
        if a.starts_with(&format!("{flag}=")) {
            continue;
        }
        out.push(a.clone());
    }
    out
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

/// The hostile files: (name, how it is made in `dir`; the path given).
fn hostile_file(kind: &str, dir: &Path) -> PathBuf {
    let p = dir.join(format!("in-{kind}.csv"));
    let write = |bytes: &[u8]| std::fs::write(&p, bytes).unwrap();
    match kind {
        "missing" => {}
        "directory" => std::fs::create_dir(&p).unwrap(),
        "fifo" => {
            let ok = Command::new("mkfifo").arg(&p).status().unwrap().success();
            assert!(ok, "mkfifo");
        }
        "device" => return PathBuf::from("/dev/zero"),
        "bom" => write(b"\xEF\xBB\xBFv0,cor\n3,0.8\n5,0.7\n"),
        "crlf" => write(b"v0,cor\r\n3,0.8\r\n5,0.7\r\n"),
        "quoted" => write(b"\"v0\",\"cor\"\n\"3\",\"0.8\"\n\"5\",\"0.7\"\n"),
        "columns" => write(b"a,b,c,d\n1,2\n3,4,5,6,7\n"),
        "huge" => {
            let f = std::fs::File::create(&p).unwrap();
            // sparse, no disk: past every reader's cap (64 MiB, `measured::file`)
            f.set_len(100 << 20).unwrap();
        }
        "binary" => write(&[0xff, 0xfe, 0, 1, 2, 0x80, b'\n']),
        "unreadable" => {
            // a good file no one may read (root reads it anyway: then it is answered as read)
            use std::os::unix::fs::PermissionsExt;
            write(b"v0,cor\n3,0.8\n5,0.7\n");
            std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o000)).unwrap();
        }
        _ => unreachable!("{kind}"),
    }
    p
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

/// The uid and gid a run drops to where the tests run as root: `nobody` on Linux.
const NOBODY: u32 = 65534;

/// How a run meets a file no one may read. Root (CAP_DAC_OVERRIDE) reads a mode-000 file
/// anyway, so under root the run drops to [`NOBODY`] with util-linux's `setpriv`; `None` where
/// the tests run as root and `setpriv` is absent (the refusal cannot be exercised then).
fn unreadable_reader(dir: &Path) -> Option<Vec<String>> {
    let probe = hostile_file("unreadable", dir);
    let privileged = std::fs::read(&probe).is_ok();
    std::fs::remove_file(&probe).unwrap();
    if !privileged {
        return Some(Vec::new());
    }
    let drop = vec![
        "setpriv".to_string(),
        format!("--reuid={NOBODY}"),
        format!("--regid={NOBODY}"),
        "--clear-groups".into(),
        "--".into(),
    ];
    let there = Command::new("setpriv")
        .arg("--version")
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    there.then_some(drop)
}

/// `bouncelab ARGS` in `dir` (its config folder too, as `command_in`), run through `prefix`
/// (`setpriv …` where the run drops its privileges).
fn command_as(prefix: &[String], dir: &Path, args: &[String]) -> Command {
    let mut words = prefix.iter().map(String::as_str).chain([bin()]);
    let mut cmd = Command::new(words.next().unwrap());
    cmd.args(words)
        .args(args)
        .env("XDG_CONFIG_HOME", dir)
        .env("HOME", dir)
        .current_dir(dir)
        .stdin(Stdio::null());
    cmd
}

/// A folder for one run under `prefix`, holding the good file `in-unreadable.csv`, of mode 000
/// or (`readable`) 644. The dropped user owns the folder (it may write the command's outputs
/// there) but not the file.
fn unreadable_room(prefix: &[String], readable: bool) -> tempfile::TempDir {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    if !prefix.is_empty() {
        std::os::unix::fs::chown(dir.path(), Some(NOBODY), Some(NOBODY)).unwrap();
    }
    let p = hostile_file("unreadable", dir.path());
    if readable {
        std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o644)).unwrap();
    }
    dir
}

/// The run of `args` under `prefix` with the file unreadable, and with it readable.
type Pair = (Result<(i32, String), String>, Result<(i32, String), String>);

fn unreadable_pair(prefix: &[String], args: &[String]) -> Pair {
    let run = |readable| {
        let dir = unreadable_room(prefix, readable);
        run_command(command_as(prefix, dir.path(), args), args)
    };
    (run(false), run(true))
}

/// The verdict on one input file flag: `Ok(true)` refused as it must be, `Ok(false)` never
/// reached (each base refuses the command before it opens the file: the run with the file
/// readable says the same), `Err` what was wrong.
fn unreadable_verdict(prefix: &[String], candidates: &[Vec<String>]) -> Result<bool, String> {
    for args in candidates {
        let (locked, open) = unreadable_pair(prefix, args);
        if locked == open {
            continue;
        }
        return match locked {
            Ok((2, stderr)) => {
                let line = stderr
                    .lines()
                    .find(|l| l.starts_with("bouncelab: error: "))
                    .unwrap_or_default();
                let said = line.contains("in-unreadable.csv")
                    && line.to_lowercase().contains("permission denied");
                said.then_some(true)
                    .ok_or_else(|| format!("{args:.300?}: refused without saying why: {line}"))
            }
            Ok((code, stderr)) => Err(format!(
                "{args:.300?}: exit {code}, not refused: {stderr:.300}"
            )),
            Err(e) => Err(format!("{args:.300?}: {e}")),
        };
    }
    Ok(false)
}

/// The refusal of an unreadable file, exercised under root too (issue 54, hostile generators:
/// root reads a mode-000 file, so the run that must refuse it had only ever been answered as
/// read). Every flag that reads a file is given a good file of mode 000; the run, under root
/// dropped to `nobody` by `setpriv`, must refuse it: exit 2, one `bouncelab: error:` line
/// naming the file and saying "permission denied". A flag is run on the command's docs
/// example, else on it without its `--preset`, else on `--preset tennis` alone, else alone,
/// the first on which the run with the
/// file readable answers otherwise (the file is opened there: a base the flag conflicts with
/// is refused before it, the same with the file readable or not).
#[test]
fn every_input_file_flag_refuses_an_unreadable_file_even_under_root() {
    let scratch = tempfile::tempdir().unwrap();
    let Some(prefix) = unreadable_reader(scratch.path()) else {
        // never a silent pass: the output says what was not tested, and why
        eprintln!(
            "NOT TESTED: the tests run as root, who reads a mode-000 file, and `setpriv` \
             (util-linux) is absent to drop to uid {NOBODY}: the unreadable file's refusal \
             is not exercised"
        );
        return;
    };
    if !prefix.is_empty() {
        eprintln!("as root: each run drops to uid/gid {NOBODY} with setpriv");
    }
    let surface = surface();
    let examples = examples(&surface);
    let mut queue = Vec::new();
    for (path, flags) in &surface {
        for flag in flags.iter().filter(|f| takes_file(f) && !writes(f)) {
            let given = format!("{}=in-unreadable.csv", flag.long);
            let example = base(path, flags, flag, &examples);
            let mut candidates = vec![example.clone()];
            if flags.iter().any(|f| f.long == "--preset") && flag.long != "--preset" {
                // `--config` and its kin name the ball themselves
                candidates.push(without(&example, "--preset", true));
                candidates.push([path.clone(), vec!["--preset".into(), "tennis".into()]].concat());
            }
            candidates.push(path.clone());
            for c in &mut candidates {
                c.push(given.clone());
            }
            candidates.dedup();
            queue.push(candidates);
        }
    }
    assert!(queue.len() >= 20, "{} input file flags", queue.len());
    let queue = Mutex::new(queue);
    let verdicts = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| {
                while let Some(candidates) = queue.lock().unwrap().pop() {
                    let v = unreadable_verdict(&prefix, &candidates);
                    let flag = format!("{} {}", candidates[0][0], candidates[0].last().unwrap());
                    verdicts.lock().unwrap().push((flag, v));
                }
            });
        }
    });
    let verdicts = verdicts.into_inner().unwrap();
    let refused = verdicts.iter().filter(|(_, v)| v == &Ok(true)).count();
    let unreached: Vec<&str> = verdicts
        .iter()
        .filter(|(_, v)| v == &Ok(false))
        .map(|(f, _)| f.as_str())
        .collect();
    eprintln!(
        "{refused} input file flags refused an unreadable file; not reached by any base: \
         {unreached:?}"
    );
    let failures: Vec<&String> = verdicts
        .iter()
        .filter_map(|(_, v)| v.as_ref().err())
        .collect();
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(refused >= 20, "only {refused} flags reached");
}
