//! What the explorer says of the surface an answer ran on and of the measurement beside it,
//! in the library's words, as the command line says them: an assumed-rigid surface's warning
//! (`SurfaceUsed::warnings`, the court rating's `SurfaceUsed::court_warnings`) in the impact
//! and oblique readouts at every size; a surface whose numbers the form moved named by the
//! library's rule (`clay-modified`, `given-surface`) as its `y` line's answer names it; and
//! why the measured values are not compared (`Ball::measurement_withheld`, `run`'s
//! `comparison_withheld`).

use crate::tui_common::*;
use bouncelab::api::SurfaceUsed;
use bouncelab::catalog::surfaces;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::physical::Field;
use bouncelab::tui::state::Severity;
use ratatui::crossterm::event::KeyCode;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// The embedded surface `name` as the command line finds it, nothing given over it.
fn surface(name: &str) -> SurfaceUsed {
    let all = surfaces::load(None).unwrap();
    SurfaceUsed::from_entry(&surfaces::find(&all, name).unwrap())
}

fn screen(app: &App, w: u16, h: u16) -> String {
    screen_text(&draw(app, w, h)).join("\n")
}

/// The text of the readout rows that begin with `start` (inside a border: "│" before it, or
/// "│ " in the impact readout) and
/// the rows under it that go on with it, joined with spaces, its "…" dropped: what the screen
/// shows of a wrapped warning, one per warning shown.
fn shown(text: &str, start: &str) -> Vec<String> {
    let rows: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        let Some(at) = row.find(start) else {
            continue;
        };
        let before = row[..at].trim_end_matches(' ');
        if !before.ends_with('│') || at - before.len() > 1 {
            continue;
        }
        let column = before.chars().count();
        let cell = |r: &str| {
            let rest: String = r.chars().skip(column).collect();
            rest.split('│').next().unwrap_or("").trim().to_string()
        };
        let mut words = cell(row);
        for next in &rows[i + 1..] {
            let more = cell(next);
            // the next warning, a note or the panel's end: not this warning's
            if words.ends_with('…') || more.is_empty() || more.starts_with(start) {
                break;
            }
            if more.starts_with("measured") || more.starts_with("energy") {
                break;
            }
            words = format!("{words} {more}");
        }
        out.push(words.trim_end_matches('…').trim_end().to_string());
    }
    out
}

/// Every `shown` text is the start of one of `warnings`, said at a word.
fn all_from(shown: &[String], warnings: &[String], at: &str) {
    for s in shown {
        assert!(
            warnings
                .iter()
                .any(|w| w.starts_with(s.as_str()) && !s.is_empty()),
            "{at}: {s:?} is none of {warnings:#?}"
        );
    }
}

#[test]
fn an_assumed_rigid_surface_is_warned_in_the_impact_readout_at_every_size() {
    let clay = surface("clay").warnings();
    assert_eq!(clay.len(), 1, "{clay:?}");
    assert!(clay[0].starts_with("surface clay: its normal give is ASSUMED rigid"));
    let app = explorer_from("bouncelab --preset tennis --surface clay");
    for (w, h) in SIZES {
        let text = screen(&app, w, h);
        let said = shown(&text, "surface clay: its");
        assert_eq!(said.len(), 1, "{w}×{h}:\n{text}");
        all_from(&said, &clay, &format!("{w}×{h}"));
    }
    // the tall panel gives it three rows
    let said = shown(&screen(&app, 160, 50), "surface clay: its");
    assert!(said[0].contains("ASSUMED rigid"), "{said:?}");
    // picked with `G`, the message line says it whole
    let dir = tempfile::tempdir().unwrap();
    let mut app = App::new(crate::common::embedded("tennis"), false);
    pick_surface(&mut app, dir.path(), "clay");
    let m = app.message().expect("a message");
    assert_eq!((&m.text, m.severity), (&clay[0], Severity::Warning));
    // the plate and hard-court (rigid as published) are warned of by no one
    for line in [
        "bouncelab --preset tennis",
        "bouncelab --preset tennis --surface hard-court",
    ] {
        let app = explorer_from(line);
        let text = screen(&app, 120, 40);
        assert!(!text.contains("ASSUMED"), "{line}:\n{text}");
    }
}

