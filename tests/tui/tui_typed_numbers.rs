//! `y`'s line writes numbers as a user types them and still runs what the screen shows
//! (issue 51 item 2): 8 psi typed in the form was `--pressure 55158.058345346886`, three
//! steps of 0.1 `--v0 3.3000000000000003`, a λ typed 0.3 `--lambda 0.30000000000000004`.
//! Now: the shortest text that reads back to the same bits (src/tui/exact.rs), and the
//! line, parsed by the command line, opens the explorer on the same ball to the bit.

use bouncelab::cli::Cli;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action};
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::param::{Dir, Param};
use bouncelab::tui::physical::Field;
use bouncelab::tui::session::Session;
use clap::Parser;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;

fn ball(name: &str) -> App {
    let p = Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == name)
        .unwrap();
    App::new(p, false)
}

fn key(app: &mut App, code: KeyCode) {
    if let Some(a) = action::from_key(KeyEvent::new(code, KeyModifiers::NONE), app.mode()) {
        app.update(a);
    }
}

/// Type `text` into the form's `field` and close the form.
fn set(app: &mut App, field: Field, text: &str) {
    let said = crate::tui_common::type_into_form(app, field, text);
    assert!(matches!(app.overlay(), Overlay::Form(_)), "{text}: {said}");
    key(app, KeyCode::Esc);
}

fn step(app: &mut App, param: Param, times: usize) {
    for _ in 0..times {
        app.update(Action::Step {
            param,
            dir: Dir::Up,
            coarse: false,
        });
    }
}

/// The significant digits of each number in `line` (a word that reads as a number, or a
/// number before a unit): none may be float noise (15 digits or more).
fn longest_number(line: &str) -> usize {
    line.split_whitespace()
        .map(|w| w.trim_end_matches(|c: char| c.is_ascii_alphabetic()))
        .filter(|w| w.parse::<f64>().is_ok())
        .map(|w| {
            let mantissa = w.split(['e', 'E']).next().unwrap_or("");
            mantissa
                .chars()
                .filter(char::is_ascii_digit)
                .collect::<String>()
                .trim_start_matches('0')
                .trim_end_matches('0')
                .len()
        })
        .max()
        .unwrap_or(0)
}

/// The explorer the line opens, parsed by the command line as typed.
fn reopened(line: &str) -> App {
    let words: Vec<String> = line.split_whitespace().map(String::from).collect();
    let cli = Cli::try_parse_from(&words).unwrap_or_else(|e| panic!("{line}: {e}"));
    cli.explore.app(&cli.choice, false).unwrap().0
}

#[test]
fn eight_psi_is_written_8psi_and_the_line_opens_the_same_ball() {
    let mut app = ball("basketball");
    set(&mut app, Field::Pressure, "8psi");
    let p = app.setting().conditions.pressure.unwrap();
    assert_eq!(p, 8.0 * bouncelab::conditions::pressure::PSI);
    let line = app.command_line();
    assert!(line.contains("--pressure 8psi"), "{line}");
    assert!(longest_number(&line) < 15, "{line}");
    let again = reopened(&line);
    assert_eq!(
        again.setting().conditions,
        app.setting().conditions,
        "{line}"
    );
    assert_eq!(again.setting().params, app.setting().params, "{line}");
}

#[test]
fn typed_and_stepped_numbers_are_written_as_typed_and_run_to_the_bit() {
    let mut app = ball("football");
    set(&mut app, Field::Mass, "425.3");
    set(&mut app, Field::Pressure, "0.83bar");
    set(&mut app, Field::Lambda, "0.3");
    step(&mut app, Param::V0, 3);
    step(&mut app, Param::Zeta, 2);
    let s = app.setting();
    assert_eq!(s.params.mass, 0.4253);
    let line = app.command_line();
    assert!(line.contains("--mass 0.4253"), "{line}");
    assert!(line.contains("--lambda 0.3 "), "{line}");
    assert!(longest_number(&line) < 15, "{line}");
    let again = reopened(&line);
    assert_eq!(again.setting().params, s.params, "{line}");
    assert_eq!(again.setting().conditions, s.conditions, "{line}");
    // the export's `bouncelab run` line is the same options: it runs the same ball
    let run = app.run_line();
    assert!(longest_number(&run) < 15, "{run}");
}

#[test]
fn the_session_writes_the_typed_and_stepped_numbers_as_typed_and_restores_them() {
    let mut app = ball("football");
    set(&mut app, Field::Mass, "425.3");
    set(&mut app, Field::Radius, "110.5");
    step(&mut app, Param::V0, 3);
    let text = app.session().to_toml();
    assert!(text.contains("mass = 0.4253"), "{text}");
    assert!(text.contains("radius = 0.1105"), "{text}");
    // three steps of 0.1 from the preset's v0: its decimal, as the session writes it
    let v0 = bouncelab::text::number(app.setting().params.v0);
    assert!(longest_number(&v0) < 15, "{v0}");
    assert!(text.contains(&format!("v0 = {v0}")), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let back = ball("football").with_session(&read).unwrap();
    assert_eq!(back.setting(), app.setting());
}

#[test]
fn the_oblique_and_flight_lines_write_stepped_values_as_typed() {
    let mut app = ball("tennis");
    key(&mut app, KeyCode::Char('i'));
    // K_t stepped by ×1.1 (from the ball's own, Mindlin's): tidy to 12 digits, never the
    // factor's noise (1e5 × 1.1 is 110000.00000000001)
    for _ in 0..2 {
        app.update(Action::Oblique(bouncelab::tui::action::ObliqueKey::Step {
            param: bouncelab::tui::views::oblique::param::ObliqueParam::TangentialStiffness,
            up: true,
            coarse: false,
        }));
    }
    let line = app.command_line();
    assert!(line.contains("--tangential-stiffness"), "{line}");
    assert!(longest_number(&line) < 15, "{line}");
    key(&mut app, KeyCode::Char('i'));
    key(&mut app, KeyCode::Char('h'));
    for _ in 0..3 {
        app.update(Action::Flight(bouncelab::tui::action::FlightKey::Step {
            param: bouncelab::tui::views::flight::param::FlightParam::Height,
            up: true,
            coarse: false,
        }));
    }
    let line = app.command_line();
    assert!(line.starts_with("bouncelab shot"), "{line}");
    assert!(longest_number(&line) < 15, "{line}");
}
