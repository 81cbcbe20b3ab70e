//! Speed of the design map (issue 21; medians recorded in BENCHMARKS.md).
//! Run: `cargo bench --bench map`. The whole `bouncelab map` process is timed with hyperfine
//! (BENCHMARKS.md gives the command).

use bouncelab::map::{Axis, MapSpec, Param, Scale, compute};
use bouncelab::{ContactLaw, SolveOptions, simulate_normalized};
use divan::black_box;

fn main() {
    divan::main();
}

/// Points across the plane: the paper's balls' region, the Maxwell edge, a stiff dashpot.
const POINTS: [(f64, f64); 4] = [
    (1.0, 0.1),
    (0.4, 0.3),
    (0.02, 1.7861026411617908),
    (5.0, 20.0),
];

/// One linear-law impact, summary only (COR, peak force, contact time), through `simulate`
/// (the exact solver) as a map cell runs it. Target: median ≤ 0.3 µs.
#[divan::bench(args = POINTS)]
fn impact_summary(p: (f64, f64)) -> f64 {
    let r = simulate_normalized(
        black_box(p.0),
        black_box(p.1),
        ContactLaw::Linear,
        &SolveOptions::default(),
    )
    .unwrap();
    r.cor + r.max_force_normalized
}

fn spec(nl: usize, nz: usize) -> MapSpec {
    let l = Axis::new(Param::Lambda, 0.01, 100.0, nl, Scale::Log).unwrap();
    let z = Axis::new(Param::Zeta, 0.01, 100.0, nz, Scale::Log).unwrap();
    MapSpec::normalized(None, ContactLaw::Linear, l, z).unwrap()
}

/// A 200 × 120 normalized map (ζ × λ), every pass on all cores. Target: median ≤ 5 ms.
#[divan::bench(sample_count = 20)]
fn map_200x120() -> usize {
    compute(black_box(spec(120, 200))).cells().len()
}

/// The fast linear-law summary (`map::fast`, closed form) at the same points. Target: median
/// ≤ 0.3 µs.
#[divan::bench(args = POINTS)]
fn fast_summary(p: (f64, f64)) -> f64 {
    let s = bouncelab::map::fast::summary(black_box(p.0), black_box(p.1)).unwrap();
    s.cor + s.max_force
}

/// `map::fast::summary` over every (λ, ζ) of the 200 × 120 map, one after the other on one
/// core (where it answers: the map then takes the exact solver for the rest): the cost of an
/// impact across the plane, not only at the four points. Per impact: the median / 24 000.
#[divan::bench(sample_count = 20)]
fn fast_summary_grid() -> f64 {
    let l = Axis::new(Param::Lambda, 0.01, 100.0, 120, Scale::Log).unwrap();
    let z = Axis::new(Param::Zeta, 0.01, 100.0, 200, Scale::Log).unwrap();
    let mut sum = 0.0;
    for i in 0..l.n {
        for j in 0..z.n {
            let (lambda, zeta) = (black_box(l.value(i)), black_box(z.value(j)));
            sum += bouncelab::map::fast::summary(lambda, zeta).map_or(0.0, |s| s.cor);
        }
    }
    sum
}

/// The 200 × 120 map on the fast path (`MapSpec::with_fast`): its cells through the lanes,
/// eight at a time (`map::eval::cells_at`). Issue 30 item 3: ≤ 0.1 µs an impact on one core
/// (`RAYON_NUM_THREADS=1`: ≤ 2.4 ms).
#[divan::bench(sample_count = 20)]
fn map_200x120_fast() -> usize {
    compute(black_box(spec(120, 200).with_fast(true)))
        .cells()
        .len()
}

/// The (λ, ζ) of the 200 × 120 map's cells, λ outer: the lanes benches' input.
fn grid_200x120() -> (Vec<f64>, Vec<f64>) {
    let l = Axis::new(Param::Lambda, 0.01, 100.0, 120, Scale::Log).unwrap();
    let z = Axis::new(Param::Zeta, 0.01, 100.0, 200, Scale::Log).unwrap();
    (0..l.n)
        .flat_map(|i| (0..z.n).map(move |j| (i, j)))
        .map(|(i, j)| (l.value(i), z.value(j)))
        .unzip()
}

/// The same grid through the lanes (`map::fast::lanes::summaries`: eight cells a call, the
/// scalar path for the cells they leave; issue 30 item 3: target ≤ 0.1 µs an impact on one
/// core). Per impact: the median / 24 000.
#[divan::bench(sample_count = 20)]
fn fast_summary_grid_lanes(b: divan::Bencher) {
    let (lambda, zeta) = grid_200x120();
    let mut out = vec![None; lambda.len()];
    b.bench_local(|| {
        bouncelab::map::fast::lanes::summaries(black_box(&lambda), black_box(&zeta), &mut out);
        out.iter().map(|s| s.map_or(0.0, |s| s.cor)).sum::<f64>()
    });
}

/// The lanes' own share of [`fast_summary_grid_lanes`]: the same grid through
/// `lanes::lanes_only8` (eight cells a call, two AVX registers), without the scalar path that
/// `summaries` hands the cells the lanes leave (11 of the 24 000: three real roots whose
/// rounding bound refuses, tests/physics/map_lanes.rs `lanes_hand_back_few_cells_of_the_map`). Per
/// impact: the median / 24 000.
#[divan::bench(sample_count = 20)]
fn fast_summary_grid_lanes_only(b: divan::Bencher) {
    use bouncelab::map::fast::lanes::{WIDE, lanes_only8};
    let (lambda, zeta) = grid_200x120();
    b.bench_local(|| {
        let mut sum = 0.0;
        for (l, z) in lambda.chunks_exact(WIDE).zip(zeta.chunks_exact(WIDE)) {
            let (l, z) = (l.try_into().unwrap(), z.try_into().unwrap());
            let out = lanes_only8(black_box(l), black_box(z));
            sum += out.iter().map(|s| s.map_or(0.0, |s| s.cor)).sum::<f64>();
        }
        sum
    });
}

/// A normalized 200 × 60 map (ζ × λ) under the Hertz law (κ = 2/3: the normalized ball's K_h
/// at z̄_p = 1), every pass on all cores: the Taylor steps of `solver::taylor` where they
/// answer (`with_fast_laws`), the adaptive solver elsewhere. Issue 30: ≤ 50 ms.
#[divan::bench(sample_count = 10)]
fn map_200x60_hertz_fast() -> usize {
    let l = Axis::new(Param::Lambda, 0.01, 100.0, 60, Scale::Log).unwrap();
    let z = Axis::new(Param::Zeta, 0.01, 100.0, 200, Scale::Log).unwrap();
    let spec = MapSpec::normalized(None, ContactLaw::Hertz, l, z).unwrap();
    compute(black_box(spec.with_fast_laws(true))).cells().len()
}
