//! The surface in the explorer (issue 53 item 6): the picker (`G`) lists the embedded and the
//! user's surfaces with their numbers, Enter puts the ball on one as `--surface NAME` does (its
//! K_s, c_s, M the target, its μ, K_t the oblique view's, its c_t the dashpot beside K_t); the
//! impact and oblique readouts name it with its numbers, the court pace gives its e; `y`'s
//! lines carry `--surface` and run to the screen's numbers; `S` keeps it and `--session`
//! restores it; `u` undoes it and says so.

use crate::common;
use crate::common::embedded;
use crate::tui_common;

use bouncelab::tui::action::{Action, Scroll};
use bouncelab::tui::app::{App, Overlay, View};
use bouncelab::tui::physical::Field;
use bouncelab::tui::session::Session;
use bouncelab::tui::surface::list_in;
use ratatui::crossterm::event::KeyCode;
use serde_json::Value;
use std::path::Path;
use tui_common::*;

fn tennis() -> App {
    let p = embedded("tennis");
    App::new(p, false)
}

/// A config home holding one user surface, `gym`: a floor that gives, with μ, K_t and c_t
/// (test numbers, each with its "source" as a surface file must give one).
fn config_with_gym() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("bouncelab/surfaces");
    std::fs::create_dir_all(&folder).unwrap();
    let mut text = String::from(
        "name = \"gym\"\ndescription = \"a test floor\"\n[normal]\nstiffness = 4e5\n\
         damping = 30.0\n[tangential]\nfriction = 0.45\nstiffness = 5e4\ndamping = 2.0\n",
    );
    for q in [
        "stiffness",
        "damping",
        "friction",
        "tangential_stiffness",
        "tangential_damping",
    ] {
        text.push_str(&format!(
            "[[sources]]\nquantity = \"{q}\"\nsource = \"a test\"\n"
        ));
    }
    std::fs::write(folder.join("gym.toml"), text).unwrap();
    dir
}

fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(String::from).collect()
}

#[test]
fn the_picker_lists_the_surfaces_and_puts_the_ball_on_one() {
    let config = config_with_gym();
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('G')]);
    let (entries, _) = list_in(Some(&config.path().join("bouncelab/surfaces")));
    let n = entries.len();
    app.update(Action::SurfacesListed(entries, None));
    app.update(Action::PickerMove(Scroll::End));
    let text = screen_text(&draw(&app, 100, 30)).join("\n");
    assert!(
        text.contains("gym") && text.contains("K_s 4.000e5 N/m"),
        "{text}"
    );
    assert!(text.contains("μ 0.4500, K_t 50000 N/m"), "{text}");
    assert_eq!(n, 9, "eight embedded surfaces and the user's");
    press(&mut app, &[KeyCode::Esc]);
    assert!(matches!(app.overlay(), Overlay::None));
    // Enter: the target is the gym's, the oblique view's μ and K_t, the c_t
    let before = app.run().unwrap().cor;
    pick_surface(&mut app, config.path(), "gym");
    let s = app.setting();
    assert_eq!((s.target.stiffness, s.target.damping), (4e5, 30.0));
    assert_eq!((s.target.mass, s.target.speed), (f64::INFINITY, 0.0));
    assert_eq!(s.tangential_damping, Some(2.0));
    assert_eq!(s.surface.as_ref().unwrap().name, "gym");
    let o = app.oblique_view().values;
    assert_eq!((o.friction, o.tangential_stiffness), (0.45, Some(5e4)));
    assert_ne!(
        app.run().unwrap().cor,
        before,
        "the impact is on the gym's floor"
    );
    let said = app.message().unwrap().text.clone();
    assert!(said.starts_with("surface gym: K_s 4.000e5 N/m"), "{said}");
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("surface gym:"), "{text}");
    // y: the explorer's line names the surface, and `run` on it gives the screen's impact
    let line = app.command_line();
    assert!(line.ends_with("--surface gym"), "{line}");
    let mut args = vec!["run".to_string()];
    args.extend(words(&line)[1..].iter().cloned());
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::bl_in(config.path(), &args);
    assert_eq!(out.code, 0, "{line}: {}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let run = app.run().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs());
    for (k, v) in [("cor", run.cor), ("max_force", run.max_force)] {
        let f = j[k].as_f64().unwrap();
        assert!(close(f, v), "{line}: {k} {f} {v}");
    }
    // u: back on the wall, saying so
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(app.setting().surface, None);
    assert_eq!(app.setting().target.stiffness, f64::INFINITY);
    assert_eq!(app.oblique_view().values.friction, 0.6);
    let said = app.message().unwrap().text.clone();
    assert!(
        said.starts_with("undone: surface gym → steel-plate"),
        "{said}"
    );
    assert_eq!(app.run().unwrap().cor, before);
}

