//! Issue 54 item 3: outputs are written over regular files only. `mknod dev_null c 1 3;
//! bouncelab fit --cor-table cor.csv --plot dev_null --force` left a regular file where the
//! device was (run as root against /dev/null it replaced the machine's own); so did `mc` and
//! `batch --csv-out`, `map --out` and `figure --csv-out`. Now a device, FIFO or socket is
//! refused with its kind named, exit 2, with `--force` or without, and left as it was.
#![cfg(unix)]

use crate::common;
use common::{argv, argv_with, assert_bad, bl_at};
use std::fs;
use std::os::unix::fs::FileTypeExt;
use std::path::Path;
use std::process::Command;

const COR: &str = "v0,cor\n2,0.8\n4,0.75\n6,0.7\n";
const LOT: &str = "id,drop_height_m,rebound_height_m\nA1,2.54,1.40\nA2,2.54,1.45\n";

/// Every command × output flag of the issue, writing to `target`.
fn commands(target: &str) -> Vec<Vec<&str>> {
    vec![
        vec!["fit", "--cor-table", "cor.csv", "--plot", target],
        argv_with("mc --vary k_p=5% --samples 20 --csv-out {}", &[target]),
        argv_with("batch lot.csv --preset tennis --csv-out {}", &[target]),
        argv_with("map --lambda 0.1:10:4 --zeta 0.1:10:4 --out {}", &[target]),
        argv_with("figure force-time --out f.svg --csv-out {}", &[target]),
    ]
}

/// (name, kind in the message, maker); the device only where this process may make one.
fn specials(d: &Path) -> Vec<(&'static str, &'static str)> {
    let mut v = Vec::new();
    let ok = |c: &mut Command| c.current_dir(d).status().is_ok_and(|s| s.success());
    if ok(Command::new("mkfifo").arg("fifo")) {
        v.push(("fifo", "is a FIFO, not a regular file"));
    }
    if std::os::unix::net::UnixListener::bind(d.join("sock")).is_ok() {
        v.push(("sock", "is a socket, not a regular file"));
    }
    // a character device like /dev/null (1, 3): root only
    if ok(Command::new("mknod").args(["dev_null", "c", "1", "3"])) {
        v.push(("dev_null", "is a character device, not a regular file"));
    }
    v
}

fn kind_of(p: &Path) -> fs::FileType {
    fs::symlink_metadata(p).unwrap().file_type()
}

#[test]
fn no_output_flag_replaces_a_device_a_fifo_or_a_socket() {
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    fs::write(d.join("cor.csv"), COR).unwrap();
    fs::write(d.join("lot.csv"), LOT).unwrap();
    let specials = specials(d);
    assert!(
        specials.len() >= 2,
        "a FIFO and a socket can always be made"
    );
    for (name, says) in &specials {
        for cmd in commands(name) {
            for force in [true, false] {
                let mut args = cmd.clone();
                args.extend(force.then_some("--force"));
                let o = bl_at(d, &args);
                assert_bad(&o, &[name, says, "outputs replace regular files only"]);
                let t = kind_of(&d.join(name));
                assert!(!t.is_file(), "{args:?} replaced {name} with a regular file");
                assert!(!d.join("f.svg").exists(), "{args:?}: a figure beside it");
            }
        }
    }
    // the special files are the same kind they were
    for (name, _) in &specials {
        let t = kind_of(&d.join(name));
        assert!(t.is_fifo() || t.is_socket() || t.is_char_device(), "{name}");
    }
}

#[test]
fn a_link_to_a_device_is_replaced_itself_never_the_device() {
    // the rename replaces the name: the link goes, what it led to stays
    let d = tempfile::tempdir().unwrap();
    let d = d.path();
    fs::write(d.join("cor.csv"), COR).unwrap();
    assert!(
        Command::new("mkfifo")
            .arg("fifo")
            .current_dir(d)
            .status()
            .unwrap()
            .success()
    );
    std::os::unix::fs::symlink("fifo", d.join("plot.svg")).unwrap();
    let o = bl_at(d, &argv("fit --cor-table cor.csv --plot plot.svg --force"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(kind_of(&d.join("plot.svg")).is_file());
    assert!(kind_of(&d.join("fifo")).is_fifo());
}

#[test]
fn the_atomic_writer_refuses_a_special_file_that_appears_after_the_check() {
    // the commit checks again: a FIFO made between the staging and the rename stays
    let d = tempfile::tempdir().unwrap();
    let target = d.path().join("out.csv");
    let mut files = bouncelab::atomic::Outputs::new(true);
    files.text(&target, "a,b\n").unwrap();
    assert!(
        Command::new("mkfifo")
            .arg(&target)
            .status()
            .unwrap()
            .success()
    );
    let e = files.commit().unwrap_err();
    assert_eq!(e.error.kind(), std::io::ErrorKind::InvalidInput);
    assert!(
        e.error.to_string().contains("a FIFO, not a regular file"),
        "{e}"
    );
    assert!(kind_of(&target).is_fifo());
    // and nothing staged is left behind
    let names: Vec<_> = fs::read_dir(d.path()).unwrap().collect();
    assert_eq!(names.len(), 1, "{names:?}");
}
