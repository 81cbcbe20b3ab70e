//! Heavy views stay inside the budget (issue 29 item 13): the map under the Hertz law shows
//! a coarse full picture first — its first pass held to `FIRST_PASS_WORK` linear-law impacts
//! of work, some 2–7 ms (BENCHMARKS.md, `map_view`'s `first_pass_hertz_worst`) — then
//! refines pass by pass on the worker.

mod tui_common;

use bouncelab::map::Quantity;
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect};
use bouncelab::tui::state::View;
use bouncelab::tui::views::map::state::{FIRST_PASS_WORK, first_pass_cells};
use bouncelab::{ContactLaw, analysis::work};

/// Golf under the Hertz law in the map view at 200 × 60, the map left to the worker: the job
/// handed out, as the event loop gets it.
fn hertz_map_job() -> (App, bouncelab::tui::views::map::state::MapJob) {
    let mut a = App::new(Preset::embedded().remove(1), true).with_background_sweeps();
    a.update(Action::Resize(200, 60));
    a.update(Action::CycleLaw);
    a.update(Action::CycleLaw);
    assert_eq!(a.setting().law, ContactLaw::Hertz);
    let mut job = None;
    while a.view() != View::Map {
        for e in a.update(Action::NextView) {
            if let Effect::Map(j) = e {
                job = Some(j);
            }
        }
    }
    (a, job.expect("the map goes to the worker"))
}

#[test]
fn the_hertz_map_shows_a_coarse_full_picture_first() {
    let (mut a, job) = hertz_map_job();
    let mut map = job.map.clone();
    let first = map.next_pass_cells();
    let cost = work::cost(ContactLaw::Hertz);
    assert!(
        first > 0 && first <= first_pass_cells(ContactLaw::Hertz),
        "{first} cells"
    );
    assert!(
        first as u64 * cost <= FIRST_PASS_WORK,
        "{first} cells × {cost}"
    );
    map.refine();
    let (rows, cols) = (map.lambdas.len(), map.zetas.len());
    assert!(rows * cols > 10_000, "200 × 60: {rows} × {cols}");
    assert!(
        (0..rows).all(|i| (0..cols).all(|j| map.nearest(i, j).is_some())),
        "the first pass covers the whole map"
    );
    // that pass drawn: no cell of the heat map is left blank
    let generation = job.generation;
    a.update(Action::MapPass {
        generation,
        map: Box::new(map.clone()),
    });
    let field = a.map_view().map().unwrap().field(Quantity::Cor);
    assert!(field.iter().filter(|v| v.is_finite()).count() == first);
    let screen = tui_common::screen_text(&tui_common::draw(&a, 200, 60)).join("\n");
    assert!(screen.contains("refining…"), "{screen}");
    // the next pass is finer (the lattice halves: src/map/eval.rs tests that the passes
    // refine to the whole map)
    assert!(map.next_pass_cells() > first);
}
