//! The models view's export (`e`) without a calibration: one still out waits for it
//! (tests/tui/tui_models.rs `the_export_is_what_is_on_screen`), and one that failed or whose
//! worker stopped writes no file and says why — so no SVG of the models view is written
//! whose peers are missing (`figure::explorer::missing`, src/tui/app/refresh.rs). The
//! figure's own subtitle without a calibration says none is there, not that one is coming.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect, Severity, View};
use bouncelab::tui::background::Work;
use bouncelab::tui::ui::{self, Chart};
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

/// The superball at λ = 0 and ζ large (no rebound: no peer can be calibrated to e = 0), with
/// background workers, `keys` pressed after the ball's.
fn no_rebound(keys: &[KeyCode]) -> (App, Vec<Effect>) {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    app.update(Action::Resize(120, 40));
    let mut all = vec![KeyCode::Char(']')];
    all.extend([KeyCode::Char('L'); 15]);
    all.extend([KeyCode::Char('z'); 13]);
    all.extend(keys);
    let effects = press(&mut app, &all);
    assert!(!app.run().unwrap().rebound);
    (app, effects)
}

/// No export effect among `effects`, and the message line an error saying what is missing.
fn refused(app: &App, effects: &[Effect]) {
    assert!(
        !effects.iter().any(|e| matches!(e, Effect::Export(_))),
        "{effects:?}"
    );
    let m = app.message().expect("a message");
    assert_eq!(m.severity, Severity::Error, "{}", m.text);
    assert!(
        m.text.contains("no calibration of the models to export"),
        "{}",
        m.text
    );
}

/// Without a rebound there is nothing to calibrate the models to: no calibration is asked
/// (issue 51 item 5, the view says so in words), `e` writes nothing and says why, and the
/// figures say no calibration is there (not "calibrating…").
#[test]
fn an_export_without_a_rebound_writes_nothing_and_says_why() {
    let (mut app, _) = no_rebound(&[KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Models);
    assert!(app.models_request().is_none(), "a calibration asked");
    let effects = press(&mut app, &[KeyCode::Char('e')]);
    refused(&app, &effects);
    for chart in [
        Chart::ModelsCorSpeed,
        Chart::ModelsForceTime,
        Chart::ModelsForceDisplacement,
    ] {
        let fig = ui::figure(&app, chart);
        assert!(!fig.subtitle.contains("calibrating"), "{}", fig.subtitle);
    }
}

/// The models' worker stops: `e` writes nothing and says why.
#[test]
fn an_export_after_the_calibrations_worker_stopped_writes_nothing() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    app.update(Action::Resize(120, 40));
    press(&mut app, &[KeyCode::Tab, KeyCode::Tab]);
    assert!(app.models_request().is_some());
    let why = "it panicked: test".to_string();
    app.update(Action::WorkerStopped {
        work: Work::Models,
        why,
    });
    assert!(app.models().is_none());
    let effects = press(&mut app, &[KeyCode::Char('e')]);
    refused(&app, &effects);
}
