//! Speed of the peers' impacts and calibrations (medians recorded in BENCHMARKS.md).
//! Run: `cargo bench --bench peers`.

use bouncelab::Ball;
use bouncelab::peers::calibrate::{compare, exact};
use bouncelab::peers::{PeerBall, PeerModel, cor, impact};
use divan::black_box;
use std::sync::LazyLock;

fn main() {
    divan::main();
}

/// The embedded golf preset's adopted set (docs/model.md §7: m = 45.6 g, R = 20.75 mm,
/// v0 = 1.47 m/s, K_p = 5.6e5 N/m, K_h = K_p/(1.5 √z_p)), read once: the table bench times
/// the comparison, not the catalog.
static GOLF: LazyLock<PeerBall> = LazyLock::new(|| {
    let b = Ball::from_preset("golf").expect("the embedded golf preset");
    let radius = b.measured.as_ref().expect("golf's radius").radius;
    PeerBall::from_params(&b.params, radius)
});

/// One Hunt–Crossley impact, summary only (target: median ≤ 10 µs).
#[divan::bench]
fn hunt_crossley_impact(b: divan::Bencher) {
    let ball = *GOLF;
    b.bench(|| {
        impact(PeerModel::HuntCrossley, black_box(&ball), 0.285, 0)
            .unwrap()
            .cor
    });
}

/// One impact of each model, COR only.
#[divan::bench(args = PeerModel::ALL)]
fn cor_only(model: PeerModel) -> f64 {
    cor(black_box(model), 0.3).unwrap()
}

/// One exact calibration to e = 0.84 (target: median ≤ 0.5 ms).
#[divan::bench(args = PeerModel::ALL)]
fn exact_calibration(model: PeerModel) -> f64 {
    exact(black_box(model), 0.84).unwrap()
}

/// The whole comparison table of `bouncelab peers` (11 calibrated impacts).
#[divan::bench]
fn compare_table() -> usize {
    compare(black_box(&*GOLF), 0.84, 0).unwrap().len()
}
