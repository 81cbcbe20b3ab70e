//! The catalog `run(preset=…)` and every preset call read, kept between calls (issue 30 item 5:
//! re-reading and re-parsing every preset on each call cost tens of µs). The user's folder is
//! still seen at each call as the command line sees it (docs/library.md): the cache holds
//! while the folder's path and the name, size and modification time of each of its entries
//! (the stamp) are those it was loaded with, so a preset added, edited or removed is seen at
//! the next call.
//!
//! Looking at the stamp is a walk of the folder's path (an `open`, or a `stat` of each entry)
//! at each call: some 2–3 µs of system time, as much as the closed-form impact it serves
//! (BENCHMARKS.md). On Linux an inotify watch stands in for it where it can tell every change
//! (`watch.rs`): the kernel queues an event on any change to the folder or its path before the
//! change's own system call returns, so one non-blocking `read` of the watch — no event —
//! says the stamp has not moved, and on any event the stamp is taken again.

use bouncelab::catalog::{Catalog, CatalogError};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

#[cfg(target_os = "linux")]
#[path = "catalog_watch.rs"]
mod watch;
#[cfg(not(target_os = "linux"))]
mod watch {
    //! Elsewhere no watch: the stamp is taken at each call.
    use std::path::Path;

    pub(super) struct Watch;

    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub(super) enum News {
        None,
        Path,
        Folder,
    }

    impl Watch {
        pub(super) fn arm(_dir: Option<&Path>) -> Option<Watch> {
            None
        }

        pub(super) fn news(&self) -> News {
            News::Path
        }
    }
}
use watch::{News, Watch};

/// What the catalog was loaded from: the folder, which folder it was (device and inode, where
/// the system has them: a folder put in its place is another), and its entries (name, size,
/// modified).
type Stamp = (
    Option<PathBuf>,
    Option<(u64, u64)>,
    Vec<(std::ffi::OsString, u64, Option<SystemTime>)>,
);

/// The catalog, the stamp it was loaded at, and the watch armed before that stamp was taken.
struct Cached {
    stamp: Stamp,
    catalog: Arc<Catalog>,
    watch: Option<Watch>,
}

static CACHE: Mutex<Option<Cached>> = Mutex::new(None);

/// The variables `catalog::user_presets_dir` reads, and the folder it named from them.
type Named = ((Option<OsString>, Option<OsString>), Option<PathBuf>);

static FOLDER: Mutex<Option<Named>> = Mutex::new(None);

/// The user's presets folder, `catalog::user_presets_dir()`: its variables (XDG_CONFIG_HOME,
/// HOME) read at each call — Python may change them between two — and the path joined again
/// only when they change (its three joins were a fifth of a `run(preset=…)`, BENCHMARKS.md).
fn user_presets_dir() -> Option<PathBuf> {
    let vars = (
        std::env::var_os("XDG_CONFIG_HOME"),
        std::env::var_os("HOME"),
    );
    let mut named = FOLDER.lock().unwrap_or_else(|e| e.into_inner());
    match named.as_ref() {
        Some((v, dir)) if *v == vars => dir.clone(),
        _ => {
            let dir = bouncelab::catalog::user_presets_dir();
            *named = Some((vars, dir.clone()));
            dir
        }
    }
}

/// The catalog of the user's presets folder, as the command line sees it (`catalog`).
pub(crate) fn user_catalog() -> Result<Arc<Catalog>, CatalogError> {
    catalog(user_presets_dir().as_deref())
}

/// The folder's entries as they stand (none when it does not exist or cannot be read: the
/// load then says why, if anything is wrong).
fn stamp(dir: Option<&Path>) -> Stamp {
    #[cfg(unix)]
    let which = dir.and_then(|d| std::fs::metadata(d).ok()).map(|m| {
        use std::os::unix::fs::MetadataExt;
        (m.dev(), m.ino())
    });
    #[cfg(not(unix))]
    let which = None;
    let mut files = Vec::new();
    if let Some(rd) = dir.and_then(|d| std::fs::read_dir(d).ok()) {
        for e in rd.flatten() {
            // follows links, as the catalog's read of the file does
            let meta = std::fs::metadata(e.path()).ok();
            let len = meta.as_ref().map_or(0, |m| m.len());
            let modified = meta.and_then(|m| m.modified().ok());
            files.push((e.file_name(), len, modified));
        }
    }
    files.sort();
    (dir.map(Path::to_path_buf), which, files)
}

/// The catalog of `dir` (the user's presets folder), from the cache while the folder is
/// unchanged: no news from the watch, or a stamp that has not moved after news on the path
/// alone (or at each call where no watch could be armed); news from the folder itself, and it
/// is read again. Errors are not kept (the next call reads again).
fn catalog(dir: Option<&Path>) -> Result<Arc<Catalog>, CatalogError> {
    let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(c) = cache.as_mut()
        && c.stamp.0.as_deref() == dir
    {
        match c.watch.as_ref().map(Watch::news) {
            Some(News::None) => return Ok(c.catalog.clone()),
            Some(News::Path) => {
                // armed before the stamp is taken: a change after it is news at the next call
                let watch = Watch::arm(dir);
                if stamp(dir) == c.stamp {
                    c.watch = watch;
                    return Ok(c.catalog.clone());
                }
            }
            Some(News::Folder) => {}
            // no watch could be armed (a link, a remote file system…): the stamp at each call,
            // a watch tried again once it moves
            None if stamp(dir) == c.stamp => return Ok(c.catalog.clone()),
            None => {}
        }
    }
    *cache = None;
    let watch = Watch::arm(dir);
    let now = stamp(dir);
    let catalog = Arc::new(Catalog::load(dir, None)?);
    *cache = Some(Cached {
        stamp: now,
        catalog: catalog.clone(),
        watch,
    });
    Ok(catalog)
}
