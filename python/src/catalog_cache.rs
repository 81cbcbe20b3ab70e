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
//!
//! Beside the catalog it keeps the balls built from it (`PresetBalls`): a preset's ball under
//! a parameter set and a law is built and checked once per catalog, and dropped with it when
//! the folder changes (python/tests/test_preset_balls.py) — building and dropping it at each
//! call, its strings and tables cloned, was about a sixth of a `run(preset=…)`'s instructions
//! (BENCHMARKS.md).

use bouncelab::catalog::{Catalog, CatalogError};
use bouncelab::preset::ParamSource;
use bouncelab::{Ball, BallError, ContactLaw};
use pyo3::prelude::*;
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

/// The catalog, the stamp it was loaded at, the watch armed before that stamp was taken, and
/// the balls built from the catalog.
struct Cached {
    stamp: Stamp,
    catalog: Arc<Catalog>,
    watch: Option<Watch>,
    balls: PresetBalls,
}

/// A preset's name, parameter set and law (`None`: the preset's own), at the preset's speed.
type BallKey = (String, Option<ParamSource>, Option<ContactLaw>);

/// The balls built from one catalog, by what they were built with. At most one for each of
/// its presets, parameter sets (the preset's, adopted, materials) and laws (the preset's and
/// three): a few hundred at the most, so a scan (a name compared first) rather than a hash
/// of the name at each call.
#[derive(Default)]
struct PresetBalls(Vec<(BallKey, Arc<Ball>)>);

static CACHE: Mutex<Option<Cached>> = Mutex::new(None);

/// The variables `catalog::user_presets_dir` reads, and the folder it named from them.
type Named = ((Option<OsString>, Option<OsString>), Option<PathBuf>);

static FOLDER: Mutex<Option<Named>> = Mutex::new(None);

/// `f` of the user's presets folder, `catalog::user_presets_dir()`: its variables
/// (XDG_CONFIG_HOME, HOME) read at each call — Python may change them between two — and the
/// path joined again only when they change (its three joins were a fifth of a
/// `run(preset=…)`, BENCHMARKS.md); lent to `f` under the lock, not cloned (a clone and its
/// free were a tenth of what is left of a `run(preset=…)` around its closed form). The lock
/// is taken before the cache's, always in that order.
fn in_user_presets_dir<T>(f: impl FnOnce(Option<&Path>) -> T) -> T {
    let vars = (
        std::env::var_os("XDG_CONFIG_HOME"),
        std::env::var_os("HOME"),
    );
    let mut named = FOLDER.lock().unwrap_or_else(|e| e.into_inner());
    if !matches!(named.as_ref(), Some((v, _)) if *v == vars) {
        *named = Some((vars, bouncelab::catalog::user_presets_dir()));
    }
    f(named.as_ref().and_then(|(_, dir)| dir.as_deref()))
}

/// The catalog of the user's presets folder, as the command line sees it (`catalog`).
pub(crate) fn user_catalog() -> Result<Arc<Catalog>, CatalogError> {
    in_user_presets_dir(|dir| {
        let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
        Ok(fresh(&mut cache, dir)?.catalog.clone())
    })
}

/// The ball of the user's catalog's preset `name` with the parameter set and law given
/// (`None` keeps the preset's), at the preset's speed: `Ball::from_entry(entry, source, law,
/// None)`, built and checked once while the catalog holds. An unknown name is the catalog's
/// error, and `choose` (the caller's parse of its set and law) runs after the name is found,
/// as the command line checks them; the library's errors are the caller's by `error`, and
/// none is kept. The files the folder skipped are warned of first ([`warn_skipped`]).
pub(crate) fn preset_ball<E: From<PyErr>>(
    name: &str,
    choose: impl FnOnce() -> Result<(Option<ParamSource>, Option<ContactLaw>), E>,
    error: fn(BallError) -> E,
) -> Result<Arc<Ball>, E> {
    let (skipped, ball) = in_user_presets_dir(|dir| {
        let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
        let cached = fresh(&mut cache, dir).map_err(|e| error(BallError::Catalog(e)))?;
        // the catalog held for the warnings only where it skipped a file
        let skipped = (!cached.catalog.skipped().is_empty()).then(|| cached.catalog.clone());
        Ok::<_, E>((skipped, built(cached, name, choose, error)))
    })?;
    if let Some(catalog) = skipped {
        warn_skipped(&catalog, Some(name))?;
    }
    ball
}

