//! `e` in the explorer: state → export request → files (in a temporary folder) → the message
//! in the header. Never overwriting, valid SVG, the documented CSV headers, and figures drawn
//! from the curves the state already holds.

use crate::tui_common;
use crate::tui_common::superball;

use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action};
use bouncelab::tui::app::{App, Effect, Severity, View};
use bouncelab::tui::export::{self, ExportRequest};
use bouncelab::tui::param::Param;
use bouncelab::tui::ui;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::cell::RefCell;
use std::fs;
use std::path::{Path, PathBuf};
use tui_common::file_names;

thread_local! {
    /// The effects `update` returned that the test has not carried out yet, as the event
    /// loop holds them (each test runs on a thread of its own).
    static PENDING: RefCell<Vec<Effect>> = const { RefCell::new(Vec::new()) };
}

/// `update`, keeping the effects it returns for [`perform`].
fn update(app: &mut App, action: Action) {
    let effects = app.update(action);
    PENDING.with(|p| p.borrow_mut().extend(effects));
}

/// The export `update` asked for and the test has not carried out yet.
fn export_request() -> Option<ExportRequest> {
    PENDING.with(|p| {
        p.borrow().iter().rev().find_map(|e| match e {
            Effect::Export(r) => Some(r.clone()),
            _ => None,
        })
    })
}

/// Take the pending export off the list, to carry it out.
fn take_export() -> Option<ExportRequest> {
    let request = export_request();
    PENDING.with(|p| p.borrow_mut().retain(|e| !matches!(e, Effect::Export(_))));
    request
}

fn press(app: &mut App, keys: &str) {
    for c in keys.chars() {
        let m = if c.is_ascii_uppercase() {
            KeyModifiers::SHIFT
        } else {
            KeyModifiers::NONE
        };
        let code = match c {
            '\t' => KeyCode::Tab,
            c => KeyCode::Char(c),
        };
        if let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) {
            update(app, a);
        }
    }
}

/// What the event loop does with a pending export.
fn perform(app: &mut App, dir: &Path) -> Vec<PathBuf> {
    let request = take_export().expect("an export is pending");
    let files = export::write(&request, dir).expect("written");
    update(
        app,
        Action::Exported {
            files: files.clone(),
        },
    );
    assert!(
        export_request().is_none(),
        "the answer asks for no other export"
    );
    files
}

fn message(app: &App) -> (String, Severity) {
    let m = app.message().expect("a message");
    (m.text.clone(), m.severity)
}

#[test]
fn e_asks_for_the_views_charts_and_the_loop_writes_them() {
    let mut app = superball();
    assert!(export_request().is_none());
    press(&mut app, "e");
    let r = export_request().expect("e asks for an export");
    assert_eq!(r.ball, "superball");
    let charts: Vec<&str> = r.charts.iter().map(|c| c.0).collect();
    assert_eq!(charts, ["force-time", "force-displacement", "cor-zeta"]);

    let dir = tempfile::tempdir().unwrap();
    let files = perform(&mut app, dir.path());
    assert_eq!(
        file_names(&files),
        [
            "bouncelab-superball-force-time-1.svg",
            "bouncelab-superball-force-time-1.csv",
            "bouncelab-superball-force-displacement-1.svg",
            "bouncelab-superball-force-displacement-1.csv",
            "bouncelab-superball-cor-zeta-1.svg",
            "bouncelab-superball-cor-zeta-1.csv",
        ]
    );
    for f in &files {
        assert!(f.is_file(), "{}", f.display());
    }
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Info);
    assert!(
        text.starts_with("exported bouncelab-superball-*-1.svg/.csv (3 charts) in "),
        "{text}"
    );
    // the next key clears the message, and nothing is exported again
    press(&mut app, "l");
    assert!(app.message().is_none());
    assert!(export_request().is_none());
}

