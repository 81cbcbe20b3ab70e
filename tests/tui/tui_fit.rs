//! Measured data and the fit in the explorer (`o`, `f`, `F`, `O`): through `App::update` and
//! its effects, the fit run as the fit worker runs it
//! (`bouncelab::tui::views::fit::state::run`), and the fit pane drawn on a TestBackend.

use crate::fit_common;
use crate::tui_common;

use bouncelab::figure::explorer::Chart;
use bouncelab::measured::Data;
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect, Overlay, Purpose};
use bouncelab::tui::param::{Dir, Param};
use bouncelab::tui::ui::figure;
use bouncelab::tui::views::fit::state::{self as measured, FitRequest, FitStatus, Standing};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use std::path::{Path, PathBuf};
use tui_common::{draw, screen_text};

/// COR at five speeds from the solver on `p` (linear law), past the flattening onset, with
/// noise of sd 0.005: what an air cannon would give.
fn cor_csv(p: &ImpactParams) -> String {
    let mut rng = fit_common::Rng::new(16);
    let mut s = String::from("# made by the solver\nv0,cor\n");
    for v0 in [10.0, 20.0, 30.0, 40.0, 50.0] {
        let r = simulate(
            &ImpactParams { v0, ..*p },
            ContactLaw::Linear,
            &SolveOptions::default(),
        )
        .unwrap();
        s.push_str(&format!("{v0},{}\n", r.cor + 0.005 * rng.normal()));
    }
    s
}

/// The golf ball, with a measured COR table of a ball like it (K_r and z_p off by a little)
/// loaded as `o` loads it; the file is left in `dir`.
fn loaded(dir: &Path) -> (App, PathBuf) {
    let golf = Preset::embedded().remove(1);
    let truth = ImpactParams {
        k_r: golf.params().k_r * 1.3,
        z_p: golf.params().z_p * 0.8,
        ..golf.params()
    };
    let path = dir.join("cannon.csv");
    std::fs::write(&path, cor_csv(&truth)).unwrap();
    let mut app = App::new(golf, false);
    let data = measured::load(&path).unwrap();
    app.update(Action::MeasuredLoaded {
        path: path.clone(),
        data,
    });
    (app, path)
}

/// `f`: the request the app hands the worker.
fn ask_fit(app: &mut App) -> FitRequest {
    match app.update(Action::Fit).as_slice() {
        [Effect::Fit(r)] => r.clone(),
        other => panic!("expected one fit effect, got {other:?}"),
    }
}

/// The worker's part: run the fit, hand its answer back.
fn answer(app: &mut App, r: &FitRequest) {
    app.update(Action::FitReady(r.id, measured::run(r).into()));
}

fn text(t: &Terminal<TestBackend>) -> String {
    let b = t.backend().buffer();
    let w = b.area.width as usize;
    let cells: Vec<&str> = b.content().iter().map(|c| c.symbol()).collect();
    cells.chunks(w).map(|r| r.concat() + "\n").collect()
}

#[test]
fn o_asks_for_a_path_and_enter_asks_the_loop_to_read_it() {
    let mut app = App::new(Preset::embedded().remove(0), false);
    assert!(app.update(Action::OpenMeasured).is_empty());
    assert!(matches!(app.overlay(), Overlay::Input(i) if i.purpose == Purpose::MeasuredPath));
    for c in "data/x.csv".chars() {
        app.update(Action::InputChar(c));
    }
    let effects = app.update(Action::InputSubmit);
    assert_eq!(effects, vec![Effect::LoadMeasured("data/x.csv".into())]);
    assert_eq!(app.overlay(), &Overlay::None);
    // an empty entry asks nothing
    app.update(Action::OpenMeasured);
    assert!(app.update(Action::InputSubmit).is_empty());
}

#[test]
fn a_loaded_file_is_drawn_and_held_for_the_fit() {
    let dir = tempfile::tempdir().unwrap();
    let (app, _) = loaded(dir.path());
    let l = app.loaded().expect("held");
    assert_eq!(l.label, "cannon.csv");
    assert!(matches!(l.data, Data::Cor(ref t) if t.points.len() == 5));
    let fig = figure(&app, Chart::CorSpeed);
    let s = fig.series.iter().find(|s| s.label == "cannon.csv").unwrap();
    assert_eq!(s.points.len(), 5);
    assert_eq!(app.undo_depth(), 0, "loading data does not change the ball");
}

