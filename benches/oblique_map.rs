//! The oblique view's (angle, μ) map, 90 × 50 cells (issue 31: it settles ≤ 50 ms). Run:
//! `cargo bench --bench oblique_map`.
//!
//! - `compute`: the map alone, as the worker computes it (all cores, each angle's 50
//!   frictions sharing its normal impact: `oblique::solve_frictions`).
//! - `key_to_settled_map`: the tennis ball in the oblique view's map page at 120 × 40, `w`
//!   (spin +10 rad/s, so a new map) through `App::update` with the map computed inside it (no
//!   worker: the time from the key to the settled map), then the screen drawn.
//! - `one_by_one`: the same 4500 impacts each through `Ball::oblique`, one core — the
//!   baseline the shared normal impact and the cores improve on.

use bouncelab::Ball;
use bouncelab::api::ObliqueSpec;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{Action, ObliqueKey};
use bouncelab::tui::app::App;
use bouncelab::tui::views::oblique::map::{self, MapSpec};
use bouncelab::tui::views::oblique::param::ObliqueParam;
use divan::{Bencher, black_box};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;
use std::sync::atomic::AtomicBool;

fn main() {
    divan::main();
}

const AREA: Rect = Rect {
    x: 0,
    y: 0,
    width: 120,
    height: 40,
};

fn tennis() -> Ball {
    Ball::from_preset("tennis").unwrap()
}

#[divan::bench(sample_count = 20)]
fn compute(b: Bencher) {
    let spec = MapSpec {
        ball: tennis(),
        spin: 300.0,
        tangential_stiffness: None,
        inertia_factor: None,
    };
    b.bench(|| map::compute(black_box(&spec), &AtomicBool::new(false)));
}

#[divan::bench(sample_count = 20)]
fn key_to_settled_map(b: Bencher) {
    let preset = Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == "tennis")
        .unwrap();
    let mut app = App::new(preset, true);
    app.update(Action::Resize(AREA.width, AREA.height));
    app.update(Action::Oblique(ObliqueKey::Toggle));
    app.update(Action::Oblique(ObliqueKey::Page));
    let key = Action::Oblique(ObliqueKey::Step {
        param: ObliqueParam::Spin,
        up: true,
        coarse: false,
    });
    b.with_inputs(|| (app.clone(), Buffer::empty(AREA)))
        .bench_local_refs(|(app, buf)| {
            app.update(key.clone());
            app.render(AREA, buf);
        });
}

#[divan::bench(sample_count = 5)]
fn one_by_one(b: Bencher) {
    let ball = tennis();
    b.bench(|| {
        let mut n = 0.0;
        for i in 0..map::ANGLES {
            for j in 0..map::FRICTIONS {
                let spec = ObliqueSpec {
                    v: None,
                    angle_deg: map::angle_at(i),
                    spin: 300.0,
                    friction: map::friction_at(j),
                    tangential_stiffness: None,
                    inertia_factor: None,
                };
                n += ball.oblique(&spec, 0).unwrap().spin_out;
            }
        }
        n
    });
}
