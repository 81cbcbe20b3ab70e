//! Writing a preset file so that a crash or a kill at any moment leaves either no file or a
//! complete one — never a truncated preset, which would stop every command that reads the
//! catalog — and so that nothing is replaced unless the caller says so.
//!
//! Both functions go through the program's one atomic writer, [`crate::atomic::Outputs`]
//! (see there for what holds): a synced temporary file beside the target, named
//! `.<file>.<pid>-<random>.tmp` — it starts with `.` and does not end in `.toml`, so the
//! catalog never reads a leftover one — published by a rename that, for [`create_new`],
//! refuses an existing target in the same step (with a fallback for file systems without hard
//! links), and removed on every error path. The text is written as given (a preset is TOML
//! the caller built; no control characters are rewritten).

use crate::atomic::{OutputError, Outputs};
use std::io;
use std::path::Path;

/// Write `text` to `path`, which must not exist: `AlreadyExists` if it does (also when it
/// appears while this runs). The folder must exist.
pub fn create_new(path: &Path, text: &str) -> io::Result<()> {
    write(path, text, false)
}

/// Replace `path` with `text` (or create it), atomically; a replaced file keeps its mode.
pub fn replace(path: &Path, text: &str) -> io::Result<()> {
    write(path, text, true)
}

fn write(path: &Path, text: &str, force: bool) -> io::Result<()> {
    let mut out = Outputs::new(force);
    out.bytes(path, text.as_bytes())
        .and_then(|()| out.commit().map(drop))
        .map_err(|e: OutputError| e.error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::atomic::tests::entries;
    use std::fs;

    #[test]
    fn create_new_writes_and_leaves_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.toml");
        create_new(&p, "name = \"a\"\n").unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "name = \"a\"\n");
        assert_eq!(entries(dir.path()), ["a.toml"]);
    }

    #[test]
    fn create_new_never_clobbers_and_cleans_up() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.toml");
        fs::write(&p, "mine").unwrap();
        let e = create_new(&p, "theirs").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(fs::read_to_string(&p).unwrap(), "mine");
        assert_eq!(
            entries(dir.path()),
            ["a.toml"],
            "the temporary file is removed"
        );
    }

    #[test]
    fn replace_swaps_the_content() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.toml");
        fs::write(&p, "old").unwrap();
        replace(&p, "new").unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "new");
        assert_eq!(entries(dir.path()), ["a.toml"]);
    }

    #[test]
    fn a_failed_publication_removes_the_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        // renaming a file over a non-empty folder fails
        let p = dir.path().join("a.toml");
        fs::create_dir(&p).unwrap();
        fs::write(p.join("inside"), "x").unwrap();
        assert!(replace(&p, "new").is_err());
        assert_eq!(entries(dir.path()), ["a.toml"]);
    }

    #[cfg(unix)]
    #[test]
    fn replace_keeps_the_mode_of_the_replaced_file() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.toml");
        fs::write(&p, "old").unwrap();
        fs::set_permissions(&p, fs::Permissions::from_mode(0o640)).unwrap();
        replace(&p, "new").unwrap();
        let mode = fs::metadata(&p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
    }
}
