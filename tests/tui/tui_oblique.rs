//! The explorer's oblique view (`i`, issue 31): snapshots at the five sizes in colour and
//! without, its numbers against `bouncelab oblique` and `bouncelab court` for the same state,
//! and its keys through `update`.

use crate::common;
use crate::common::embedded;
use crate::tui_common;

use bouncelab::tui::action::Mode;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::views::oblique::map::{Quantity, angle_at, friction_at};
use bouncelab::tui::views::oblique::state::Page;
use ratatui::crossterm::event::KeyCode;
use ratatui::style::Color;
use serde_json::Value;
use tui_common::*;

/// Type `text` and Enter into the entry `=` opens.
/// The tennis ball at 25 m/s in the oblique view at θ 16°, ω 300 rad/s, μ 0.6: the issue's
/// example, set by typed entries.
fn tennis_example(color: bool) -> App {
    let mut app = App::new(embedded("tennis"), color);
    press(&mut app, &[KeyCode::Char('v')]);
    enter(&mut app, "25");
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Oblique);
    enter(&mut app, "16");
    press(&mut app, &[KeyCode::Char('w')]);
    enter(&mut app, "300");
    press(&mut app, &[KeyCode::Char('k')]);
    enter(&mut app, "0.6");
    app
}

const SIZES: [(u16, u16); 5] = [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)];

/// Every cell without colour when drawn without (NO_COLOR).
fn assert_colourless(t: &ratatui::Terminal<ratatui::backend::TestBackend>) {
    let buf = t.backend().buffer();
    for c in buf.content() {
        assert!(
            c.fg == Color::Reset && c.bg == Color::Reset,
            "a coloured cell without colour: {c:?}"
        );
    }
}

#[test]
fn charts_at_every_size_in_colour_and_without() {
    for color in [true, false] {
        let app = tennis_example(color);
        for (w, h) in SIZES {
            let t = draw(&app, w, h);
            let text = screen_text(&t).join("\n");
            assert!(text.contains("oblique"), "{w}×{h}\n{text}");
            if !color {
                assert_colourless(&t);
            }
            let name = format!(
                "charts_{w}x{h}_{}",
                if color { "colour" } else { "no_color" }
            );
            insta::assert_snapshot!(name, t.backend());
        }
    }
}

#[test]
fn map_at_every_size_in_colour_and_without() {
    for color in [true, false] {
        let mut app = tennis_example(color);
        press(&mut app, &[KeyCode::Char('t')]);
        assert_eq!(app.mode(), Mode::ObliqueMap);
        for (w, h) in SIZES {
            let t = draw(&app, w, h);
            if !color {
                assert_colourless(&t);
            }
            let name = format!("map_{w}x{h}_{}", if color { "colour" } else { "no_color" });
            insta::assert_snapshot!(name, t.backend());
        }
    }
}

