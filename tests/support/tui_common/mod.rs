//! Helpers for the explorer's tests: keys sent through `action::from_key` and `App::update`
//! as the event loop sends them, and the screen drawn into a `TestBackend`.
#![allow(dead_code)]

use bouncelab::tui::action;
use bouncelab::tui::app::{App, Effect};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Press `keys` in turn (an upper-case letter with Shift, as a terminal sends it); the effects
/// `update` returned, in order.
pub fn press(app: &mut App, keys: &[KeyCode]) -> Vec<Effect> {
    let mut effects = Vec::new();
    for &code in keys {
        let m = match code {
            KeyCode::Char(c) if c.is_ascii_uppercase() => KeyModifiers::SHIFT,
            _ => KeyModifiers::NONE,
        };
        if let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) {
            effects.extend(app.update(a));
        }
    }
    effects
}

/// The keys of `s`, one character each.
pub fn chars(s: &str) -> Vec<KeyCode> {
    s.chars().map(KeyCode::Char).collect()
}

/// The whole explorer drawn at `w` × `h`.
pub fn draw(app: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t
}

/// The screen's rows as text.
pub fn screen_text(t: &Terminal<TestBackend>) -> Vec<String> {
    let buf = t.backend().buffer();
    (0..buf.area.height)
        .map(|y| {
            (0..buf.area.width)
                .map(|x| buf[(x, y)].symbol())
                .collect::<String>()
        })
        .collect()
}

/// Type `keys` as a terminal sends them: a letter (upper case with Shift), `\t` Tab, `\u{1b}`
/// Esc; the effects `update` returned, in order.
pub fn type_keys(app: &mut App, keys: &str) -> Vec<Effect> {
    let codes: Vec<KeyCode> = keys
        .chars()
        .map(|c| match c {
            '\t' => KeyCode::Tab,
            '\u{1b}' => KeyCode::Esc,
            c => KeyCode::Char(c),
        })
        .collect();
    press(app, &codes)
}
