//! A worker that dies (a panic in its job): the view whose computation it was stops saying
//! "computing" and says that it stopped and why, the message line too; nothing is asked of a
//! worker again by itself (a panic again and again), but `R` asks again and so does a new
//! request (another ball), which the loop hands to a new thread (src/tui/workers.rs).
//! The panic here is a real one, on a real worker thread ([`panicked`]); the real explorer
//! with the test fault `panic-in-worker` is tests/tui/tui_worker_pty.rs.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect, Severity, View};
use bouncelab::tui::background::{Background, Stopped, Work};
use bouncelab::tui::views::fit::state::{self as measured, FitStatus};
use ratatui::crossterm::event::KeyCode;
use std::time::{Duration, Instant};

use tui_common::*;

/// Why a worker thread whose job panics with `msg` is gone, as the loop finds it.
fn panicked(msg: &'static str) -> String {
    let mut b = Background::<(), ()>::spawn("test-dies", move |inbox, _| {
        if inbox.recv().is_ok() {
            panic!("{msg}");
        }
    })
    .unwrap();
    b.send(());
    let start = Instant::now();
    loop {
        match b.try_recv() {
            Ok(None) => assert!(start.elapsed() < Duration::from_secs(60), "no news"),
            Ok(Some(())) => unreachable!("the job answers nothing"),
            Err(Stopped(why)) => return why,
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

const WHY: &str = "it panicked: test: a job that panics";

fn stopped(app: &mut App, work: Work) -> Vec<Effect> {
    let why = panicked("test: a job that panics");
    assert_eq!(why, WHY);
    app.update(Action::WorkerStopped { work, why })
}

/// `R` asks the stopped work again: its one effect the job (`is_job`), and the view waits for
/// it (`pending`).
fn assert_r_asks_again(app: &mut App, is_job: fn(&Effect) -> bool, pending: fn(&App) -> bool) {
    let effects = press(app, &[KeyCode::Char('R')]);
    assert!(
        matches!(effects.as_slice(), [job] if is_job(job)),
        "{effects:?}"
    );
    assert!(pending(app));
}

/// The superball with background workers (each view's computation handed to a worker, as
/// the explorer runs) on a `w` × `h` screen, in its first view.
fn with_workers(w: u16, h: u16) -> App {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    app.update(Action::Resize(w, h));
    app
}

/// The superball with background workers on a `w` × `h` screen, in the sweeps view: the
/// sweep asked of the worker.
fn sweeping(w: u16, h: u16) -> (App, Vec<bouncelab::tui::views::sweeps::speed::SpeedRequest>) {
    let mut app = with_workers(w, h);
    let asked = match press(&mut app, &[KeyCode::Tab]).as_slice() {
        [Effect::Compute(r)] => r.clone(),
        other => panic!("expected the sweep asked, got {other:?}"),
    };
    assert_eq!(app.view(), View::Sweeps);
    assert!(!app.speed_requests().is_empty());
    (app, asked)
}

fn message(app: &App) -> (String, Severity) {
    let m = app.message().expect("a message");
    (m.text.clone(), m.severity)
}

/// The sweeps' worker dies: its chart's title says "stopped" and why where it said
/// "updating…", the message line says so, nothing is waited for; the next refresh asks
/// nothing; `R` asks the same sweep again.
#[test]
fn a_sweep_that_stopped_says_why_and_r_retries() {
    let (mut app, asked) = sweeping(120, 40);
    let before = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(before.contains("updating…"), "{before}");
    assert!(stopped(&mut app, Work::Sweeps).is_empty());
    assert!(app.speed_requests().is_empty(), "nothing waited for");
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Error);
    assert_eq!(
        text,
        format!("the COR-vs-speed sweep stopped: {WHY} (R retries)")
    );
    let after = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(!after.contains("updating…"), "{after}");
    assert!(
        after.contains("stopped: it panicked: test: a job"),
        "{after}"
    );
    // another key that asks nothing new does not ask the sweep again
    assert!(press(&mut app, &[KeyCode::Char('[')]).is_empty());
    match press(&mut app, &[KeyCode::Char('R')]).as_slice() {
        [Effect::Compute(again)] => assert_eq!(*again, asked),
        other => panic!("R: expected the sweep asked again, got {other:?}"),
    }
    assert!(!app.speed_requests().is_empty());
    assert!(
        message(&app)
            .0
            .starts_with("retrying the COR-vs-speed sweep")
    );
    let retried = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(retried.contains("updating…") && !retried.contains("stopped"));
}

/// A new request after a stop (another ball) goes to the worker — the loop starts a new
/// thread for it — and the stop is forgotten.
#[test]
fn a_new_request_after_a_stop_is_asked() {
    let (mut app, asked) = sweeping(120, 40);
    stopped(&mut app, Work::Sweeps);
    match press(&mut app, &[KeyCode::Char('l')]).as_slice() {
        [Effect::Compute(new)] => assert_ne!(*new, asked),
        other => panic!("expected the new ball's sweep asked, got {other:?}"),
    }
    assert!(!app.speed_requests().is_empty());
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(
        text.contains("updating…") && !text.contains("stopped"),
        "{text}"
    );
}

/// The sweeps view with its worker stopped, at the five sizes the explorer promises.
#[test]
fn a_stopped_sweep_on_screen() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let (mut app, _) = sweeping(w, h);
        stopped(&mut app, Work::Sweeps);
        insta::assert_snapshot!(
            format!("sweeps_stopped_{w}x{h}"),
            draw(&app, w, h).backend()
        );
    }
}