/// [`preset_ball`]'s ball from the catalog `cached`: the one kept, else built and kept.
fn built<E>(
    cached: &mut Cached,
    name: &str,
    choose: impl FnOnce() -> Result<(Option<ParamSource>, Option<ContactLaw>), E>,
    error: fn(BallError) -> E,
) -> Result<Arc<Ball>, E> {
    let entry = (cached.catalog.get(name)).map_err(|e| error(BallError::Catalog(e)))?;
    let (source, law) = choose()?;
    let balls = &mut cached.balls.0;
    let kept = balls
        .iter()
        .find(|((n, s, l), _)| n == name && *s == source && *l == law);
    if let Some((_, ball)) = kept {
        return Ok(ball.clone());
    }
    let ball = Arc::new(Ball::from_entry(entry, source, law, None).map_err(error)?);
    balls.push(((name.to_string(), source, law), ball.clone()));
    Ok(ball)
}

/// The command line's warnings of the presets folder's files it skipped (src/cli/ball.rs,
/// `warn_skipped`), as Python's `UserWarning`s: each file's one line, as the command line
/// prints it after `bouncelab: warning: `, but for the file whose error ends a call asking
/// for `asked`. Given with no lock held: a warning filter may call into the package again.
pub(crate) fn warn_skipped(catalog: &Catalog, asked: Option<&str>) -> PyResult<()> {
    if catalog.skipped().is_empty() {
        return Ok(());
    }
    let asked = asked.and_then(|name| catalog.skipped_for(name));
    Python::attach(|py| {
        let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
        for s in catalog.skipped().iter().filter(|s| Some(*s) != asked) {
            let line = bouncelab::sanitize::line(&s.message()).into_owned();
            let line = std::ffi::CString::new(line).map_err(PyErr::from)?;
            // at the caller's line, past bouncelab/_boundary.py's guard
            PyErr::warn(py, &category, &line, 2)?;
        }
        Ok(())
    })
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

/// The cache of `dir` (the user's presets folder), its catalog kept while the folder is
/// unchanged: no news from the watch, or a stamp that has not moved after news on the path
/// alone (or at each call where no watch could be armed); news from the folder itself, and it
/// is read again. Errors are not kept (the next call reads again).
fn fresh<'c>(
    cache: &'c mut Option<Cached>,
    dir: Option<&Path>,
) -> Result<&'c mut Cached, CatalogError> {
    if let Some(c) = cache.as_mut()
        && c.stamp.0.as_deref() == dir
    {
        let holds = match c.watch.as_ref().map(Watch::news) {
            Some(News::None) => true,
            Some(News::Path) => {
                // armed before the stamp is taken: a change after it is news at the next call
                let watch = Watch::arm(dir);
                let same = stamp(dir) == c.stamp;
                if same {
                    c.watch = watch;
                }
                same
            }
            Some(News::Folder) => false,
            // no watch could be armed (a link, a remote file system…): the stamp at each call,
            // a watch tried again once it moves
            None => stamp(dir) == c.stamp,
        };
        if holds {
            return Ok(cache.as_mut().expect("looked at above"));
        }
    }
    *cache = None;
    let watch = Watch::arm(dir);
    let now = stamp(dir);
    let catalog = Arc::new(Catalog::load(dir, None)?);
    Ok(cache.insert(Cached {
        stamp: now,
        catalog,
        watch,
        balls: PresetBalls::default(),
    }))
}
