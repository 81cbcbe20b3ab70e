//! Every command's outputs as one transaction (docs/guarantees.md, "All or none"): its files
//! (and a preset) are checked before any work by [`check`], staged ([`crate::atomic`]), and
//! published together by [`commit`] only once the report on stdout has gone out
//! ([`report_then_commit`]); a failure anywhere leaves none of them behind. One check, one
//! set of messages and exit codes for `figure`, `fit`, `map`, `mc` and `reproduce`
//! (tests/cli/cli_outputs.rs, one test per command):
//!
//! - a target given twice: "X is given twice: each output needs a file of its own", exit 2;
//! - a directory: "X is a directory, not a file", exit 2;
//! - a device, FIFO or socket, with `--force` too: "X is a character device, not a regular
//!   file (outputs replace regular files only)", exit 2 (`atomic::refused_kind`);
//! - an existing file (a symbolic link too, dangling or not) without `--force`: "X exists (use
//!   --force to overwrite it)", exit 2;
//! - a missing folder: "cannot write X: no such directory D", exit 2 (the user's path);
//! - a folder that takes no new file (read-only): "cannot write X: Permission denied", exit 1
//!   (not the input's fault), found before the work by staging an empty temporary there.

use crate::atomic::{self, Outputs};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Refuse, before any work, targets that cannot be written (see the module comment).
pub fn check(paths: &[&Path], force: bool) -> anyhow::Result<()> {
    // compared as absolute paths, so `a.svg` and `./a.svg` are one file
    let same = |a: &Path, b: &Path| match (std::path::absolute(a), std::path::absolute(b)) {
        (Ok(a), Ok(b)) => a == b,
        _ => a == b,
    };
    for (i, p) in paths.iter().enumerate() {
        if paths[..i].iter().any(|q| same(q, p)) {
            anyhow::bail!(
                "{} is given twice: each output needs a file of its own (--out and --csv-out \
                 must differ)",
                p.display()
            );
        }
        check_one(p, force)?;
    }
    Ok(())
}

/// One target: not a directory, not existing without `force`, in a folder that exists and
/// takes a new file.
fn check_one(p: &Path, force: bool) -> anyhow::Result<()> {
    if p.is_dir() {
        anyhow::bail!("{} is a directory, not a file", p.display());
    }
    // with --force or without: a device, FIFO or socket is named for what it is
    if let Some(kind) = atomic::refused_kind(p) {
        anyhow::bail!("{} is {}", p.display(), atomic::not_regular(kind));
    }
    // a symbolic link is an existing entry, dangling or looping too: without --force it is
    // not replaced, with it the link itself is (the rename replaces the name)
    if std::fs::symlink_metadata(p).is_ok() && !force {
        anyhow::bail!("{} exists (use --force to overwrite it)", p.display());
    }
    let parent = p.parent().filter(|d| !d.as_os_str().is_empty());
    if let Some(d) = parent
        && !d.is_dir()
    {
        anyhow::bail!(
            "cannot write {}: no such directory {}",
            p.display(),
            d.display()
        );
    }
    atomic::probe(p)?;
    Ok(())
}

/// Publish staged files; an existing target is bad input (exit 2), any other failure I/O.
/// Ctrl-C during the work publishes nothing (exit 130).
pub fn commit(files: Outputs) -> anyhow::Result<Vec<PathBuf>> {
    if super::budget::interrupted() {
        // the staged files go with `files`
        return Err(super::budget::Interrupted.into());
    }
    files.commit().map_err(|e| {
        if e.exists {
            anyhow::anyhow!("{e}")
        } else if e.error.kind() == io::ErrorKind::InvalidInput {
            // a target that became a device, FIFO or socket: bad input, as at the check
            anyhow::anyhow!("{}: {}", e, e.error)
        } else {
            anyhow::Error::new(e)
        }
    })
}

/// The report on stdout first, then the files: a stdout that cannot take the report (full, an
/// I/O error) fails the command with nothing published. A reader that went away (a closed
/// pipe, `| head`) is no failure: the files are published and the command ends as for any
/// closed pipe (exit 0; `a_closed_stdout_still_publishes`). A report that names the files
/// (`figure`, `reproduce`) so names them just before they are published: a publication that
/// still fails (a file that appeared meanwhile) ends in its error line after it.
pub fn report_then_commit(
    out: &mut dyn Write,
    report: &[u8],
    files: Outputs,
) -> anyhow::Result<Vec<PathBuf>> {
    // a signal during the work: neither the report nor the files (exit 130)
    if super::budget::interrupted() {
        return Err(super::budget::Interrupted.into());
    }
    match out.write_all(report).and_then(|()| out.flush()) {
        Ok(()) => commit(files),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
            commit(files)?;
            Err(e.into())
        }
        // dropping `files` removes what was staged
        Err(e) => Err(anyhow::Error::new(e).context("cannot write the report to stdout")),
    }
}