/// Export of a sweep whose worker stopped: refused at once with why, not left waiting.
#[test]
fn an_export_does_not_wait_for_a_stopped_sweep() {
    let (mut app, _) = sweeping(120, 40);
    stopped(&mut app, Work::Sweeps);
    assert!(press(&mut app, &[KeyCode::Char('e')]).is_empty());
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Error);
    assert!(
        text.starts_with("export failed: the COR-vs-speed sweep stopped: it panicked"),
        "{text}"
    );
}

/// The map's worker dies mid-refinement: the coarse map stays, its line says the refinement
/// stopped and why, no job is handed out again until `R`.
#[test]
fn a_map_whose_refinement_stopped() {
    let mut app = with_workers(120, 40);
    let effects = press(&mut app, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Tab]);
    assert!(effects.iter().any(|e| matches!(e, Effect::Map(_))));
    assert!(app.map_pending());
    stopped(&mut app, Work::Map);
    assert!(!app.map_pending(), "not waited for");
    assert!(app.map_view().map().is_some(), "the coarse map stays");
    assert!(
        message(&app)
            .0
            .starts_with("the map's refinement stopped: it panicked")
    );
    let t = draw(&app, 120, 40);
    let text = screen_text(&t).join("\n");
    assert!(text.contains("refining stopped: it panicked"), "{text}");
    insta::assert_snapshot!("map_stopped_120x40", t.backend());
    assert!(
        app.update(Action::Resize(120, 40)).is_empty(),
        "not asked again"
    );
    assert_r_asks_again(&mut app, |e| matches!(e, Effect::Map(_)), App::map_pending);
}

/// The models' worker dies: the table says "no calibration: stopped: …" where it said
/// "calibrating…"; `R` asks the calibration again.
#[test]
fn a_calibration_that_stopped() {
    let mut app = with_workers(120, 40);
    let effects = press(&mut app, &[KeyCode::Tab, KeyCode::Tab]);
    let asked = effects.iter().find_map(|e| match e {
        Effect::ComputeModels(r) if !r.is_empty() => Some(r.clone()),
        _ => None,
    });
    let asked = asked.expect("the calibration asked");
    assert!(app.models_request().is_some());
    stopped(&mut app, Work::Models);
    assert!(app.models_request().is_none(), "not waited for");
    let error = app.models_error().unwrap();
    assert_eq!(error, format!("stopped: {WHY} (R retries)"));
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("no calibration: stopped"), "{text}");
    assert!(!text.contains("calibrating…"), "{text}");
    let effects = press(&mut app, &[KeyCode::Char('R')]);
    assert_eq!(effects, [Effect::ComputeModels(asked)]);
}

/// The oblique map's worker dies: the map says it stopped and why; `R` asks it again.
#[test]
fn an_oblique_map_that_stopped() {
    let mut app = with_workers(120, 40);
    let effects = press(&mut app, &[KeyCode::Char('i')]);
    assert!(effects.iter().any(|e| matches!(e, Effect::ObliqueMap(_))));
    assert!(app.oblique_pending());
    stopped(&mut app, Work::ObliqueMap);
    assert!(!app.oblique_pending(), "not waited for");
    press(&mut app, &[KeyCode::Char('t')]); // the map page
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("stopped: it panicked: test: a job"), "{text}");
    assert!(!text.contains("computing the map…"), "{text}");
    assert_r_asks_again(
        &mut app,
        |e| matches!(e, Effect::ObliqueMap(_)),
        App::oblique_pending,
    );
}

/// The fit's worker dies: the pane says the fit stopped and why where it said "fitting…";
/// `f` fits again.
#[test]
fn a_fit_that_stopped() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cor.csv");
    std::fs::write(&path, "v0,cor\n1,0.8\n2,0.75\n3,0.7\n").unwrap();
    let mut app = App::new(Preset::embedded().remove(1), false);
    let data = measured::load(&path).unwrap();
    app.update(Action::MeasuredLoaded { path, data });
    assert!(matches!(
        app.update(Action::Fit).as_slice(),
        [Effect::Fit(_)]
    ));
    assert!(app.fitting());
    stopped(&mut app, Work::Fit);
    assert!(!app.fitting(), "not waited for");
    let status = &app.fit_pane().unwrap().status;
    assert_eq!(*status, FitStatus::Done(Err(format!("stopped: {WHY}"))));
    assert_eq!(
        message(&app).0,
        format!("the fit stopped: {WHY} (f fits again)")
    );
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("failed: stopped: it panicked"), "{text}");
    assert!(matches!(
        app.update(Action::Fit).as_slice(),
        [Effect::Fit(_)]
    ));
    assert!(app.fitting());
}

/// `R` with nothing stopped says so and asks nothing.
#[test]
fn r_with_nothing_stopped() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    assert!(press(&mut app, &[KeyCode::Char('R')]).is_empty());
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Warning);
    assert!(text.starts_with("nothing stopped to retry"), "{text}");
}
