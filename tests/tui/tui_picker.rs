//! The preset picker (`g`): it lists the embedded and user presets, one just saved with `s`
//! included, with their descriptions; Enter loads, Esc closes; it scrolls at small sizes.

use crate::tui_common::superball;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Effect, Overlay};
use bouncelab::tui::param::Param;
use bouncelab::tui::{picker, save};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;

/// Press keys as the event loop would, carrying out the effects with `dir` as the user presets
/// folder (saves written there, the picker's list read from there).
fn press(app: &mut App, keys: &[KeyCode], dir: &Path) {
    for &code in keys {
        let m = match code {
            KeyCode::Char(c) if c.is_ascii_uppercase() => KeyModifiers::SHIFT,
            _ => KeyModifiers::NONE,
        };
        let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) else {
            continue;
        };
        let mut effects = app.update(a);
        while let Some(e) = effects.pop() {
            let answer = match e {
                Effect::ListPresets => {
                    let (entries, error) = picker::list_in(Some(dir));
                    Action::PresetsListed(entries, error)
                }
                Effect::Save(r) => save::write(&r, Some(dir)),
                _ => continue,
            };
            effects.extend(app.update(answer));
        }
    }
}

fn keys(s: &str) -> Vec<KeyCode> {
    s.chars().map(KeyCode::Char).collect()
}

fn picker_of(app: &App) -> &picker::Picker {
    match app.overlay() {
        Overlay::Picker(p) => p,
        other => panic!("the picker is open: {other:?}"),
    }
}

#[test]
fn g_lists_every_preset_with_its_description_and_the_current_one_highlighted() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    let effects = app.update(Action::OpenPicker);
    assert_eq!(
        effects,
        [Effect::ListPresets],
        "listing reads files: an effect"
    );
    assert_eq!(app.mode(), Mode::Normal);
    press(&mut app, &keys("2g"), dir.path());
    assert_eq!(app.mode(), Mode::Picker);
    let p = picker_of(&app);
    let names: Vec<&str> = p.entries.iter().map(|e| e.preset.name.as_str()).collect();
    let embedded: Vec<String> = Preset::embedded_all().into_iter().map(|p| p.name).collect();
    assert_eq!(names, embedded);
    assert_eq!(names[p.selected], "golf");
    assert!(p.entries.iter().all(|e| !e.preset.description.is_empty()));
    assert!(p.error.is_none());
    press(&mut app, &[KeyCode::Esc], dir.path());
    assert_eq!(app.overlay(), &Overlay::None);
    assert_eq!(app.preset().name, "golf", "Esc loads nothing");
}

#[test]
fn a_preset_just_saved_is_listed_and_loads_as_saved() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    press(&mut app, &keys("lllZv"), dir.path());
    let saved = app.setting().params;
    press(&mut app, &[KeyCode::Char('s')], dir.path());
    press(&mut app, &[KeyCode::Enter], dir.path()); // the suggested name
    assert!(
        app.message()
            .unwrap()
            .text
            .starts_with("saved preset superball-custom"),
        "{:?}",
        app.message()
    );
    press(&mut app, &keys("2g"), dir.path());
    let p = picker_of(&app);
    let last = p.entries.last().unwrap();
    assert_eq!(last.preset.name, "superball-custom");
    assert!(last.origin.ends_with("superball-custom.toml"));
    press(&mut app, &[KeyCode::End, KeyCode::Enter], dir.path());
    assert_eq!(app.overlay(), &Overlay::None);
    assert_eq!(app.preset().name, "superball-custom");
    assert_eq!(app.message().unwrap().text, "loaded superball-custom");
    let now = app.setting().params;
    for param in Param::ALL {
        assert_eq!(param.get(&now), param.get(&saved), "{param:?}");
    }
    // loading it again finds it among the explorer's presets, not added twice
    let count = app.presets().len();
    press(
        &mut app,
        &[KeyCode::Char('g'), KeyCode::End, KeyCode::Enter],
        dir.path(),
    );
    assert_eq!(app.presets().len(), count);
    // the second load changed nothing; undo goes back to golf, before the first
    press(&mut app, &keys("u"), dir.path());
    assert_eq!(app.preset().name, "golf");
}

#[test]
fn unreadable_user_presets_leave_the_embedded_ones_and_say_why() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("broken.toml"), "name = ").unwrap();
    let mut app = superball();
    press(&mut app, &keys("g"), dir.path());
    let p = picker_of(&app);
    assert_eq!(p.entries.len(), Preset::embedded_all().len());
    let error = p.error.as_deref().unwrap();
    assert!(error.contains("broken.toml"), "{error}");
}

#[test]
fn the_picker_scrolls_at_a_small_size() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    press(&mut app, &keys("g"), dir.path());
    press(&mut app, &[KeyCode::End], dir.path());
    let last = Preset::embedded_all().pop().unwrap().name;
    let mut t = Terminal::new(TestBackend::new(50, 16)).unwrap();
    t.draw(|f| f.render_widget(&app, f.area())).unwrap();
    let screen = format!("{:?}", t.backend());
    assert!(
        screen.contains(&format!("▶{last}")),
        "the last preset is in view"
    );
    // a description too long for the box is cut at a word with "…", not by its border
    let row = (0..16)
        .map(|y| {
            (1..49)
                .map(|x| t.backend().buffer()[(x, y)].symbol())
                .collect::<String>()
        })
        .find(|r| r.starts_with("   Softball"))
        .expect("a softball's description in view");
    assert!(row.trim_end().ends_with('…'), "{row}");
    insta::assert_snapshot!(t.backend());
    press(&mut app, &[KeyCode::Home, KeyCode::Down], dir.path());
    assert_eq!(picker_of(&app).selected, 1);
}

/// The list that comes back while the terminal is below the minimum size is taken, as every
/// other answer of the loop is: the picker opens once the terminal is large enough again.
#[test]
fn the_list_that_comes_back_while_the_terminal_is_too_small_is_taken() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    assert_eq!(app.update(Action::OpenPicker), [Effect::ListPresets]);
    app.update(Action::Resize(40, 10));
    assert!(app.too_small());
    let (entries, error) = picker::list_in(Some(dir.path()));
    app.update(Action::PresetsListed(entries, error));
    app.update(Action::Resize(120, 40));
    assert_eq!(app.mode(), Mode::Picker);
    assert!(!picker_of(&app).entries.is_empty());
}
