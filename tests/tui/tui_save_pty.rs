//! Saving a preset from the real explorer under a pseudo-terminal (`s`, Enter, and `y` at the
//! overwrite question), and a SIGKILL in the middle of the write: with the test-only fault
//! `BOUNCELAB_TEST_FAULT=pause-mid-save` the writer stops for 30 s with half of the temporary
//! file written, and the test kills the process there. Afterwards there must be no preset
//! file (a new name) or the old one byte for byte (an overwrite), never a truncated preset;
//! and the catalog must still load, the leftover hidden temporary file being ignored.
#![cfg(unix)]

use crate::pty;

use bouncelab::catalog::{self, Catalog};
use pty::{Explorer, signal};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const NAME: &str = "superball-custom";

fn presets_dir(home: &Path) -> PathBuf {
    home.join("bouncelab").join("presets")
}

/// The hidden temporary files in `dir` that hold something.
fn partial_temp_files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else {
        return Vec::new();
    };
    entries
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.starts_with('.')
                && name.ends_with(".tmp")
                && fs::metadata(p).is_ok_and(|m| m.len() > 0)
        })
        .collect()
}

/// `bouncelab ARGS` with `home` as the config folder: (success, stdout, stderr).
fn cli(home: &Path, args: &[&str]) -> (bool, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_bouncelab"))
        .args(args)
        .env("XDG_CONFIG_HOME", home)
        .env("HOME", home)
        .env_remove("BOUNCELAB_TEST_FAULT")
        .output()
        .unwrap();
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// Kill the explorer once the writer has paused with the temporary file half written; the
/// temporary file (still there: nobody cleaned up) is returned.
fn kill_mid_write(mut x: Explorer, dir: &Path) -> PathBuf {
    x.wait_until("a half-written temporary file", || {
        !partial_temp_files(dir).is_empty()
    });
    x.kill();
    let (status, _, out) = x.finish();
    assert_eq!(
        signal(&status),
        Some(9),
        "{status:?}\n{}",
        out.escape_debug()
    );
    let mut tmp = partial_temp_files(dir);
    assert_eq!(tmp.len(), 1, "{tmp:?}");
    tmp.remove(0)
}

/// The temporary file is a strict prefix of a preset, which does not parse on its own.
fn assert_truncated(tmp: &Path) {
    let text = fs::read_to_string(tmp).unwrap();
    assert!(
        text.starts_with("# Saved from the bouncelab explorer"),
        "{text}"
    );
    assert!(
        !text.contains("\n[adopted]\n"),
        "the second half was never written"
    );
    assert!(
        bouncelab::preset::Preset::parse(&text, "tmp").is_err(),
        "half a preset is not a preset"
    );
}

/// The catalog still loads, the dot-file is not read, and `presets` says so on the command
/// line too.
fn assert_catalog_loads(home: &Path, expect_saved: bool) {
    let cat = Catalog::load(Some(&presets_dir(home)), None).expect("the catalog loads");
    assert_eq!(cat.get(NAME).is_ok(), expect_saved);
    let embedded = bouncelab::preset::EMBEDDED.len();
    assert_eq!(cat.entries().len(), embedded + usize::from(expect_saved));
    let (ok, out, err) = cli(home, &["presets"]);
    assert!(ok && err.is_empty(), "{err}");
    assert_eq!(out.contains(NAME), expect_saved, "{out}");
}

#[test]
fn a_kill_while_saving_a_new_preset_leaves_no_preset_file() {
    let home = tempfile::tempdir().unwrap();
    let dir = presets_dir(home.path());
    let mut x = Explorer::spawn(home.path(), Some("pause-mid-save"), &[]);
    x.wait_for_first_draw();
    x.send(b"lls");
    x.wait_for(NAME); // the prompt, with the suggested name
    x.send(b"\r");
    let tmp = kill_mid_write(x, &dir);
    assert_truncated(&tmp);
    assert!(
        !dir.join(format!("{NAME}.toml")).exists(),
        "no preset file, not even an empty or partial one"
    );
    assert_catalog_loads(home.path(), false);
}

#[test]
fn a_kill_while_overwriting_leaves_the_old_file_intact() {
    let home = tempfile::tempdir().unwrap();
    let dir = presets_dir(home.path());
    let file = dir.join(format!("{NAME}.toml"));

    // a real save first, through the explorer's own loop
    let mut x = Explorer::spawn(home.path(), None, &[]);
    x.wait_for_first_draw();
    x.send(b"lls");
    x.wait_for(NAME);
    x.send(b"\r");
    x.wait_until("the saved file", || file.exists());
    x.wait_for("saved");
    x.send(b"q");
    let (status, _, _) = x.finish();
    assert!(status.success());
    let old = fs::read(&file).unwrap();
    let first = catalog::read_preset_file(&file).expect("a complete preset");
    assert_catalog_loads(home.path(), true);

    // the same name again with other parameters; y to the question; killed mid-write
    let mut x = Explorer::spawn(home.path(), Some("pause-mid-save"), &[]);
    x.wait_for_first_draw();
    x.send(b"LLs");
    x.wait_for(NAME);
    x.send(b"\r");
    x.wait_for("y/n");
    assert!(
        partial_temp_files(&dir).is_empty(),
        "nothing is written before the answer"
    );
    x.send(b"y");
    let tmp = kill_mid_write(x, &dir);
    assert_truncated(&tmp);
    assert_eq!(fs::read(&file).unwrap(), old, "the old file, byte for byte");
    assert_eq!(catalog::read_preset_file(&file).unwrap(), first);
    assert_catalog_loads(home.path(), true);
    let (ok, out, err) = cli(home.path(), &["run", "--preset", NAME, "--format", "json"]);
    assert!(ok, "{err}");
    assert!(out.contains("\"preset\":\"superball-custom\""), "{out}");
}

/// `S` in the real loop: onto a file that exists it asks y/n (n keeps the file byte for
/// byte, y replaces it with the session); into a folder that does not exist it names the
/// system's reason and keeps the entry open (issue 51 item 2).
#[test]
fn s_asks_before_replacing_a_session_file_and_says_why_a_write_failed() {
    let home = tempfile::tempdir().unwrap();
    let file = home.path().join("s.toml");
    fs::write(&file, "old\n").unwrap();
    let mut x = Explorer::spawn(home.path(), None, &[]);
    x.wait_for_first_draw();
    let save_to = |x: &mut Explorer, path: &str| {
        x.send(b"S");
        x.wait_for("session");
        x.send(b"\x15"); // Ctrl-U: the suggested name cleared
        x.send(path.as_bytes());
        x.send(b"\r");
    };
    let path = file.to_string_lossy().into_owned();
    save_to(&mut x, &path);
    x.wait_for("y/n");
    x.send(b"n");
    x.wait_for("kept");
    assert_eq!(fs::read_to_string(&file).unwrap(), "old\n");
    save_to(&mut x, &path);
    x.wait_for("y/n");
    x.send(b"y");
    x.wait_until("the session written", || {
        fs::read_to_string(&file).is_ok_and(|t| t.contains("view"))
    });
    let nowhere = home.path().join("no-such-folder").join("s.toml");
    save_to(&mut x, &nowhere.to_string_lossy());
    x.wait_for("No such file");
    // the entry is still open: Esc closes it, then q quits (the session is saved)
    x.send(b"\x1b");
    // apart from the Esc, or the terminal reads Alt-q
    std::thread::sleep(std::time::Duration::from_millis(300));
    x.send(b"q");
    let (status, _, out) = x.finish();
    assert!(status.success(), "{status:?}\n{}", out.escape_debug());
}
