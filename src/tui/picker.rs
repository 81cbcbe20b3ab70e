//! The preset picker (`g`): what it lists and how the event loop reads it. Listing reads the
//! user presets folder, so it is an effect ([`super::effect::Effect::ListPresets`]) carried
//! out by the loop with [`list`]; the state keeps the answer in a [`Picker`].

use crate::catalog::{self, Catalog, Origin};
use crate::preset::Preset;

/// One preset in the picker.
#[derive(Debug, Clone, PartialEq)]
pub struct PickEntry {
    pub preset: Preset,
    /// "embedded", or the file it was read from.
    pub origin: String,
}

/// An open picker (the preset picker's entries by default; the surface picker's are
/// [`crate::tui::surface::SurfacePicker`]): every entry, the highlighted one, and why the
/// user's folder could not be read (then only the embedded entries are listed).
#[derive(Debug, Clone, PartialEq)]
pub struct Picker<E = PickEntry> {
    pub entries: Vec<E>,
    pub selected: usize,
    pub error: Option<String>,
}

impl<E> Picker<E> {
    /// The picker on the loop's list, the entry `current` says is the one in use highlighted
    /// (the first when none is).
    pub fn opened(entries: Vec<E>, error: Option<String>, current: impl Fn(&E) -> bool) -> Self {
        let selected = entries.iter().position(current).unwrap_or(0);
        Picker {
            entries,
            selected,
            error,
        }
    }

    /// The highlighted entry, taken out of the picker (Enter).
    pub fn chosen(self) -> Option<E> {
        self.entries.into_iter().nth(self.selected)
    }
}

/// Every preset `run --preset` knows now: embedded ones, then user presets from `dir` (one
/// just saved too). When the folder cannot be read, the embedded ones and the reason; a file
/// of it that cannot be read or parsed is skipped (`Catalog::load`) and named with its reason.
pub fn list_in(dir: Option<&std::path::Path>) -> (Vec<PickEntry>, Option<String>) {
    let (catalog, error) = match Catalog::load(dir, None) {
        Ok(c) => {
            let bad: Vec<&str> = c
                .skipped()
                .iter()
                .filter(|s| s.error.is_some())
                .map(|s| s.why.as_str())
                .collect();
            let error = (!bad.is_empty()).then(|| format!("skipped: {}", bad.join("; ")));
            (c, error)
        }
        Err(e) => (
            Catalog::embedded(),
            Some(format!("user presets not read: {e}")),
        ),
    };
    let entries = catalog
        .entries()
        .iter()
        .map(|e| PickEntry {
            preset: e.preset.clone(),
            origin: match &e.origin {
                Origin::Embedded => "embedded".into(),
                Origin::File(p) => p.display().to_string(),
            },
        })
        .collect();
    (entries, error)
}

/// [`list_in`] the user presets folder.
pub fn list() -> (Vec<PickEntry>, Option<String>) {
    list_in(catalog::user_presets_dir().as_deref())
}