#[test]
fn exporting_twice_never_overwrites() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    press(&mut app, "e");
    let first = perform(&mut app, dir.path());
    let before: Vec<Vec<u8>> = first.iter().map(|f| fs::read(f).unwrap()).collect();
    // a different state, the same names but for <n>
    press(&mut app, "lle");
    let second = perform(&mut app, dir.path());
    assert!(
        file_names(&second)
            .iter()
            .all(|n| n.ends_with("-2.svg") || n.ends_with("-2.csv"))
    );
    for (f, old) in first.iter().zip(&before) {
        assert_eq!(&fs::read(f).unwrap(), old, "{} untouched", f.display());
    }
    // any one file of a number takes the whole number: a stranger's file with n = 3 (even a
    // dangling link) makes the next export 4, and stays as it was
    let stranger = dir.path().join("bouncelab-superball-cor-zeta-3.csv");
    fs::write(&stranger, "mine").unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(
        dir.path().join("nowhere"),
        dir.path().join("bouncelab-superball-force-time-4.svg"),
    )
    .unwrap();
    press(&mut app, "e");
    let third = perform(&mut app, dir.path());
    let n = if cfg!(unix) { "5" } else { "4" };
    assert!(
        file_names(&third)
            .iter()
            .all(|f| f.ends_with(&format!("-{n}.svg")) || f.ends_with(&format!("-{n}.csv"))),
        "{third:?}"
    );
    assert_eq!(fs::read_to_string(&stranger).unwrap(), "mine");
    let all: Vec<_> = first.iter().chain(&second).chain(&third).collect();
    let mut unique = all.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), all.len());
}

#[test]
fn pictures_parse_and_data_files_have_the_documented_headers() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    press(&mut app, "p"); // a ghost, so the pinned series are written too
    press(&mut app, "LLLvve");
    let mut files = perform(&mut app, dir.path());
    press(&mut app, "\te");
    assert_eq!(app.view(), View::Sweeps);
    let sweeps = perform(&mut app, dir.path());
    assert_eq!(
        file_names(&sweeps),
        [
            "bouncelab-superball-force-zeta-1.svg",
            "bouncelab-superball-force-zeta-1.csv",
            "bouncelab-superball-cor-velocity-1.svg",
            "bouncelab-superball-cor-velocity-1.csv",
        ]
    );
    files.extend(sweeps);
    let headers = [
        ("force-time", "series,kind,t,force"),
        ("force-displacement", "series,kind,displacement,force"),
        ("cor-zeta", "series,kind,zeta,cor"),
        ("force-zeta", "series,kind,zeta,max_force_normalized"),
        ("cor-velocity", "series,kind,v0,cor"),
    ];
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let text = fs::read_to_string(f).unwrap();
        if name.ends_with(".svg") {
            let doc = roxmltree::Document::parse(&text)
                .unwrap_or_else(|e| panic!("{name} is not XML: {e}"));
            assert_eq!(doc.root_element().tag_name().name(), "svg", "{name}");
            assert!(text.contains("<title>"), "{name}");
        } else {
            let (_, header) = headers
                .iter()
                .find(|(chart, _)| name.contains(&format!("-{chart}-")))
                .unwrap();
            // the `#` lines: the command and the parameters (tests/tui/tui_command.rs)
            let mut lines = text.lines().skip_while(|l| l.starts_with('#'));
            assert_eq!(lines.next(), Some(*header), "{name}");
            let rows: Vec<&str> = lines.collect();
            assert!(rows.len() > 10, "{name}");
            assert!(rows.iter().all(|r| r.split(',').count() == 4), "{name}");
            assert!(
                rows.iter().any(|r| r.starts_with("pinned")),
                "{name}: the pinned curve"
            );
            if !name.contains("force-time") && !name.contains("force-displacement") {
                assert!(
                    rows.iter().any(|r| r.starts_with("this run,model,")),
                    "{name}"
                );
            }
        }
    }
}

/// The CSV rows of `series` in a written file, as numbers.
fn rows(file: &Path, series: &str) -> Vec<(f64, f64)> {
    fs::read_to_string(file)
        .unwrap()
        .lines()
        .skip_while(|l| l.starts_with('#'))
        .skip(1)
        .filter_map(|l| {
            let mut f = l.rsplitn(3, ',');
            let (y, x, head) = (f.next()?, f.next()?, f.next()?);
            (head.rsplit_once(',')?.0 == series).then(|| (x.parse().unwrap(), y.parse().unwrap()))
        })
        .collect()
}

