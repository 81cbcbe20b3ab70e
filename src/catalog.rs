//! The preset catalog: the embedded balls plus the user's preset files. All preset file I/O
//! lives here; `preset` only parses text.
//!
//! User presets are read from `$XDG_CONFIG_HOME/bouncelab/presets/*.toml` (or
//! `~/.config/bouncelab/presets/*.toml` when `XDG_CONFIG_HOME` is unset, empty or relative) and
//! from one extra file given on the command line (`--config FILE`). Rules:
//!
//! - a preset is known by its `name` field, not by its file name;
//! - a user preset may not take the name of an embedded one, nor of another user preset: both
//!   are errors naming the two origins (rename one of them);
//! - a file of the presets folder that cannot be read or parsed is skipped with a warning
//!   naming `file:line:column` and why ([`Catalog::skipped`]): one bad file does not stop every
//!   command. Asked for by its name (its `name` field or its file name without `.toml`), or
//!   given as `--config`, it is the error;
//! - in the presets folder only regular `*.toml` files not starting with `.` are read, in
//!   file-name order; a missing folder means no user presets.
//!
//! Writing a preset file (the explorer's `s`, `fit --save`) is the application's: `write`
//! (feature `tui`), atomic, and never replacing a file unless asked to.

// through the application's atomic writer (`crate::atomic`, feature `tui`)
#[cfg(feature = "tui")]
pub mod write;

pub mod surfaces;

use crate::preset::{Preset, PresetError};
use std::fmt;
use std::io::Read;
use std::path::{Path, PathBuf};

/// Largest preset file read: a preset is a few hundred bytes; this guards against
/// `--config /dev/zero`-like mistakes.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Where a preset came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Origin {
    /// Compiled into the library ([`crate::preset::EMBEDDED`]).
    Embedded,
    /// Read from this file (the user's presets folder or `--config`).
    File(PathBuf),
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::Embedded => f.write_str("embedded"),
            Origin::File(p) => write!(f, "{}", p.display()),
        }
    }
}

/// A preset and its origin.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The preset, parsed and checked.
    pub preset: Preset,
    /// Where it came from.
    pub origin: Origin,
}

/// Why the catalog could not be built or a preset not found. Every message is one line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CatalogError {
    /// A file or folder could not be read.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The system's reason, one line.
        message: String,
    },
    /// A preset file does not parse or validate (carries file:line:column).
    #[error(transparent)]
    Preset(#[from] PresetError),
    /// Two presets (or two surfaces) share a name.
    #[error("{}", duplicate_message(what, name, first, second))]
    Duplicate {
        /// What shares it: `"preset"` or `"surface"`.
        what: &'static str,
        /// The shared name.
        name: String,
        /// Where the first preset of that name came from.
        first: Origin,
        /// Where the second one came from.
        second: Origin,
    },
    /// No preset of that name.
    #[error("unknown preset '{name}' (available: {})", available.join(", "))]
    Unknown {
        /// The name asked for.
        name: String,
        /// The names the catalog holds, in its order.
        available: Vec<String>,
    },
}

/// Two presets (`what`: or surfaces) named `name`: which, and which file to change.
fn duplicate_message(what: &str, name: &str, first: &Origin, second: &Origin) -> String {
    match (first, second) {
        (Origin::Embedded, Origin::File(file)) | (Origin::File(file), Origin::Embedded) => {
            format!(
                "duplicate {what} name '{name}': {} and the embedded {what} \
                 (embedded:{name}); change the name in {}",
                file.display(),
                file.display()
            )
        }
        _ => format!(
            "duplicate {what} name '{name}': {first} and {second}; change the name in one of \
             them"
        ),
    }
}

/// The folder user presets are read from: `$XDG_CONFIG_HOME/bouncelab/presets`, falling back
/// to `$HOME/.config/bouncelab/presets`; `None` if neither variable is usable.
pub fn user_presets_dir() -> Option<PathBuf> {
    let absolute = |var: &str| {
        std::env::var_os(var)
            .map(PathBuf::from)
            .filter(|p| p.is_absolute())
    };
    let config =
        absolute("XDG_CONFIG_HOME").or_else(|| absolute("HOME").map(|h| h.join(".config")))?;
    Some(config.join("bouncelab").join("presets"))
}

/// Read and parse one preset file. Errors name the file, and line:column where the text is
/// at fault (TOML syntax, unknown keys, bad values, bytes that are not UTF-8).
pub fn read_preset_file(path: &Path) -> Result<Preset, CatalogError> {
    let io = |message: String| CatalogError::Io {
        path: path.to_path_buf(),
        message,
    };
    let meta = std::fs::metadata(path).map_err(|e| io(describe_io(&e)))?;
    if meta.is_dir() {
        return Err(io("is a directory, not a preset file".into()));
    }
    if !meta.is_file() {
        return Err(io("is not a regular file".into()));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(io(format!(
            "is {} bytes; a preset file is at most {MAX_FILE_BYTES} bytes",
            meta.len()
        )));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| io(describe_io(&e)))?;
    parse_preset_bytes(bytes, &path.display().to_string()).map_err(CatalogError::Preset)
}

