//! The explorer's state machine: key → action → `update` → state.

use crate::common::embedded;
use crate::tui_common;

use bouncelab::ContactLaw;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Overlay, Severity, View};
use bouncelab::tui::param::{Dir, Param, V0_MIN};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use tui_common::*;

fn superball() -> App {
    App::new(Preset::embedded().remove(0), true)
}

fn get(app: &App, p: Param) -> f64 {
    app.setting().get(p)
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs().max(1.0)
}

fn warned(app: &App) -> bool {
    app.message()
        .is_some_and(|m| m.severity == Severity::Warning)
}

#[test]
fn starts_on_the_preset_with_results() {
    let app = superball();
    let preset = &app.presets()[0];
    assert_eq!(app.setting().params, preset.params());
    assert_eq!(app.setting().law, ContactLaw::Linear);
    let run = app.run().expect("the preset runs");
    assert!((run.cor - 0.75).abs() < 0.01, "e = {}", run.cor);
    assert!(close(
        app.zeta_curve().unwrap().lambda,
        get(&app, Param::Lambda)
    ));
    assert_eq!(app.view(), View::Impact);
    assert!(
        app.speed_curve().is_none(),
        "the sweeps view computes it when shown"
    );
    assert_eq!(app.mode(), Mode::Normal);
}

#[test]
fn lambda_keys_step_and_recompute() {
    let mut app = superball();
    let (l0, e0) = (get(&app, Param::Lambda), app.run().unwrap().cor);
    press(&mut app, &chars("lll"));
    assert!(close(get(&app, Param::Lambda), l0 + 0.03));
    assert!(
        app.run().unwrap().cor > e0,
        "stiffer recoil spring → higher e"
    );
    assert!(close(app.zeta_curve().unwrap().lambda, l0 + 0.03));
    assert_eq!(app.selected(), Param::Lambda);
    press(&mut app, &chars("L"));
    assert!(close(get(&app, Param::Lambda), l0 + 0.02));
    // K_p, m, c stay: only K_r moves
    let p = app.setting().params;
    let p0 = app.presets()[0].params();
    assert_eq!((p.k_p, p.mass, p.damping), (p0.k_p, p0.mass, p0.damping));
}

#[test]
fn zeta_steps_multiplicatively_fine_and_coarse() {
    let mut app = superball();
    let z0 = get(&app, Param::Zeta);
    press(&mut app, &chars("ZZ"));
    assert!(close(get(&app, Param::Zeta), z0 / 1.21));
    assert_eq!(app.selected(), Param::Zeta);
    press(&mut app, &[KeyCode::Char(']'), KeyCode::Char('z')]);
    assert!(app.coarse());
    assert!(close(get(&app, Param::Zeta), 2.0 * z0 / 1.21));
    press(&mut app, &[KeyCode::Char('[')]);
    app.update(Action::StepSelected {
        dir: Dir::Up,
        coarse: true,
    });
    assert!(
        close(get(&app, Param::Zeta), 4.0 * z0 / 1.21),
        "Shift+arrow is coarse"
    );
    press(&mut app, &[KeyCode::Up]);
    assert!(
        close(get(&app, Param::Zeta), 4.4 * z0 / 1.21),
        "plain arrow is fine again"
    );
}

#[test]
fn arrows_select_and_change_the_selected_parameter() {
    let mut app = superball();
    let v0 = get(&app, Param::V0);
    press(&mut app, &[KeyCode::Right, KeyCode::Right]);
    assert_eq!(app.selected(), Param::V0);
    press(&mut app, &[KeyCode::Up, KeyCode::Up, KeyCode::Down]);
    assert!(close(get(&app, Param::V0), v0 + 0.1));
    press(&mut app, &[KeyCode::PageUp]);
    assert!(close(get(&app, Param::V0), v0 + 1.1));
    press(&mut app, &[KeyCode::Left, KeyCode::Left, KeyCode::Left]);
    assert_eq!(app.selected(), Param::V0, "selection wraps");
}

#[test]
fn undo_walks_back_every_change() {
    let mut app = superball();
    let start = app.setting().clone();
    press(&mut app, &chars("lllZZc"));
    assert_eq!(app.undo_depth(), 6);
    press(&mut app, &chars("u"));
    assert_eq!(app.setting().law, ContactLaw::Linear);
    press(&mut app, &chars("uuuuu"));
    assert_eq!(*app.setting(), start);
    assert_eq!(app.run().unwrap().law, ContactLaw::Linear);
    press(&mut app, &chars("u"));
    assert!(warned(&app), "nothing to undo");
    assert_eq!(*app.setting(), start);
}

