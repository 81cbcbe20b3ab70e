//! The explorer's state machine, key → action → `update` → state: the parameters stepped,
//! selected, clamped and typed, undo, and the presets loaded and reset.

use crate::common::embedded;
use crate::tui_common;
use bouncelab::ContactLaw;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{Action, Mode};
use bouncelab::tui::app::{App, Overlay, Severity, View};
use bouncelab::tui::param::{Dir, Param, V0_MIN};
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

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