/// Parse the bytes of a preset file: bytes that are not UTF-8 are an error at the line:column
/// of the first bad byte, then `Preset::parse`. (The fuzz target `preset_toml` enters here.)
pub fn parse_preset_bytes(bytes: Vec<u8>, origin: &str) -> Result<Preset, PresetError> {
    let text = String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = valid.iter().filter(|&&b| b == b'\n').count() + 1;
        let last_line = valid.rsplit(|&b| b == b'\n').next().unwrap_or(&[]);
        // the valid prefix is UTF-8, so counting chars of the last line gives the column
        let col = String::from_utf8_lossy(last_line).chars().count() + 1;
        PresetError {
            origin: origin.to_string(),
            position: Some((line, col)),
            message: "not valid UTF-8 text (a preset file must be UTF-8)".into(),
        }
    })?;
    Preset::parse(&text, origin)
}

/// An I/O error as a short lower-case phrase without the OS error number.
fn describe_io(e: &std::io::Error) -> String {
    use std::io::ErrorKind::*;
    match e.kind() {
        NotFound => "no such file".into(),
        PermissionDenied => "permission denied".into(),
        _ => e.to_string(),
    }
}

/// Every preset the program knows: embedded first, then user presets.
#[derive(Debug, Clone, PartialEq)]
pub struct Catalog {
    entries: Vec<Entry>,
    /// `*.toml` entries of the presets folder that are symbolic links leading to no file
    /// (dangling or looping), or files that cannot be read or parsed: skipped, and said so by
    /// the caller ([`Catalog::skipped`]).
    skipped: Vec<Skipped>,
}

/// A `*.toml` name in the presets folder that was not read, and why ("a symbolic link to a
/// missing file", "a symbolic link that cannot be followed: …", or the file's error).
#[derive(Debug, Clone, PartialEq)]
pub struct Skipped {
    /// The link or file, in the presets folder.
    pub path: PathBuf,
    /// Why it was not read.
    pub why: String,
    /// For a file that could not be read or parsed: its error (file:line:column), the error
    /// of a command that asks for it ([`Catalog::get`]).
    pub error: Option<CatalogError>,
    /// The `name` its text holds, where the TOML parses that far.
    pub name: Option<String>,
}

impl Skipped {
    /// A folder file that could not be read or parsed.
    fn bad_file(path: PathBuf, error: CatalogError) -> Skipped {
        Skipped {
            name: name_field(&path),
            why: error.to_string(),
            error: Some(error),
            path,
        }
    }

    /// The warning, one line: the file (with line:column where the text is at fault) and why.
    pub fn message(&self) -> String {
        match self.error {
            Some(_) => format!("{} (file skipped: fix or remove it)", self.why),
            None => format!("{} skipped: {}", self.path.display(), self.why),
        }
    }

    /// Whether a command asking for preset `name` means this file: its `name` field or its
    /// file name without `.toml`.
    pub fn is_named(&self, name: &str) -> bool {
        self.name.as_deref() == Some(name) || self.path.file_stem().is_some_and(|stem| stem == name)
    }
}

/// The string a preset file's `name` key holds, if the file reads as TOML that far (a name
/// that fails the preset's own checks, e.g. an invisible character, is still read).
fn name_field(path: &Path) -> Option<String> {
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES).read_to_end(&mut bytes))
        .ok()?;
    let table: toml::Table = std::str::from_utf8(&bytes).ok()?.parse().ok()?;
    table.get("name")?.as_str().map(str::to_string)
}

impl Catalog {
    /// The embedded presets only.
    pub fn embedded() -> Catalog {
        Catalog {
            entries: Preset::embedded_all()
                .into_iter()
                .map(|preset| Entry {
                    preset,
                    origin: Origin::Embedded,
                })
                .collect(),
            skipped: Vec::new(),
        }
    }

    /// The embedded presets, the `*.toml` files of `dir` (if it exists) and `extra` (a file
    /// given on the command line; not counted twice if it is also in `dir`).
    pub fn load(dir: Option<&Path>, extra: Option<&Path>) -> Result<Catalog, CatalogError> {
        let mut catalog = Catalog::embedded();
        let (mut files, skipped) = match dir {
            Some(d) => preset_files(d)?,
            None => (Vec::new(), Vec::new()),
        };
        catalog.skipped = skipped;
        // the file given on the command line is asked for: its error is the command's
        let mut asked = None;
        if let Some(x) = extra {
            let same = |a: &Path| match (a.canonicalize(), x.canonicalize()) {
                (Ok(a), Ok(b)) => a == b,
                _ => false,
            };
            asked = files.iter().position(|f| same(f));
            if asked.is_none() {
                asked = Some(files.len());
                files.push(x.to_path_buf());
            }
        }
        for (i, path) in files.into_iter().enumerate() {
            match read_preset_file(&path) {
                Ok(preset) => catalog.add(Entry {
                    preset,
                    origin: Origin::File(path),
                })?,
                Err(e) if asked != Some(i) => catalog.skipped.push(Skipped::bad_file(path, e)),
                Err(e) => return Err(e),
            }
        }
        catalog.skipped.sort_by(|a, b| a.path.cmp(&b.path));
        Ok(catalog)
    }

