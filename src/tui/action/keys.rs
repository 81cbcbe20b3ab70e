//! Key → action mapping. Pure: it reads the key and the current input mode, nothing else.

use super::{Action, CursorMove, Mode, Scroll};
use crate::tui::param::{Dir, Param};
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

/// The action for a terminal event, if any (key presses and repeats; releases are ignored).
pub fn from_event(event: &Event, mode: Mode) -> Option<Action> {
    match event {
        Event::Key(key) if key.kind != KeyEventKind::Release => from_key(*key, mode),
        Event::Resize(w, h) => Some(Action::Resize(*w, *h)),
        _ => None,
    }
}

/// The action for a key in `mode`.
pub fn from_key(key: KeyEvent, mode: Mode) -> Option<Action> {
    let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
    if ctrl && matches!(key.code, KeyCode::Char('c' | 'C')) {
        return Some(Action::QuitNow);
    }
    if ctrl && mode == Mode::Input && matches!(key.code, KeyCode::Char('u' | 'U')) {
        return Some(Action::InputClear);
    }
    match mode {
        Mode::Input => match key.code {
            KeyCode::Enter => Some(Action::InputSubmit),
            KeyCode::Esc => Some(Action::InputCancel),
            KeyCode::Backspace => Some(Action::InputBackspace),
            KeyCode::Delete => Some(Action::InputDelete),
            KeyCode::Left => Some(Action::InputCursor(CursorMove::Left)),
            KeyCode::Right => Some(Action::InputCursor(CursorMove::Right)),
            KeyCode::Home => Some(Action::InputCursor(CursorMove::Home)),
            KeyCode::End => Some(Action::InputCursor(CursorMove::End)),
            KeyCode::Char(c) if !ctrl && !c.is_control() => Some(Action::InputChar(c)),
            _ => None,
        },
        Mode::Confirm => match key.code {
            KeyCode::Char('y' | 'Y') => Some(Action::ConfirmYes),
            KeyCode::Char('n' | 'N') | KeyCode::Esc => Some(Action::ConfirmNo),
            _ => None,
        },
        Mode::Help => help(key.code),
        Mode::Picker => picker(key.code),
        Mode::Form => form(key.code),
        // Esc never quits (issue 29): only q, which may ask first
        Mode::TooSmall => match key.code {
            KeyCode::Char('q' | 'y') => Some(Action::Quit),
            // leaves `q`'s question (src/tui/ui.rs writes it on the small screen)
            KeyCode::Char('n') => Some(Action::CloseHelp),
            _ => None,
        },
        Mode::QuitConfirm => match key.code {
            KeyCode::Char('q' | 'y' | 'Y') => Some(Action::Quit),
            KeyCode::Char('n' | 'N') | KeyCode::Esc => Some(Action::CloseHelp),
            _ => None,
        },
        Mode::Normal
        | Mode::Map
        | Mode::Crosshair
        | Mode::Oblique
        | Mode::ObliqueMap
        | Mode::Flight
            if ctrl =>
        {
            None
        }
        Mode::Flight => flight::keys(key).or_else(|| normal(key)),
        Mode::Oblique => oblique::charts(key).or_else(|| normal(key)),
        Mode::ObliqueMap => oblique::map(key).or_else(|| normal(key)),
        Mode::Normal => normal(key),
        Mode::Map => map(key).or_else(|| normal(key)),
        Mode::Crosshair => crosshair(key).or_else(|| normal(key)),
    }
}

/// In the help: scroll, or close it (`q` too: the help is left, not the explorer).
fn help(code: KeyCode) -> Option<Action> {
    let scroll = |s| Some(Action::HelpScroll(s));
    match code {
        KeyCode::Esc | KeyCode::Enter | KeyCode::Char('?' | 'q') => Some(Action::CloseHelp),
        KeyCode::Up | KeyCode::Char('k') => scroll(Scroll::Up),
        KeyCode::Down | KeyCode::Char('j') => scroll(Scroll::Down),
        KeyCode::PageUp => scroll(Scroll::PageUp),
        KeyCode::PageDown | KeyCode::Char(' ') => scroll(Scroll::PageDown),
        KeyCode::Home | KeyCode::Char('g') => scroll(Scroll::Home),
        KeyCode::End | KeyCode::Char('G') => scroll(Scroll::End),
        _ => None,
    }
}

/// The cells or steps an arrow key moves something: (right, up), one (Shift: `leap`); `None`
/// for any other key. The map views' cursors and the crosshair move by it.
fn arrow(key: KeyEvent, leap: i32) -> Option<(i32, i32)> {
    let n = if key.modifiers.contains(KeyModifiers::SHIFT) {
        leap
    } else {
        1
    };
    match key.code {
        KeyCode::Right => Some((n, 0)),
        KeyCode::Left => Some((-n, 0)),
        KeyCode::Up => Some((0, n)),
        KeyCode::Down => Some((0, -n)),
        _ => None,
    }
}

