//! The hostile generators' means (tests/cli/hostile_generators.rs, hostile_unreadable.rs):
//! every flag of every subcommand read from the binary's own `--help`, a base command line
//! for each from the docs' examples, the hostile files, and the runs, four at a time, each
//! ended by itself within `LIMIT` or killed.

use crate::common::command_in;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A run that has not ended by then is a failure (it is killed): the debug binary on a loaded
/// machine; a refusal takes milliseconds, the work limit bounds the rest (docs/guarantees.md).
pub const LIMIT: Duration = Duration::from_secs(60);

pub fn bin() -> &'static str {
    env!("CARGO_BIN_EXE_bouncelab")
}

pub fn help(args: &[&str]) -> String {
    let o = Command::new(bin())
        .args(args)
        .arg("--help")
        .output()
        .unwrap();
    String::from_utf8(o.stdout).unwrap()
}

/// The names listed under `Commands:` in a help text (but `help`).
pub fn commands(help: &str) -> Vec<String> {
    section(help, "Commands:")
        .iter()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_string)
        .collect()
}

/// The lines of one section of a help text (`Commands:`, `Options:`), each an entry's first.
pub fn section<'a>(help: &'a str, title: &str) -> Vec<&'a str> {
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
pub struct Flag {
    pub long: String,
    pub value: Option<String>,
}

pub fn flags(help: &str) -> Vec<Flag> {
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
pub fn surface() -> Vec<(Vec<String>, Vec<Flag>)> {
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
pub fn writes(f: &Flag) -> bool {
    ["out", "plot", "save", "export", "dir"]
        .iter()
        .any(|w| f.long.contains(w))
}

/// A flag whose value is a path.
pub fn takes_file(f: &Flag) -> bool {
    f.value.as_deref().is_some_and(|v| {
        let v = v.to_ascii_uppercase();
        v.contains("FILE") || v.contains("PATH") || v.contains("DIR")
    })
}

/// One run's verdict: `Err` with what was wrong.
pub fn run(args: &[String], dir: &Path) -> Result<i32, String> {
    run_command(command_in(dir, args), args).map(|(code, _)| code)
}

/// The verdict of `cmd`, a run of `args`: its exit code and stderr, `Err` with what was wrong.
pub fn run_command(mut cmd: Command, args: &[String]) -> Result<(i32, String), String> {
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
pub fn run_all(
    runs: Vec<Vec<String>>,
    prepare: &(dyn Fn(&Path) + Sync),
) -> (Vec<String>, [usize; 3]) {
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

/// The docs' `$ bouncelab …` examples that answer (tests/project/docs_examples.rs runs them;
/// one shown refused, its next line `bouncelab: error:`, is left out), plain words only (no
/// pipe, redirection or quote), a file they name made absolute: the first of each command
/// path is that command's base, so the flag under test meets a command that otherwise
/// answers.
pub fn examples(surface: &[(Vec<String>, Vec<Flag>)]) -> Vec<(Vec<String>, Vec<String>)> {
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
        let lines: Vec<&str> = text.lines().map(str::trim).collect();
        for (i, line) in lines.iter().enumerate() {
            let Some(rest) = line.strip_prefix("$ bouncelab ") else {
                continue;
            };
            // an example the page shows refused is no base: a base answers
            if lines
                .get(i + 1)
                .is_some_and(|next| next.starts_with("bouncelab: error:"))
            {
                continue;
            }
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
pub fn base(
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
pub fn without(args: &[String], flag: &str, valued: bool) -> Vec<String> {
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

/// The hostile files: (name, how it is made in `dir`; the path given).
pub fn hostile_file(kind: &str, dir: &Path) -> PathBuf {
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
