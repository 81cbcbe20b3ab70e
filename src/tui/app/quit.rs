//! Quitting (issue 29): Esc never quits; `q` quits at once when nothing would be lost, else
//! asks first, naming what would go — a change to the ball, the target or the oblique inputs
//! since the start or the last `S` (issue 51), the pins, the measured data, the fit that `S`
//! has not saved — and a second `q` (or `y`) quits; Ctrl-C quits at once, as an interrupt.

use super::{App, Setting, Undoable};
use crate::tui::state::Overlay;
use std::path::PathBuf;

/// What a session file holds of what `q` would otherwise ask for: the pins' settings, the
/// measured file by path, and the fit as the file writes it (its fields, in `Debug` form:
/// the app does not name the session's types, which name the app's).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Held {
    pub pins: Vec<Setting>,
    pub measured: Option<PathBuf>,
    pub fit: Option<String>,
}

impl App {
    /// `q`: quit, or ask first when work would be lost; in the question, quit.
    pub(super) fn ask_to_quit(&mut self) {
        match (&self.overlay, self.at_stake()) {
            (Overlay::Quit(_), _) | (_, None) => self.quit = true,
            (_, Some(what)) => self.overlay = Overlay::Quit(what),
        }
    }

    /// The setting, oblique and flight values now are the ones kept: `q` loses nothing of them.
    pub(in crate::tui) fn keep(&mut self) {
        self.kept = Undoable {
            setting: self.setting.clone(),
            oblique: self.oblique.values,
            flight: self.flight.values,
            measured: None,
        };
    }

    /// What quitting would lose, as the question names it: "2 pins, measured data, the fit,
    /// your changes (S saves them)". What the session last saved or opened holds is not lost:
    /// its pins, its measured file (by path) and its fit.
    pub fn at_stake(&self) -> Option<String> {
        let mut lost = Vec::new();
        let held = self.session_held.as_ref();
        let now = self.held();
        let pins = (now.pins.iter())
            .filter(|p| !held.is_some_and(|h| h.pins.contains(p)))
            .count();
        match pins {
            0 => {}
            1 => lost.push("1 pin".to_string()),
            n => lost.push(format!("{n} pins")),
        }
        let file_held = now.measured.is_some() && held.is_some_and(|h| h.measured == now.measured);
        if (now.measured.is_some() || !self.fit.overlays.is_empty()) && !file_held {
            lost.push("measured data".into());
        }
        let fit_held = now.fit.is_some() && held.is_some_and(|h| h.fit == now.fit);
        if self.fit.pane.is_some() && !fit_held {
            lost.push("the fit".into());
        }
        // a change undone back to the start is none (tests/tui/tui_quit.rs:
        // `q_asks_after_any_edit_and_not_after_it_is_undone`)
        if self.setting != self.kept.setting
            || self.oblique.values != self.kept.oblique
            || self.flight.values != self.kept.flight
        {
            lost.push("your changes (S saves them)".to_string());
        }
        (!lost.is_empty()).then(|| lost.join(", "))
    }
}