/// The map view's own keys: arrows move the cursor a cell (Shift: [`MAP_LEAP`] cells), `n`
/// the quantity, `t` the targets.
fn map(key: KeyEvent) -> Option<Action> {
    if let Some((zeta, lambda)) = arrow(key, MAP_LEAP) {
        return Some(Action::MapCursor { lambda, zeta });
    }
    match key.code {
        KeyCode::Char('n') => Some(Action::MapQuantity),
        KeyCode::Char('t') => Some(Action::MapTargets),
        _ => None,
    }
}

/// In the preset or surface picker: move, choose, or close (`q`, `g` and `G` close it too).
fn picker(code: KeyCode) -> Option<Action> {
    let move_by = |s| Some(Action::PickerMove(s));
    match code {
        KeyCode::Esc | KeyCode::Char('q' | 'g' | 'G') => Some(Action::CloseHelp),
        KeyCode::Enter => Some(Action::PickerChoose),
        KeyCode::Up | KeyCode::Char('k') => move_by(Scroll::Up),
        KeyCode::Down | KeyCode::Char('j') => move_by(Scroll::Down),
        KeyCode::PageUp => move_by(Scroll::PageUp),
        KeyCode::PageDown => move_by(Scroll::PageDown),
        KeyCode::Home => move_by(Scroll::Home),
        KeyCode::End => move_by(Scroll::End),
        _ => None,
    }
}

mod flight;
mod modal;
mod oblique;
use modal::{crosshair, form};

/// Cells a Shift+arrow moves the map's cursor.
pub const MAP_LEAP: i32 = 8;

fn normal(key: KeyEvent) -> Option<Action> {
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    let step = |param, dir| {
        Some(Action::Step {
            param,
            dir,
            coarse: false,
        })
    };
    let selected = |dir, coarse| Some(Action::StepSelected { dir, coarse });
    match key.code {
        KeyCode::Char('q') => Some(Action::Quit),
        KeyCode::Esc => Some(Action::Dismiss),
        KeyCode::Char('l') => step(Param::Lambda, Dir::Up),
        KeyCode::Char('L') => step(Param::Lambda, Dir::Down),
        KeyCode::Char('z') => step(Param::Zeta, Dir::Up),
        KeyCode::Char('Z') => step(Param::Zeta, Dir::Down),
        KeyCode::Char('v') => step(Param::V0, Dir::Up),
        KeyCode::Char('V') => step(Param::V0, Dir::Down),
        KeyCode::Up => selected(Dir::Up, shift),
        KeyCode::Down => selected(Dir::Down, shift),
        KeyCode::PageUp => selected(Dir::Up, true),
        KeyCode::PageDown => selected(Dir::Down, true),
        KeyCode::Right => Some(Action::SelectNext),
        KeyCode::Left => Some(Action::SelectPrev),
        KeyCode::Char('[') => Some(Action::SetCoarse(false)),
        KeyCode::Char(']') => Some(Action::SetCoarse(true)),
        KeyCode::Char('=') | KeyCode::Enter => Some(Action::OpenInput),
        KeyCode::Char(c @ '1'..='9') => Some(Action::LoadPreset(c as usize - '1' as usize)),
        KeyCode::Char('c') => Some(Action::CycleLaw),
        KeyCode::Char('r') => Some(Action::Reset),
        KeyCode::Char('R') => Some(Action::Retry),
        KeyCode::Char('p') => Some(Action::Pin),
        KeyCode::Char('P') => Some(Action::Unpin),
        KeyCode::Char('u') => Some(Action::Undo),
        KeyCode::Char('e') => Some(Action::Export),
        KeyCode::Char('s') => Some(Action::SavePreset),
        KeyCode::Char('S') => Some(Action::SaveSession),
        KeyCode::Char('y') => Some(Action::ShowCommand),
        KeyCode::Char('g') => Some(Action::OpenPicker),
        KeyCode::Char('G') => Some(Action::OpenSurfaces),
        KeyCode::Char('m') => Some(Action::OpenForm),
        KeyCode::Char('x') => Some(Action::Crosshair),
        KeyCode::Tab => Some(Action::NextView),
        KeyCode::BackTab => Some(Action::PrevView),
        KeyCode::Char('?') => Some(Action::ToggleHelp),
        KeyCode::Char('d') => Some(Action::ToggleDrop),
        KeyCode::Char('i') => Some(Action::Oblique(super::ObliqueKey::Toggle)),
        KeyCode::Char('h') => Some(Action::Flight(super::FlightKey::Toggle)),
        KeyCode::Char(' ') => Some(Action::DropPause),
        KeyCode::Char('b') => Some(Action::DropReplay),
        KeyCode::Char('o') => Some(Action::OpenMeasured),
        KeyCode::Char('O') => Some(Action::ClearMeasured),
        KeyCode::Char('f') => Some(Action::Fit),
        KeyCode::Char('F') => Some(Action::ApplyFit),
        KeyCode::Char('N') => Some(Action::Normalize),
        KeyCode::Char('+') => Some(Action::Zoom(1)),
        KeyCode::Char('-') => Some(Action::Zoom(-1)),
        KeyCode::Char('0') => Some(Action::Zoom(0)),
        _ => None,
    }
}

#[cfg(test)]
mod tests;