    /// The presets folder's `*.toml` links that lead to no file and files that cannot be read
    /// or parsed, skipped by [`Catalog::load`] (the command line warns once:
    /// tests/cli/cli_small.rs, `dangling_links_are_named_once`, `a_bad_user_preset_is_skipped`).
    pub fn skipped(&self) -> &[Skipped] {
        &self.skipped
    }

    /// Add one entry; a name already taken is an error naming both origins.
    pub fn add(&mut self, entry: Entry) -> Result<(), CatalogError> {
        if let Some(old) = self
            .entries
            .iter()
            .find(|e| e.preset.name == entry.preset.name)
        {
            return Err(CatalogError::Duplicate {
                what: "preset",
                name: entry.preset.name.clone(),
                first: old.origin.clone(),
                second: entry.origin,
            });
        }
        self.entries.push(entry);
        Ok(())
    }

    /// Every preset: the embedded ones first, then the files (sorted by path), then `extra`.
    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// The preset called `name`; else the error of a skipped file of that name (its `name`
    /// field or file name), else an error listing the available names.
    pub fn get(&self, name: &str) -> Result<&Entry, CatalogError> {
        if let Some(entry) = self.entries.iter().find(|e| e.preset.name == name) {
            return Ok(entry);
        }
        let skipped_error = self.skipped_for(name).and_then(|s| s.error.clone());
        Err(skipped_error.unwrap_or_else(|| CatalogError::Unknown {
            name: name.to_string(),
            available: self.entries.iter().map(|e| e.preset.name.clone()).collect(),
        }))
    }

    /// A skipped file that may hold the name `name` (its `name` field or file name is it, or
    /// its `name` cannot be read): a save of `name` would not know whether it makes a second
    /// preset of that name once the file is mended, so it is refused with this file's error
    /// (the explorer's `s`, `fit --save`).
    pub fn may_hold(&self, name: &str) -> Option<&Skipped> {
        self.skipped
            .iter()
            .find(|s| s.error.is_some() && (s.name.is_none() || s.is_named(name)))
    }

    /// The skipped file whose error [`Catalog::get`] gives for `name`: none when a preset of
    /// that name loaded.
    pub fn skipped_for(&self, name: &str) -> Option<&Skipped> {
        if self.entries.iter().any(|e| e.preset.name == name) {
            return None;
        }
        self.skipped
            .iter()
            .find(|s| s.error.is_some() && s.is_named(name))
    }

    /// The entry read from `path` (the `--config` file).
    pub fn from_file(&self, path: &Path) -> Option<&Entry> {
        let want = path.canonicalize().ok();
        self.entries.iter().find(|e| match &e.origin {
            Origin::File(p) => p == path || (want.is_some() && p.canonicalize().ok() == want),
            Origin::Embedded => false,
        })
    }
}

/// The regular, non-hidden `*.toml` files of `dir`, sorted; none if `dir` does not exist.
/// Besides, the `*.toml` symbolic links that lead to no file (dangling, looping), skipped.
fn preset_files(dir: &Path) -> Result<(Vec<PathBuf>, Vec<Skipped>), CatalogError> {
    let io = |path: &Path, e: std::io::Error| CatalogError::Io {
        path: path.to_path_buf(),
        message: describe_io(&e),
    };
    let read = match std::fs::read_dir(dir) {
        Ok(r) => r,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok((Vec::new(), Vec::new())),
        Err(e) if e.kind() == std::io::ErrorKind::NotADirectory => {
            return Err(CatalogError::Io {
                path: dir.to_path_buf(),
                message: "is not a directory (user presets are read from this folder)".into(),
            });
        }
        Err(e) => return Err(io(dir, e)),
    };
    let (mut files, mut skipped) = (Vec::new(), Vec::new());
    for entry in read {
        let entry = entry.map_err(|e| io(dir, e))?;
        let path = entry.path();
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if name.starts_with('.') || !name.ends_with(".toml") {
            continue;
        }
        if path.is_file() {
            files.push(path);
        } else if entry.file_type().is_ok_and(|t| t.is_symlink())
            && let Err(e) = std::fs::metadata(&path)
        {
            let why = match e.kind() {
                std::io::ErrorKind::NotFound => "a symbolic link to a missing file".into(),
                _ => format!(
                    "a symbolic link that cannot be followed: {}",
                    describe_io(&e)
                ),
            };
            skipped.push(Skipped {
                path,
                why,
                error: None,
                name: None,
            });
        }
    }
    files.sort();
    skipped.sort_by(|a, b| a.path.cmp(&b.path));
    Ok((files, skipped))
}

#[cfg(test)]
mod tests;
