//! The explorer's dialogs, as part of [`App::update`]: the text entry (an exact value, or the
//! name to save a preset under) and the question before a preset file is overwritten.

use super::{App, Confirm, Effect, Input, Overlay, Purpose};
use crate::model::params::ImpactParams;
use crate::text::parse::number;
use crate::tui::action::Action;
use crate::tui::param::Param;
use crate::tui::save::{self, SaveRequest};
use std::path::{Path, PathBuf};

/// Longest text the entry holds. Values and names are kept whole up to here and checked on
/// Enter (a name over `save::NAME_MAX` is refused then, with the reason), never cut; past it
/// a key is refused with a message — no number or name needs that many characters.
const ENTRY_MAX: usize = 100;

impl App {
    /// Whether `action` is one of [`App::dialog`]'s.
    pub(super) fn is_dialog(action: &Action) -> bool {
        matches!(
            action,
            Action::OpenInput
                | Action::InputChar(_)
                | Action::InputBackspace
                | Action::InputClear
                | Action::InputDelete
                | Action::InputCursor(_)
                | Action::InputSubmit
                | Action::InputCancel
                | Action::SavePreset
                | Action::ConfirmYes
                | Action::ConfirmNo
                | Action::OpenMeasured
                | Action::ToggleHelp
                | Action::CloseHelp
        )
    }

    /// The actions of the dialogs and the help overlay; a save to write when one is accepted.
    pub(super) fn dialog(&mut self, action: Action) -> Option<Effect> {
        match action {
            Action::OpenInput => self.open_input(Purpose::Value(self.selected), String::new()),
            Action::InputChar(c) => self.input_char(c),
            Action::InputClear | Action::InputBackspace | Action::InputDelete => {
                if let Overlay::Input(input) = &mut self.overlay {
                    match action {
                        Action::InputClear => input.clear(),
                        Action::InputBackspace => input.backspace(),
                        _ => input.delete(),
                    }
                }
            }
            Action::InputCursor(m) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.move_cursor(m);
                }
            }
            Action::InputSubmit => return self.submit_input(),
            Action::InputCancel => self.cancel_input(),
            Action::SavePreset => self.open_save(),
            Action::OpenMeasured => self.open_measured(),
            Action::ConfirmYes => return self.confirm(true),
            Action::ConfirmNo => return self.confirm(false),
            Action::CloseHelp => self.overlay = Overlay::None,
            Action::ToggleHelp => {
                self.help_scroll = 0;
                self.overlay = match self.overlay {
                    Overlay::Help => Overlay::None,
                    _ => Overlay::Help,
                }
            }
            _ => {}
        }
        None
    }

    pub(in crate::tui) fn open_input(&mut self, purpose: Purpose, text: String) {
        self.overlay = Overlay::Input(Input::new(purpose, text));
    }

    pub(super) fn input_char(&mut self, c: char) {
        if let Overlay::Input(input) = &mut self.overlay {
            if input.text.chars().count() < ENTRY_MAX {
                input.insert(c);
            } else {
                input.error = Some(format!("the entry holds at most {ENTRY_MAX} characters"));
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
            Purpose::MeasuredPath => return self.submit_path(text),
            Purpose::SessionPath => {
                self.overlay = Overlay::None;
                if text.is_empty() {
                    return None;
                }
                let text_out = self.session().to_toml();
                return Some(Effect::SaveSession {
                    path: std::path::PathBuf::from(text),
                    text: text_out,
                    replace: false,
                });
            }
            Purpose::Targets => {
                self.submit_targets(&text);
                return None;
            }
            Purpose::Physical(field) => {
                self.submit_physical(field, &text);
                return None;
            }
            Purpose::Oblique(p) => {
                self.submit_oblique(p, &text);
                return None;
            }
        };
        if text.is_empty() {
            self.overlay = Overlay::None;
            return None;
        }
        let checked = read_value(&text, param, &self.setting.params);
        match checked {
            Ok(params) => {
                self.overlay = Overlay::None;
                self.set_params(params);
            }
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
            }
        }
        None
    }

    pub(super) fn cancel_input(&mut self) {
        if let Overlay::Input(input) = &self.overlay {
            match input.purpose {
                Purpose::PresetName => self.info("not saved".into()),
                // Esc in a form field's entry goes back to the form
                Purpose::Physical(field) => return self.open_form(field),
                _ => {}
            }
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
        let c = match std::mem::replace(&mut self.overlay, Overlay::None) {
            Overlay::Confirm(c) => c,
            Overlay::Ask(ask) => return self.answer_ask(ask, yes),
            _ => return None,
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

/// A typed value for `param`, read as the command line reads numbers (so `1e999` is a
/// number, out of range) and checked by [`Param::check`]; or why not, in one line.
fn read_value(text: &str, param: Param, params: &ImpactParams) -> Result<ImpactParams, String> {
    let kept = format!("; {} kept", param.symbol());
    let v = number(text).map_err(|e| {
        // a long text is not echoed: the reason stays readable
        if text.chars().count() > 16 && e.ends_with("is not a number") {
            format!("not a number{kept}")
        } else {
            format!("{e}{kept}")
        }
    })?;
    param.check(v, params)
}
