//! What a walk through the explorer at the five sizes found (issue 51): the readout's
//! measured column at four digits as the model's (`0.7506` beside `0.75`), the energy
//! residual's round-off read as 0 (`residual 2e-16`), the surface named in the impact and
//! oblique views (the steel plate said nothing), and no frame's title touching its corner
//! (`┌Paths · angles…`, `┌ball`), a measured COR table drawn whole on COR against speed.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::views::fit::state as measured;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

fn superball() -> App {
    App::new(Preset::embedded().remove(0), false)
}

fn text(app: &mut App, w: u16, h: u16) -> String {
    app.update(Action::Resize(w, h));
    screen_text(&draw(app, w, h)).join("\n")
}

/// The readout's row of `name` ("e", "t_f ms") at 120×40, its words.
fn result_row(app: &mut App, name: &str) -> Vec<String> {
    let screen = text(app, 120, 40);
    let row = screen
        .lines()
        .filter_map(|l| l.rsplit("││").next())
        .find(|r| {
            r.trim_start_matches('│')
                .trim_start()
                .starts_with(&format!("{name} "))
        })
        .unwrap_or_else(|| panic!("no row {name}\n{screen}"))
        .to_string();
    row.split_whitespace()
        .filter(|w| *w != "│")
        .map(|w| w.trim_matches('│').to_string())
        .collect()
}

#[test]
fn the_measured_column_has_the_models_four_digits() {
    let mut app = superball();
    // the superball's measured e 0.75 and t_f 3 ms (presets/superball.toml)
    assert_eq!(result_row(&mut app, "e")[..3], ["e", "0.7506", "0.7500"]);
    assert_eq!(
        result_row(&mut app, "t_f")[..4],
        ["t_f", "ms", "2.743", "3.000"]
    );
    // the note of the speed they were taken at, as the v0 line above it writes v0
    let screen = text(&mut app, 120, 40);
    assert!(screen.contains("measured at v0 = 3.120 m/s"), "{screen}");
    // the compact readout's line at 80×24 too
    let small = text(&mut app, 80, 24);
    assert!(small.contains("e 0.7506 (0.7500, +0.1%)"), "{small}");
}

#[test]
fn a_round_off_energy_residual_reads_0() {
    let mut app = superball();
    let screen = text(&mut app, 120, 40);
    let line = screen
        .lines()
        .find(|l| l.contains("residual"))
        .unwrap_or_else(|| panic!("{screen}"));
    assert!(line.contains("residual 0 "), "{line}");
}

#[test]
fn the_impact_and_oblique_views_name_the_steel_plate() {
    let mut app = superball();
    for (w, h) in [(100, 30), (120, 40), (160, 50), (200, 60)] {
        let screen = text(&mut app, w, h);
        assert!(
            screen.contains("surface steel-plate: rigid"),
            "impact {w}×{h}\n{screen}"
        );
    }
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Oblique);
    for (w, h) in [(100, 30), (120, 40), (160, 50), (200, 60)] {
        let screen = text(&mut app, w, h);
        assert!(
            screen.contains("surface steel-plate: rigid"),
            "oblique {w}×{h}\n{screen}"
        );
    }
}

/// Every frame's top-left corner `┌` followed by a title's letter rather than a space or `─`.
fn titles_on_corners(screen: &str) -> Vec<String> {
    screen
        .lines()
        .flat_map(|l| l.match_indices('┌').map(move |(i, _)| &l[i..]))
        .filter(|rest| rest.chars().nth(1).is_some_and(char::is_alphanumeric))
        .map(|rest| rest.chars().take(24).collect())
        .collect()
}

#[test]
fn no_title_touches_its_frames_corner_in_any_view_at_any_size() {
    let mut app = superball();
    let check = |app: &mut App, what: &str| {
        for (w, h) in SIZES {
            let screen = text(app, w, h);
            let bad = titles_on_corners(&screen);
            assert!(bad.is_empty(), "{what} {w}×{h}: {bad:?}\n{screen}");
        }
    };
    for view in ["impact", "sweeps", "models", "map"] {
        check(&mut app, view);
        press(&mut app, &[KeyCode::Tab]);
    }
    press(&mut app, &[KeyCode::Char('d')]);
    assert_eq!(app.view(), View::Drop);
    check(&mut app, "drop");
    press(&mut app, &[KeyCode::Char('d'), KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Oblique);
    check(&mut app, "oblique");
    press(&mut app, &[KeyCode::Char('t')]);
    check(&mut app, "oblique map");
    press(
        &mut app,
        &[KeyCode::Char('t'), KeyCode::Char('i'), KeyCode::Char('h')],
    );
    assert_eq!(app.view(), View::Flight);
    check(&mut app, "flight");
}

#[test]
fn the_finder_finds_a_title_on_its_corner() {
    assert_eq!(titles_on_corners("┌Paths · angles─┐").len(), 1);
    assert!(titles_on_corners("┌ Paths · angles ─┐ ┌───┐").is_empty());
}

/// A cannon's COR table to 50 m/s on the superball, whose own sweep ends at 20 m/s: the
/// COR-vs-speed chart showed the rows at 10 and 20 m/s and hid the other three.
#[test]
fn the_speed_chart_reaches_the_measured_tables_fastest_row() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("cannon.csv");
    std::fs::write(
        &path,
        "v0,cor\n10,0.80\n20,0.76\n30,0.72\n40,0.69\n50,0.66\n",
    )
    .unwrap();
    let mut app = superball().with_background_sweeps();
    // the sweeps view: the speed chart's sweeps are asked for while it shows
    press(&mut app, &[KeyCode::Tab]);
    let reach = |app: &mut App| {
        app.refresh();
        let v: Vec<f64> = app.speed_requests().iter().map(|r| r.v_max).collect();
        assert!(!v.is_empty());
        v.into_iter().fold(f64::INFINITY, f64::min)
    };
    assert!(reach(&mut app) < 50.0, "the sweep already reaches 50 m/s");
    let data = measured::load(&path).unwrap();
    app.update(Action::MeasuredLoaded { path, data });
    assert!(
        reach(&mut app) >= 50.0,
        "the sweep ends at {}",
        reach(&mut app)
    );
}

/// The flight view's readout: its selected value marked ▶ (it was marked by reverse video
/// alone, which a copy of the screen loses), and its key line keeping `a/w/k` whole (it
/// broke as `· a` / `w k ·` at 120×40 and 160×50).
#[test]
fn the_flight_readout_marks_its_selection_and_keeps_its_keys_whole() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Char('h')]);
    assert_eq!(app.view(), View::Flight);
    for (w, h) in SIZES {
        let screen = text(&mut app, w, h);
        assert!(screen.contains("▶v 50.00 m/s"), "{w}×{h}\n{screen}");
        assert!(
            !screen
                .lines()
                .any(|l| l.contains("· a│") || l.contains("│w k ·")),
            "{w}×{h}\n{screen}"
        );
    }
    press(&mut app, &[KeyCode::Right]);
    let screen = text(&mut app, 120, 40);
    assert!(screen.contains("▶elev -5.000°"), "{screen}");
}
