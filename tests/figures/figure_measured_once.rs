//! `figure --measured FILE` reads each file once, before any solving, and draws what it read.
//! It read each file a second time after the solving: a file moved away or rewritten while a
//! long figure was computed failed the command, or drew data other than what was checked.

use crate::common;
use std::process::Stdio;
use std::time::{Duration, Instant, SystemTime};

/// Whether reading a file is seen here by its access time (set in the past, a `relatime` or
/// `strictatime` mount updates it on the next read; a `noatime` one never does).
fn reads_are_seen(dir: &std::path::Path, past: SystemTime) -> bool {
    let probe = dir.join("probe");
    std::fs::write(&probe, "x").unwrap();
    set_accessed(&probe, past);
    std::fs::read(&probe).unwrap();
    accessed_since(&probe, past)
}

fn set_accessed(path: &std::path::Path, t: SystemTime) {
    let f = std::fs::File::options().write(true).open(path).unwrap();
    f.set_times(std::fs::FileTimes::new().set_accessed(t))
        .unwrap();
}

fn accessed_since(path: &std::path::Path, t: SystemTime) -> bool {
    std::fs::metadata(path).unwrap().accessed().unwrap() > t
}

/// The file, removed as soon as the command has read it, is drawn: four balls' model curves of
/// 20 000 impacts each (some two seconds) lie between that read and the drawing. Fails on the old code:
/// "cors.csv: no such file", exit 2, from the second read.
#[test]
fn a_measured_file_is_read_once_before_the_solving() {
    let d = tempfile::tempdir().unwrap();
    let past = SystemTime::UNIX_EPOCH + Duration::from_secs(1_000_000_000);
    if !reads_are_seen(d.path(), past) {
        eprintln!("skipped: a read does not change a file's access time here (noatime)");
        return;
    }
    let path = d.path().join("cors.csv");
    std::fs::write(&path, "v0,cor\n1,0.85\n2,0.84\n4,0.83\n").unwrap();
    set_accessed(&path, past);
    let args = common::argv(
        "figure cor-velocity --preset superball --preset golf --preset tennis --preset baseball \
         --points 20000 --measured cors.csv --out f.svg",
    );
    let mut child = common::command_in(d.path(), &args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while !accessed_since(&path, past) {
        assert!(
            child.try_wait().unwrap().is_none(),
            "ended before reading the file"
        );
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "the file was never read"
        );
        std::thread::sleep(Duration::from_millis(1));
    }
    std::fs::remove_file(&path).unwrap();
    let o = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    let fig = common::parse_svg(&std::fs::read_to_string(d.path().join("f.svg")).unwrap());
    assert!(fig.texts.iter().any(|t| t == "cors.csv"), "{:?}", fig.texts);
}
