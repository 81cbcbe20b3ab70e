//! The save flow's test helpers, shared by `tui_save.rs` and `tui_save_overwrite.rs`: keys as
//! the event loop maps them, and the loop's part of a save.
#![allow(dead_code)] // each test crate uses a part

use bouncelab::ContactLaw;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action};
use bouncelab::tui::app::{App, Effect, Overlay, Severity};
use bouncelab::tui::param::Param;
use bouncelab::tui::save::{self, SaveRequest};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::cell::RefCell;
use std::path::{Path, PathBuf};

thread_local! {
    /// The effects `update` returned that the test has not carried out yet, as the event
    /// loop holds them (each test runs on a thread of its own).
    static PENDING: RefCell<Vec<Effect>> = const { RefCell::new(Vec::new()) };
}

/// `update`, keeping the effects it returns for [`perform`].
pub fn update(app: &mut App, action: Action) {
    let effects = app.update(action);
    PENDING.with(|p| p.borrow_mut().extend(effects));
}

/// The save `update` asked for and the test has not carried out yet.
pub fn save_request() -> Option<SaveRequest> {
    PENDING.with(|p| {
        p.borrow().iter().rev().find_map(|e| match e {
            Effect::Save(r) => Some(r.clone()),
            _ => None,
        })
    })
}

/// Take the pending save off the list, to carry it out.
pub fn take_save() -> Option<SaveRequest> {
    let request = save_request();
    PENDING.with(|p| p.borrow_mut().retain(|e| !matches!(e, Effect::Save(_))));
    request
}

pub fn superball() -> App {
    App::new(Preset::embedded().remove(0), true)
}

/// Press keys as the event loop would; `\n` is Enter, `\x1b` Esc, `\x08` Backspace.
pub fn press(app: &mut App, keys: &str) {
    for c in keys.chars() {
        let code = match c {
            '\n' => KeyCode::Enter,
            '\x1b' => KeyCode::Esc,
            '\x08' => KeyCode::Backspace,
            c => KeyCode::Char(c),
        };
        let m = if c.is_ascii_uppercase() {
            KeyModifiers::SHIFT
        } else {
            KeyModifiers::NONE
        };
        if let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) {
            update(app, a);
        }
    }
}

/// Press `keys` (ending in the save key), type `name` over the suggested one, Enter.
pub fn save_as(app: &mut App, keys: &str, name: &str) {
    press(app, keys);
    type_name(app, name);
    press(app, "\n");
}

/// Replace the prompt's text with `name`.
pub fn type_name(app: &mut App, name: &str) {
    let n = match app.overlay() {
        Overlay::Input(i) => i.text.chars().count(),
        other => panic!("no prompt: {other:?}"),
    };
    press(app, &"\x08".repeat(n));
    press(app, name);
}

/// What the event loop does with a pending save; returns the loop's answer.
pub fn perform(app: &mut App, dir: &Path) -> Action {
    let request = take_save().expect("a save is pending");
    let answer = save::write(&request, Some(dir));
    update(app, answer.clone());
    assert!(
        save_request().is_none(),
        "the answer asks for no other save"
    );
    answer
}

pub fn message(app: &App) -> (String, Severity) {
    let m = app.message().expect("a message");
    (m.text.clone(), m.severity)
}

pub fn state(app: &App) -> (f64, f64, f64, ContactLaw) {
    let s = app.setting();
    (
        s.get(Param::Lambda),
        s.get(Param::Zeta),
        s.get(Param::V0),
        s.law,
    )
}

/// Move λ, ζ, v0 and the law off the preset, then save as `name` into `dir`.
pub fn save_modified(dir: &Path, name: &str) -> (App, PathBuf) {
    let mut app = superball();
    press(&mut app, "lllZZvvvvvc");
    save_as(&mut app, "s", name);
    let Action::Saved { path, replaced } = perform(&mut app, dir) else {
        panic!("not saved: {:?}", app.message());
    };
    assert!(!replaced);
    (app, path)
}
