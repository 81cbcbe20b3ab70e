//! One keystroke's work in the explorer (target: median ≤ 5 ms for the total), split into
//! physics and drawing. Run: `cargo bench --bench keystroke`.
//!
//! - `keystroke_total`: one key through `App::update` — every curve on screen that the key
//!   makes stale is recomputed — then the whole screen rendered into a 200×60 `Buffer` with
//!   the widget the event loop draws (`&App`).
//! - `keystroke_physics`: the `update` alone.
//! - `keystroke_draw`: the render alone, of the state after the key.
//!
//! Every case starts from the superball preset (a fresh clone each iteration, not timed).
//! Cases: the view (impact: force–time, force–displacement, COR vs ζ; sweeps: normalized peak
//! force vs ζ, COR vs speed) and the key (`l` = λ up: new impact and a new current-λ curve;
//! `v` = v0 up: new impact). On the sweeps view the key also makes the COR-vs-speed sweep
//! stale: `sync` runs it inside `update` (all the work the key causes, as the tests run it),
//! `worker` is what the explorer's UI thread does (the sweep goes to the background worker;
//! `update` only returns it as an `Effect::Compute`). Two more cases run `l` under the
//! elastic–plastic law, whose impacts take the adaptive solver (the ζ curves stay linear, as
//! in the paper). On the models view, `worker` is what the UI thread does when the key sends
//! the calibration of the peer models to their background worker.
//!
//! Drawing includes building each chart's figure from the state (`crate::figure::explorer`),
//! as the explorer does on every frame.
//!
//! The slowest corner (issue 18, defect 11): elastic–plastic law, λ = 0, ζ = 1000, sweeps
//! view, `z` (`sweeps z worker e-p corner`): the UI thread's work per key; and the worker's
//! COR-vs-speed sweep there (`corner_sweep`): until its first coarse curve (4 speeds, drawn
//! as "refining…") and whole (40 speeds).

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::param::{Dir, Param};
use divan::Bencher;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;
use std::fmt;

fn main() {
    divan::main();
}

const AREA: Rect = Rect::new(0, 0, 200, 60);

#[derive(Clone, Copy)]
struct Case {
    view: View,
    param: Param,
    /// COR-vs-speed sweeps on the background worker (the explorer) or inside `update`.
    worker: bool,
    /// The preset's linear law, or the elastic–plastic one (`c` once: the adaptive solver).
    plastic: bool,
    /// Start at λ = 0, ζ = 1000 (the ball sinks into the dashpot).
    corner: bool,
}

impl fmt::Display for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let view = self.view.name();
        let key = match self.param {
            Param::Lambda => "l",
            Param::Zeta => "z",
            Param::V0 => "v",
        };
        let how = match (self.view, self.worker) {
            (View::Impact | View::Map | View::Drop | View::Oblique | View::Flight, _) => "",
            (View::Sweeps | View::Models, false) => " sync",
            (View::Sweeps | View::Models, true) => " worker",
        };
        let law = if self.plastic { " e-p law" } else { "" };
        let corner = if self.corner { " corner" } else { "" };
        write!(f, "{view} {key}{how}{law}{corner}")
    }
}

impl fmt::Debug for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

const fn case(view: View, param: Param, worker: bool, plastic: bool) -> Case {
    Case {
        view,
        param,
        worker,
        plastic,
        corner: false,
    }
}

const CORNER: Case = Case {
    corner: true,
    ..case(View::Sweeps, Param::Zeta, true, true)
};

const CASES: [Case; 10] = [
    case(View::Impact, Param::Lambda, false, false),
    case(View::Impact, Param::V0, false, false),
    case(View::Sweeps, Param::Lambda, false, false),
    case(View::Sweeps, Param::V0, false, false),
    case(View::Sweeps, Param::Lambda, true, false),
    case(View::Sweeps, Param::V0, true, false),
    case(View::Impact, Param::Lambda, false, true),
    case(View::Sweeps, Param::Lambda, false, true),
    case(View::Models, Param::Lambda, true, false),
    CORNER,
];

/// The superball on the case's view, everything on screen up to date.
fn start(c: Case) -> App {
    let mut app = App::new(Preset::embedded().remove(0), true);
    if c.plastic {
        app.update(Action::CycleLaw);
    }
    if c.corner {
        type_value(&mut app, "0");
        app.update(Action::SelectNext);
        type_value(&mut app, "1000");
    }
    if c.view == View::Sweeps {
        app.update(Action::NextView);
    }
    if c.view == View::Models {
        app.update(Action::PrevView);
    }
    if c.worker {
        app = app.with_background_sweeps();
    }
    app
}

/// Type `text` as the selected parameter's value.
fn type_value(app: &mut App, text: &str) {
    app.update(Action::OpenInput);
    for ch in text.chars() {
        app.update(Action::InputChar(ch));
    }
    app.update(Action::InputSubmit);
}

/// The worker's sweep at the corner: until its first coarse curve, or whole.
#[divan::bench(args = ["first coarse curve", "whole"])]
fn corner_sweep(b: Bencher, until: &str) {
    let mut app = start(CORNER);
    app.update(key(CORNER));
    let request = app.speed_requests()[0].clone();
    let first = until.starts_with("first");
    b.bench_local(|| {
        let stop = std::cell::Cell::new(false);
        request.run_refining(|| !(first && stop.get()), |_| stop.set(true))
    });
}

fn key(c: Case) -> Action {
    Action::Step {
        param: c.param,
        dir: Dir::Up,
        coarse: false,
    }
}

fn draw(app: &App, buf: &mut Buffer) {
    app.render(AREA, buf);
}

#[divan::bench(args = CASES)]
fn keystroke_total(b: Bencher, c: Case) {
    let app = start(c);
    b.with_inputs(|| (app.clone(), Buffer::empty(AREA)))
        .bench_local_refs(|(app, buf)| {
            app.update(key(c));
            draw(app, buf);
        });
}

#[divan::bench(args = CASES)]
fn keystroke_physics(b: Bencher, c: Case) {
    let app = start(c);
    b.with_inputs(|| app.clone())
        .bench_local_refs(|app| app.update(key(c)));
}

#[divan::bench(args = CASES)]
fn keystroke_draw(b: Bencher, c: Case) {
    let mut app = start(c);
    app.update(key(c));
    b.with_inputs(|| Buffer::empty(AREA))
        .bench_local_refs(|buf| draw(&app, buf));
}
