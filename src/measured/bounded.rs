//! A measured-data file's text, read within bounds: a regular file (never a FIFO, a device or
//! a directory, which could block or never end), at most [`MAX_DATA_BYTES`], UTF-8. Every
//! reader of the project's data files reads through [`read_bounded`] and words its refusals
//! for its own users: `measured::file::read_text` for the command line (with the `tui`
//! feature, as that module), `python/src/batch.rs` for Python (the library without it).

use std::io::Read;
use std::path::Path;

/// Largest data file read: 64 MiB holds a million rows of a few numbers with room to spare.
pub const MAX_DATA_BYTES: u64 = 64 << 20;

/// Why a data file gave no text: the file itself (missing, unreadable, not a regular file)
/// or what it holds (too large, not UTF-8). Each reader words it for its own users:
/// `measured::file::read_text` for the command line, python/src/batch.rs for Python.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ReadError {
    /// The system refused it: "no such file", "permission denied", or its own words without
    /// the error number.
    Io(String),
    /// A directory.
    Directory,
    /// A FIFO, socket or device (which could block or never end).
    NotRegular,
    /// Larger than [`MAX_DATA_BYTES`]: its size in bytes.
    TooLarge(u64),
    /// Not UTF-8 from this line and column (1-based, the column in characters) on.
    NotUtf8 {
        /// The line of the first byte that is not.
        line: usize,
        /// Its column.
        column: usize,
    },
}

/// The text of the data file `path`: a regular file of at most [`MAX_DATA_BYTES`], UTF-8.
pub fn read_bounded(path: &Path) -> Result<String, ReadError> {
    let io = |e: std::io::Error| ReadError::Io(describe(&e));
    let meta = std::fs::metadata(path).map_err(io)?;
    if meta.is_dir() {
        return Err(ReadError::Directory);
    }
    if !meta.is_file() {
        return Err(ReadError::NotRegular);
    }
    if meta.len() > MAX_DATA_BYTES {
        return Err(ReadError::TooLarge(meta.len()));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_DATA_BYTES + 1).read_to_end(&mut bytes))
        .map_err(io)?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = valid.iter().filter(|&&b| b == b'\n').count() + 1;
        let last = valid.rsplit(|&b| b == b'\n').next().unwrap_or(&[]);
        let column = String::from_utf8_lossy(last).chars().count() + 1;
        ReadError::NotUtf8 { line, column }
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