#[test]
fn clamping_keeps_parameters_in_range_with_a_message() {
    let mut app = superball();
    app.update(Action::Step {
        param: Param::Lambda,
        dir: Dir::Down,
        coarse: true,
    });
    for _ in 0..14 {
        app.update(Action::Step {
            param: Param::Lambda,
            dir: Dir::Down,
            coarse: true,
        });
    }
    assert_eq!(get(&app, Param::Lambda), 0.0);
    assert!(warned(&app));
    assert!(app.message().unwrap().text.contains("λ held at 0"));
    for _ in 0..40 {
        app.update(Action::Step {
            param: Param::Zeta,
            dir: Dir::Up,
            coarse: true,
        });
    }
    // run's bound (model::params::ZETA_MAX)
    assert!(close(get(&app, Param::Zeta), 1e6));
    assert!(warned(&app));
    // λ = 0 and ζ ≥ 1: no rebound, and nothing is NaN
    let run = app.run().unwrap();
    assert!(!run.rebound && run.cor == 0.0);
    for _ in 0..40 {
        app.update(Action::Step {
            param: Param::V0,
            dir: Dir::Down,
            coarse: true,
        });
    }
    assert_eq!(get(&app, Param::V0), V0_MIN);
    assert!(app.run().unwrap().max_force.is_finite());
}

#[test]
fn typed_values_are_accepted_or_refused() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Right, KeyCode::Char('=')]);
    assert_eq!(app.mode(), Mode::Input);
    press(&mut app, &chars("0.5q"));
    press(&mut app, &[KeyCode::Backspace, KeyCode::Enter]);
    assert_eq!(app.mode(), Mode::Normal);
    assert!(close(get(&app, Param::Zeta), 0.5));
    assert!(app.message().is_none());

    // invalid text: refused, old value kept, the dialog stays open with the reason
    press(&mut app, &[KeyCode::Enter]);
    press(&mut app, &chars("abc"));
    press(&mut app, &[KeyCode::Enter]);
    match app.overlay() {
        Overlay::Input(i) => assert!(i.error.as_deref().unwrap().contains("not a number")),
        other => panic!("dialog closed: {other:?}"),
    }
    assert!(warned(&app));
    assert!(close(get(&app, Param::Zeta), 0.5));
    for text in ["nan", "inf", "1e999", ""] {
        press(
            &mut app,
            &[KeyCode::Backspace, KeyCode::Backspace, KeyCode::Backspace],
        );
        press(&mut app, &[KeyCode::Backspace, KeyCode::Backspace]);
        press(&mut app, &chars(text));
        press(&mut app, &[KeyCode::Enter]);
        assert!(close(get(&app, Param::Zeta), 0.5), "{text}");
    }
    assert_eq!(app.mode(), Mode::Normal, "an empty entry closes the dialog");

    // out of range: refused with the range, never clamped in (tests/tui/tui_guards.rs)
    press(&mut app, &[KeyCode::Char('=')]);
    press(&mut app, &chars("5e6"));
    press(&mut app, &[KeyCode::Enter]);
    assert!(close(get(&app, Param::Zeta), 0.5));
    assert!(warned(&app));
    press(&mut app, &[KeyCode::Esc]);

    // Esc cancels without change; q typed in the dialog is text, not quit
    press(&mut app, &[KeyCode::Char('=')]);
    press(&mut app, &chars("2q"));
    press(&mut app, &[KeyCode::Esc]);
    assert!(!app.should_quit());
    assert!(close(get(&app, Param::Zeta), 0.5));
    assert_eq!(app.mode(), Mode::Normal);
}

#[test]
fn law_cycles_through_all_three() {
    let mut app = superball();
    press(&mut app, &chars("c"));
    assert_eq!(app.setting().law, ContactLaw::ElasticPlastic);
    assert_eq!(app.run().unwrap().law, ContactLaw::ElasticPlastic);
    press(&mut app, &chars("c"));
    assert_eq!(app.run().unwrap().law, ContactLaw::Hertz);
    press(&mut app, &chars("c"));
    assert_eq!(app.setting().law, ContactLaw::Linear);
}

#[test]
fn presets_load_by_number_and_reset_restores() {
    let mut app = superball();
    press(&mut app, &chars("2"));
    assert_eq!(app.preset().name, "golf");
    assert_eq!(app.setting().params, app.presets()[1].params());
    assert!((app.run().unwrap().cor - 0.84).abs() < 0.01);
    press(&mut app, &chars("3"));
    assert_eq!(app.preset().name, "baseball");
    press(&mut app, &chars("9"));
    assert!(warned(&app));
    assert_eq!(app.preset().name, "baseball");

    press(&mut app, &chars("lllzc"));
    press(&mut app, &[KeyCode::Right, KeyCode::Up]);
    assert_ne!(app.setting().params, app.presets()[2].params());
    press(&mut app, &chars("r"));
    assert_eq!(app.setting().params, app.presets()[2].params());
    assert_eq!(app.setting().law, ContactLaw::Linear);
    press(&mut app, &chars("u"));
    assert_eq!(
        app.setting().law,
        ContactLaw::ElasticPlastic,
        "reset can be undone"
    );
    press(&mut app, &chars("1"));
    assert_eq!(app.preset().name, "superball");
}