#[test]
fn a_bad_file_changes_nothing_and_names_file_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    let before = (app.setting().clone(), app.loaded().cloned());
    let drawn = figure(&app, Chart::CorSpeed);
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "v0,cor\n1,0.8\n2,abc\n").unwrap();
    let msg = measured::load(&bad).unwrap_err();
    assert_eq!(
        msg,
        format!("{}:3:3: COR 'abc' is not a number", bad.display())
    );
    app.update(Action::MeasuredFailed { msg: msg.clone() });
    assert_eq!(app.message().unwrap().text, msg);
    assert_eq!((app.setting().clone(), app.loaded().cloned()), before);
    assert_eq!(figure(&app, Chart::CorSpeed), drawn);
    // a directory, and a trace without a pulse (parsed, but not drawable): the same
    let msg = measured::load(dir.path()).unwrap_err();
    assert!(msg.ends_with(": is a directory, not a data file"), "{msg}");
    let flat = Data::Trace(bouncelab::measured::Trace::parse("t,F\n0,0\n1,0\n2,0\n").unwrap());
    app.update(Action::MeasuredLoaded {
        path: "flat.csv".into(),
        data: flat,
    });
    assert!(
        app.message().unwrap().text.starts_with("flat.csv:"),
        "{:?}",
        app.message()
    );
    assert_eq!((app.setting().clone(), app.loaded().cloned()), before);
}

#[test]
fn the_load_error_is_on_screen_with_file_line_and_column() {
    let mut app = App::new(Preset::embedded().remove(0), false);
    let msg = measured::load(Path::new("tests/golden/../no-such.csv")).unwrap_err();
    assert_eq!(msg, "tests/golden/../no-such.csv: no such file");
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("b.csv");
    std::fs::write(&bad, "t,F\n0,zero\n").unwrap();
    let msg = measured::load(&bad).unwrap_err();
    app.update(Action::MeasuredFailed { msg });
    let shown = text(&draw(&app, 160, 40));
    let rows: Vec<&str> = shown.lines().collect();
    // the message has its own line(s) above the key hints
    let s = bouncelab::tui::ui::screen(&app, ratatui::layout::Rect::new(0, 0, 160, 40)).unwrap();
    let line = (s.message.y..s.message.bottom())
        .map(|y| rows[usize::from(y)].trim())
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        line.contains("b.csv:2:3: force 'zero' is not a number"),
        "{line}"
    );
}

#[test]
fn f_without_data_says_how_to_load_some() {
    let mut app = App::new(Preset::embedded().remove(0), false);
    assert!(app.update(Action::Fit).is_empty());
    assert!(app.message().unwrap().text.contains("o loads a file"));
    assert!(app.fit_pane().is_none());
}

#[test]
fn the_fit_runs_in_the_background_comes_back_and_applies_as_one_undo() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    let base = app.setting().clone();
    let r = ask_fit(&mut app);
    // the CLI's defaults for a COR table of five points
    assert_eq!(
        r.free,
        bouncelab::analysis::fit::Param::defaults(false, 5, r.law)
    );
    assert_eq!(r.base, base.params);
    assert!(app.fitting());
    assert_eq!(app.fit_pane().unwrap().status, FitStatus::Running);
    // the keys act meanwhile
    app.update(Action::ToggleHelp);
    app.update(Action::CloseHelp);
    answer(&mut app, &r);
    assert!(!app.fitting());
    let FitStatus::Done(Ok(o)) = &app.fit_pane().unwrap().status else {
        panic!("{:?}", app.fit_pane());
    };
    let fitted = o.params;
    assert!(o.rms_residual < 0.01, "{}", o.rms_residual);
    // the truth's K_r and z_p within the intervals
    let truth = [base.params.k_r * 1.3, base.params.z_p * 0.8];
    for (e, t) in o.fitted.iter().zip(truth) {
        assert!(e.ci95[0] <= t && t <= e.ci95[1], "{} {e:?} vs {t}", e.name);
    }
    assert_eq!(app.fit_standing(), Some(Standing::Ready));
    assert!(app.message().unwrap().text.contains("F applies"));
    // F: one change
    app.update(Action::ApplyFit);
    assert_eq!(app.setting().params, fitted);
    assert_ne!(fitted, base.params);
    assert_eq!(app.undo_depth(), 1);
    assert_eq!(app.fit_standing(), Some(Standing::Applied));
    // u: the ball before the fit
    app.update(Action::Undo);
    assert_eq!(*app.setting(), base);
    assert_eq!(app.fit_standing(), Some(Standing::Ready));
}

