//! The surface catalog: the embedded surfaces plus the user's surface files, read from
//! `surfaces/` beside the user presets folder (`$XDG_CONFIG_HOME/bouncelab/surfaces/*.toml`,
//! docs/surfaces.md). The rules are the presets': a surface is known by its `name`; a name
//! taken twice is an error naming both origins; a file that cannot be read or parsed is an
//! error at `file:line:column`, never skipped.

use super::{CatalogError, MAX_FILE_BYTES, Origin, describe_io, preset_files};
use crate::preset::PresetError;
use crate::target::surface::Surface;
use std::io::Read;
use std::path::{Path, PathBuf};

/// A surface and where it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceEntry {
    /// The surface, parsed and checked.
    pub surface: Surface,
    /// Where it came from.
    pub origin: Origin,
}

/// The folder user surfaces are read from: `surfaces` beside the user presets folder.
pub fn user_surfaces_dir() -> Option<PathBuf> {
    super::user_presets_dir().and_then(|p| p.parent().map(|d| d.join("surfaces")))
}

/// Every surface known: the embedded ones, then the files of `dir` (none when `None` or
/// missing), in file-name order.
pub fn load(dir: Option<&Path>) -> Result<Vec<SurfaceEntry>, CatalogError> {
    let mut all: Vec<SurfaceEntry> = Surface::embedded()
        .into_iter()
        .map(|surface| SurfaceEntry {
            surface,
            origin: Origin::Embedded,
        })
        .collect();
    let files = match dir {
        Some(d) => preset_files(d)?.0,
        None => Vec::new(),
    };
    for path in files {
        let surface = read_surface_file(&path)?;
        if let Some(old) = all.iter().find(|e| e.surface.name == surface.name) {
            return Err(CatalogError::Duplicate {
                what: "surface",
                name: surface.name,
                first: old.origin.clone(),
                second: Origin::File(path),
            });
        }
        all.push(SurfaceEntry {
            surface,
            origin: Origin::File(path),
        });
    }
    Ok(all)
}

/// The surface named `name` among `all`, or a one-line error listing the names there are.
pub fn find(all: &[SurfaceEntry], name: &str) -> Result<SurfaceEntry, String> {
    all.iter()
        .find(|e| e.surface.name == name)
        .cloned()
        .ok_or_else(|| {
            let names: Vec<&str> = all.iter().map(|e| e.surface.name.as_str()).collect();
            format!(
                "unknown surface '{}' (available: {})",
                crate::sanitize::line(name),
                names.join(", ")
            )
        })
}

/// Read and parse one surface file (at most [`MAX_FILE_BYTES`], UTF-8).
pub fn read_surface_file(path: &Path) -> Result<Surface, CatalogError> {
    let io = |message: String| CatalogError::Io {
        path: path.to_path_buf(),
        message,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| io(describe_io(&e)))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(io(format!(
            "a surface file is at most {MAX_FILE_BYTES} bytes"
        )));
    }
    let origin = path.display().to_string();
    let text = String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let text = String::from_utf8_lossy(valid);
        CatalogError::Preset(PresetError {
            origin: origin.clone(),
            position: Some(crate::preset::error::line_col(&text, text.len())),
            message: "not valid UTF-8 text (a surface file must be UTF-8)".into(),
        })
    })?;
    Surface::parse(&text, &origin).map_err(CatalogError::Preset)
}