#[test]
fn the_view_s_numbers_are_the_command_line_s() {
    let app = tennis_example(false);
    let r = app.oblique_view().response().expect("an answer");
    let line = "oblique --preset tennis --v0 25 --angle 16 --spin 300 --friction 0.6 --format json";
    let out = common::bl(&common::argv(line));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let keys = [
        "v_out",
        "angle_out_deg",
        "spin_out",
        "cor_normal",
        "cor_tangential",
        "apparent_friction",
        "grip_time",
        "contact_time",
        "max_normal_force",
        "max_friction_force",
        "vx_out",
        "vy_out",
    ];
    assert_oblique_numbers_are(&app, &j, line, &keys);
    assert_eq!(j["slid_throughout"].as_bool(), Some(r.slid_throughout));
    // the court pace of the readout is `bouncelab court`'s
    let out = common::bl(&common::argv(
        "court --preset tennis --friction 0.6 --format json",
    ));
    assert_eq!(out.code, 0, "{}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let pace = app.oblique_view().pace.clone().unwrap().unwrap();
    assert!(close(j["cpr"].as_f64().unwrap(), pace.cpr));
    assert_eq!(j["category"].as_u64(), Some(u64::from(pace.category)));
    // and the screen shows them
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    for shown in [
        "out 17.56 m/s at 17.61°",
        "spin  656.6 rad/s",
        "CPR 47.35",
        "5 fast",
    ] {
        assert!(text.contains(shown), "{shown}\n{text}");
    }
}

#[test]
fn a_map_cell_is_the_command_line_s_impact() {
    let mut app = tennis_example(false);
    press(&mut app, &[KeyCode::Char('t')]);
    let map = app
        .oblique_view()
        .held_map()
        .expect("computed without a worker")
        .clone();
    let (i, j) = (29, 19); // θ 30°, μ 0.4
    assert_eq!((angle_at(i), friction_at(j)), (30.0, 0.4));
    let c = map.at(i, j).unwrap();
    let out = common::bl(&common::argv(
        "oblique --preset tennis --v0 25 --angle 30 --spin 300 --friction 0.4 --format json",
    ));
    let jv: Value = serde_json::from_str(&out.stdout).unwrap();
    assert!(close(jv["angle_out_deg"].as_f64().unwrap(), c.angle_out));
    assert!(close(jv["spin_out"].as_f64().unwrap(), c.spin_out));
    assert!(close(jv["cor_tangential"].as_f64().unwrap(), c.ex.unwrap()));
    // the cursor moved onto that cell makes the view's impact the cell's
    type_keys(&mut app, "");
    let v = app.oblique_view();
    let (di, dj) = (29 - v.cursor().0 as i32, 19 - v.cursor().1 as i32);
    let mut keys = Vec::new();
    keys.extend(std::iter::repeat_n(
        if di > 0 {
            KeyCode::Right
        } else {
            KeyCode::Left
        },
        di.unsigned_abs() as usize,
    ));
    keys.extend(std::iter::repeat_n(
        if dj > 0 { KeyCode::Up } else { KeyCode::Down },
        dj.unsigned_abs() as usize,
    ));
    press(&mut app, &keys);
    let v = app.oblique_view();
    assert_eq!((v.values.angle, v.values.friction), (30.0, 0.4));
    let r = v.response().unwrap();
    assert_eq!((r.angle_out_deg, r.spin_out), (c.angle_out, c.spin_out));
}

#[test]
fn keys_step_select_and_type_in_the_library_s_ranges() {
    let mut app = App::new(embedded("tennis"), false);
    assert_eq!(app.mode(), Mode::Normal);
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!((app.view(), app.mode()), (View::Oblique, Mode::Oblique));
    let v = |app: &App| {
        let o = app.oblique_view().values;
        (o.angle, o.spin, o.friction)
    };
    assert_eq!(v(&app), (16.0, 0.0, 0.6));
    type_keys(&mut app, "aaaWkK");
    assert_eq!(v(&app), (19.0, -10.0, 0.6));
    // the arrows step the selected one (μ, last stepped), ← → select
    press(&mut app, &[KeyCode::Up, KeyCode::Left, KeyCode::Down]);
    assert_eq!(v(&app), (19.0, -20.0, 0.61));
    // past θ's open end it holds, and says the range
    press(&mut app, &[KeyCode::Left]);
    assert_eq!(
        app.oblique_view().selected,
        bouncelab::tui::views::oblique::param::ObliqueParam::Angle
    );
    enter(&mut app, "1");
    assert_eq!(v(&app).0, 1.0);
    press(&mut app, &[KeyCode::Char('A')]);
    assert_eq!(v(&app).0, 1.0);
    let msg = app.message().unwrap().text.clone();
    assert_eq!(msg, "θ held at 1°: the range is (0, 90] degrees");
    // a typed value out of range is the library's message, the entry stays open
    assert_entry_refused(
        &mut app,
        "95",
        "invalid angle: 95 (must lie in (0, 90] degrees); θ kept",
    );
    assert_eq!(v(&app).0, 1.0);
    // μ stops at 0
    press(&mut app, &[KeyCode::Char('k')]);
    enter(&mut app, "0");
    press(&mut app, &[KeyCode::Char('K')]);
    assert_eq!(v(&app).2, 0.0);
    assert!(app.message().unwrap().text.contains("[0, 1e6]"));
    // μ = 0 leaves v_x and ω as they came (docs/oblique.md §5)
    let r = app.oblique_view().response().unwrap();
    assert_eq!((r.vx_out, r.spin_out), (r.vx_in, r.spin_in));
    // λ still steps from the oblique view, and the impact follows the ball
    let before = app.oblique_view().response().unwrap().cor_normal;
    press(&mut app, &[KeyCode::Char('L')]);
    assert!(app.oblique_view().response().unwrap().cor_normal < before);
    // `e` exports the impact's charts (tests/tui/tui_oblique_export.rs writes them)
    let effects = app.update(bouncelab::tui::action::Action::Export);
    assert!(
        effects
            .iter()
            .any(|e| matches!(e, bouncelab::tui::app::Effect::Export(_))),
        "{effects:?}"
    );
    // `t` the map: arrows move the cursor cell by cell, held in the grid; `n` the quantity
    press(&mut app, &[KeyCode::Char('t')]);
    assert_eq!(app.mode(), Mode::ObliqueMap);
    // μ 0 lies below the grid: the cursor shows it on the first row (0.02), two rows up is
    // 0.06; θ 1° is the first column, where ← holds
    press(&mut app, &[KeyCode::Left, KeyCode::Up, KeyCode::Up]);
    assert_eq!((v(&app).0, v(&app).2), (1.0, 0.06));
    assert_eq!(app.oblique_view().quantity, Quantity::AngleOut);
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.oblique_view().quantity, Quantity::SpinOut);
    press(&mut app, &[KeyCode::Char('t')]);
    assert_eq!(app.oblique_view().page, Page::Charts);
    // `i` leaves for the impact view, Tab too (the view is outside the cycle, as the drop's)
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Impact);
    press(&mut app, &[KeyCode::Char('i'), KeyCode::Tab]);
    assert_eq!(app.view(), View::Impact);
}

