//! The y/n questions before something is lost or replaced (issue 51): `O` before putting
//! away the measured data and the fit (`u` puts them back), `S` before replacing a session
//! file that exists; and a session file that could not be written, which keeps its entry
//! open with the system's reason.

use super::{App, Effect, Overlay, Purpose, Undoable};
use crate::tui::state::Ask;
use crate::tui::views::fit::state::FitState;
use std::path::PathBuf;

/// What `O` puts away: "measured data", "measured data and the fit".
pub fn put_away_what(fit: &FitState) -> String {
    if fit.pane.is_some() {
        "measured data and the fit".into()
    } else {
        "measured data".into()
    }
}

impl App {
    /// The answer to an [`Ask`]: `y` goes on, `n` (or Esc) keeps things as they are.
    pub(super) fn answer_ask(&mut self, ask: Ask, yes: bool) -> Option<Effect> {
        match (ask, yes) {
            (Ask::PutAway(what), true) => {
                self.put_away();
                self.info(format!("{what} put away (u puts them back)"));
                None
            }
            (Ask::PutAway(what), false) => {
                self.info(format!("{what} kept"));
                None
            }
            (Ask::Session { path, text }, true) => Some(Effect::SaveSession {
                path,
                text,
                replace: true,
            }),
            (Ask::Session { path, .. }, false) => {
                self.info(format!("session not saved: {} kept", path.display()));
                None
            }
        }
    }

    /// The measured data, the data to fit and the fit pane put away, as one change `u`
    /// undoes (tests/tui/tui_fit.rs: `o_asks_before_putting_away_and_u_puts_back`).
    fn put_away(&mut self) {
        let id = self.fit.id;
        let was = std::mem::take(&mut self.fit);
        self.fit.id = id;
        self.undo.push(Undoable {
            setting: self.setting.clone(),
            oblique: self.oblique.values,
            flight: self.flight.values,
            measured: Some(Box::new(was)),
        });
    }

    /// `u` after `O`: the measured data and the fit as they were (the fit's id stays the
    /// newest, so an answer for an older fit is still dropped).
    pub(super) fn put_back(&mut self, was: FitState) {
        let id = self.fit.id;
        self.fit = FitState { id, ..was };
    }

    /// The session file exists: ask before replacing it.
    pub(super) fn ask_session_overwrite(&mut self, path: PathBuf, text: String) {
        let file = path.display().to_string();
        self.warn(format!("{file} exists: overwrite it? y/n"));
        self.overlay = Overlay::Ask(Ask::Session { path, text });
    }

    /// The session file could not be written: the entry again, holding the name, with why.
    pub(super) fn session_failed(&mut self, path: &std::path::Path, why: String) {
        self.open_input(Purpose::SessionPath, path.display().to_string());
        if let Overlay::Input(input) = &mut self.overlay {
            input.error = Some(why.clone());
        }
        self.error(format!("session not saved: {why}"));
    }
}
