//! The oblique view's state beyond its screen (issue 31): θ, ω, μ undone by `u` as λ and ζ
//! are, kept in a session (version 2; a version-1 file still reads), K_t and κ set in the
//! view with the command line's ranges, and `y` there giving the `bouncelab oblique` line
//! that computes the impact the view shows.

use crate::common;
use crate::common::embedded;
use crate::tui_common;
use common::argv_with;

use bouncelab::tui::app::{App, View};
use bouncelab::tui::session::Session;
use bouncelab::tui::views::oblique::param::ObliqueParam;
use bouncelab::tui::views::oblique::state::{ObliqueValues, Page};
use ratatui::crossterm::event::KeyCode;
use serde_json::Value;
use std::path::Path;
use tui_common::*;

fn tennis() -> App {
    let p = embedded("tennis");
    App::new(p, false)
}

/// Type `text` and Enter into the entry `=` opens.
fn values(app: &App) -> ObliqueValues {
    app.oblique_view().values
}

/// Select `p` with → from wherever the selection is.
fn select(app: &mut App, p: ObliqueParam) {
    for _ in 0..ObliqueParam::ALL.len() {
        if app.oblique_view().selected == p {
            return;
        }
        press(app, &[KeyCode::Right]);
    }
    panic!("{p:?} not reached");
}

#[test]
fn u_undoes_the_angle_spin_and_friction_as_it_does_lambda() {
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('i')]);
    let start = values(&app);
    type_keys(&mut app, "aawk");
    press(&mut app, &[KeyCode::Char('l')]);
    let moved = values(&app);
    assert_eq!(
        (moved.angle, moved.spin, moved.friction),
        (18.0, 10.0, 0.61)
    );
    // λ first (the last change), then μ, ω, θ, θ: one `u` each, in reverse order
    let lambda = app.setting().clone();
    press(&mut app, &[KeyCode::Char('u')]);
    assert_ne!(*app.setting(), lambda);
    assert_eq!(values(&app), moved);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(values(&app).friction, 0.6);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(values(&app).spin, 0.0);
    press(&mut app, &[KeyCode::Char('u'), KeyCode::Char('u')]);
    assert_eq!(values(&app), start);
    // a typed value and a move on the map are undone too
    select(&mut app, ObliqueParam::Angle);
    enter(&mut app, "40");
    assert_eq!(values(&app).angle, 40.0);
    press(&mut app, &[KeyCode::Char('t'), KeyCode::Right]);
    assert_eq!(values(&app).angle, 41.0);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(values(&app).angle, 40.0);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(values(&app), start);
    // and the impact follows what was undone
    let r = app.oblique_view().response().unwrap();
    assert_eq!(r.angle_in_deg, 16.0);
}

#[test]
fn k_t_and_kappa_are_set_in_the_view_with_the_command_line_s_ranges() {
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('i')]);
    // the ball's until set: Mindlin's K_t, the preset's κ
    let ball = app.oblique_ball();
    let k_t = ball.tangential_stiffness().unwrap();
    assert_eq!(app.oblique_value(ObliqueParam::TangentialStiffness), k_t);
    assert_eq!(
        app.oblique_value(ObliqueParam::InertiaFactor),
        ball.inertia_factor()
    );
    select(&mut app, ObliqueParam::TangentialStiffness);
    assert_entry_refused(
        &mut app,
        "0",
        "invalid tangential_stiffness: 0 (must be positive); K_t kept",
    );
    enter(&mut app, "2e5");
    assert_eq!(values(&app).tangential_stiffness, Some(2e5));
    // ↑ steps K_t by 10 %, Shift by ×2
    press(&mut app, &[KeyCode::Up]);
    assert!((values(&app).tangential_stiffness.unwrap() - 2.2e5).abs() < 1e-6);
    select(&mut app, ObliqueParam::InertiaFactor);
    enter(&mut app, "1.5");
    assert!(app.message().unwrap().text.contains("(0, 1]"));
    press(&mut app, &[KeyCode::Esc]);
    enter(&mut app, "0.99");
    press(&mut app, &[KeyCode::Up, KeyCode::Up]);
    assert_eq!(values(&app).inertia_factor, Some(1.0));
    assert!(app.message().unwrap().text.contains("κ held at 1"));
    // the impact runs on them, as `bouncelab oblique --tangential-stiffness --inertia-factor`
    let r = app.oblique_view().response().unwrap().clone();
    let out = common::bl(&argv_with(
        "oblique --preset tennis --angle 16 --friction 0.6 --tangential-stiffness {} \
         --inertia-factor 1 --format json",
        &[&format!("{}", values(&app).tangential_stiffness.unwrap())],
    ));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(j["spin_out"].as_f64().unwrap(), r.spin_out);
    assert_eq!(j["vx_out"].as_f64().unwrap(), r.vx_out);
    // the screen says them
    let text = screen_text(&draw(&app, 100, 30)).join("\n");
    assert!(text.contains("K_t 2.200e5 N/m ▶κ 1.000"), "{text}");
}

