//! Writing a command's output files all or nothing.
//!
//! [`Outputs`] stages each file as a temporary file in the folder of its target (so the last
//! step is a rename within one file system), named `.<name>.<pid>-<random>.tmp`, written,
//! then synced; [`Outputs::commit`] renames them all into place once every one is staged,
//! then syncs the folders. What holds:
//!
//! - an existing file is replaced only by a complete new one (rename is atomic on POSIX): a
//!   full disk or a kill mid-write leaves the old file as it was
//!   (tests/cli/cli_guarantees.rs, `a_full_disk_leaves_the_old_figure_untouched`);
//! - a command that fails while staging leaves no new file and no temporary one: dropping
//!   [`Outputs`] removes its temporaries
//!   (`a_failure_leaves_no_new_file_and_a_rerun_is_not_refused`, and the unit tests in
//!   `atomic/tests.rs`);
//! - without `force` a target that exists is never replaced, not even one that appears while
//!   the command runs (`persist_noclobber`); if one does, the files this commit had already
//!   published are removed again;
//! - a temporary left by a killed process (kill -9 runs no destructor) is removed by the next
//!   writer of the same target, or by [`remove_stale`] at the explorer's start, once its
//!   process is gone (`stale_temporaries_of_dead_processes_are_removed`);
//! - a rename that fails after others succeeded (no cause is known short of a failing disk)
//!   undoes them: new files are removed, replaced ones put back from a hard link taken before
//!   the first rename (`a_failed_rename_puts_the_replaced_files_back`). Only on a file system
//!   without hard links does a replaced file stay replaced then.
//! - without `force` on a file system without hard links (FAT, some network shares), where
//!   the no-clobber rename is refused, the name is claimed with an empty file created "new"
//!   (fails if it exists) and the complete temporary renamed over it (`claim_then_rename`):
//!   still no clobbering; a kill between those two steps (microseconds) can leave an empty
//!   file, which a reader reports naming the file.
//!
//! This is the one atomic writer of the program: preset files (`catalog::write`) go through
//! it too.

mod kind;
pub use kind::{not_regular, refused_kind};

use std::ffi::OsStr;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use tempfile::NamedTempFile;

/// Files staged for one command.
pub struct Outputs {
    force: bool,
    staged: Vec<(PathBuf, NamedTempFile)>,
}

/// A failure, with the file it concerns.
#[derive(Debug)]
pub struct OutputError {
    pub path: PathBuf,
    pub error: io::Error,
    /// Without `force`, the target existed (or appeared meanwhile).
    pub exists: bool,
}

impl std::fmt::Display for OutputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.exists {
            write!(
                f,
                "{} exists (use --force to overwrite it)",
                self.path.display()
            )
        } else {
            // the cause follows as the error's source ("cannot write a.svg: No space left …")
            write!(f, "cannot write {}", self.path.display())
        }
    }
}

impl std::error::Error for OutputError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.error)
    }
}

fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

impl Outputs {
    /// `force`: replace existing targets; otherwise refuse them.
    pub fn new(force: bool) -> Self {
        Outputs {
            force,
            staged: Vec::new(),
        }
    }

    /// Stage `text` for `path`, with control characters made visible ([`crate::sanitize::text`]).
    pub fn text(&mut self, path: &Path, text: &str) -> Result<(), OutputError> {
        let clean = crate::sanitize::text(text);
        self.bytes(path, clean.as_bytes())
    }

    /// Stage `bytes` for `path`: written to a temporary file beside it and synced.
    pub fn bytes(&mut self, path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
        let fail = |error| OutputError {
            path: path.to_path_buf(),
            error,
            exists: false,
        };
        let dir = folder(path);
        let name = path.file_name().unwrap_or(OsStr::new("output"));
        remove_stale_of(dir, name);
        let prefix = format!(".{}.{}-", name.to_string_lossy(), std::process::id());
        let mut builder = tempfile::Builder::new();
        builder.prefix(&prefix).suffix(".tmp").rand_bytes(8);
        if let Some(mode) = mode_for(path) {
            builder.permissions(mode);
        }
        let mut tmp = builder
            .tempfile_in(dir)
            // tempfile names its temporary in the message: the user knows only `path`
            .map_err(|e| fail(io::Error::new(e.kind(), without_path(&e))))?;
        write_synced(tmp.as_file_mut(), bytes).map_err(fail)?;
        self.staged.push((path.to_path_buf(), tmp));
        Ok(())
    }

