//! Issue 54 item 5 (and item 9's `--session` with `--measured`): `--session` reads a regular
//! file only, at most 1 MiB, as the data readers do. `mkfifo f; bouncelab --session f` hung,
//! `--session /dev/zero` reached 3 GB, a missing or non-UTF-8 session exited 1; now each is one
//! line naming the file, exit 2, at once.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// `bouncelab ARGS` with a deadline: (exit code, stderr); a run past it is killed and fails.
fn run_within(args: &[&str], seconds: u64) -> (i32, String) {
    let home = tempfile::tempdir().unwrap();
    wait_within(crate::common::command(home.path(), args), args, seconds)
}

/// `cmd` run to its end with a deadline: (exit code, stderr); a run past it is killed and
/// fails, naming `args`.
fn wait_within(mut cmd: Command, args: &[&str], seconds: u64) -> (i32, String) {
    let mut child = cmd
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let mut err = String::new();
            std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
            return (status.code().expect("exited"), err);
        }
        if start.elapsed() > Duration::from_secs(seconds) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?} still ran after {seconds} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn refused(path: &Path, why: &str) {
    let p = path.to_str().unwrap();
    let (code, err) = run_within(&["--session", p], 20);
    assert_eq!(code, 2, "{p}: {err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("bouncelab: error: --session "), "{err}");
    assert!(err.contains(p), "names the file: {err}");
    assert!(err.contains(why), "{why:?} not in {err}");
}

#[test]
fn missing_directories_and_non_utf8_are_exit_2_naming_the_file() {
    let d = tempfile::tempdir().unwrap();
    refused(&d.path().join("gone.toml"), "no such file");
    refused(d.path(), "is a directory");
    let latin1 = d.path().join("latin1.toml");
    std::fs::write(&latin1, b"# caf\xe9\nversion = 2\n").unwrap();
    refused(&latin1, "not UTF-8");
}

#[test]
fn a_file_too_large_is_refused_before_it_is_read() {
    let d = tempfile::tempdir().unwrap();
    let big = d.path().join("big.toml");
    let line = "# a comment line, a session holds none this long\n";
    std::fs::write(&big, line.repeat((2 << 20) / line.len())).unwrap();
    refused(&big, "a session file is at most 1048576 bytes");
}

#[cfg(unix)]
#[test]
fn fifos_and_devices_are_not_read() {
    let d = tempfile::tempdir().unwrap();
    let fifo = d.path().join("f");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    refused(&fifo, "is not a regular file");
    refused(Path::new("/dev/zero"), "is not a regular file");
}

#[cfg(unix)]
#[test]
fn an_unreadable_session_is_exit_2() {
    use std::os::unix::fs::PermissionsExt;
    let d = tempfile::tempdir().unwrap();
    // the folder open to all (a dropped user must reach the file to be refused by it)
    std::fs::set_permissions(d.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let p = d.path().join("locked.toml");
    std::fs::write(&p, "version = 2\n").unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o000)).unwrap();
    if std::fs::read(&p).is_err() {
        return refused(&p, "permission denied");
    }
    // root reads a mode-000 file: the run drops to nobody (65534) with util-linux's setpriv,
    // as hostile_generators' unreadable-file test does; never a silent pass without it
    let there = Command::new("setpriv").arg("--version").output();
    if !there.is_ok_and(|o| o.status.success()) {
        eprintln!(
            "NOT TESTED: root reads a mode-000 file and `setpriv` is absent to drop to nobody"
        );
        return;
    }
    let home = tempfile::tempdir().unwrap();
    std::os::unix::fs::chown(home.path(), Some(65534), Some(65534)).unwrap();
    let path = p.to_str().unwrap();
    let mut cmd = Command::new("setpriv");
    cmd.args(["--reuid=65534", "--regid=65534", "--clear-groups", "--"])
        .arg(env!("CARGO_BIN_EXE_bouncelab"))
        .args(["--session", path])
        .env("XDG_CONFIG_HOME", home.path())
        .env("HOME", home.path())
        .stdin(Stdio::null());
    let (code, err) = wait_within(cmd, &["--session", path], 20);
    assert_eq!(code, 2, "{path}: {err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("bouncelab: error: --session "), "{err}");
    assert!(
        err.contains(path) && err.contains("permission denied"),
        "{err}"
    );
}

#[test]
fn a_session_with_measured_is_refused_as_the_docs_say() {
    // docs/explorer.md, Sessions: `--session` takes no `--measured` (the session names its
    // own); a session naming none let `--measured` through
    let d = tempfile::tempdir().unwrap();
    let s = d.path().join("s.toml");
    let cor = d.path().join("cor.csv");
    std::fs::write(&cor, "v0,cor\n2,0.8\n4,0.75\n").unwrap();
    let app = bouncelab::tui::app::App::new(bouncelab::preset::Preset::embedded().remove(1), false);
    std::fs::write(&s, app.session().to_toml()).unwrap();
    let (code, err) = run_within(
        &[
            "--session",
            s.to_str().unwrap(),
            "--measured",
            cor.to_str().unwrap(),
        ],
        20,
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--session restores the whole state"), "{err}");
}
