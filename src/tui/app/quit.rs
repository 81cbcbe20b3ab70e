//! Quitting (issue 29): Esc never quits; `q` quits at once when nothing would be lost, else
//! asks first, naming what would go — the pins, the measured data, the fit — and a second `q`
//! (or `y`) quits; Ctrl-C quits at once, as an interrupt.

use super::App;
use crate::tui::state::Overlay;

impl App {
    /// `q`: quit, or ask first when work would be lost; in the question, quit.
    pub(super) fn ask_to_quit(&mut self) {
        match (&self.overlay, self.at_stake()) {
            (Overlay::Quit(_), _) | (_, None) => self.quit = true,
            (_, Some(what)) => self.overlay = Overlay::Quit(what),
        }
    }

    /// What quitting would lose, as the question names it: "2 pins, measured data, the fit".
    pub fn at_stake(&self) -> Option<String> {
        let mut lost = Vec::new();
        match self.pins.len() {
            0 => {}
            1 => lost.push("1 pin".to_string()),
            n => lost.push(format!("{n} pins")),
        }
        if self.fit.loaded.is_some() || !self.fit.overlays.is_empty() {
            lost.push("measured data".into());
        }
        if self.fit.pane.is_some() {
            lost.push("the fit".into());
        }
        (!lost.is_empty()).then(|| lost.join(", "))
    }
}