/// The picker at the five sizes, on the embedded surfaces (a user surface's path would
/// change from run to run).
#[test]
fn the_picker_at_every_size() {
    let empty = tempfile::tempdir().unwrap();
    for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)] {
        let mut app = tennis();
        press(&mut app, &[KeyCode::Char('G')]);
        let (entries, _) = list_in(Some(empty.path()));
        app.update(Action::SurfacesListed(entries, None));
        app.update(Action::PickerMove(Scroll::Down));
        let text = screen_text(&draw(&app, w, h)).join("\n");
        assert!(text.contains("▶concrete  embedded"), "{w}×{h}\n{text}");
        insta::assert_snapshot!(
            format!("surfaces_picker_{w}x{h}"),
            draw(&app, w, h).backend()
        );
    }
}

#[test]
fn the_oblique_view_bounces_on_the_surface_and_its_line_runs_to_the_screen() {
    let config = config_with_gym();
    let mut app = tennis();
    pick_surface(&mut app, config.path(), "gym");
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Oblique);
    let text = screen_text(&draw(&app, 160, 50)).join("\n");
    assert!(text.contains("surface gym: K_s 4.000e5 N/m"), "{text}");
    // the court pace with its e (tennis)
    assert!(text.contains("ITF court pace at μ 0.4500"), "{text}");
    let pace = app.oblique_view().pace.clone().unwrap().unwrap();
    let e = format!("e\u{a0}{}", bouncelab::tui::format::value(pace.cor_normal));
    assert!(text.contains(&e), "{e}\n{text}");
    let line = app.command_line();
    // the gym's own c_t comes with --surface gym
    assert!(line.contains("--surface gym"), "{line}");
    assert!(!line.contains("--tangential-damping"), "{line}");
    let mut args = words(&line)[1..].to_vec();
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::bl_in(config.path(), &args);
    assert_eq!(out.code, 0, "{line}: {}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    assert_oblique_answer_is(&app, &j, &line);
    let r = app.oblique_view().response().expect("an impact");
    // on the wall the gym's K_s makes a difference: the bounce is not the wall's
    let mut wall = tennis();
    press(&mut wall, &[KeyCode::Char('i'), KeyCode::Char('K')]);
    assert_ne!(
        wall.oblique_view().response().unwrap().cor_normal,
        r.cor_normal
    );
}

#[test]
fn y_carries_the_surface_and_the_explorer_opens_on_it_again() {
    // an embedded surface, the form's K_s and c_s typed over it
    let mut app = tennis();
    let dir = tempfile::tempdir().unwrap();
    pick_surface(&mut app, dir.path(), "hard-court");
    for (field, text) in [
        (Field::TargetStiffness, "3e5"),
        (Field::TargetDamping, "12"),
    ] {
        press(&mut app, &[KeyCode::Char('m')]);
        let n = Field::ALL.iter().position(|&f| f == field).unwrap();
        for _ in 0..n {
            press(&mut app, &[KeyCode::Down]);
        }
        press(&mut app, &[KeyCode::Enter]);
        app.update(Action::InputClear);
        type_keys(&mut app, text);
        press(&mut app, &[KeyCode::Enter, KeyCode::Esc]);
    }
    assert_eq!(app.setting().target.stiffness, 3e5);
    let line = app.command_line();
    assert!(
        line.contains("--surface hard-court --target-stiffness 300000 --target-damping 12"),
        "{line}"
    );
    let again = explorer_from(&line);
    assert_eq!(again.setting(), app.setting(), "{line}");
    assert_eq!(again.run().unwrap().cor, app.run().unwrap().cor);
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    // named for what it is now, as the line's `collide` names it (docs/surfaces.md §1)
    assert!(text.contains("surface hard-court-modified: K_s"), "{text}");
    assert!(text.contains("K_s 3.000e5 N/m, c_s 12.00 kg/s"), "{text}");
    // an unknown surface is refused, naming the flag's value
    let e = explorer_refuses("bouncelab --preset tennis --surface moon");
    assert!(e.contains("moon"), "{e}");
}

