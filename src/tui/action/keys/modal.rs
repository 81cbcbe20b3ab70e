//! The keys of the crosshair (`x`) and of the physical-inputs form (`m`).

use super::{Action, Scroll};
use ratatui::crossterm::event::{KeyCode, KeyEvent};

/// With the crosshair on: arrows move it a step (Shift: [`crate::tui::crosshair::LEAP`]
/// steps), Tab or `x` the next chart, Esc off.
pub(super) fn crosshair(key: KeyEvent) -> Option<Action> {
    if let Some((dx, dy)) = super::arrow(key, crate::tui::crosshair::LEAP as i32) {
        return Some(Action::CrosshairMove { dx, dy });
    }
    match key.code {
        KeyCode::Tab | KeyCode::Char('x') => Some(Action::CrosshairNext),
        KeyCode::Esc => Some(Action::CrosshairOff),
        _ => None,
    }
}

/// In the physical-inputs form: select a field, type its value, or close (`m`, `q` too).
pub(super) fn form(code: KeyCode) -> Option<Action> {
    match code {
        KeyCode::Esc | KeyCode::Char('q' | 'm') => Some(Action::CloseHelp),
        KeyCode::Enter | KeyCode::Char('=') => Some(Action::FormEdit),
        KeyCode::Up | KeyCode::Char('k') => Some(Action::FormMove(Scroll::Up)),
        KeyCode::Down | KeyCode::Char('j') => Some(Action::FormMove(Scroll::Down)),
        _ => None,
    }
}