#[test]
fn y_in_the_oblique_view_gives_the_oblique_line_that_computes_its_impact() {
    let mut app = tennis();
    // λ and ζ moved (K_r and c: `oblique` takes them as --k-r, --damping), v0, θ, ω, μ, K_t
    type_keys(&mut app, "llzV");
    press(&mut app, &[KeyCode::Char('i')]);
    type_keys(&mut app, "aaaWWk");
    select(&mut app, ObliqueParam::TangentialStiffness);
    enter(&mut app, "1.5e5");
    press(&mut app, &[KeyCode::Char('y')]);
    let line = app.last_command().unwrap().to_string();
    let boxed = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(boxed.contains("computes this impact"), "{boxed}");
    assert!(
        line.starts_with("bouncelab oblique --preset tennis "),
        "{line}"
    );
    for part in [
        "--k-r ",
        "--damping ",
        "--angle 19 --spin -20 --friction 0.61 --tangential-stiffness 150000",
    ] {
        assert!(line.contains(part), "{part}: {line}");
    }
    assert!(
        !line.contains("--inertia-factor"),
        "κ is the ball's: {line}"
    );
    let words: Vec<&str> = line.split(' ').skip(1).collect();
    let mut args = words.clone();
    args.extend(["--format", "json"]);
    let out = common::bl(&args);
    assert_eq!(out.code, 0, "{line}: {}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let r = app.oblique_view().response().unwrap();
    for (k, v) in [
        ("v_out", r.v_out),
        ("angle_out_deg", r.angle_out_deg),
        ("spin_out", r.spin_out),
        ("cor_normal", r.cor_normal),
        ("contact_time", r.contact_time),
        ("max_normal_force", r.max_normal_force),
    ] {
        let cli = j[k].as_f64().unwrap();
        assert!(
            (cli - v).abs() <= 1e-12 * v.abs().max(1.0),
            "{k}: command line {cli}, view {v}"
        );
    }
    // outside the view `y` is the explorer's line, as before
    press(
        &mut app,
        &[KeyCode::Esc, KeyCode::Char('i'), KeyCode::Char('y')],
    );
    assert_eq!(app.view(), View::Impact);
    assert!(
        app.last_command()
            .unwrap()
            .starts_with("bouncelab --preset tennis")
    );
}

#[test]
fn a_session_keeps_the_oblique_view_and_a_version_1_file_still_reads() {
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('i')]);
    type_keys(&mut app, "aawwwK");
    select(&mut app, ObliqueParam::InertiaFactor);
    enter(&mut app, "0.5");
    press(&mut app, &[KeyCode::Char('t'), KeyCode::Char('n')]);
    let text = app.session().to_toml();
    assert!(text.contains("version = 3"), "{text}");
    assert!(text.contains("[oblique]"), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let back = tennis().with_session(&read).unwrap();
    assert_eq!(back.view(), View::Oblique);
    assert_eq!(values(&back), values(&app));
    let (a, b) = (app.oblique_view(), back.oblique_view());
    assert_eq!(
        (b.selected, b.page, b.quantity),
        (a.selected, a.page, a.quantity)
    );
    assert_eq!(b.page, Page::Map);
    assert_eq!(
        b.response().unwrap().spin_out,
        a.response().unwrap().spin_out
    );
    // a version-1 file (no [oblique]) reads, the view at its defaults
    let v1 = tennis()
        .session()
        .to_toml()
        .replace("version = 3", "version = 1");
    let v1 = v1.split("[oblique]").next().unwrap().to_string();
    let read = Session::parse(Path::new("v1.toml"), &v1).unwrap();
    let old = tennis().with_session(&read).unwrap();
    assert_eq!(values(&old), ObliqueValues::default());
    // a value out of the library's range is refused, naming it
    let bad = text.replace("inertia_factor = 0.5", "inertia_factor = 2.0");
    let read = Session::parse(Path::new("bad.toml"), &bad).unwrap();
    let e = tennis().with_session(&read).err().unwrap();
    assert!(e.starts_with("oblique: invalid inertia_factor: 2"), "{e}");
}
