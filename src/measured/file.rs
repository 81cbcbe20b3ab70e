//! Reading a measured-data file at the edge: a regular file (never a FIFO, a device or a
//! directory, which could block or never end), at most [`MAX_DATA_BYTES`], UTF-8; then
//! [`crate::measured`] parses it. Every error is one line `FILE:LINE:COLUMN: message`
//! (`FILE: message` when it is about the file as a whole).

use crate::measured::{self, CorTable, Data, DropTest, MeasuredError, Trace};
use std::io::Read;
use std::path::Path;

/// Largest data file read: 64 MiB holds a million rows of a few numbers with room to spare.
pub const MAX_DATA_BYTES: u64 = 64 << 20;

fn whole(path: &Path, msg: impl std::fmt::Display) -> anyhow::Error {
    anyhow::anyhow!("{}: {msg}", path.display())
}

/// The text of `path`, or an error naming it.
pub fn read_text(path: &Path) -> anyhow::Result<String> {
    let meta = std::fs::metadata(path).map_err(|e| whole(path, describe(&e)))?;
    if meta.is_dir() {
        return Err(whole(path, "is a directory, not a data file"));
    }
    if !meta.is_file() {
        return Err(whole(
            path,
            "is not a regular file (a FIFO, socket or device is not read)",
        ));
    }
    if meta.len() > MAX_DATA_BYTES {
        return Err(whole(
            path,
            format!(
                "is {} bytes; a data file is at most {MAX_DATA_BYTES} bytes",
                meta.len()
            ),
        ));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_DATA_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| whole(path, describe(&e)))?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = valid.iter().filter(|&&b| b == b'\n').count() + 1;
        let last = valid.rsplit(|&b| b == b'\n').next().unwrap_or(&[]);
        let col = String::from_utf8_lossy(last).chars().count() + 1;
        anyhow::anyhow!("{}:{line}:{col}: not UTF-8 text", path.display())
    })
}

fn describe(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => {
            let s = e.to_string();
            s.split(" (os error").next().unwrap_or(&s).to_string()
        }
    }
}

/// A parse error at its place in `path`.
pub fn at(path: &Path, e: MeasuredError) -> anyhow::Error {
    anyhow::anyhow!("{}:{e}", path.display())
}

/// The force–time trace in `path`.
pub fn trace(path: &Path) -> anyhow::Result<Trace> {
    Trace::parse(&read_text(path)?).map_err(|e| at(path, e))
}

/// The COR table in `path`.
pub fn cor_table(path: &Path) -> anyhow::Result<CorTable> {
    CorTable::parse(&read_text(path)?).map_err(|e| at(path, e))
}

/// The drop tests in `path`.
pub fn drop_test(path: &Path) -> anyhow::Result<DropTest> {
    DropTest::parse(&read_text(path)?).map_err(|e| at(path, e))
}

/// The oblique bounces in `path` (docs/oblique.md §9).
pub fn oblique(path: &Path) -> anyhow::Result<Vec<measured::ObliqueRow>> {
    measured::parse_oblique(&read_text(path)?).map_err(|e| at(path, e))
}

/// The ITF court test bounces in `path` (docs/oblique.md §6).
pub fn court(path: &Path) -> anyhow::Result<Vec<measured::CourtRow>> {
    measured::parse_court(&read_text(path)?).map_err(|e| at(path, e))
}

/// The pressure readings in `path` (docs/model.md §10.3).
pub fn pressure(path: &Path) -> anyhow::Result<Vec<measured::PressureRow>> {
    measured::parse_pressure(&read_text(path)?).map_err(|e| at(path, e))
}

/// The static deflections in `path` (`fit --static`).
pub fn statics(path: &Path) -> anyhow::Result<Vec<measured::StaticRow>> {
    measured::parse_static(&read_text(path)?).map_err(|e| at(path, e))
}

/// CORs at several temperatures (`fit --cor-temperature`).
pub fn cor_temperature(path: &Path) -> anyhow::Result<Vec<measured::CorTemperatureRow>> {
    measured::parse_cor_temperature(&read_text(path)?).map_err(|e| at(path, e))
}

/// Any kind, told by the header.
pub fn any(path: &Path) -> anyhow::Result<Data> {
    measured::parse_any(&read_text(path)?).map_err(|e| at(path, e))
}

/// The file name alone, to label a user's data on figures.
pub fn label(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}