#[test]
fn a_session_keeps_the_surface() {
    let mut app = tennis();
    let dir = tempfile::tempdir().unwrap();
    pick_surface(&mut app, dir.path(), "clay");
    let text = app.session().to_toml();
    assert!(text.contains("surface = \"clay\""), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let back = tennis().with_session(&read).unwrap();
    assert_eq!(back.setting(), app.setting());
    assert_eq!(back.at_stake(), None);
    let bad = text.replace("surface = \"clay\"", "surface = \"moon\"");
    let read = Session::parse(Path::new("bad.toml"), &bad).unwrap();
    let e = tennis().with_session(&read).err().unwrap();
    assert!(e.starts_with("surface: ") && e.contains("moon"), "{e}");
}

#[test]
fn c_t_is_a_field_of_the_form_and_the_lines_carry_it() {
    let mut app = tennis();
    press(&mut app, &[KeyCode::Char('m')]);
    let n = Field::ALL
        .iter()
        .position(|&f| f == Field::TangentialDamping)
        .unwrap();
    for _ in 0..n {
        press(&mut app, &[KeyCode::Down]);
    }
    press(&mut app, &[KeyCode::Enter]);
    app.update(Action::InputClear);
    type_keys(&mut app, "-1");
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.setting().tangential_damping, None, "refused");
    let why = app.message().unwrap().text.clone();
    assert!(why.contains("invalid tangential_damping"), "{why}");
    app.update(Action::InputClear);
    type_keys(&mut app, "1.5");
    press(&mut app, &[KeyCode::Enter, KeyCode::Esc]);
    assert_eq!(app.setting().tangential_damping, Some(1.5));
    // the explorer's line opens on it again
    let line = app.command_line();
    assert!(line.contains("--tangential-damping 1.5"), "{line}");
    let again = explorer_from(&line);
    assert_eq!(again.setting(), app.setting(), "{line}");
    // the oblique line carries it and runs to the screen's bounce
    press(&mut app, &[KeyCode::Char('i')]);
    let line = app.command_line();
    assert!(line.contains("--tangential-damping 1.5"), "{line}");
    let mut args = words(&line)[1..].to_vec();
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let j = common::json(&args);
    let r = app.oblique_view().response().unwrap();
    let f = j["spin_out"].as_f64().unwrap();
    assert!(
        (f - r.spin_out).abs() <= 1e-12 * f.abs().max(1.0),
        "{f} {}",
        r.spin_out
    );
    // u undoes it, naming it
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(app.setting().tangential_damping, None);
    let said = app.message().unwrap().text.clone();
    assert!(said.starts_with("undone: c_t 1.500 → 0 kg/s"), "{said}");
}

/// The compact 80×24 readout has no row for the surface: the header names it ("tennis on
/// clay"; issue 51 item 6, issue 53 item 6), the plate's name before one is picked; where
/// the side panel says `│ surface clay: …` the header does not repeat it.
#[test]
fn the_compact_screen_names_the_surface_in_its_header() {
    let dir = config_with_gym();
    let mut app = tennis();
    let header = |app: &App, w, h| {
        let s = buffer_text(draw(app, w, h).backend().buffer());
        (s.lines().next().unwrap().to_string(), s)
    };
    for (w, h) in [(80, 24), (60, 20)] {
        let (first, s) = header(&app, w, h);
        assert!(first.contains("tennis on steel-plate ·"), "{w}×{h}:\n{s}");
    }
    pick_surface(&mut app, dir.path(), "clay");
    // impact, sweeps and map (the models view has its table beside the charts, no readout)
    for view in 0..4 {
        let (first, s) = header(&app, 80, 24);
        if app.view() != View::Models {
            assert!(first.contains("tennis on clay ·"), "view {view}:\n{s}");
        }
        press(&mut app, &[KeyCode::Tab]);
    }
    // at 60×20 too, the smallest screen the explorer promises: the header shortens its
    // other words before it leaves the surface out
    for view in 0..4 {
        let (first, s) = header(&app, 60, 20);
        if app.view() != View::Models {
            assert!(
                first.contains("tennis on clay ·"),
                "60×20 view {view}:\n{s}"
            );
        }
        press(&mut app, &[KeyCode::Tab]);
    }
    for key in ['i', 'i', 'h', 'h', 'd'] {
        press(&mut app, &[KeyCode::Char(key)]);
        let (first, s) = header(&app, 60, 20);
        assert!(
            first.contains("tennis on clay ·"),
            "60×20 {:?}:\n{s}",
            app.view()
        );
    }
    press(&mut app, &[KeyCode::Char('d')]);
    let (first, s) = header(&app, 120, 40);
    assert!(!first.contains(" on clay"), "{s}");
    // the side panel's own line, not the pick's message
    assert!(s.lines().any(|l| l.contains("│ surface clay")), "{s}");
}
