//! Speed of the peers' impacts and calibrations (medians recorded in BENCHMARKS.md).
//! Run: `cargo bench --bench peers`.

use bouncelab::peers::calibrate::{compare, exact};
use bouncelab::peers::{PeerBall, PeerModel, cor, impact};
use divan::black_box;

fn main() {
    divan::main();
}

/// The golf ball's adopted stiffnesses (docs/model.md §7).
fn golf() -> PeerBall {
    PeerBall {
        mass: 0.0456,
        radius: 0.02075,
        v0: 1.47,
        k: 5.6e5,
        k_h: 5.6e5 / (1.5 * 3.0e-3f64.sqrt()),
    }
}

/// One Hunt–Crossley impact, summary only (target: median ≤ 10 µs).
#[divan::bench]
fn hunt_crossley_impact(b: divan::Bencher) {
    let ball = golf();
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
    compare(black_box(&golf()), 0.84, 0).unwrap().len()
}
