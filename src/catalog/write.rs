//! Writing a preset file so that a crash or a kill at any moment leaves either no file or a
//! complete one — never a truncated preset, which would stop every command that reads the
//! catalog — and so that nothing is replaced unless the caller says so.
//!
//! The text goes first to a temporary file in the same folder (so the final step is a link or
//! rename within one file system), named `.<file>.<pid>-<nanos>.tmp`: it starts with `.` and
//! does not end in `.toml`, so the catalog never reads a leftover one. It is synced before it
//! is published:
//!
//! - [`create_new`] publishes with `hard_link(tmp, final)`, which fails when `final` exists:
//!   the check and the publication are one atomic step, so a file that appears at the last
//!   moment is not clobbered (the caller gets `AlreadyExists`). On file systems without hard
//!   links (FAT, some network shares) it claims the name with an empty `create_new` file and
//!   renames the temporary file over it: still no clobbering, but a kill between those two
//!   steps (microseconds) can leave an empty `final`, which the catalog then reports as an
//!   error naming the file. A link is preferred for that reason.
//! - [`replace`] (an overwrite the user confirmed) publishes with `rename(tmp, final)`, atomic
//!   on POSIX: readers see the old file or the new one.
//!
//! Afterwards the folder is synced so the new name survives a power cut. The temporary file is
//! removed on every error path.

use crate::fault::{self, Fault};
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Write `text` to `path`, which must not exist: `AlreadyExists` if it does (also when it
/// appears while this runs). The folder must exist.
pub fn create_new(path: &Path, text: &str) -> io::Result<()> {
    publish(path, text, |tmp, path| match fs::hard_link(tmp, path) {
        Err(e) if no_hard_links(&e) => claim_then_rename(tmp, path),
        other => other,
    })
}

/// Replace `path` with `text` (or create it), atomically.
pub fn replace(path: &Path, text: &str) -> io::Result<()> {
    publish(path, text, |tmp, path| fs::rename(tmp, path))
}

/// Write the temporary file, publish it with `step`, sync the folder; the temporary file is
/// gone afterwards whatever happened (after a hard link it is a second name to remove).
fn publish(
    path: &Path,
    text: &str,
    step: impl FnOnce(&Path, &Path) -> io::Result<()>,
) -> io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let (tmp, file) = create_temp(dir, path)?;
    let result = write_synced(file, text).and_then(|()| step(&tmp, path));
    // after a rename the temporary name no longer exists; NotFound is expected then
    let _ = fs::remove_file(&tmp);
    result?;
    sync_dir(dir)
}

/// A new temporary file next to `path`, created "new" so two writers never share one.
fn create_temp(dir: &Path, path: &Path) -> io::Result<(PathBuf, File)> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "preset".into());
    let mut last = None;
    for attempt in 0..16u32 {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.subsec_nanos());
        let tmp = dir.join(format!(
            ".{name}.{}-{}.tmp",
            std::process::id(),
            nanos.wrapping_add(attempt)
        ));
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| io::Error::other("no free temporary name")))
}

/// Write all of `text` and wait until it is on disk.
fn write_synced(mut file: File, text: &str) -> io::Result<()> {
    let bytes = text.as_bytes();
    if Fault::PauseMidSave.active() {
        // test-only (see `crate::fault`): stop with half the text written, so that a test can
        // kill the process mid-write
        let half = bytes.len() / 2;
        file.write_all(&bytes[..half])?;
        file.sync_all()?;
        std::thread::sleep(fault::PAUSE);
        file.write_all(&bytes[half..])?;
    } else {
        file.write_all(bytes)?;
    }
    file.sync_all()
}

/// Whether a failed `hard_link` means the file system has none (rather than a real error).
fn no_hard_links(e: &io::Error) -> bool {
    // EPERM is what Linux's FAT driver answers; a folder we may not write to fails earlier,
    // when the temporary file is created
    matches!(
        e.kind(),
        io::ErrorKind::Unsupported | io::ErrorKind::PermissionDenied
    )
}

/// The fallback publication without hard links: take the name with an empty file created
/// "new" (fails if it exists), then move the complete temporary file over it.
fn claim_then_rename(tmp: &Path, path: &Path) -> io::Result<()> {
    OpenOptions::new().write(true).create_new(true).open(path)?;
    fs::rename(tmp, path).inspect_err(|_| {
        // the empty placeholder is ours: do not leave it behind as a broken preset
        let _ = fs::remove_file(path);
    })
}

/// Make the folder's new entry durable. Some file systems cannot sync a folder (EINVAL): the
/// file itself is synced, so that is not treated as a failure.
fn sync_dir(dir: &Path) -> io::Result<()> {
    #[cfg(unix)]
    {
        match File::open(dir).and_then(|d| d.sync_all()) {
            Err(e) if e.kind() != io::ErrorKind::InvalidInput => return Err(e),
            _ => {}
        }
    }
    #[cfg(not(unix))]
    let _ = dir;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

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
}
