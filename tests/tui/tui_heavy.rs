//! Heavy views stay inside the budget (issue 29 item 13): the map under the Hertz law shows
//! a coarse full picture first — its first pass held to `FIRST_PASS_WORK` linear-law impacts
//! of work, some 2–7 ms (BENCHMARKS.md, `map_view`'s `first_pass_hertz_worst`) — then
//! refines pass by pass on the worker; a fit of a 200 000-row trace (binned to the model's
//! resolution, src/analysis/fit/bins.rs) reports its progress to the pane while it runs and
//! stops at its next model run once a later fit is asked for.

use crate::fit_common;
use crate::tui_common;

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
    let mut map = job.work.clone();
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

/// A 200 000-row force trace of `fit_common::truth`'s ball (20 ms at 10 MHz, noise 0.5 N):
/// the data and the fit of the ball `guess` starts from.
fn dense_trace_request(id: u64) -> bouncelab::tui::views::fit::state::FitRequest {
    use bouncelab::measured::Data;
    use bouncelab::tui::views::fit::state::{Loaded, request};
    let t = fit_common::truth();
    let mut rng = fit_common::Rng::new(29);
    let trace = fit_common::trace(
        &t,
        ContactLaw::Linear,
        2e-3,
        0.5,
        0.0,
        (200_000, 1e-7),
        &mut rng,
    );
    assert_eq!(trace.time.len(), 200_000);
    let loaded = Loaded {
        path: "dense.csv".into(),
        label: "dense.csv".into(),
        data: Data::Trace(trace),
    };
    request(id, &loaded, &fit_common::guess(&t), ContactLaw::Linear).unwrap()
}

/// The fit worker on a 200 000-row trace: progress comes back while it runs (model runs
/// done, growing), then the outcome — the truth found again. The worker reports after every
/// model run here: at the explorer's `PROGRESS_EVERY` an optimised build's fit ends before its
/// first report (`cargo test` builds this crate at opt-level 1: Cargo.toml). (That a later fit
/// asked for stops a running one at its next model run is `Reporter`'s unit test in
/// src/tui/views/fit/worker.rs: with real time the first fit may end before the second is
/// asked.)
#[test]
fn a_dense_trace_fit_reports_progress_then_its_answer() {
    use bouncelab::tui::views::fit::state::FitNews;
    use bouncelab::tui::views::fit::worker::FitWorker;
    use std::time::{Duration, Instant};
    let mut w = FitWorker::spawn_reporting_every(Duration::ZERO).unwrap();
    w.want(dense_trace_request(1));
    let start = Instant::now();
    let mut runs = Vec::new();
    let outcome = loop {
        match w.try_recv().unwrap() {
            Some((1, FitNews::Progress(p))) => runs.push(p.runs),
            Some((1, FitNews::Done(o))) => break o,
            Some(other) => panic!("{other:?}"),
            None => std::thread::sleep(Duration::from_millis(5)),
        }
        assert!(start.elapsed() < Duration::from_secs(600), "hung");
    };
    assert!(!runs.is_empty() && runs[0] > 0, "{runs:?}");
    assert!(runs.windows(2).all(|w| w[1] >= w[0]), "{runs:?}");
    let o = outcome.unwrap();
    let k_p = o.fitted.iter().find(|e| e.name == "k_p").unwrap();
    assert!(
        (k_p.value / fit_common::truth().k_p - 1.0).abs() < 0.01,
        "{k_p:?}"
    );
}

/// The pane says how far the fit is: the worker's progress, as `bouncelab fit` counts it.
#[test]
fn the_fit_pane_shows_the_progress() {
    use bouncelab::tui::views::fit::state::{FitNews, FitProgress};
    let mut a = App::new(Preset::embedded().remove(1), false);
    let r = dense_trace_request(0);
    let bouncelab::tui::views::fit::state::FitInput::Trace(trace) = r.input else {
        unreachable!()
    };
    a.update(Action::MeasuredLoaded {
        path: "dense.csv".into(),
        data: bouncelab::measured::Data::Trace(trace),
    });
    let asked = a.update(Action::Fit);
    let [Effect::Fit(r)] = asked.as_slice() else {
        panic!("{asked:?}")
    };
    let p = FitProgress {
        runs: 1234,
        seconds: 3.25,
    };
    a.update(Action::FitReady(r.id, FitNews::Progress(p)));
    assert!(a.fitting());
    for (w, h) in [(80, 24), (120, 40)] {
        let screen = tui_common::screen_text(&tui_common::draw(&a, w, h)).join("\n");
        assert!(
            screen.contains("1234 model runs, 3.2 s"),
            "{w}×{h}: {screen}"
        );
    }
    // news of a fit superseded is dropped
    a.update(Action::FitReady(
        r.id + 7,
        FitNews::Progress(FitProgress {
            runs: 9,
            seconds: 9.0,
        }),
    ));
    assert_eq!(a.fit_pane().unwrap().progress, Some(p));
}
