//! The explorer's map view (issue 21), its state through `update`: the cursor moving the ball,
//! the cell under the cursor against `run` at the same (λ, ζ), the quantity, and the worker's
//! passes (stale ones dropped).

use crate::tui_common;
use bouncelab::map::Quantity;
use bouncelab::preset::Preset;
use bouncelab::solver::{SolveOptions, simulate};
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Effect};
use bouncelab::tui::param::Param;
use bouncelab::tui::views::map::state::cell_of;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use tui_common::*;

fn point(app: &App) -> (f64, f64) {
    let s = app.setting();
    (s.get(Param::Lambda), s.get(Param::Zeta))
}

#[test]
fn arrows_move_the_cursor_and_the_ball_one_undoable_cell_at_a_time() {
    let mut app = map_app(true, 120, 40);
    let depth = app.undo_depth();
    let generation = app.map_view().job.generation;
    let (i, j) = {
        let (l, z) = point(&app);
        cell_of(app.map_view().map().unwrap(), l, z)
    };
    press(&mut app, &[KeyCode::Right]);
    let map = app.map_view().map().unwrap().clone();
    // the ball holds K_r = λ K_p and c = √(m K_p)/(2ζ): λ and ζ read back from them are the
    // cell's to an ulp or two of the round trip
    let same = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    let (l, z) = point(&app);
    assert!(same(z, map.zetas[j + 1]), "ζ on the next column: {z}");
    assert!(same(l, map.lambdas[i]), "λ snapped to its row: {l}");
    press(&mut app, &[KeyCode::Up, KeyCode::Up]);
    assert!(same(point(&app).0, map.lambdas[i + 2]));
    assert_eq!(app.undo_depth(), depth + 3, "one change per step");
    // the impact (and so the impact view) follows the ball
    let run = app.run().unwrap();
    let (l, z) = point(&app);
    let want = simulate(
        &app.setting().params,
        app.setting().law,
        &SolveOptions::default(),
    )
    .unwrap();
    assert_eq!(run.cor, want.cor);
    assert!((l - map.lambdas[i + 2]).abs() < 1e-12 && (z - map.zetas[j + 1]).abs() < 1e-15);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(point(&app).0, map.lambdas[i + 1], "undo: one cell back");
    // the same map all along: moving inside the window re-solves no map
    assert_eq!(app.map_view().job.generation, generation);
    // l / L still work in the map view, and the cursor follows
    press(&mut app, &[KeyCode::Char('l')]);
    assert_eq!(app.mode(), Mode::Map);
}

/// The cell under the cursor is `run` at that (λ, ζ): the map's cells and the impact the
/// readout shows are the same numbers.
#[test]
fn the_cell_under_the_cursor_is_run_at_that_point() {
    let mut app = map_app(true, 120, 40);
    press(&mut app, &[KeyCode::Left, KeyCode::Down, KeyCode::Down]);
    let (l, z) = point(&app);
    let map = app.map_view().map().unwrap();
    let (i, j) = cell_of(map, l, z);
    let cell = map.cell(i, j).unwrap();
    let run = simulate(
        &app.setting().params,
        app.setting().law,
        &SolveOptions::default(),
    )
    .unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
    assert!(close(cell.cor, run.cor), "{} vs {}", cell.cor, run.cor);
    assert!(close(cell.max_force, run.max_force));
    assert!(close(cell.contact_time.unwrap(), run.contact_time.unwrap()));
    let shown = app.run().unwrap();
    assert!(close(cell.cor, shown.cor) && close(cell.max_force, shown.max_force));
    // and at the same (λ, ζ) as `bouncelab run --lambda --zeta` sets them
    let p = Preset::embedded()[0]
        .params()
        .with_lambda_zeta(map.lambdas[i], map.zetas[j]);
    let cli = simulate(&p, app.setting().law, &SolveOptions::default()).unwrap();
    assert!(close(cell.cor, cli.cor));
}