    /// Rename every staged file into place, in staging order; returns the targets. If one
    /// rename fails, those before it are undone: new files removed, replaced ones put back
    /// from a hard link taken before the first rename (where the file system has links).
    pub fn commit(self) -> Result<Vec<PathBuf>, OutputError> {
        // (without `force` every target is new: nothing to back up)
        let existed: Vec<bool> = self
            .staged
            .iter()
            .map(|(path, _)| self.force && fs::symlink_metadata(path).is_ok())
            .collect();
        let backups: Vec<Option<PathBuf>> = self
            .staged
            .iter()
            .zip(&existed)
            .map(|((path, _), &old)| if old { backup(path) } else { None })
            .collect();
        let mut published: Vec<PathBuf> = Vec::new();
        for (path, tmp) in self.staged {
            // a device, FIFO or socket is never replaced, also one that appeared after the
            // command's check (`refused_kind`)
            let result = if let Some(kind) = refused_kind(&path) {
                Err(tempfile::PersistError {
                    error: io::Error::new(io::ErrorKind::InvalidInput, not_regular(kind)),
                    file: tmp,
                })
            } else if self.force {
                tmp.persist(&path).map(drop)
            } else {
                persist_new(tmp, &path)
            };
            if let Err(e) = result {
                // dropping `e` removes the temporary file; the remaining ones go with `staged`
                let exists = !self.force && e.error.kind() == io::ErrorKind::AlreadyExists;
                for ((p, b), &old) in published.iter().zip(&backups).zip(&existed) {
                    let _ = match b {
                        Some(b) => fs::rename(b, p),
                        None if !old => fs::remove_file(p),
                        // replaced, with no link to put back (a file system without links)
                        None => Ok(()),
                    };
                }
                remove_all(&backups);
                return Err(OutputError {
                    path,
                    error: e.error,
                    exists,
                });
            }
            published.push(path);
        }
        remove_all(&backups);
        for dir in published.iter().map(|p| folder(p)) {
            sync_dir(dir);
        }
        Ok(published)
    }
}

/// Whether a file can be staged for `path` (its folder exists and takes a new file): a
/// temporary of the staging's own name made and removed at once, so that a command refuses a
/// read-only folder before its work, not after it (`cli::outputs::check`). A full disk shows
/// only when the staging writes.
pub fn probe(path: &Path) -> Result<(), OutputError> {
    let name = path.file_name().unwrap_or(OsStr::new("output"));
    let prefix = format!(".{}.{}-", name.to_string_lossy(), std::process::id());
    tempfile::Builder::new()
        .prefix(&prefix)
        .suffix(".tmp")
        .rand_bytes(8)
        .tempfile_in(folder(path))
        .map(drop)
        .map_err(|e| OutputError {
            path: path.to_path_buf(),
            error: io::Error::new(e.kind(), without_path(&e)),
            exists: false,
        })
}

/// Publish `tmp` as `path`, which must not exist (checked in the same step). Where the file
/// system has no hard links the no-clobber rename may be refused; then [`claim_then_rename`].
fn persist_new(tmp: NamedTempFile, path: &Path) -> Result<(), tempfile::PersistError> {
    match tmp.persist_noclobber(path) {
        Ok(_) => Ok(()),
        Err(e) if no_hard_links(&e.error) => {
            let tmp = e.file;
            match claim_then_rename(tmp.path(), path) {
                Ok(()) => Ok(()),
                // dropping `tmp` (inside the error) removes the temporary file
                Err(error) => Err(tempfile::PersistError { error, file: tmp }),
            }
        }
        Err(e) => Err(e),
    }
}

/// Whether a failed no-clobber publication means the file system has no hard links (rather
/// than a real error). EPERM is what Linux's FAT driver answers; a folder we may not write to
/// fails earlier, when the temporary file is created.
fn no_hard_links(e: &io::Error) -> bool {
    matches!(
        e.kind(),
        io::ErrorKind::Unsupported | io::ErrorKind::PermissionDenied
    )
}

/// The publication without hard links: take the name with an empty file created "new"
/// (`AlreadyExists` if it exists), then move the complete temporary file over it.
fn claim_then_rename(tmp: &Path, path: &Path) -> io::Result<()> {
    fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    fs::rename(tmp, path).inspect_err(|_| {
        // the empty placeholder is ours: do not leave it behind as a broken file
        let _ = fs::remove_file(path);
    })
}

static STOP: std::sync::OnceLock<std::sync::Arc<std::sync::atomic::AtomicBool>> =
    std::sync::OnceLock::new();

/// Stop staging once `flag` is set (the command line's SIGINT/SIGTERM flag): the write then
/// fails with [`io::ErrorKind::Interrupted`] and the temporary file is removed with its
/// [`Outputs`], so a signal mid-write leaves nothing behind (tests/cli/cli_progress_pty.rs,
/// `a_signal_mid_write_leaves_no_temporary_file`).
pub fn stop_on(flag: std::sync::Arc<std::sync::atomic::AtomicBool>) {
    let _ = STOP.set(flag);
}

fn stopped() -> bool {
    STOP.get()
        .is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
}

/// Bytes written between two looks at the stop flag.
const WRITE_CHUNK: usize = 1 << 20;
/// Bytes written between two waits for the disk: the final `sync_all`, which no signal
/// interrupts, then waits for at most this much (an 850 MB `mc --csv-out` once waited for all of
/// it before a Ctrl-C could end the command; issue 54 item 6).
const SYNC_EVERY: usize = 32 * WRITE_CHUNK;

