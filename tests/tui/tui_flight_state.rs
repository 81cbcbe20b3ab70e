//! The flight view's inputs kept (issue 57 item 3): `S` saves the launch, μ and the selected
//! value in the session's `[flight]` table and `--session` restores them (the same shot); `u`
//! undoes a step of the launch and says what it undid; `q` asks before losing one.

use crate::tui_common;

use bouncelab::tui::app::{App, View};
use bouncelab::tui::session::Session;
use bouncelab::tui::views::flight::param::FlightParam;
use ratatui::crossterm::event::KeyCode;
use std::path::Path;
use tui_common::*;

fn serve() -> App {
    opened_on("tennis", 'h', View::Flight)
}

/// The launch of the serve moved: elevation −3°, spin 220 rad/s, μ 0.65, speed 52 m/s, height
/// 2.9 m, the height left selected.
fn moved() -> App {
    let mut app = serve();
    press(
        &mut app,
        &[
            KeyCode::Up,
            KeyCode::Up,
            KeyCode::Char('a'),
            KeyCode::Char('a'),
            KeyCode::Char('w'),
            KeyCode::Char('w'),
            KeyCode::Char('k'),
            KeyCode::Left,
            KeyCode::Up,
        ],
    );
    let v = app.flight_view().values;
    assert_eq!(
        (v.speed, v.elevation, v.spin, v.friction),
        (52.0, -3.0, 220.0, 0.65)
    );
    assert!((v.height - 2.9).abs() < 1e-12, "{}", v.height);
    assert_eq!(app.flight_view().selected.0, FlightParam::Height);
    app
}

#[test]
fn a_session_keeps_the_flight_view_and_restores_the_same_shot() {
    let app = moved();
    let text = app.session().to_toml();
    assert!(text.contains("[flight]"), "{text}");
    assert!(text.contains("selected = \"height\""), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let mut back = serve().with_session(&read).unwrap();
    back.refresh();
    assert_eq!(back.view(), View::Flight);
    assert_eq!(back.flight_view().values, app.flight_view().values);
    assert_eq!(back.flight_view().selected, app.flight_view().selected);
    let (a, b) = (
        app.flight_view().report().unwrap(),
        back.flight_view().report().unwrap(),
    );
    assert_eq!(a.bounces[0].x, b.bounces[0].x);
    assert_eq!(a.bounces[0].v_out, b.bounces[0].v_out);
    // the restored state is the kept one: `q` loses nothing
    assert_eq!(back.at_stake(), None);
    // a file without [flight] (version 2) reads, the view at its defaults
    let v2 = text.replace("version = 3", "version = 2");
    let v2 = v2.split("[flight]").next().unwrap().to_string();
    let read = Session::parse(Path::new("v2.toml"), &v2).unwrap();
    let old = serve().with_session(&read).unwrap();
    assert_eq!(old.flight_view().values, serve().flight_view().values);
}

#[test]
fn a_session_flight_value_the_library_refuses_is_named() {
    let text = moved().session().to_toml();
    for (from, to, says) in [
        (
            // the steps' decimal, without their float noise (src/tui/exact.rs)
            "height = 2.9",
            "height = 0.01",
            "flight: invalid height",
        ),
        (
            "elevation = -3.0",
            "elevation = 95.0",
            "flight: invalid elevation",
        ),
        (
            "selected = \"height\"",
            "selected = \"loft\"",
            "flight: selected: unknown value 'loft'",
        ),
    ] {
        let bad = text.replace(from, to);
        assert_ne!(bad, text, "{from}");
        let read = Session::parse(Path::new("bad.toml"), &bad).unwrap();
        let e = serve().with_session(&read).err().unwrap();
        assert!(e.starts_with(says), "{e}");
    }
}

#[test]
fn u_undoes_a_flight_step_and_says_what_it_undid() {
    let mut app = serve();
    let start = app.flight_view().values;
    let x0 = app.flight_view().report().unwrap().bounces[0].x;
    press(&mut app, &[KeyCode::Char('w')]);
    assert_eq!(app.flight_view().values.spin, 210.0);
    assert!(
        app.at_stake().is_some(),
        "a flight step is a change q asks about"
    );
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(app.flight_view().values, start);
    let said = &app.message().unwrap().text;
    assert_eq!(said, "undone: flight ω 210.0 → 200.0 rad/s");
    // the shot is the one before the step again
    assert_eq!(app.flight_view().report().unwrap().bounces[0].x, x0);
    assert_eq!(app.at_stake(), None);
    // the height, in the view's metres
    press(&mut app, &[KeyCode::Right, KeyCode::Up]);
    assert_eq!(app.flight_view().selected.0, FlightParam::Height);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(
        app.message().unwrap().text,
        "undone: flight H 2.900 → 2.800 m"
    );
    // a refused step is no change: nothing to undo
    let mut app = serve();
    for _ in 0..30 {
        press(&mut app, &[KeyCode::Down]);
    }
    let taken = app.flight_view().values.speed;
    assert!(taken >= 0.0);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(app.flight_view().values.speed, taken + 1.0);
}