#[test]
fn a_fit_of_a_ball_changed_meanwhile_is_shown_stale_and_not_applied() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    let r = ask_fit(&mut app);
    app.update(Action::Step {
        param: Param::Lambda,
        dir: Dir::Up,
        coarse: false,
    });
    let moved = app.setting().clone();
    answer(&mut app, &r);
    assert!(matches!(
        app.fit_pane().unwrap().status,
        FitStatus::Done(Ok(_))
    ));
    assert_eq!(app.fit_standing(), Some(Standing::Stale));
    assert!(app.message().unwrap().text.contains("stale"));
    app.update(Action::ApplyFit);
    assert_eq!(*app.setting(), moved, "a stale fit is not applied");
    assert!(app.message().unwrap().text.contains("stale"));
    // back to the ball fitted from: the fit applies again
    app.update(Action::Undo);
    assert_eq!(app.fit_standing(), Some(Standing::Ready));
}

#[test]
fn an_answer_to_a_superseded_fit_is_dropped() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    let first = ask_fit(&mut app);
    let second = ask_fit(&mut app);
    assert_ne!(first.id, second.id);
    answer(&mut app, &first);
    assert_eq!(app.fit_pane().unwrap().status, FitStatus::Running);
    answer(&mut app, &second);
    assert!(matches!(
        app.fit_pane().unwrap().status,
        FitStatus::Done(Ok(_))
    ));
    // O (and y to its question) puts data and fit away; a late answer then finds no pane
    app.update(Action::ClearMeasured);
    app.update(Action::ConfirmYes);
    assert!(app.loaded().is_none() && app.fit_pane().is_none());
    answer(&mut app, &second);
    assert!(app.fit_pane().is_none());
    assert!(
        !figure(&app, Chart::CorSpeed)
            .series
            .iter()
            .any(|s| s.label == "cannon.csv")
    );
}

/// The pane's three states at 120×40 (snapshots), and the stale one marked in its title.
#[test]
fn the_fit_pane() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    app.update(Action::NextView);
    let r = ask_fit(&mut app);
    let t = draw(&app, 120, 40);
    assert!(text(&t).contains("fitting k_r, z_p…"));
    insta::assert_snapshot!("fit_pane_running", t.backend());
    answer(&mut app, &r);
    let t = draw(&app, 120, 40);
    let s = text(&t);
    for needle in [
        "k_r = ",
        "z_p = ",
        "[95 % interval]",
        "residual RMS",
        "F applies it",
    ] {
        assert!(s.contains(needle), "{needle}\n{s}");
    }
    insta::assert_snapshot!("fit_pane_done", t.backend());
    app.update(Action::Step {
        param: Param::V0,
        dir: Dir::Up,
        coarse: false,
    });
    let t = draw(&app, 120, 40);
    assert!(text(&t).contains("stale: the ball changed since f"));
    insta::assert_snapshot!("fit_pane_stale", t.backend());
    // at 80×24 the pane still shows its values
    let s = text(&draw(&app, 80, 24));
    assert!(s.contains("k_r = "), "{s}");
}

#[test]
fn the_keys() {
    use bouncelab::tui::action::{Mode, from_key};
    use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
    let key = |c| {
        from_key(
            KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE),
            Mode::Normal,
        )
    };
    assert_eq!(key('o'), Some(Action::OpenMeasured));
    assert_eq!(key('O'), Some(Action::ClearMeasured));
    assert_eq!(key('f'), Some(Action::Fit));
    assert_eq!(key('F'), Some(Action::ApplyFit));
    // in the path entry they are text
    let typed = from_key(
        KeyEvent::new(KeyCode::Char('f'), KeyModifiers::NONE),
        Mode::Input,
    );
    assert_eq!(typed, Some(Action::InputChar('f')));
}

