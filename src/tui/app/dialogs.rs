//! The explorer's dialogs, as part of [`App::update`]: the text entry (an exact value, or the
//! name to save a preset under) and the question before a preset file is overwritten.

use super::{App, Confirm, Effect, Input, Overlay, Purpose};
use crate::tui::action::Action;
use crate::tui::save::{self, NAME_MAX, SaveRequest};
use std::path::{Path, PathBuf};

/// Longest number typed in the value entry.
const VALUE_MAX: usize = 24;

impl App {
    /// The actions of the dialogs and the help overlay; a save to write when one is accepted.
    pub(super) fn dialog(&mut self, action: Action) -> Option<Effect> {
        match action {
            Action::OpenInput => self.open_input(Purpose::Value(self.selected), String::new()),
            Action::InputChar(c) => self.input_char(c),
            Action::InputBackspace => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.text.pop();
                }
            }
            Action::InputSubmit => return self.submit_input(),
            Action::InputCancel => self.cancel_input(),
            Action::SavePreset => self.open_save(),
            Action::ConfirmYes => return self.confirm(true),
            Action::ConfirmNo => return self.confirm(false),
            Action::CloseHelp => self.overlay = Overlay::None,
            Action::ToggleHelp => {
                self.overlay = match self.overlay {
                    Overlay::Help => Overlay::None,
                    _ => Overlay::Help,
                }
            }
            _ => {}
        }
        None
    }

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

    fn submit_input(&mut self) -> Option<Effect> {
        let Overlay::Input(input) = &mut self.overlay else {
            return None;
        };
        let text = input.text.trim().to_string();
        let param = match input.purpose {
            Purpose::Value(p) => p,
            Purpose::PresetName => return self.submit_name(text),
        };
        if text.is_empty() {
            self.overlay = Overlay::None;
            return None;
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
        None
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
    /// accepted one becomes a save for the event loop to write.
    fn submit_name(&mut self, name: String) -> Option<Effect> {
        match save::request(self.preset(), &self.setting, &name) {
            Ok(request) => {
                self.overlay = Overlay::None;
                Some(self.send_save(request))
            }
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
                None
            }
        }
    }

    /// Hand `request` to the event loop, keeping it until the answer comes back.
    fn send_save(&mut self, request: SaveRequest) -> Effect {
        self.save_out = Some(request.clone());
        Effect::Save(request)
    }

    pub(super) fn saved(&mut self, path: &Path, replaced: bool) {
        let name = self.save_out.take().map(|r| r.name).unwrap_or_default();
        self.info(save::saved_message(&name, path, replaced));
    }

    /// The loop found the file taken: hold the save and ask.
    pub(super) fn ask_overwrite(&mut self, path: PathBuf, holds: Option<String>) {
        let Some(mut request) = self.save_out.take() else {
            return;
        };
        self.warn(save::question(&path));
        request.replace = Some(path);
        self.overlay = Overlay::Confirm(Confirm { request, holds });
    }

    /// The answer to "overwrite …? y/n": `y` hands the save (now allowed to replace that one
    /// file) back to the loop; `n` drops it.
    fn confirm(&mut self, yes: bool) -> Option<Effect> {
        let Overlay::Confirm(c) = std::mem::replace(&mut self.overlay, Overlay::None) else {
            return None;
        };
        if yes {
            return Some(self.send_save(c.request));
        }
        if let Some(path) = &c.request.replace {
            self.info(save::declined_message(path));
        }
        None
    }
}