#[test]
fn a_start_preset_that_is_not_embedded_is_the_fourth() {
    let mut custom = Preset::embedded().remove(1);
    custom.name = "my-golf".into();
    custom.adopted.k_r *= 0.5;
    let mut app = App::new(custom.clone(), false);
    assert_eq!(app.presets().len(), 4);
    assert_eq!(app.preset().name, "my-golf");
    press(&mut app, &chars("1"));
    assert_eq!(app.preset().name, "superball");
    press(&mut app, &chars("4"));
    assert_eq!(app.setting().params, custom.params());
    // an embedded start preset is not duplicated
    assert_eq!(
        App::new(Preset::embedded().remove(2), true).presets().len(),
        3
    );
}

#[test]
fn pin_keeps_a_ghost_until_cleared() {
    let mut app = superball();
    press(&mut app, &chars("p"));
    let pinned = app.setting().clone();
    press(&mut app, &chars("LLL"));
    let g = app.ghost().expect("pinned");
    assert_eq!(g.setting, pinned);
    assert!(g.run.is_some() && g.zeta.is_some());
    assert_ne!(
        g.zeta.as_ref().unwrap().lambda,
        app.zeta_curve().unwrap().lambda
    );
    press(&mut app, &[KeyCode::Tab]);
    assert!(
        app.ghost().unwrap().speed.is_some(),
        "the sweeps view fills the ghost's sweep"
    );
    press(&mut app, &chars("P"));
    assert!(app.ghost().is_none() && app.pins().is_empty());
}

#[test]
fn views_switch_and_the_speed_sweep_follows_the_state() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Tab]);
    assert_eq!(app.view(), View::Sweeps);
    let c = app
        .speed_curve()
        .expect("computed for the sweeps view")
        .clone();
    assert!(
        c.points.last().unwrap().cor < c.points[0].cor,
        "flattening drop"
    );
    press(&mut app, &chars("c"));
    assert_eq!(app.speed_curve().unwrap().points.len(), c.points.len());
    assert_ne!(
        app.speed_curve().unwrap().points,
        c.points,
        "recomputed for the new law"
    );
    press(&mut app, &[KeyCode::BackTab]);
    assert_eq!(app.view(), View::Impact);
}

#[test]
fn help_overlay_and_quitting() {
    let mut app = superball();
    press(&mut app, &chars("?"));
    assert_eq!(app.mode(), Mode::Help);
    press(&mut app, &chars("l"));
    assert_eq!(app.undo_depth(), 0, "keys do not leak through the help");
    press(&mut app, &[KeyCode::Esc]);
    assert_eq!(app.mode(), Mode::Normal);
    assert!(!app.should_quit(), "Esc closes the dialog first");
    press(&mut app, &[KeyCode::Esc]);
    assert!(!app.should_quit(), "Esc never quits (issue 29)");
    press(&mut app, &chars("q"));
    assert!(app.should_quit(), "nothing to lose: q quits at once");

    let mut app = superball();
    press(&mut app, &[KeyCode::Char('=')]);
    let ctrl_c = KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL);
    app.update(action::from_key(ctrl_c, app.mode()).unwrap());
    assert!(app.should_quit(), "Ctrl-C quits even from a dialog");

    let mut app = superball();
    press(&mut app, &chars("q"));
    assert!(app.should_quit());
}

#[test]
fn a_batch_applied_then_refreshed_once_equals_one_update_per_key() {
    let keys = "llllzzzvvc";
    let mut one_by_one = superball();
    press(&mut one_by_one, &chars(keys));
    let mut batch = superball();
    for c in keys.chars() {
        let key = KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE);
        batch.apply(action::from_key(key, batch.mode()).unwrap());
    }
    batch.refresh();
    assert_eq!(batch.setting(), one_by_one.setting());
    assert_eq!(batch.run(), one_by_one.run());
    assert_eq!(batch.zeta_curve(), one_by_one.zeta_curve());
    assert_eq!(batch.undo_depth(), keys.len());
}

