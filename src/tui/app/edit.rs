//! How `update` changes the setting (with undo) and says what it did.

use super::{App, Message, Setting, Severity, UNDO_DEPTH, Undoable};
use crate::model::params::ImpactParams;
use crate::text::short;
use crate::tui::param::Param;

impl App {
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
            oblique: self.oblique.values(),
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
