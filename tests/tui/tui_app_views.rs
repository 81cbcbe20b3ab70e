//! The explorer's state machine, key → action → `update` → state: the law, pins, views,
//! help and quitting, batched keys, background sweeps, `u`'s message and the 80×24 screens.

use crate::tui_common;
use bouncelab::ContactLaw;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, View};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use tui_common::*;

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
