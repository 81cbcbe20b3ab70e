//! The preset picker (`g`) in [`App::update`]: the listed presets come back from the loop,
//! the arrows move the highlight, Enter loads the preset.

use super::{App, Overlay, Setting};
use crate::tui::action::{Action, Scroll};
use crate::tui::picker::Picker;

/// Rows a PgUp / PgDn moves the highlight.
const PAGE: usize = 10;

impl App {
    pub(super) fn picker(&mut self, action: Action) {
        match action {
            Action::PresetsListed(entries, error) => {
                if let Some(e) = &error {
                    self.warn(e.clone());
                }
                // the current ball highlighted, when listed
                let now = &self.preset().name;
                let picker = Picker::opened(entries, error, |e| &e.preset.name == now);
                self.overlay = Overlay::Picker(picker);
            }
            Action::PickerMove(how) => {
                let (selected, n) = match &mut self.overlay {
                    Overlay::Picker(p) => (&mut p.selected, p.entries.len()),
                    Overlay::Surfaces(p) => (&mut p.selected, p.entries.len()),
                    _ => return,
                };
                let last = n.saturating_sub(1);
                *selected = match how {
                    Scroll::Up => selected.saturating_sub(1),
                    Scroll::Down => (*selected + 1).min(last),
                    Scroll::PageUp => selected.saturating_sub(PAGE),
                    Scroll::PageDown => (*selected + PAGE).min(last),
                    Scroll::Home => 0,
                    Scroll::End => last,
                };
            }
            Action::PickerChoose if matches!(self.overlay, Overlay::Surfaces(_)) => {
                self.choose_surface()
            }
            Action::PickerChoose => self.choose(),
            _ => {}
        }
    }

    /// Load the highlighted preset: one the explorer has already by its place, another one
    /// added to its presets (so `r` and undo find it), and close the picker.
    fn choose(&mut self) {
        let Overlay::Picker(p) = std::mem::replace(&mut self.overlay, Overlay::None) else {
            return;
        };
        let Some(entry) = p.chosen() else {
            return;
        };
        let i = match self.presets.iter().position(|q| *q == entry.preset) {
            Some(i) => i,
            None => {
                self.presets.push(entry.preset);
                self.presets.len() - 1
            }
        };
        let name = self.presets[i].name.clone();
        self.change(Setting::from_preset(i, &self.presets[i]));
        self.info(format!("loaded {name}"));
    }
}
