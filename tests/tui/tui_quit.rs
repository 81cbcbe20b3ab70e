//! Quitting (issue 29 item 1), through `App::update`: Esc never quits from a main view — after
//! the crosshair is taken away, after an accepted `=` entry, in every view, below the minimum
//! size; `q` quits at once when nothing would be lost and otherwise asks, naming the pins,
//! the measured data and the fit, a second `q` or `y` quitting and `n` or Esc staying.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::{Action, Mode};
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::views::fit::state as measured;
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

fn golf() -> App {
    App::new(Preset::embedded().remove(1), false)
}

#[test]
fn esc_never_quits_from_a_main_view() {
    let mut app = golf();
    // one Esc too many after an accepted entry, after the crosshair, in the help
    press(&mut app, &chars("="));
    press(&mut app, &chars("0.5"));
    press(&mut app, &[KeyCode::Enter, KeyCode::Esc, KeyCode::Esc]);
    assert!(!app.should_quit(), "after an accepted entry");
    press(&mut app, &chars("x"));
    press(&mut app, &[KeyCode::Esc, KeyCode::Esc]);
    assert!(!app.should_quit(), "after the crosshair");
    press(&mut app, &chars("?"));
    press(&mut app, &[KeyCode::Esc, KeyCode::Esc, KeyCode::Esc]);
    assert!(!app.should_quit(), "after the help");
    // in every view, the map's mode included
    for _ in 0..6 {
        press(&mut app, &[KeyCode::Tab, KeyCode::Esc, KeyCode::Esc]);
        assert!(!app.should_quit(), "in {:?}", app.view());
    }
    // below the minimum size only q quits
    app.update(Action::Resize(20, 8));
    assert_eq!(app.mode(), Mode::TooSmall);
    press(&mut app, &[KeyCode::Esc]);
    assert!(!app.should_quit(), "too small");
    app.update(Action::Resize(120, 40));
    // Esc says how to quit instead
    press(&mut app, &[KeyCode::Esc]);
    let screen = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(screen.contains("q quits"), "{screen}");
    // the entry's change undone: nothing to lose, q quits at once
    press(&mut app, &chars("u"));
    press(&mut app, &chars("q"));
    assert!(app.should_quit(), "nothing to lose: q quits at once");
}

#[test]
fn q_asks_when_pins_would_be_lost_and_a_second_q_or_y_quits() {
    for confirm in ['q', 'y'] {
        let mut app = golf();
        press(&mut app, &chars("plp"));
        press(&mut app, &chars("q"));
        assert!(!app.should_quit(), "asks first");
        assert_eq!(app.mode(), Mode::QuitConfirm);
        // λ stepped between the pins: the change is named too (issue 51)
        let lost = "2 pins, your changes (S saves them)";
        assert_eq!(*app.overlay(), Overlay::Quit(lost.into()));
        let screen = screen_text(&draw(&app, 80, 24)).join(" ");
        assert!(screen.contains("Quit and lose 2 pins, your"), "{screen}");
        // stray keys do nothing; n and Esc stay, the pins kept
        press(&mut app, &chars("l"));
        assert_eq!(app.undo_depth(), 1, "no key leaks through the question");
        press(&mut app, &chars("n"));
        assert_eq!((app.mode(), app.should_quit()), (Mode::Normal, false));
        press(&mut app, &chars("q"));
        press(&mut app, &[KeyCode::Esc]);
        assert_eq!((app.mode(), app.should_quit()), (Mode::Normal, false));
        press(&mut app, &chars("q"));
        press(&mut app, &[KeyCode::Char(confirm)]);
        assert!(app.should_quit(), "{confirm} confirms");
    }
}

#[test]
fn q_names_measured_data_and_the_fit() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("pulse.csv");
    let mut s = String::from("t,F\n");
    for i in 0..60 {
        let t = i as f64 * 1e-4;
        let f = (std::f64::consts::PI * t / 5e-3).sin().max(0.0) * 100.0;
        s.push_str(&format!("{t},{f}\n"));
    }
    std::fs::write(&path, s).unwrap();
    let mut app = golf();
    let data = measured::load(&path).unwrap();
    app.update(Action::MeasuredLoaded { path, data });
    assert_eq!(app.at_stake().as_deref(), Some("measured data"));
    let effects = app.update(Action::Fit);
    assert!(!effects.is_empty(), "a fit is asked for");
    assert_eq!(app.at_stake().as_deref(), Some("measured data, the fit"));
    press(&mut app, &chars("p"));
    assert_eq!(
        app.at_stake().as_deref(),
        Some("1 pin, measured data, the fit")
    );
    press(&mut app, &chars("q"));
    assert!(!app.should_quit());
    press(&mut app, &chars("q"));
    assert!(app.should_quit());
}

/// Ctrl-C is an interrupt: it quits at once, pins or not.
#[test]
fn ctrl_c_quits_at_once() {
    use ratatui::crossterm::event::{KeyEvent, KeyModifiers};
    let mut app = golf();
    press(&mut app, &chars("p"));
    let ctrl_c = KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL);
    app.update(bouncelab::tui::action::from_key(ctrl_c, app.mode()).unwrap());
    assert!(app.should_quit());
}

/// `q` asks after any edit — of the ball, the target, the oblique inputs — not only with pins
/// (issue 51 item 2: an edited ball was lost without a question); a change undone back to
/// the start is none.
#[test]
fn q_asks_after_any_edit_and_not_after_it_is_undone() {
    let edits: [&[KeyCode]; 4] = [
        &[KeyCode::Char('l')],
        &[KeyCode::Char('c')],
        &[KeyCode::Char('1')],
        &[KeyCode::Char('i'), KeyCode::Char('a')],
    ];
    for keys in edits {
        let mut app = golf();
        press(&mut app, keys);
        press(&mut app, &chars("q"));
        assert!(!app.should_quit(), "{keys:?}: asks first");
        assert_eq!(
            *app.overlay(),
            Overlay::Quit("your changes (S saves them)".into()),
            "{keys:?}"
        );
        press(&mut app, &chars("n"));
        press(&mut app, &chars("u"));
        press(&mut app, &chars("q"));
        assert!(app.should_quit(), "{keys:?} undone: q quits at once");
    }
    // a target typed in the form
    let mut app = golf();
    press(&mut app, &chars("m"));
    let n = bouncelab::tui::physical::Field::ALL
        .iter()
        .position(|&f| f == bouncelab::tui::physical::Field::TargetMass)
        .unwrap();
    for _ in 0..n {
        press(&mut app, &[KeyCode::Down]);
    }
    press(&mut app, &[KeyCode::Enter]);
    press(&mut app, &chars("800"));
    press(&mut app, &[KeyCode::Enter, KeyCode::Esc]);
    assert_eq!(app.setting().target.mass, 0.8);
    press(&mut app, &chars("q"));
    assert!(!app.should_quit(), "a target edit: asks first");
    // a saved session keeps the changes: nothing to lose
    press(&mut app, &chars("n"));
    app.update(Action::SessionSaved("s.toml".into()));
    press(&mut app, &chars("q"));
    assert!(app.should_quit(), "saved: q quits at once");
}
