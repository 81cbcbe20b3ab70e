//! The explorer's dialogs, as part of [`App::update`]: the text entry (an exact value, or the
//! name to save a preset under) and the question before a preset file is overwritten.

use super::{App, Confirm, Input, Overlay, Purpose};
use crate::tui::save::{self, NAME_MAX};
use std::path::{Path, PathBuf};

/// Longest number typed in the value entry.
const VALUE_MAX: usize = 24;

impl App {
    pub(super) fn open_input(&mut self, purpose: Purpose, text: String) {
        self.overlay = Overlay::Input(Input {
            purpose,
            text,
            error: None,
        });
    }

    pub(super) fn input_char(&mut self, c: char) {
        if let Overlay::Input(input) = &mut self.overlay {
            let max = match input.purpose {
                Purpose::Value(_) => VALUE_MAX,
                Purpose::PresetName => NAME_MAX,
            };
            if input.text.chars().count() < max {
                input.text.push(c);
            }
        }
    }

    pub(super) fn submit_input(&mut self) {
        let Overlay::Input(input) = &mut self.overlay else {
            return;
        };
        let text = input.text.trim().to_string();
        let param = match input.purpose {
            Purpose::Value(p) => p,
            Purpose::PresetName => return self.submit_name(text),
        };
        if text.is_empty() {
            self.overlay = Overlay::None;
            return;
        }
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => {
                self.overlay = Overlay::None;
                self.set_param(param, v);
            }
            _ => {
                let why = format!("'{text}' is not a number; {} kept", param.symbol());
                input.error = Some(why.clone());
                self.warn(why);
            }
        }
    }

    pub(super) fn cancel_input(&mut self) {
        if let Overlay::Input(input) = &self.overlay
            && input.purpose == Purpose::PresetName
        {
            self.info("not saved".into());
        }
        self.overlay = Overlay::None;
    }

    /// `s`: the name prompt, filled with a suggestion the user can edit.
    pub(super) fn open_save(&mut self) {
        let name = save::default_name(&self.preset().name);
        self.open_input(Purpose::PresetName, name);
    }

    /// Enter in the name prompt: a refused name keeps the prompt open with the reason; an
    /// accepted one becomes a save request for the event loop.
    fn submit_name(&mut self, name: String) {
        match save::request(self, &name) {
            Ok(request) => {
                self.overlay = Overlay::None;
                self.save = Some(request);
            }
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
            }
        }
    }

    pub(super) fn saved(&mut self, path: &Path, replaced: bool) {
        let name = self.save.take().map(|r| r.name).unwrap_or_default();
        self.info(save::saved_message(&name, path, replaced));
    }

    /// The loop found the file taken: hold the save and ask.
    pub(super) fn ask_overwrite(&mut self, path: PathBuf, holds: Option<String>) {
        let Some(mut request) = self.save.take() else {
            return;
        };
        self.warn(save::question(&path));
        request.replace = Some(path);
        self.overlay = Overlay::Confirm(Confirm { request, holds });
    }

    /// The answer to "overwrite …? y/n": `y` hands the save (now allowed to replace that one
    /// file) back to the loop; `n` drops it.
    pub(super) fn confirm(&mut self, yes: bool) {
        let Overlay::Confirm(c) = std::mem::replace(&mut self.overlay, Overlay::None) else {
            return;
        };
        if yes {
            self.save = Some(c.request);
        } else if let Some(path) = &c.request.replace {
            self.info(save::declined_message(path));
        }
    }
}