#[test]
fn the_oblique_view_warns_of_its_impact_and_of_its_court_rating() {
    let clay = surface("clay");
    let both = [clay.warnings(), clay.court_warnings()].concat();
    assert_eq!(both.len(), 2, "{both:?}");
    assert_ne!(both[0], both[1]);
    // at v sin θ = 6.906 m/s, inside the tennis ball's record: no calibration warning
    let v0 = 6.906 / 16f64.to_radians().sin();
    let app = explorer_from(&format!(
        "bouncelab --preset tennis --surface clay --angle 16 --v0 {v0}"
    ));
    assert_eq!(app.view(), View::Oblique);
    assert!(app.oblique_view().pace.as_ref().is_some_and(|p| p.is_ok()));
    for (w, h) in SIZES {
        let text = screen(&app, w, h);
        let said = shown(&text, "surface clay: its");
        // the impact's over the pace, the rating's under it
        assert_eq!(said.len(), 2, "{w}×{h}:\n{text}");
        all_from(&said, &both, &format!("{w}×{h}"));
        let pace = text.find("ITF court pace").expect("the pace");
        let [first, second] =
            [0, 1].map(|i| text.match_indices("surface clay: its").nth(i).unwrap().0);
        assert!(first < pace && pace < second, "{w}×{h}:\n{text}");
    }
    // where the panel has room the consequences part: the impact's, then the rating's
    let said = shown(&screen(&app, 200, 60), "surface clay: its");
    assert_eq!(said.len(), 2);
    assert!(both[0].starts_with(&said[0]) && both[1].starts_with(&said[1]));
    assert!(said[1].contains("e_y is the rigid plate's"), "{said:?}");
}

/// The name of the surface in the JSON of the explorer's `y` line: what the command line
/// calls the surface the screen's answer ran on.
fn line_surface(app: &App) -> String {
    let line = match app.view() {
        View::Oblique => app.command_line(),
        _ => app.run_line(),
    };
    let j = line_json(&line);
    j["surface"]["name"]
        .as_str()
        .unwrap_or_else(|| panic!("{line}: {j}"))
        .to_string()
}

#[test]
fn a_surface_the_form_moved_is_named_as_its_line_names_it() {
    let mut app = explorer_from("bouncelab --preset tennis --surface clay");
    type_into_form(&mut app, Field::TargetStiffness, "1e5");
    press(&mut app, &[KeyCode::Esc]);
    assert_eq!(app.setting().target.stiffness, 1e5);
    // the impact view's line is `collide … --surface clay --target-stiffness 100000`
    assert_eq!(line_surface(&app), "clay-modified");
    let text = screen(&app, 120, 40);
    // its numbers are the ones it runs on (the row breaks after "K_s")
    assert!(text.contains("│ surface clay-modified: K_s"), "{text}");
    assert!(!text.contains("surface clay: rigid"), "{text}");
    // its K_s is given: no longer the plate's answer, no warning
    assert!(!text.contains("ASSUMED"), "{text}");
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Oblique);
    assert_eq!(line_surface(&app), "clay-modified");
    let text = screen(&app, 120, 40);
    assert!(
        text.contains("surface clay-modified: K_s 1.000e5"),
        "{text}"
    );
    // no surface picked, K_s typed: the plate given over, `given-surface`
    let app = explorer_from("bouncelab --preset tennis --target-stiffness 100000 --angle 16");
    assert_eq!(line_surface(&app), "given-surface");
    let text = screen(&app, 120, 40);
    assert!(
        text.contains("surface given-surface: K_s 1.000e5"),
        "{text}"
    );
    // the plate left as it is keeps its name
    let app = explorer_from("bouncelab --preset tennis --angle 16");
    assert_eq!(line_surface(&app), "steel-plate");
}

#[test]
fn why_the_measured_values_are_not_compared_is_the_librarys() {
    let app = explorer_from("bouncelab --preset tennis --pressure 70000");
    let j = line_json(&app.run_line());
    let why = j["comparison_withheld"]
        .as_str()
        .unwrap_or_else(|| panic!("{j}"));
    assert!(why.starts_with("the measurement is at the record's conditions"));
    let whole = format!("measured at v0 = 6.906 m/s: not compared: {why}");
    let mut seen = 0;
    for (w, h) in SIZES {
        let text = screen(&app, w, h);
        let said = shown(&text, "measured at v0");
        if said.is_empty() {
            continue;
        }
        seen += 1;
        assert_eq!(said.len(), 1, "{w}×{h}:\n{text}");
        assert!(
            said[0].starts_with("measured at v0 = 6.906 m/s: not compared: the measurement"),
            "{w}×{h}: {said:?}\n{text}"
        );
        all_from(&said, std::slice::from_ref(&whole), &format!("{w}×{h}"));
    }
    // the tall panel's sizes say it (the short readouts show no measured values, nor this)
    assert!(seen >= 3, "{seen}");
    // at the record's conditions the measured values are compared again, nothing said
    let app = explorer_from("bouncelab --preset tennis");
    assert!(!screen(&app, 120, 40).contains("not compared"));
}
