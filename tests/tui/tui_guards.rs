//! What the explorer refuses, and says so (issue 18): keys below the minimum size, the help's
//! own keys, over-long names and values.

use crate::tui_common;
use crate::tui_common::superball;

use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::param::Param;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use tui_common::*;

fn input_error(app: &App) -> Option<String> {
    match app.overlay() {
        Overlay::Input(i) => i.error.clone(),
        _ => None,
    }
}

#[test]
fn below_the_minimum_size_only_resize_and_quit_act() {
    let mut app = superball();
    let v0 = app.setting().get(Param::V0);
    app.update(Action::Resize(40, 12));
    press(&mut app, &chars("vvv?l=s"));
    press(&mut app, &[KeyCode::Enter, KeyCode::Tab]);
    assert_eq!(app.setting().get(Param::V0), v0, "v0 changed unseen");
    assert_eq!(app.mode(), Mode::TooSmall);
    assert_eq!(app.overlay(), &Overlay::None, "no invisible dialog opened");
    assert_eq!(app.undo_depth(), 0);
    app.update(Action::Resize(120, 40));
    press(&mut app, &chars("v"));
    assert!(
        app.setting().get(Param::V0) > v0,
        "keys act again once large enough"
    );
    app.update(Action::Resize(40, 12));
    // v0 changed: q asks first, on the small screen itself (issue 51), and q again quits
    press(&mut app, &chars("q"));
    assert!(!app.should_quit(), "asks before losing the change");
    let screen = screen_text(&draw(&app, 40, 12)).join(" ");
    assert!(screen.contains("Quit and lose your changes"), "{screen}");
    press(&mut app, &chars("n"));
    assert_eq!(app.overlay(), &Overlay::None, "n stays");
    press(&mut app, &chars("qq"));
    assert!(app.should_quit(), "q still quits below the minimum size");
}

#[test]
fn the_help_scrolls_and_q_closes_it() {
    let mut app = superball();
    app.update(Action::Resize(80, 24));
    press(&mut app, &chars("?"));
    assert_eq!(app.help_scroll(), 0);
    press(&mut app, &chars("j"));
    assert_eq!(app.help_scroll(), 1);
    press(&mut app, &[KeyCode::Up, KeyCode::Up]);
    assert_eq!(app.help_scroll(), 0, "stops at the top");
    press(&mut app, &[KeyCode::End]);
    let end = app.help_scroll();
    assert!(end > 0);
    press(&mut app, &[KeyCode::Down, KeyCode::PageDown]);
    assert_eq!(app.help_scroll(), end, "stops at the end");
    insta::assert_snapshot!(draw(&app, 80, 24).backend());
    press(&mut app, &[KeyCode::Home]);
    assert_eq!(app.help_scroll(), 0);
    press(&mut app, &chars("q"));
    assert!(!app.should_quit(), "q closes the help, it does not quit");
    assert_eq!(app.mode(), Mode::Normal);
}

#[test]
fn a_name_over_40_characters_is_refused_not_cut() {
    let mut app = superball();
    press(&mut app, &chars("s"));
    press(&mut app, &[KeyCode::Backspace; 16]);
    let long = "a".repeat(45);
    press(&mut app, &chars(&long));
    let Overlay::Input(i) = app.overlay() else {
        panic!("no prompt")
    };
    assert_eq!(i.text, long, "the name is kept whole");
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.mode(), Mode::Input, "the prompt stays open");
    assert_eq!(
        input_error(&app).as_deref(),
        Some("a preset name has at most 40 characters")
    );
}

#[test]
fn a_long_value_is_read_whole() {
    let mut app = superball();
    press(
        &mut app,
        &[KeyCode::Right, KeyCode::Right, KeyCode::Char('=')],
    );
    press(&mut app, &chars("1.0000000000000000000000e-1"));
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.mode(), Mode::Normal);
    assert_eq!(app.setting().get(Param::V0), 0.1);
}

/// Type `text` as the value of the selected parameter; the entry's error, if refused.
fn enter_value(app: &mut App, text: &str) -> Option<String> {
    press(app, &[KeyCode::Char('=')]);
    press(app, &chars(text));
    press(app, &[KeyCode::Enter]);
    let error = input_error(app);
    press(app, &[KeyCode::Esc]);
    error
}

#[test]
fn out_of_range_typed_values_are_refused_with_the_range() {
    let mut app = superball();
    let before = app.setting().clone();
    press(&mut app, &[KeyCode::Right, KeyCode::Right]); // v0
    let why = enter_value(&mut app, "-5").expect("v0 -5 refused");
    assert!(why.contains("range"), "{why}");
    press(&mut app, &[KeyCode::Left, KeyCode::Left]); // λ
    assert!(enter_value(&mut app, "-1").is_some(), "λ -1 refused");
    assert!(
        enter_value(&mut app, "1e-16").is_some(),
        "λ 1e-16 refused as run does"
    );
    press(&mut app, &[KeyCode::Right]); // ζ
    assert!(enter_value(&mut app, "-0.5").is_some(), "ζ -0.5 refused");
    let why = enter_value(&mut app, "1e999").unwrap();
    assert!(
        why.contains("(must be finite); ζ kept (range 0 or 1e-15 … 1e6)")
            && !why.contains("not a number"),
        "{why}"
    );
    assert_eq!(app.setting(), &before, "nothing was clamped in");
}

#[test]
fn ctrl_u_clears_the_entry() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Char('=')]);
    press(&mut app, &chars("123"));
    let ctrl_u = KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL);
    app.update(action::from_key(ctrl_u, app.mode()).expect("Ctrl-U acts"));
    let Overlay::Input(i) = app.overlay() else {
        panic!("no entry")
    };
    assert_eq!(i.text, "");
}

#[test]
fn a_long_reason_wraps_in_the_entry() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Char('=')]);
    press(&mut app, &chars("1e-16"));
    press(&mut app, &[KeyCode::Enter]);
    insta::assert_snapshot!(draw(&app, 80, 24).backend());
}

/// Issue 29, item 11: at 60 columns the help cut its longest lines ("switch view (impact,
/// sweeps, models, ma"); they wrap under their text column, and the scroll reaches the end.
#[test]
fn the_help_wraps_at_sixty_columns_and_scrolls_to_its_end() {
    let mut app = superball();
    app.update(Action::Resize(60, 20));
    press(&mut app, &[KeyCode::Char('?')]);
    let mut seen = String::new();
    for _ in 0..40 {
        let rows = screen_text(&draw(&app, 60, 20));
        seen.push_str(&rows.join("\n"));
        press(&mut app, &[KeyCode::PageDown]);
    }
    for (_, text) in bouncelab::tui::keys::KEYS
        .iter()
        .filter(|k| !k.1.is_empty())
    {
        for word in text.split(' ') {
            assert!(
                seen.contains(word),
                "'{word}' of '{text}' never shown:\n{seen}"
            );
        }
    }
    assert!(seen.contains("switch view"), "{seen}");
}
