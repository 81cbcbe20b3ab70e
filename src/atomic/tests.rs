//! The unit tests of the atomic writer (`src/atomic.rs`).

use super::*;

/// The names in `dir`, sorted: what a writer left there (also the catalog's tests').
pub(crate) fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn nothing_is_published_before_commit_and_a_drop_removes_the_temporaries() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.svg"), dir.path().join("b.csv"));
    fs::write(&a, "old").unwrap();
    let mut out = Outputs::new(true);
    out.text(&a, "new a").unwrap();
    out.text(&b, "new b").unwrap();
    assert_eq!(fs::read_to_string(&a).unwrap(), "old");
    assert!(!b.exists());
    drop(out);
    assert_eq!(entries(dir.path()), ["a.svg"]);
    assert_eq!(fs::read_to_string(&a).unwrap(), "old");
}

#[test]
fn a_failed_stage_leaves_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut out = Outputs::new(false);
    out.text(&dir.path().join("a.svg"), "a").unwrap();
    let e = out
        .text(&dir.path().join("missing/b.csv"), "b")
        .unwrap_err();
    assert!(e.to_string().ends_with("missing/b.csv"), "{e}");
    drop(out); // the command returns its error
    assert!(entries(dir.path()).is_empty());
}

#[test]
fn commit_replaces_with_force_and_refuses_without() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.svg"), dir.path().join("b.csv"));
    let mut out = Outputs::new(false);
    out.text(&a, "a1\u{1b}[2J").unwrap();
    out.text(&b, "b1").unwrap();
    assert_eq!(out.commit().unwrap(), [a.clone(), b.clone()]);
    assert_eq!(fs::read_to_string(&a).unwrap(), "a1\\u{1b}[2J");
    // b appears between staging and commit: neither file is published
    fs::remove_file(&b).unwrap();
    fs::remove_file(&a).unwrap();
    let mut out = Outputs::new(false);
    out.text(&a, "a2").unwrap();
    out.text(&b, "b2").unwrap();
    fs::write(&b, "someone else's").unwrap();
    let e = out.commit().unwrap_err();
    assert!(e.exists && e.path == b, "{e}");
    assert_eq!(entries(dir.path()), ["b.csv"]);
    let mut out = Outputs::new(true);
    out.text(&b, "b3").unwrap();
    out.commit().unwrap();
    assert_eq!(fs::read_to_string(&b).unwrap(), "b3");
    assert_eq!(entries(dir.path()), ["b.csv"]);
}

#[test]
fn a_failed_rename_puts_the_replaced_files_back() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.svg"), dir.path().join("b.csv"));
    fs::write(&a, "old").unwrap();
    // a rename over a folder that holds something fails
    fs::create_dir(&b).unwrap();
    fs::write(b.join("inside"), "x").unwrap();
    let mut out = Outputs::new(true);
    out.text(&a, "new").unwrap();
    out.text(&b, "new").unwrap();
    let e = out.commit().unwrap_err();
    assert_eq!(e.path, b);
    assert_eq!(fs::read_to_string(&a).unwrap(), "old", "a.svg is put back");
    assert_eq!(
        entries(dir.path()),
        ["a.svg", "b.csv"],
        "no temporary, no backup"
    );
}

#[test]
fn stale_temporaries_of_dead_processes_are_removed() {
    let dir = tempfile::tempdir().unwrap();
    // a process that has exited: its id is free (until reused, which this test's
    // few milliseconds do not reach)
    let mut child = std::process::Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let mine = std::process::id();
    let names = [
        format!(".golf2.toml.{dead}-1700000000.tmp"), // catalog::write's name
        format!(".a.svg.{dead}-Ab3dE5f7.tmp"),
        format!(".a.svg.{mine}-Ab3dE5f7.tmp"), // a live process's: kept
        format!(".a.svg.{dead}.tmp"),          // not our pattern: kept
        "notes.tmp".to_string(),
    ];
    for n in &names {
        fs::write(dir.path().join(n), "x").unwrap();
    }
    remove_stale(dir.path(), |_| true);
    let mut kept = names[2..].to_vec();
    kept.sort();
    assert_eq!(entries(dir.path()), kept);
}

#[test]
fn the_fallback_without_links_does_not_clobber_either() {
    let dir = tempfile::tempdir().unwrap();
    let (tmp, p) = (dir.path().join(".t.tmp"), dir.path().join("a.toml"));
    fs::write(&tmp, "new").unwrap();
    claim_then_rename(&tmp, &p).unwrap();
    assert_eq!(fs::read_to_string(&p).unwrap(), "new");
    assert!(!tmp.exists());
    fs::write(&tmp, "newer").unwrap();
    let e = claim_then_rename(&tmp, &p).unwrap_err();
    assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
    assert_eq!(fs::read_to_string(&p).unwrap(), "new");
}

#[test]
fn temp_names_parse() {
    assert_eq!(
        parse_temp_name(".a.b.svg.12-xY9.tmp"),
        Some(("a.b.svg", 12))
    );
    assert_eq!(parse_temp_name(".a.svg.12-.tmp"), None);
    assert_eq!(parse_temp_name("a.svg.12-x.tmp"), None);
    assert_eq!(parse_temp_name(".a.svg.1x-y.tmp"), None);
}
