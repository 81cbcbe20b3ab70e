//! The key mapping's tests: a key in a mode gives its action, releases none.

use super::*;
use ratatui::crossterm::event::{Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

fn key(code: KeyCode) -> KeyEvent {
    KeyEvent::new(code, KeyModifiers::NONE)
}

#[test]
fn parameter_keys() {
    assert_eq!(
        from_key(key(KeyCode::Char('l')), Mode::Normal),
        Some(Action::Step {
            param: Param::Lambda,
            dir: Dir::Up,
            coarse: false
        })
    );
    let shift_l = KeyEvent::new(KeyCode::Char('L'), KeyModifiers::SHIFT);
    assert_eq!(
        from_key(shift_l, Mode::Normal),
        Some(Action::Step {
            param: Param::Lambda,
            dir: Dir::Down,
            coarse: false
        })
    );
    let shift_up = KeyEvent::new(KeyCode::Up, KeyModifiers::SHIFT);
    assert_eq!(
        from_key(shift_up, Mode::Normal),
        Some(Action::StepSelected {
            dir: Dir::Up,
            coarse: true
        })
    );
    assert_eq!(
        from_key(key(KeyCode::Char('3')), Mode::Normal),
        Some(Action::LoadPreset(2))
    );
    assert_eq!(
        from_key(key(KeyCode::Char('e')), Mode::Normal),
        Some(Action::Export)
    );
    assert_eq!(
        from_key(key(KeyCode::Char('e')), Mode::Input),
        Some(Action::InputChar('e'))
    );
}

#[test]
fn quitting() {
    let ctrl_c = KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL);
    for mode in [
        Mode::Normal,
        Mode::Help,
        Mode::Input,
        Mode::Confirm,
        Mode::TooSmall,
    ] {
        assert_eq!(from_key(ctrl_c, mode), Some(Action::QuitNow));
    }
    // Esc never quits from a main view (issue 29)
    for mode in [Mode::Normal, Mode::Map, Mode::Crosshair, Mode::TooSmall] {
        assert_ne!(
            from_key(key(KeyCode::Esc), mode),
            Some(Action::Quit),
            "{mode:?}"
        );
    }
    assert_eq!(
        from_key(key(KeyCode::Esc), Mode::Normal),
        Some(Action::Dismiss)
    );
    assert_eq!(
        from_key(key(KeyCode::Char('q')), Mode::Normal),
        Some(Action::Quit)
    );
    let quit = |c| from_key(key(c), Mode::QuitConfirm);
    assert_eq!(quit(KeyCode::Char('q')), Some(Action::Quit));
    assert_eq!(quit(KeyCode::Char('y')), Some(Action::Quit));
    assert_eq!(quit(KeyCode::Char('n')), Some(Action::CloseHelp));
    assert_eq!(quit(KeyCode::Esc), Some(Action::CloseHelp));
    assert_eq!(quit(KeyCode::Char('l')), None);
    assert_eq!(
        from_key(key(KeyCode::Esc), Mode::Help),
        Some(Action::CloseHelp)
    );
    assert_eq!(
        from_key(key(KeyCode::Esc), Mode::Input),
        Some(Action::InputCancel)
    );
    assert_eq!(
        from_key(key(KeyCode::Char('q')), Mode::Input),
        Some(Action::InputChar('q'))
    );
    assert_eq!(
        from_key(key(KeyCode::Char('c')), Mode::Normal),
        Some(Action::CycleLaw)
    );
}

#[test]
fn save_and_the_question() {
    assert_eq!(
        from_key(key(KeyCode::Char('s')), Mode::Normal),
        Some(Action::SavePreset)
    );
    assert_eq!(
        from_key(key(KeyCode::Char('s')), Mode::Input),
        Some(Action::InputChar('s'))
    );
    let answer = |c| from_key(key(c), Mode::Confirm);
    assert_eq!(answer(KeyCode::Char('y')), Some(Action::ConfirmYes));
    assert_eq!(answer(KeyCode::Char('Y')), Some(Action::ConfirmYes));
    assert_eq!(answer(KeyCode::Char('n')), Some(Action::ConfirmNo));
    assert_eq!(answer(KeyCode::Esc), Some(Action::ConfirmNo));
    // a stray key does not answer, and q does not quit past the question
    for c in [KeyCode::Enter, KeyCode::Char('q'), KeyCode::Char('l')] {
        assert_eq!(answer(c), None, "{c:?}");
    }
}

#[test]
fn releases_are_ignored() {
    let mut k = key(KeyCode::Char('l'));
    k.kind = KeyEventKind::Release;
    assert_eq!(from_event(&Event::Key(k), Mode::Normal), None);
    assert_eq!(
        from_event(&Event::Resize(10, 10), Mode::Normal),
        Some(Action::Resize(10, 10))
    );
}
