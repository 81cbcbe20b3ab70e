//! The catalog `run(preset=…)` and every preset call read, kept between calls (issue 30 item 5:
//! re-reading and re-parsing every preset on each call cost tens of µs). The user's folder is
//! still read at each call, as the command line reads it (docs/library.md): the cache holds
//! while the folder's path and the name, size and modification time of each of its entries
//! are those it was loaded with, so a preset added, edited or removed is seen at the next call.

use bouncelab::catalog::{Catalog, CatalogError};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

/// What the catalog was loaded from: the folder and its entries (name, size, modified).
type Stamp = (
    Option<PathBuf>,
    Vec<(std::ffi::OsString, u64, Option<SystemTime>)>,
);

static CACHE: Mutex<Option<(Stamp, Arc<Catalog>)>> = Mutex::new(None);

/// The folder's entries as they stand (none when it does not exist or cannot be read: the
/// load then says why, if anything is wrong).
fn stamp(dir: Option<&Path>) -> Stamp {
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
    (dir.map(Path::to_path_buf), files)
}

/// The catalog of `dir` (the user's presets folder), from the cache while the folder is
/// unchanged; errors are not kept (the next call reads again).
pub(crate) fn catalog(dir: Option<&Path>) -> Result<Arc<Catalog>, CatalogError> {
    let now = stamp(dir);
    let mut cache = CACHE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((s, cat)) = cache.as_ref()
        && *s == now
    {
        return Ok(cat.clone());
    }
    let cat = Arc::new(Catalog::load(dir, None)?);
    *cache = Some((now, cat.clone()));
    Ok(cat)
}