/// Write all of `bytes` and wait until they are on disk, the disk waited for every
/// [`SYNC_EVERY`] bytes; [`io::ErrorKind::Interrupted`] once the stop flag is set.
fn write_synced(file: &mut fs::File, bytes: &[u8]) -> io::Result<()> {
    use crate::fault::{self, Fault};
    let stop = || io::Error::new(io::ErrorKind::Interrupted, "interrupted");
    let half = bytes.len() / 2;
    let pause = Fault::PauseMidSave.active();
    let (first, second) = if pause {
        bytes.split_at(half)
    } else {
        (bytes, &bytes[..0])
    };
    for (i, part) in [first, second].into_iter().enumerate() {
        for (k, chunk) in part.chunks(WRITE_CHUNK).enumerate() {
            if stopped() {
                return Err(stop());
            }
            file.write_all(chunk)?;
            if (k + 1) % (SYNC_EVERY / WRITE_CHUNK) == 0 {
                file.sync_data()?;
            }
        }
        if pause && i == 0 {
            // test-only (see `crate::fault`): stop with half the text written, so that a test
            // can kill or signal the process mid-write
            file.sync_all()?;
            let until = std::time::Instant::now() + fault::PAUSE;
            while std::time::Instant::now() < until && !stopped() {
                std::thread::sleep(std::time::Duration::from_millis(10));
            }
        }
    }
    if stopped() {
        return Err(stop());
    }
    file.sync_all()
}

/// A second name for the file at `path` (`.NAME.PID-bakN.tmp`, beside it), to put it back if
/// the commit fails; `None` when there is no file or no hard link can be made.
fn backup(path: &Path) -> Option<PathBuf> {
    static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    if !fs::symlink_metadata(path).is_ok_and(|m| m.is_file()) {
        return None;
    }
    let name = path.file_name()?.to_string_lossy().into_owned();
    for _ in 0..8 {
        let n = N.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let b = folder(path).join(format!(".{name}.{}-bak{n}.tmp", std::process::id()));
        match fs::hard_link(path, &b) {
            Ok(()) => return Some(b),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(_) => return None,
        }
    }
    None
}

fn remove_all(backups: &[Option<PathBuf>]) {
    for b in backups.iter().flatten() {
        let _ = fs::remove_file(b);
    }
}

/// The mode of a new file: the replaced file's, else what a plain create gives (0666 less
/// the umask; tempfile's own default, 0600, would hide a figure from the user's group).
fn mode_for(path: &Path) -> Option<fs::Permissions> {
    match fs::metadata(path) {
        Ok(m) if m.is_file() => Some(m.permissions()),
        #[cfg(unix)]
        _ => Some(std::os::unix::fs::PermissionsExt::from_mode(0o666)),
        #[cfg(not(unix))]
        _ => None,
    }
}

/// An I/O error's text without tempfile's "at path …" tail.
fn without_path(e: &io::Error) -> String {
    let s = e.to_string();
    s.split(" at path ").next().unwrap_or(&s).to_string()
}

/// Make the new names durable; a file system that cannot sync a folder is not an error (the
/// files themselves are synced).
fn sync_dir(dir: &Path) {
    #[cfg(unix)]
    let _ = fs::File::open(dir).and_then(|d| d.sync_all());
    #[cfg(not(unix))]
    let _ = dir;
}

/// Remove, in `dir`, the temporaries of this program's writers (`.NAME.PID-X.tmp`, the names
/// [`Outputs`] and `catalog::write` use) whose process is gone and whose target NAME passes
/// `ours`. Best effort: what cannot be read or removed is left.
pub fn remove_stale(dir: &Path, ours: impl Fn(&str) -> bool) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let file = e.file_name();
        let Some((target, pid)) = file.to_str().and_then(parse_temp_name) else {
            continue;
        };
        let is_file = e.file_type().is_ok_and(|t| t.is_file());
        if ours(target) && is_file && pid != std::process::id() && process_gone(pid) {
            let _ = fs::remove_file(e.path());
        }
    }
}

/// As [`remove_stale`], for the temporaries of target `name`.
fn remove_stale_of(dir: &Path, name: &OsStr) {
    remove_stale(dir, |target| name.to_str() == Some(target));
}

/// `.NAME.PID-X.tmp` → (NAME, PID), with X letters and digits.
fn parse_temp_name(file: &str) -> Option<(&str, u32)> {
    let inner = file.strip_prefix('.')?.strip_suffix(".tmp")?;
    let (target, tail) = inner.rsplit_once('.')?;
    let (pid, tag) = tail.split_once('-')?;
    let ok = !target.is_empty()
        && !tag.is_empty()
        && tag.chars().all(|c| c.is_ascii_alphanumeric())
        && pid.chars().all(|c| c.is_ascii_digit());
    Some((target, pid.parse().ok()?)).filter(|_| ok)
}

/// Whether no process has this id. Only where `/proc` tells (Linux); elsewhere a temporary
/// is never taken for stale.
fn process_gone(pid: u32) -> bool {
    let proc = Path::new("/proc");
    proc.join("self").exists() && !proc.join(pid.to_string()).exists()
}

#[cfg(test)]
pub(crate) mod tests;
