//! How `update` changes the setting (with undo) and says what it did: the keys that step,
//! select, load, reset, pin and undo.

use super::{App, Message, Setting, Severity, UNDO_DEPTH, Undoable};
use crate::model::params::ImpactParams;
use crate::text::short;
use crate::tui::action::Action;
use crate::tui::param::Param;

impl App {
    /// The actions that change the setting, the selection or the ghost.
    pub(super) fn edit(&mut self, action: Action) {
        match action {
            Action::Step { param, dir, coarse } => {
                self.selected = param;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.step_param(param, value);
            }
            Action::StepSelected { dir, coarse } => {
                let param = self.selected;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.step_param(param, value);
            }
            Action::SelectNext => self.selected = self.selected.next(),
            Action::SelectPrev => self.selected = self.selected.prev(),
            Action::SetCoarse(coarse) => {
                self.coarse = coarse;
                self.info(if coarse { "coarse steps" } else { "fine steps" }.into());
            }
            Action::LoadPreset(i) => self.load_preset(i),
            Action::CycleLaw => {
                let law = self.setting.law.next();
                self.change(Setting {
                    law,
                    ..self.setting.clone()
                });
                self.info(format!("contact law: {law}"));
            }
            Action::Reset => {
                let i = self.setting.preset;
                self.change(Setting::from_preset(i, &self.presets[i]));
                self.info(format!("reset to the {} preset", self.presets[i].name));
            }
            Action::Pin => self.pin(),
            Action::Unpin => self.unpin(),
            Action::Undo => match self.undo.pop() {
                Some(previous) => {
                    let said = self.undone_text(&previous);
                    self.setting = previous.setting;
                    self.oblique.values = previous.oblique;
                    self.flight.values = previous.flight;
                    if let Some(m) = previous.measured {
                        self.put_back(*m);
                    }
                    self.info(said);
                }
                None => self.warn("nothing to undo".into()),
            },
            _ => {}
        }
    }

    fn load_preset(&mut self, i: usize) {
        match self.presets.get(i) {
            Some(p) => {
                let name = p.name.clone();
                self.change(Setting::from_preset(i, p));
                self.info(format!("loaded {name}"));
            }
            // 4 loads a start preset that is none of the three; the help offers it, so
            // say why it does nothing here (tests/tui/tui_app.rs: `four_says_why_it_loads_nothing`)
            None if i == 3 => self.warn(format!(
                "4 loads the start preset when it is not one of 1–3: 1–{} load one",
                self.presets.len()
            )),
            None => self.warn(format!(
                "no preset {}: 1–{} load one",
                i + 1,
                self.presets.len()
            )),
        }
    }

    /// A stepping key moved `param` to `value`: taken when `run` takes it; past a bound it
    /// stops at the bound (or, when `run` refuses even that, where it is) and says so.
    pub(super) fn step_param(&mut self, param: Param, value: f64) {
        let now = self.setting.get(param);
        let Some((bound, moved)) = param.clamp(value) else {
            self.warn(format!("{} must be a finite number", param.symbol()));
            return;
        };
        let params = &self.setting.params;
        let (params, held) = match param.check(bound, params) {
            Ok(p) => (p, moved.then_some(bound)),
            Err(_) => (*params, Some(now)),
        };
        if let Some(at) = held {
            self.warn(format!(
                "{} held at {}{}: the range is {}",
                param.symbol(),
                short(at, 4),
                param.unit(),
                param.range_text()
            ));
        }
        self.set_params(params);
    }

    /// Take parameters already checked ([`Param::check`]).
    pub(super) fn set_params(&mut self, params: ImpactParams) {
        self.change(Setting {
            params,
            ..self.setting.clone()
        });
    }

    /// Move to `next`, remembering the current setting for undo.
    pub(in crate::tui) fn change(&mut self, next: Setting) {
        if next != self.setting {
            self.remember();
            self.setting = next;
        }
    }

    /// Put the current setting and the oblique view's values on the undo history (the
    /// oldest dropped past [`UNDO_DEPTH`]).
    pub(in crate::tui) fn remember(&mut self) {
        if self.undo.len() == UNDO_DEPTH {
            self.undo.remove(0);
        }
        self.undo.push(Undoable {
            setting: self.setting.clone(),
            oblique: self.oblique.values,
            flight: self.flight.values,
            measured: None,
        });
    }

    pub(in crate::tui) fn info(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Info,
        });
    }
    pub(in crate::tui) fn warn(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Warning,
        });
    }
    pub(in crate::tui) fn error(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Error,
        });
    }
}
