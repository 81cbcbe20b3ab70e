//! The surface's μ and K_t are fields of the form (issue 53 item 1; c_t was already): typed
//! there, checked as the oblique view checks them, they are the values the oblique impact and
//! the court pace run on (μ the flight view's bounce's too); the oblique and shot lines (`y`)
//! carry them and run to the screen's numbers; `S` keeps them; `u` undoes them, naming them;
//! the form still scrolls to them at 80 × 24. Before, the form had no μ or K_t field.

use crate::common;
use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Overlay, View};
use bouncelab::tui::physical::Field;
use bouncelab::tui::session::Session;
use ratatui::crossterm::event::KeyCode;
use std::path::Path;
use tui_common::*;

fn tennis() -> App {
    let p = Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == "tennis")
        .unwrap();
    App::new(p, false)
}

/// Open the form on `field` and type `text` over its value; Enter. What the message said.
fn type_in(app: &mut App, field: Field, text: &str) -> String {
    press(app, &[KeyCode::Char('m')]);
    let n = Field::ALL.iter().position(|&f| f == field).unwrap();
    for _ in 0..n {
        press(app, &[KeyCode::Down]);
    }
    press(app, &[KeyCode::Enter]);
    app.update(Action::InputClear);
    type_keys(app, text);
    press(app, &[KeyCode::Enter]);
    app.message().map(|m| m.text.clone()).unwrap_or_default()
}

/// The tennis ball with μ 0.45 and K_t 5e4 typed in the form (each entry closed).
fn tennis_at_mu_and_k_t() -> App {
    let mut app = tennis();
    type_in(&mut app, Field::Friction, "0.45");
    press(&mut app, &[KeyCode::Esc]);
    type_in(&mut app, Field::TangentialStiffness, "5e4");
    press(&mut app, &[KeyCode::Esc]);
    app
}

#[test]
fn mu_and_k_t_are_typed_in_the_form_and_refused_out_of_range() {
    let mut app = tennis();
    let said = type_in(&mut app, Field::Friction, "-0.5");
    assert!(said.contains("μ kept"), "{said}");
    assert!(
        matches!(app.overlay(), Overlay::Input(_)),
        "the entry stays open"
    );
    assert_eq!(app.oblique_view().values.friction, 0.6);
    app.update(Action::InputClear);
    type_keys(&mut app, "0.45");
    press(&mut app, &[KeyCode::Enter]);
    assert!(
        matches!(app.overlay(), Overlay::Form(_)),
        "back in the form"
    );
    press(&mut app, &[KeyCode::Esc]);
    assert_eq!(app.oblique_view().values.friction, 0.45);
    assert_eq!(
        app.flight_view().values.friction,
        0.45,
        "the flight's bounce too"
    );
    let said = type_in(&mut app, Field::TangentialStiffness, "0");
    assert!(said.contains("K_t kept"), "{said}");
    app.update(Action::InputClear);
    type_keys(&mut app, "5e4");
    press(&mut app, &[KeyCode::Enter, KeyCode::Esc]);
    assert_eq!(app.oblique_view().values.tangential_stiffness, Some(5e4));
    // the form shows them in its format (four digits)
    assert_eq!(app.form_surface(), [0.45, 5e4]);
    assert_eq!(Field::Friction.show(0.45), "0.4500");
}

#[test]
fn the_oblique_impact_and_the_court_pace_run_on_them_and_the_lines_carry_them() {
    let mut app = tennis_at_mu_and_k_t();
    press(&mut app, &[KeyCode::Char('i')]);
    app.refresh();
    assert_eq!(app.view(), View::Oblique);
    let line = app.command_line();
    assert!(
        line.contains("--friction 0.45 --tangential-stiffness 50000"),
        "{line}"
    );
    let j = line_json(&line);
    let r = app.oblique_view().response().expect("an impact");
    for (k, v) in [
        ("v_out", r.v_out),
        ("angle_out_deg", r.angle_out_deg),
        ("spin_out", r.spin_out),
    ] {
        let got = j[k].as_f64().unwrap();
        assert!(close(got, v), "{line}: {k} {got} {v}");
    }
    // the court pace at the form's μ and K_t, as `bouncelab court` rates it
    let pace = app.oblique_view().pace.clone().unwrap().unwrap();
    let c = common::json(&[
        "court",
        "--preset",
        "tennis",
        "--friction",
        "0.45",
        "--tangential-stiffness",
        "5e4",
        "--format",
        "json",
    ]);
    let cpr = c["cpr"].as_f64().unwrap();
    assert!(close(cpr, pace.cpr), "{cpr} {}", pace.cpr);
    // the flight view's shot bounces on the form's μ
    press(&mut app, &[KeyCode::Char('i'), KeyCode::Char('h')]);
    app.refresh();
    let line = app.command_line();
    assert!(line.contains("--friction 0.45"), "{line}");
    let j = line_json(&line);
    let r = app.flight_view().report().expect("a shot");
    let got = j["bounces"][0]["v_out"].as_f64().unwrap();
    assert!(close(got, r.bounces[0].v_out), "{line}");
}

#[test]
fn a_session_keeps_them_and_u_undoes_them_naming_them() {
    let mut app = tennis_at_mu_and_k_t();
    let text = app.session().to_toml();
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let back = tennis().with_session(&read).unwrap();
    assert_eq!(back.oblique_view().values.friction, 0.45);
    assert_eq!(back.oblique_view().values.tangential_stiffness, Some(5e4));
    assert_eq!(back.flight_view().values.friction, 0.45);
    press(&mut app, &[KeyCode::Char('u')]);
    let said = app.message().unwrap().text.clone();
    assert!(said.starts_with("undone: K_t "), "{said}");
    assert_eq!(app.oblique_view().values.tangential_stiffness, None);
    press(&mut app, &[KeyCode::Char('u')]);
    let said = app.message().unwrap().text.clone();
    assert!(said.contains("μ 0.4500 → 0.6000"), "{said}");
    assert_eq!(app.oblique_view().values.friction, 0.6);
    assert_eq!(app.flight_view().values.friction, 0.6);
}

#[test]
fn the_form_scrolls_to_them_at_80x24() {
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('m')]);
    for field in [
        Field::Friction,
        Field::TangentialStiffness,
        Field::TangentialDamping,
    ] {
        while !matches!(app.overlay(), Overlay::Form(f) if f.selected == field) {
            press(&mut app, &[KeyCode::Down]);
        }
        let screen = screen_text(&draw(&app, 80, 24)).join("\n");
        let symbol = format!("▶{:<4}", field.symbol());
        assert!(screen.contains(&symbol), "{field:?}\n{screen}");
    }
}
