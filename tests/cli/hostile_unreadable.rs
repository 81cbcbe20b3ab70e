//! Issue 54's hostile generators (tests/support/hostile): every flag that reads a file refuses
//! one it may not read, exit 2, even when the tests run as root (the run is then made as
//! `nobody`).

use crate::hostile;
use hostile::*;
use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::Mutex;

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