#[test]
fn n_cycles_the_quantity() {
    let mut app = map_app(true, 120, 40);
    assert_eq!(app.map_view().quantity, Quantity::Cor);
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::MaxForce);
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::ContactTime);
    let t = draw(&app, 120, 40);
    assert!(format!("{:?}", t.backend()).contains("t_f (ms)"));
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::Cor);
    // outside the map view n and t do nothing
    press(&mut app, &[KeyCode::Tab]);
    assert_eq!(
        action::from_key(
            KeyEvent::new(KeyCode::Char('n'), KeyModifiers::NONE),
            app.mode()
        ),
        None
    );
}

/// With the worker: a new map's first pass is in `update`, the rest is asked for; a pass of
/// an older map is dropped, one of the current map taken; leaving the view stops the work.
#[test]
fn passes_come_from_the_worker_and_stale_ones_are_dropped() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    app.update(Action::Resize(120, 40));
    app.update(Action::NextView);
    app.update(Action::NextView);
    let effects = app.update(Action::NextView);
    let job = effects
        .iter()
        .find_map(|e| match e {
            Effect::Map(job) => Some(job.clone()),
            _ => None,
        })
        .expect("the rest of the map asked of the worker");
    assert!(app.map_pending());
    let coarse = app.map_view().map().unwrap().clone();
    assert!(
        !coarse.is_complete() && coarse.nearest(0, 0).is_some(),
        "a coarse picture"
    );
    // the worker's answer, done here: the whole map of that job
    let mut full = job.work.clone();
    while full.refine().is_some() {}
    // the ball changes (v0): a new map, the old job cancelled
    press(&mut app, &[KeyCode::Char('v')]);
    assert!(
        job.cancel.load(std::sync::atomic::Ordering::Relaxed),
        "stale job cancelled"
    );
    let now = app.map_view().job.generation;
    assert_eq!(now, job.generation + 1);
    app.update(Action::MapPass {
        generation: job.generation,
        map: Box::new(full),
    });
    assert!(
        !app.map_view().map().unwrap().is_complete(),
        "stale pass dropped"
    );
    assert_eq!(
        app.map_view().job.generation,
        now,
        "the map held is untouched"
    );
    let mut fresh = app.map_view().map().unwrap().clone();
    while fresh.refine().is_some() {}
    app.update(Action::MapPass {
        generation: now,
        map: Box::new(fresh.clone()),
    });
    assert_eq!(app.map_view().map(), Some(&fresh));
    assert!(!app.map_pending(), "complete: nothing out");
    // leaving the view while a map is out stops it
    press(&mut app, &[KeyCode::Char('v')]);
    assert!(app.map_pending());
    press(&mut app, &[KeyCode::Tab]);
    assert!(!app.map_pending());
}

/// Issue 51 item 4: the map's cell line writes its numbers as the readout does, four
/// significant digits: it read "cell λ 1.45 ζ 0.17" (trailing zeros trimmed) and
/// "∂e/∂ln ζ -0.085" (three decimals, two digits) beside a readout's "ζ 0.1612".
#[test]
fn the_map_cell_line_writes_four_significant_digits() {
    use bouncelab::tui::format::value;
    let app = map_app(false, 120, 40);
    let map = app.map_view().map().unwrap();
    let (l, z) = point(&app);
    let (i, j) = cell_of(map, l, z);
    let s = screen_text(&draw(&app, 120, 40)).join("\n");
    let cell = format!("cell λ {} ζ {}", value(map.lambdas[i]), value(map.zetas[j]));
    assert!(s.contains(&cell), "{cell:?} in\n{s}");
    let line = s
        .lines()
        .find(|r| r.contains("∂e/∂ln λ"))
        .expect("the sensitivities' line");
    for part in line.split("∂e/∂ln ").skip(1) {
        let number = part.split_whitespace().nth(1).unwrap();
        let digits = number
            .trim_start_matches(['+', '-', '0', '.'])
            .replace('.', "");
        assert_eq!(digits.len(), 4, "{number:?} in {line:?}");
    }
}
