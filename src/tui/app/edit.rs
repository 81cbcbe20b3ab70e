//! How `update` changes the setting (with undo) and says what it did.

use super::{App, Message, Setting, Severity, UNDO_DEPTH};
use crate::text::sig_trim;
use crate::tui::param::Param;

impl App {
    /// Set `param` to `value` brought into range; a note when it had to move.
    pub(super) fn set_param(&mut self, param: Param, value: f64) {
        let Some((v, moved)) = param.clamp(value) else {
            self.warn(format!("{} must be a finite number", param.symbol()));
            return;
        };
        if moved {
            self.warn(format!(
                "{} held at {}{} (range {})",
                param.symbol(),
                sig_trim(v, 4),
                param.unit(),
                param.range_text()
            ));
        }
        let params = param.set(&self.setting.params, v);
        self.change(Setting {
            params,
            ..self.setting.clone()
        });
    }

    /// Move to `next`, remembering the current setting for undo.
    pub(super) fn change(&mut self, next: Setting) {
        if next != self.setting {
            let previous = std::mem::replace(&mut self.setting, next);
            if self.undo.len() == UNDO_DEPTH {
                self.undo.remove(0);
            }
            self.undo.push(previous);
        }
    }

    pub(super) fn info(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Info,
        });
    }
    pub(super) fn warn(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Warning,
        });
    }
    pub(super) fn error(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Error,
        });
    }
}
