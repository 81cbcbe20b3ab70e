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

/// The arrows of a view that steps values of its own (the impact view's λ, ζ, v0, the
/// oblique view's charts, the flight view): ↑ ↓ `step` the selected one, `up` or not (Shift,
/// PgUp/PgDn: `coarse`), → ← `select` the next one or the previous; `None` for other keys.
fn stepping<K>(
    key: KeyEvent,
    step: impl Fn(bool, bool) -> K,
    select: impl Fn(bool) -> K,
) -> Option<K> {
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    match key.code {
        KeyCode::Up => Some(step(true, shift)),
        KeyCode::Down => Some(step(false, shift)),
        KeyCode::PageUp => Some(step(true, true)),
        KeyCode::PageDown => Some(step(false, true)),
        KeyCode::Right => Some(select(true)),
        KeyCode::Left => Some(select(false)),
        _ => None,
    }
}

/// The letters that step a view's values directly: each of `letters`' in lower case steps
/// its value up, in upper case down (`l` `z` `v` λ, ζ, v0; `a` `w` `k` θ or the elevation,
/// ω, μ); the value and whether up, or `None` for other keys.
fn lettered<P: Copy>(code: KeyCode, letters: [(char, P); 3]) -> Option<(P, bool)> {
    let KeyCode::Char(c) = code else { return None };
    letters.into_iter().find_map(|(letter, param)| {
        if c == letter {
            Some((param, true))
        } else if c == letter.to_ascii_uppercase() {
            Some((param, false))
        } else {
            None
        }
    })
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
    let dir = |up| if up { Dir::Up } else { Dir::Down };
    let letters = [('l', Param::Lambda), ('z', Param::Zeta), ('v', Param::V0)];
    if let Some((param, up)) = lettered(key.code, letters) {
        return Some(Action::Step {
            param,
            dir: dir(up),
            coarse: false,
        });
    }
    let arrows = stepping(
        key,
        |up, coarse| Action::StepSelected {
            dir: dir(up),
            coarse,
        },
        |next| {
            if next {
                Action::SelectNext
            } else {
                Action::SelectPrev
            }
        },
    );
    if arrows.is_some() {
        return arrows;
    }
    match key.code {
        KeyCode::Char('q') => Some(Action::Quit),
        KeyCode::Esc => Some(Action::Dismiss),
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