#[test]
fn background_sweeps_are_requested_then_received_and_stale_ones_dropped() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    assert!(
        app.speed_requests().is_empty(),
        "nothing wanted on the impact view"
    );
    press(&mut app, &[KeyCode::Tab]);
    assert!(app.speed_curve().is_none());
    let old = app.speed_requests().to_vec();
    assert_eq!(old.len(), 1);
    // the user moves on before the sweep is back: the old one is no longer wanted
    press(&mut app, &chars("c"));
    let new = app.speed_requests().to_vec();
    assert_eq!(new.len(), 1);
    assert_ne!(new, old);
    let message = app.message().cloned();
    app.update(Action::SpeedReady(old[0].clone(), old[0].run()));
    assert!(app.speed_curve().is_none(), "a stale sweep is dropped");
    assert_eq!(
        app.message().cloned(),
        message,
        "a finished sweep leaves the message alone"
    );
    app.update(Action::SpeedReady(new[0].clone(), new[0].run()));
    assert_eq!(app.speed_curve().unwrap().request, new[0]);
    assert!(app.speed_requests().is_empty());
    // pinning adds the ghost's sweep only when it differs
    press(&mut app, &chars("p"));
    assert!(app.speed_requests().is_empty());
    press(&mut app, &chars("L"));
    assert_eq!(
        app.speed_requests().len(),
        1,
        "only the current one is stale"
    );
    // leaving the view drops what is pending
    press(&mut app, &[KeyCode::Tab]);
    assert!(app.speed_requests().is_empty());
}

/// Issue 29 item 11: the help offers `4` ("the start preset, if another"); started on one of
/// the three balls it loaded nothing with a message that did not say why. It says so now,
/// and loads the start preset when that is a fourth ball.
#[test]
fn four_says_why_it_loads_nothing() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Char('4')]);
    assert!(warned(&app));
    let text = &app.message().unwrap().text;
    assert!(
        text.contains("start preset") && text.contains("1–3"),
        "{text}"
    );
    let tennis = embedded("tennis");
    let mut app = App::new(tennis, false);
    press(&mut app, &[KeyCode::Char('1'), KeyCode::Char('4')]);
    assert!(app.message().unwrap().text.contains("loaded tennis"));
}

/// `u` says what it undid, from what it was to what it is again, in the readout's units
/// (issue 51 item 2: it said "undone" alone).
#[test]
fn u_says_what_it_undid() {
    let said = |app: &App| app.message().map(|m| m.text.clone()).unwrap_or_default();
    let mut app = superball();
    let m0 = app.setting().params.mass;
    // the mass typed in the form: its value in g both ways
    press(&mut app, &chars("m"));
    press(&mut app, &[KeyCode::Enter]);
    app.update(Action::InputClear);
    press(&mut app, &chars("50"));
    press(&mut app, &[KeyCode::Enter, KeyCode::Esc]);
    assert_eq!(app.setting().params.mass, 0.05);
    press(&mut app, &chars("u"));
    let text = said(&app);
    let want = format!(
        "undone: m 50.00 → {} g",
        bouncelab::tui::format::value(m0 * 1e3)
    );
    assert!(text.starts_with(&want), "{text} / {want}");
    // the law
    press(&mut app, &chars("c"));
    press(&mut app, &chars("u"));
    assert!(said(&app).starts_with("undone: law "), "{}", said(&app));
    // an oblique input
    press(&mut app, &chars("ia"));
    press(&mut app, &chars("u"));
    assert_eq!(said(&app), "undone: θ 17.00 → 16.00°");
}

/// At 80 × 24 the readout beside the charts marks the selected parameter (▶, seen without
/// colour) and says fine or coarse, and the oblique view's key row keeps `i back`
/// (issue 51 item 6).
#[test]
fn the_80x24_screens_show_the_selection_the_step_and_the_way_back() {
    let mut app = superball();
    let shown = tui_common::screen_text(&tui_common::draw(&app, 80, 24)).join("\n");
    assert!(shown.contains("▶λ "), "{shown}");
    assert!(shown.contains("[fine]"), "{shown}");
    press(&mut app, &[KeyCode::Right, KeyCode::Char(']')]);
    let shown = tui_common::screen_text(&tui_common::draw(&app, 80, 24)).join("\n");
    assert!(shown.contains("▶ζ ") && !shown.contains("▶λ"), "{shown}");
    assert!(shown.contains("[coarse]"), "{shown}");
    press(&mut app, &[KeyCode::Char('i')]);
    for (w, h) in [(80, 24), (100, 30), (120, 40)] {
        let shown = tui_common::screen_text(&tui_common::draw(&app, w, h));
        let keys = shown.last().unwrap();
        assert!(
            keys.contains("i back") && keys.contains("t map"),
            "{w}x{h}: {keys}"
        );
    }
}
