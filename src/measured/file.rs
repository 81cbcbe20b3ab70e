//! Reading a measured-data file at the edge: a regular file (never a FIFO, a device or a
//! directory, which could block or never end), at most [`MAX_DATA_BYTES`], UTF-8; then
//! [`crate::measured`] parses it. Every error is one line `FILE:LINE:COLUMN: message`
//! (`FILE: message` when it is about the file as a whole).

pub use super::bounded::{MAX_DATA_BYTES, ReadError, read_bounded};
use crate::measured::{self, CorTable, Data, DropTest, MeasuredError, Trace};
use std::path::Path;

/// The text of `path`, or an error naming it: `FILE: message`, or `FILE:LINE:COLUMN: not
/// UTF-8 text`.
pub fn read_text(path: &Path) -> anyhow::Result<String> {
    let file = path.display();
    read_bounded(path).map_err(|e| match e {
        ReadError::Io(why) => anyhow::anyhow!("{file}: {why}"),
        ReadError::Directory => anyhow::anyhow!("{file}: is a directory, not a data file"),
        ReadError::NotRegular => {
            anyhow::anyhow!("{file}: is not a regular file (a FIFO, socket or device is not read)")
        }
        ReadError::TooLarge(n) => {
            anyhow::anyhow!("{file}: is {n} bytes; a data file is at most {MAX_DATA_BYTES} bytes")
        }
        ReadError::NotUtf8 { line, column } => {
            anyhow::anyhow!("{file}:{line}:{column}: not UTF-8 text")
        }
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Each refusal in the command line's words, naming the file (and the place of the first
    /// byte that is not UTF-8).
    #[test]
    fn refusals_name_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let said = |p: &Path| read_text(p).unwrap_err().to_string();
        let missing = dir.path().join("none.csv");
        assert_eq!(
            said(&missing),
            format!("{}: no such file", missing.display())
        );
        assert_eq!(
            read_bounded(&missing),
            Err(ReadError::Io("no such file".into()))
        );
        let d = dir.path().display();
        assert_eq!(
            said(dir.path()),
            format!("{d}: is a directory, not a data file")
        );
        let latin = dir.path().join("latin.csv");
        std::fs::write(&latin, b"v0,cor\n1,0.5 \xe9t\xe9\n").unwrap();
        assert_eq!(
            said(&latin),
            format!("{}:2:7: not UTF-8 text", latin.display())
        );
        // a sparse file one byte over the limit: its size is read, not its bytes
        let big = dir.path().join("big.csv");
        std::fs::File::create(&big)
            .and_then(|f| f.set_len(MAX_DATA_BYTES + 1))
            .unwrap();
        assert_eq!(
            said(&big),
            format!(
                "{}: is {} bytes; a data file is at most {MAX_DATA_BYTES} bytes",
                big.display(),
                MAX_DATA_BYTES + 1
            )
        );
        #[cfg(unix)]
        assert_eq!(
            said(Path::new("/dev/null")),
            "/dev/null: is not a regular file (a FIFO, socket or device is not read)"
        );
        let fine = dir.path().join("fine.csv");
        std::fs::write(&fine, "v0,cor\n1,0.5\n").unwrap();
        assert_eq!(read_text(&fine).unwrap(), "v0,cor\n1,0.5\n");
    }
}