#[test]
fn the_files_hold_the_curves_on_screen_not_new_runs() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    press(&mut app, "lle");
    let files = perform(&mut app, dir.path());
    let find = |suffix: &str| files.iter().find(|f| f.ends_with(suffix)).unwrap();
    let run = app.run().unwrap();
    let ft = rows(find("bouncelab-superball-force-time-1.csv"), "model");
    let h = &run.history;
    assert_eq!(ft.len(), h.t.len());
    assert!(
        ft.iter()
            .zip(h.t.iter().zip(&h.force))
            .all(|(a, (t, f))| a == &(*t, *f))
    );

    let curve = app.zeta_curve().unwrap();
    let id = format!("model lambda={}", bouncelab::text::short(curve.lambda, 6));
    let cz = rows(find("bouncelab-superball-cor-zeta-1.csv"), &id);
    // the decades on screen: 0.01 … 100, 20 points each
    assert_eq!(cz.len(), 81);
    for (zeta, cor) in cz {
        let p = curve.points.iter().find(|p| p.zeta == zeta).unwrap();
        assert_eq!(p.cor, cor);
    }
    let zeta = app.setting().get(Param::Zeta);
    assert_eq!(
        rows(find("bouncelab-superball-cor-zeta-1.csv"), "this run"),
        [(zeta, run.cor)]
    );
}

#[test]
fn on_the_sweeps_view_the_export_waits_for_the_background_sweep() {
    let mut app = App::new(Preset::embedded().remove(1), true).with_background_sweeps();
    press(&mut app, "\te");
    assert!(export_request().is_none(), "the sweep is still out");
    let (text, _) = message(&app);
    assert!(text.contains("waits"), "{text}");
    let pending = app.speed_requests().to_vec();
    assert_eq!(pending.len(), 1);
    update(
        &mut app,
        Action::SpeedReady(pending[0].clone(), pending[0].run()),
    );
    let r: &ExportRequest = &export_request().expect("ready now");
    assert_eq!(r.ball, "golf");
    let cv = &r.charts[1].1;
    assert_eq!(r.charts[1].0, "cor-velocity");
    let model = cv.series.iter().find(|s| s.id == "model").unwrap();
    assert_eq!(model.points.len(), app.speed_curve().unwrap().points.len());
}

#[test]
fn a_failed_export_says_why_in_one_line_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    fs::write(&file, "x").unwrap();
    let mut app = superball();
    press(&mut app, "e");
    let request = take_export().unwrap();
    let msg = export::write(&request, &file.join("sub")).unwrap_err();
    assert!(msg.starts_with("cannot create "), "{msg}");
    assert!(!msg.contains('\n') && !msg.contains("os error"), "{msg}");
    update(&mut app, Action::ExportFailed { msg: msg.clone() });
    assert!(export_request().is_none());
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Error);
    assert_eq!(text, format!("export failed: {msg}"));
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);

    // a folder that is missing is created
    let nested = dir.path().join("new/exports");
    let files = export::write(&request, &nested).unwrap();
    assert!(files.iter().all(|f| f.starts_with(&nested) && f.is_file()));
}

#[test]
fn the_export_folder_comes_from_the_environment() {
    assert_eq!(export::dir_from(None), PathBuf::from("."));
    assert_eq!(export::dir_from(Some("".into())), PathBuf::from("."));
    assert_eq!(
        export::dir_from(Some("/tmp/figs".into())),
        PathBuf::from("/tmp/figs")
    );
    assert_eq!(export::DIR_ENV, "BOUNCELAB_EXPORT_DIR");
}

#[test]
fn a_user_ball_name_becomes_a_safe_file_name() {
    let mut custom = Preset::embedded().remove(1);
    custom.name = "my golf/ball".into();
    let mut app = App::new(custom, false);
    press(&mut app, "e");
    assert_eq!(export_request().unwrap().ball, "my-golf-ball");
}

/// The export writes the very figures the screen draws: the same description, rendered once
/// as braille and once as SVG.
#[test]
fn the_export_holds_the_figures_on_screen() {
    let mut app = superball();
    press(&mut app, "pLLvv");
    for keys in ["e", "\te"] {
        press(&mut app, keys);
        let r = take_export().expect("an export");
        let charts = app.view().charts();
        assert_eq!(r.charts.len(), charts.len());
        for (&chart, (name, fig)) in charts.iter().zip(&r.charts) {
            assert_eq!(*name, chart.file_name());
            assert_eq!(fig, &ui::figure(&app, chart), "{name}");
            assert!(
                fig.series.iter().any(|s| s.id.starts_with("pinned")),
                "{name}"
            );
        }
    }
}
