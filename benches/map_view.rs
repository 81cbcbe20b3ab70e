//! The explorer's map view at 200 × 60 (issue 21: first picture ≤ 16 ms after a key, full
//! detail ≤ 50 ms). Run: `cargo bench --bench map_view`.
//!
//! Every case starts from the superball in the map view with its map up to date, a fresh
//! clone each iteration (not timed), and presses a key through `App::update`, then renders
//! the whole screen into a 200 × 60 `Buffer` with the widget the event loop draws (`&App`):
//!
//! - `first_picture`: `v` (v0 up) makes a new map: `update` evaluates its first, coarse pass
//!   (as in the explorer, the rest goes to the background worker) and the screen is drawn —
//!   what the user sees within the frame after the key.
//! - `full_detail`: the same key with every pass evaluated inside `update` (all cores, as the
//!   worker does them), then one draw: the time to the full-detail picture, without the
//!   event loop's poll (≤ 5 ms while a map is refined) and the coarser frames in between.
//! - `cursor`: `→` moves the cursor a cell: one impact and the sensitivities, no new map.
//! - `full_detail_tennis`: `full_detail` for the tennis ball, which flattens over much of its
//!   map (those cells take the flattening closed form, eight at a time in lanes, the
//!   others the no-flattening one).
//! - `full_detail_hertz`, `full_detail_elastic_plastic`: `full_detail` for the superball
//!   under the Hertz and elastic–plastic laws (the Taylor steps, issue 30).
//! - `draw`: the render alone of the complete map.

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use bouncelab::tui::param::{Dir, Param};
use bouncelab::tui::state::View;
use divan::Bencher;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

fn main() {
    divan::main();
}

const AREA: Rect = Rect::new(0, 0, 200, 60);

/// A preset in the map view at 200 × 60, its map complete; with the background worker
/// (`update` then evaluates only a new map's first pass) or without (every pass).
fn start_with(preset: &str, background: bool) -> App {
    let preset = Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == preset);
    let mut app = App::new(preset.expect("an embedded preset"), true);
    app.update(Action::Resize(AREA.width, AREA.height));
    while app.view() != View::Map {
        app.update(Action::NextView);
    }
    if background {
        app = app.with_background_sweeps();
    }
    app
}

/// The superball (the explorer's default) in the map view.
fn start(background: bool) -> App {
    start_with("superball", background)
}

const V_UP: Action = Action::Step {
    param: Param::V0,
    dir: Dir::Up,
    coarse: false,
};

fn key_and_draw(b: Bencher, app: App, key: Action) {
    b.with_inputs(|| (app.clone(), Buffer::empty(AREA)))
        .bench_local_refs(|(app, buf)| {
            app.update(key.clone());
            app.render(AREA, buf);
        });
}

#[divan::bench]
fn first_picture(b: Bencher) {
    key_and_draw(b, start(true), V_UP);
}

#[divan::bench]
fn full_detail(b: Bencher) {
    key_and_draw(b, start(false), V_UP);
}

/// The tennis ball flattens over much of its map: those cells take the flattening closed
/// form in lanes (`map::fast::lanes::flattenings`; the exact solver before issue 30), the
/// others the no-flattening closed form.
#[divan::bench]
fn full_detail_tennis(b: Bencher) {
    key_and_draw(b, start_with("tennis", false), V_UP);
}

/// The superball under the Hertz law (two presses of `c`: linear → elastic–plastic → Hertz),
/// its map complete, then `v`: every cell takes the Taylor steps of `solver::taylor` within
/// their domain, the adaptive solver elsewhere (issue 30: ≤ 50 ms).
#[divan::bench]
fn full_detail_hertz(b: Bencher) {
    let mut app = start(false);
    app.update(Action::CycleLaw);
    app.update(Action::CycleLaw);
    key_and_draw(b, app, V_UP);
}

/// The same under the elastic–plastic law (one press of `c`).
#[divan::bench]
fn full_detail_elastic_plastic(b: Bencher) {
    let mut app = start(false);
    app.update(Action::CycleLaw);
    key_and_draw(b, app, V_UP);
}

#[divan::bench]
fn cursor(b: Bencher) {
    key_and_draw(b, start(true), Action::MapCursor { lambda: 0, zeta: 1 });
}

#[divan::bench]
fn draw(b: Bencher) {
    let app = start(false);
    b.with_inputs(|| Buffer::empty(AREA))
        .bench_local_refs(|buf| app.render(AREA, buf));
}

/// Issue 29 item 13's worst case: the Hertz law at λ 1000, ζ 0.001, v0 80 m/s on the
/// superball, a 200 × 60 screen's grid. `first_pass_hertz_worst`: the first pass the worker
/// runs (held to `FIRST_PASS_WORK`: the coarse full picture); `old_first_pass_hertz_worst`:
/// the first pass of `Map::new` alone (before issue 29, about 80 cells) — the baseline in the
/// same run.
fn hertz_worst() -> bouncelab::map::Map {
    use bouncelab::tui::views::map::state::{Window, grid};
    let p = Preset::embedded()[0]
        .params()
        .with_lambda_zeta(1000.0, 0.001);
    let p = bouncelab::ImpactParams { v0: 80.0, ..p };
    let (rows, cols) = grid(Some((AREA.width, AREA.height)), true, 0).unwrap();
    let (l, z) = Window::around(1000.0, 0.001).axes(rows, cols).unwrap();
    let spec = bouncelab::map::MapSpec::dimensional(p, bouncelab::ContactLaw::Hertz, l, z)
        .unwrap()
        .with_fast(true);
    bouncelab::map::Map::new(spec)
}

#[divan::bench(sample_count = 20)]
fn first_pass_hertz_worst(b: Bencher) {
    use bouncelab::tui::views::map::state::first_pass_cells;
    let map = hertz_worst().first_cells_at_most(first_pass_cells(bouncelab::ContactLaw::Hertz));
    b.with_inputs(|| map.clone())
        .bench_local_refs(|m| m.refine());
}

#[divan::bench(sample_count = 20)]
fn old_first_pass_hertz_worst(b: Bencher) {
    let map = hertz_worst();
    b.with_inputs(|| map.clone())
        .bench_local_refs(|m| m.refine());
}