/// Every law runs obliquely (docs/oblique.md §2): the view under Hertz is `Ball::oblique`'s
/// under Hertz (its map shares `oblique::solve_frictions`, which equals `solve_law` under
/// any law: `frictions_equal_solve`).
#[test]
fn other_laws_run_in_the_view_and_its_map() {
    let mut app = App::new(embedded("golf"), false);
    type_keys(&mut app, "c");
    let law = app.setting().law;
    assert_ne!(law, bouncelab::ContactLaw::Linear);
    press(&mut app, &[KeyCode::Char('i')]);
    let r = app
        .oblique_view()
        .response()
        .expect("an answer under another law")
        .clone();
    assert_eq!(r.normal.law, law);
    let text = screen_text(&draw(&app, 100, 30)).join("\n");
    assert!(!text.contains("invalid law"), "{text}");
    // golf is no tennis ball: no court pace
    assert!(app.oblique_view().pace.is_none());
}

#[test]
fn a_grip_shows_the_friction_reversal() {
    // the superball at 40° grips: its friction force reverses during contact (Cross 2002)
    let mut app = App::new(embedded("superball"), false);
    press(&mut app, &[KeyCode::Char('i')]);
    enter(&mut app, "40");
    press(&mut app, &[KeyCode::Char('k')]);
    enter(&mut app, "0.5");
    let r = app.oblique_view().response().unwrap();
    assert!(!r.slid_throughout && r.grip_time > 0.0);
    let rev = bouncelab::tui::views::oblique::charts::reversals(r.history.as_ref().unwrap());
    assert!(!rev.is_empty());
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    // dashed (╍), apart from F_t's dots (┄) without colour
    assert!(text.contains("╍ reversal"), "{text}");
}

#[test]
fn the_map_goes_to_the_worker_and_is_asked_again_after_a_cancel() {
    use bouncelab::tui::app::Effect;
    let mut app = App::new(embedded("tennis"), false).with_background_sweeps();
    let asked = |effects: &[Effect]| {
        effects
            .iter()
            .filter(|e| matches!(e, Effect::ObliqueMap(_)))
            .count()
    };
    assert_eq!(asked(&press(&mut app, &[KeyCode::Char('i')])), 1);
    assert!(app.oblique_pending());
    // θ and μ do not change the map; ω does
    assert_eq!(asked(&type_keys(&mut app, "ak")), 0);
    assert_eq!(asked(&type_keys(&mut app, "w")), 1);
    // leaving stops the job; coming back asks for the map again
    press(&mut app, &[KeyCode::Char('i')]);
    assert!(!app.oblique_pending());
    assert_eq!(asked(&press(&mut app, &[KeyCode::Char('i')])), 1);
    // the map of an older generation is dropped, the current one kept
    let Some(Effect::ObliqueMap(job)) = press(&mut app, &[KeyCode::Char('W')]).pop() else {
        panic!("a new map for the new spin");
    };
    let map = bouncelab::tui::views::oblique::map::compute(&job.work, &Default::default());
    let stale = bouncelab::tui::action::Action::ObliqueMapReady {
        generation: job.generation - 1,
        map: Box::new(map.clone().unwrap()),
    };
    app.update(stale);
    assert!(app.oblique_view().map.is_none());
    app.update(bouncelab::tui::action::Action::ObliqueMapReady {
        generation: job.generation,
        map: Box::new(map.unwrap()),
    });
    assert!(app.oblique_view().held_map().is_some() && !app.oblique_pending());
}

/// The map that comes back while the terminal is below the minimum size is taken, as the
/// other workers' answers are: the view holds it, nothing waits for it any more.
#[test]
fn the_map_that_comes_back_while_the_terminal_is_too_small_is_taken() {
    use bouncelab::tui::action::Action;
    use bouncelab::tui::app::Effect;
    let mut app = App::new(embedded("tennis"), false).with_background_sweeps();
    let job = press(&mut app, &[KeyCode::Char('i')])
        .into_iter()
        .find_map(|e| match e {
            Effect::ObliqueMap(job) => Some(job),
            _ => None,
        })
        .expect("the map asked of the worker");
    app.update(Action::Resize(40, 10));
    assert!(app.too_small());
    app.update(Action::ObliqueMapReady {
        generation: job.generation,
        map: Box::new(Err("no map here".into())),
    });
    app.update(Action::Resize(120, 40));
    assert!(!app.oblique_pending(), "still waited for");
    let held = &app.oblique_view().map;
    assert!(
        matches!(held, Some(Err(e)) if e == "no map here"),
        "{held:?}"
    );
}