/// Data that cannot pin K_r (two drops whose COR the ball cannot reach by K_r alone): the
/// pane says so, as `bouncelab fit` does, rather than print an endless interval.
#[test]
fn an_unpinned_parameter_is_said_so() {
    let mut app = App::new(Preset::embedded().remove(1), false);
    let data =
        bouncelab::measured::parse_any("drop_height_m,rebound_height_m\n1,0.55\n2,1.05\n").unwrap();
    app.update(Action::MeasuredLoaded {
        path: "drops.csv".into(),
        data,
    });
    let r = ask_fit(&mut app);
    answer(&mut app, &r);
    let s = text(&draw(&app, 120, 40));
    assert!(
        s.contains("k_r = ") && s.contains("not pinned by the data"),
        "{s}"
    );
    // F asks first for a fit that gave no answer (issue 27: it applied a fit the pane itself
    // marked "not converged"): the first F only says so, the second applies it
    let before = app.setting().params;
    app.update(Action::ApplyFit);
    assert_eq!(app.setting().params, before);
    let m = app.message().unwrap().text.clone();
    assert!(
        m.contains("no answer") && m.contains("F again applies"),
        "{m}"
    );
    app.update(Action::ApplyFit);
    assert_ne!(app.setting().params, before);
    assert_eq!(app.fit_standing(), Some(Standing::Applied));
}

/// A drop-test file fitted in the explorer weighs each drop by its rebound height's reading,
/// as `bouncelab fit --drop-test` does (a low drop's COR the least precise): the fit's points
/// are the library's.
#[test]
fn drops_weigh_by_their_reading_as_the_command_line_weighs_them() {
    use bouncelab::tui::views::fit::state::FitInput;
    let mut app = App::new(Preset::embedded().remove(1), false);
    let text = "drop_height_m,rebound_height_m\n0.2,0.11\n1.0,0.55\n2,1.05\n";
    app.update(Action::MeasuredLoaded {
        path: "drops.csv".into(),
        data: bouncelab::measured::parse_any(text).unwrap(),
    });
    let r = ask_fit(&mut app);
    let FitInput::Cor(points) = &r.input else {
        panic!("{:?}", r.input)
    };
    let pairs = [(0.2, 0.11), (1.0, 0.55), (2.0, 1.05)];
    let flight = bouncelab::measured::Flight::vacuum();
    assert_eq!(
        points,
        &bouncelab::measured::drops_to_points(&pairs, &flight, None)
    );
    // the lowest drop's COR the least precise: ∂e/∂R = 1/(2√(RH)) largest there
    assert!(points[0].cor_sd_relative > 3.0 * points[2].cor_sd_relative);
}

/// `O` asks before putting away the measured data and the fit; `n` keeps them, `y` puts them
/// away, and `u` puts them back, saying so (issue 51 item 2: `O` dropped them at once, and
/// nothing brought them back).
#[test]
fn o_asks_before_putting_away_and_u_puts_back() {
    let dir = tempfile::tempdir().unwrap();
    let (mut app, _) = loaded(dir.path());
    let request = ask_fit(&mut app);
    answer(&mut app, &request);
    let (data, pane) = (app.loaded().cloned(), app.fit_pane().cloned());
    assert!(data.is_some() && pane.is_some());
    app.update(Action::ClearMeasured);
    assert!(matches!(app.overlay(), Overlay::Ask(_)), "asks first");
    let screen = screen_text(&draw(&app, 100, 30)).concat();
    assert!(
        screen.contains("Put away the measured data and the fit?"),
        "{screen}"
    );
    app.update(Action::ConfirmNo);
    assert_eq!(
        (app.loaded().cloned(), app.fit_pane().cloned()),
        (data.clone(), pane.clone())
    );
    app.update(Action::ClearMeasured);
    app.update(Action::ConfirmYes);
    assert!(app.loaded().is_none() && app.fit_pane().is_none());
    app.update(Action::Undo);
    assert_eq!(
        (app.loaded().cloned(), app.fit_pane().cloned()),
        (data, pane)
    );
    let said = app.message().unwrap().text.clone();
    assert_eq!(said, "undone: measured data and the fit put back");
}
