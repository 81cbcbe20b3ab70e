//! Pressure and temperature live in the explorer (issue 56): the form's `p` and `T` for an
//! inflated ball move K_p (K_r, c with it) as `--pressure` and `--temperature` do, the answers
//! recompute, the readout states the conditions, `y`'s line carries them and runs to the
//! screen's numbers, `S` keeps them and `--session` restores them, `u` undoes them; a solid
//! ball is refused a pressure with the library's reason.

use crate::common;
use crate::common::embedded;
use crate::tui_common;

use bouncelab::tui::action::{self, Action};
use bouncelab::tui::app::{App, Overlay, View};
use bouncelab::tui::physical::Field;
use bouncelab::tui::session::Session;
use common::{f, json};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;
use tui_common::*;

fn ball(name: &str) -> App {
    let p = embedded(name);
    App::new(p, false)
}

fn key(app: &mut App, code: KeyCode) {
    if let Some(a) = action::from_key(KeyEvent::new(code, KeyModifiers::NONE), app.mode()) {
        app.update(a);
    }
}

/// Open the form, go to `field`, type `text` over its value and press Enter; the form closed.
/// What the message line said before it closed.
fn set(app: &mut App, field: Field, text: &str) -> String {
    let said = type_into_form(app, field, text);
    // a refused entry stays open: Esc closes it, then the form
    for _ in 0..2 {
        if !matches!(app.overlay(), Overlay::None) {
            key(app, KeyCode::Esc);
        }
    }
    said
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// `bouncelab run … --format json` for the explorer's line `line` (its words after
/// `bouncelab`), the state it opens the explorer in, and the checks that both give `app`'s
/// COR, F_m and t_f to 1e-12.
fn runs_to_the_screen(app: &App, line: &str) {
    let words: Vec<String> = line.split_whitespace().map(String::from).collect();
    assert_eq!(words[0], "bouncelab", "{line}");
    let mut run = vec!["run".to_string()];
    run.extend(words[1..].iter().cloned());
    run.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = run.iter().map(String::as_str).collect();
    let r = json(&args);
    let again = explorer_from(line);
    let screen = app.run().expect("a run");
    let back = again.run().expect("a run");
    for (key, got, other) in [
        ("cor", screen.cor, back.cor),
        ("max_force", screen.max_force, back.max_force),
        (
            "contact_time",
            screen.contact_time.unwrap(),
            back.contact_time.unwrap(),
        ),
    ] {
        assert!(same(f(&r, key), got), "{line}: {key} {} {got}", f(&r, key));
        assert!(same(other, got), "{line}: reopened {key} {other} {got}");
    }
    assert_eq!(
        again.setting().conditions,
        app.setting().conditions,
        "{line}"
    );
}

#[test]
fn a_pressure_moves_k_p_and_the_answer_and_the_readout_says_so() {
    let mut app = ball("football");
    let (k_p, cor) = (app.setting().params.k_p, app.run().unwrap().cor);
    let lambda = app.setting().params.k_r / k_p;
    let said = set(&mut app, Field::Pressure, "40");
    let s = app.setting();
    assert_eq!(s.conditions.pressure, Some(40e3));
    assert!(s.params.k_p < k_p, "softer below the nominal pressure");
    assert!(same(s.params.k_r / s.params.k_p, lambda), "λ kept");
    assert_ne!(app.run().unwrap().cor, cor, "the answer recomputed");
    assert_eq!(said, "p = 40.00 kPa");
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    // the gauge pressure at the run's temperature (the record's 20 °C here)
    assert!(text.contains("conditions 20.00 °C,"), "{text}");
    assert!(text.contains("gauge 40.00 kPa"), "{text}");
    // with its unit, as --pressure reads it
    set(&mut app, Field::Pressure, "0.5bar");
    assert_eq!(app.setting().conditions.pressure, Some(50e3));
    // u undoes it, naming the pressure first
    key(&mut app, KeyCode::Char('u'));
    let said = app.message().unwrap().text.clone();
    assert!(
        said.starts_with("undone: p 50.00 → 40.00 kPa, K_p "),
        "{said}"
    );
    key(&mut app, KeyCode::Char('u'));
    assert_eq!(app.setting().conditions.pressure, None);
    assert_eq!(app.setting().params.k_p, k_p);
    assert_eq!(app.run().unwrap().cor, cor);
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(!text.contains("conditions "), "{text}");
}

#[test]
fn a_temperature_carries_the_pressure_by_the_gas_law() {
    let mut app = ball("football");
    let k_p = app.setting().params.k_p;
    set(&mut app, Field::Temperature, "0");
    let s = app.setting();
    assert_eq!(s.conditions.temperature, Some(0.0));
    assert!(s.params.k_p < k_p, "cold: lower pressure, softer");
    let text = screen_text(&draw(&app, 160, 50)).join("\n");
    assert!(text.contains("conditions 0 °C, gauge "), "{text}");
    // back at the record's temperature: no condition left to state
    set(&mut app, Field::Temperature, "20");
    assert_eq!(app.setting().conditions.temperature, None);
    assert_eq!(app.setting().params.k_p, k_p);
}

#[test]
fn a_solid_ball_takes_no_pressure_and_k_p_is_not_typed_beside_one() {
    let mut app = ball("superball");
    let why = set(&mut app, Field::Pressure, "50");
    assert_eq!(app.setting().conditions.pressure, None);
    assert!(why.contains("is not inflated"), "{why}");
    // a typed K_p and then a pressure: refused, as `run --k-p … --pressure …` is
    let mut app = ball("football");
    set(&mut app, Field::KP, "5000");
    let why = set(&mut app, Field::Pressure, "50");
    assert_eq!(app.setting().conditions.pressure, None);
    assert!(why.contains("K_p was typed"), "{why}");
    // a pressure and then a K_p: refused too
    let mut app = ball("football");
    set(&mut app, Field::Pressure, "50");
    let k_p = app.setting().params.k_p;
    let why = set(&mut app, Field::KP, "5000");
    assert_eq!(app.setting().params.k_p, k_p);
    assert!(why.contains("type p instead"), "{why}");
}

#[test]
fn y_carries_the_conditions_and_its_line_runs_to_the_screen() {
    for (field, text, option) in [
        (Field::Pressure, "45", "--pressure 45000"),
        (Field::Temperature, "5", "--temperature 5"),
    ] {
        let mut app = ball("football");
        set(&mut app, field, text);
        // a ζ of the user's own on top: the line's --zeta is taken at the conditions' K_p
        app.update(Action::Step {
            param: bouncelab::tui::param::Param::Zeta,
            dir: bouncelab::tui::param::Dir::Up,
            coarse: false,
        });
        let line = app.command_line();
        assert!(line.contains(option), "{line}");
        assert!(!line.contains("--k-p"), "{line}");
        runs_to_the_screen(&app, &line);
    }
}

#[test]
fn the_oblique_and_flight_lines_carry_the_conditions() {
    let mut app = ball("football");
    set(&mut app, Field::Pressure, "45");
    app.update(Action::Step {
        param: bouncelab::tui::param::Param::Lambda,
        dir: bouncelab::tui::param::Dir::Up,
        coarse: false,
    });
    key(&mut app, KeyCode::Char('i'));
    app.refresh();
    assert_eq!(app.view(), View::Oblique);
    let line = app.command_line();
    assert!(
        line.contains("--pressure 45000") && line.contains("--k-r"),
        "{line}"
    );
    // to 1e-12, as the oblique view's own line (tests/tui/tui_oblique.rs)
    assert_oblique_answer_is(&app, &line_json(&line), &line);
    // the flight view's `bouncelab shot` line too
    key(&mut app, KeyCode::Char('i'));
    key(&mut app, KeyCode::Char('h'));
    app.refresh();
    assert_eq!(app.view(), View::Flight);
    let line = app.command_line();
    assert!(
        line.starts_with("bouncelab shot") && line.contains("--pressure 45000"),
        "{line}"
    );
    let j = line_json(&line);
    let r = app.flight_view().report().expect("a shot");
    let b = &j["bounces"][0];
    for (k, v) in [("x", r.bounces[0].x), ("v_out", r.bounces[0].v_out)] {
        let got = b[k].as_f64().unwrap();
        assert!(close(got, v), "{line}: {k} {got} {v}");
    }
}

#[test]
fn a_session_keeps_the_conditions_and_restores_them() {
    let mut app = ball("football");
    set(&mut app, Field::Pressure, "45");
    set(&mut app, Field::Temperature, "5");
    let text = app.session().to_toml();
    assert!(text.contains("pressure = 45000.0"), "{text}");
    assert!(text.contains("temperature = 5.0"), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let back = ball("football").with_session(&read).unwrap();
    assert_eq!(back.setting(), app.setting());
    assert_eq!(back.run().unwrap().cor, app.run().unwrap().cor);
    // a pressure the library refuses is named
    let bad = text.replace("pressure = 45000.0", "pressure = -2e5");
    let read = Session::parse(Path::new("bad.toml"), &bad).unwrap();
    let e = ball("football").with_session(&read).err().unwrap();
    assert!(e.starts_with("invalid pressure"), "{e}");
}

#[test]
fn the_form_shows_p_and_t() {
    let mut app = ball("football");
    key(&mut app, KeyCode::Char('m'));
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("p        80.00 kPa"), "{text}");
    assert!(text.contains("T        20.00 °C"), "{text}");
    insta::assert_snapshot!("conditions_form_120x40", draw(&app, 120, 40).backend());
}
