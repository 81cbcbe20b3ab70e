//! Speed of the physics core (medians recorded in BENCHMARKS.md).
//! Run: `cargo bench --bench solver`.

use bouncelab::analysis::sweep::{cor_vs_zeta, log_space};
use bouncelab::preset::Preset;
use bouncelab::{ContactLaw, ImpactParams, ImpactResponse, SolveOptions, simulate};
use divan::black_box;

fn main() {
    divan::main();
}

/// One linearized impact, summary only (target: median ≤ 2 µs). Superball's adopted set.
#[divan::bench]
fn linear_impact_summary(b: divan::Bencher) {
    let p = Preset::embedded()[0].params();
    b.bench(|| {
        simulate(black_box(&p), ContactLaw::Linear, &SolveOptions::default())
            .unwrap()
            .cor
    });
}

/// One linearized impact with the ball flattening (two distinct phases, z_f > 0).
#[divan::bench]
fn linear_impact_flattening() -> f64 {
    let p = ImpactParams::from_normalized(1.3, 0.16, 0.3);
    simulate(black_box(&p), ContactLaw::Linear, &SolveOptions::default())
        .unwrap()
        .cor
}

/// A 4 × 400-point COR-vs-ζ sweep, ζ log-spaced over 0.01 … 100 (target: ≤ 3 ms).
#[divan::bench]
fn cor_zeta_sweep_4x400() -> usize {
    let zetas = log_space(0.01, 100.0, 400);
    cor_vs_zeta(black_box(&[0.0, 0.4, 1.0, 1.3]), &zetas, ContactLaw::Linear)
        .unwrap()
        .len()
}

/// Superball hit at 3× its measured speed, so that it goes well past z_p; rtol 1e-9, a
/// history of `samples`; each answer `read`.
fn elastic_plastic_bench<T>(
    b: divan::Bencher,
    samples: usize,
    read: impl Fn(ImpactResponse) -> T + Sync,
) {
    let p = Preset::embedded()[0].params();
    let p = ImpactParams {
        v0: 3.0 * p.v0,
        ..p
    };
    let o = SolveOptions {
        rtol: 1e-9,
        ..SolveOptions::default()
    }
    .with_samples(samples);
    b.bench(|| read(simulate(black_box(&p), ContactLaw::ElasticPlastic, &o).unwrap()));
}

/// One elastic–fully-plastic impact at rtol 1e-9 (target: ≤ 50 µs).
#[divan::bench]
fn elastic_plastic_impact(b: divan::Bencher) {
    elastic_plastic_bench(b, 0, |r| r.cor);
}

/// The same impact with a 400-sample history (what the explorer asks for).
#[divan::bench]
fn elastic_plastic_with_history(b: divan::Bencher) {
    elastic_plastic_bench(b, 400, |r| r.history.t.len());
}

/// The issue 30 points: the superball's adopted set at 1×, 3× its measured speed (elastic–
/// plastic: past yield), and a stiff-ish (λ, ζ) = (1, 2) normalized ball.
fn fast_law_cases() -> [(ContactLaw, ImpactParams); 4] {
    let p = Preset::embedded()[0].params();
    let fast = ImpactParams {
        v0: 3.0 * p.v0,
        ..p
    };
    [
        (ContactLaw::Hertz, p),
        (ContactLaw::ElasticPlastic, fast),
        (
            ContactLaw::Hertz,
            ImpactParams::from_normalized(1.0, 2.0, f64::INFINITY),
        ),
        (
            ContactLaw::Linear,
            ImpactParams::from_normalized(1.3, 0.16, 0.3),
        ),
    ]
}

/// The cases, built once (parsing the embedded presets costs some 37 µs: not what is timed).
static CASES: std::sync::LazyLock<[(ContactLaw, ImpactParams); 4]> =
    std::sync::LazyLock::new(fast_law_cases);

/// One impact's summary by the Taylor steps (`solver::taylor::summary`, issue 30 items 1 and
/// 2: target ≤ 1 µs for Hertz and elastic–plastic, ≤ 0.5 µs for the flattening linear ball).
#[divan::bench(args = [0, 1, 2, 3])]
fn taylor_summary(case: usize) -> f64 {
    let (law, p) = CASES[case];
    let n = black_box(p).normalized();
    bouncelab::solver::taylor::summary(&n, law).unwrap().cor
}

/// The same impacts through `simulate` (the adaptive solver for Hertz and elastic–plastic at
/// rtol 1e-10, the exact one for the linear law), in the same run.
#[divan::bench(args = [0, 1, 2, 3])]
fn solver_summary(case: usize) -> f64 {
    let (law, p) = CASES[case];
    simulate(black_box(&p), law, &SolveOptions::default())
        .unwrap()
        .cor
}

/// The linear law's closed form (`map::fast::summary`) at the superball's (λ, ζ), the fast
/// path the others are measured against.
#[divan::bench]
fn linear_fast_summary() -> f64 {
    let n = black_box(CASES[0].1).normalized();
    bouncelab::map::fast::summary(n.lambda, n.zeta).unwrap().cor
}

/// A flattening cell in closed form (`map::fast::flattening`, issue 30 item 2: target
/// ≤ 0.5 µs), case 3's ball (λ = 1.3, ζ = 0.16, z̄_p = 0.3): against `taylor_summary` 3 and
/// `linear_fast_summary` in the same run.
#[divan::bench]
fn flattening_summary() -> f64 {
    let n = black_box(CASES[3].1).normalized();
    bouncelab::map::fast::flattening(n.lambda, n.zeta, n.zp_bar)
        .unwrap()
        .cor
}

/// The Hertz cases (0: the superball's adopted set, 2: the normalized (λ, ζ) = (1, 2) ball)
/// through the Hertz table (`solver::table::hertz`, issue 30 item 1: target ≤ 1 µs), in the
/// same run as `taylor_summary` and `linear_fast_summary`. The table is read before timing.
#[divan::bench(args = [0, 2])]
fn table_hertz_summary(b: divan::Bencher, case: usize) {
    let (_, p) = CASES[case];
    let n = p.normalized();
    assert!(bouncelab::solver::table::hertz(&n).is_some(), "case {case}");
    b.bench(|| {
        bouncelab::solver::table::hertz(&black_box(p).normalized())
            .unwrap()
            .cor
    });
}

/// The elastic–plastic balls of `CASES` 0 and 1: the superball at its measured speed (its
/// Hertz impact turns below yield: the Hertz table answers, `taylor::plastic`) and at 3× it
/// (past yield: the Taylor steps).
fn elastic_plastic_ball(case: usize) -> ImpactParams {
    CASES[case].1
}

/// An elastic–plastic summary through `solver::table::summary`, as the map's cells take it
/// (issue 30 item 1: target ≤ 1 µs), against `elastic_plastic_taylor` (the path before) in the
/// same run. The table is read before timing.
#[divan::bench(args = [0, 1])]
fn elastic_plastic_summary(b: divan::Bencher, case: usize) {
    let p = elastic_plastic_ball(case);
    let law = ContactLaw::ElasticPlastic;
    assert!(bouncelab::solver::table::summary(&p.normalized(), law).is_some());
    b.bench(|| {
        bouncelab::solver::table::summary(&black_box(p).normalized(), law)
            .unwrap()
            .cor
    });
}

/// The same balls on the Taylor steps alone (`solver::taylor::summary`: every elastic–plastic
/// cell before `taylor::plastic`).
#[divan::bench(args = [0, 1])]
fn elastic_plastic_taylor(case: usize) -> f64 {
    let p = elastic_plastic_ball(case);
    let n = black_box(p).normalized();
    bouncelab::solver::taylor::summary(&n, ContactLaw::ElasticPlastic)
        .unwrap()
        .cor
}

/// 256 elastic–plastic impacts past yield: case 1's ball (the superball at 3 v0) with K_p, c
/// and K_r each moved by up to ±5 % (a Monte Carlo's spread, in a fixed pattern).
static PAST_YIELD: std::sync::LazyLock<Vec<bouncelab::Normalized>> =
    std::sync::LazyLock::new(|| {
        let p = elastic_plastic_ball(1);
        let spread = |i: usize, m: usize| 1.0 + 0.05 * (2.0 * ((i * m) % 97) as f64 / 96.0 - 1.0);
        (0..256)
            .map(|i| {
                ImpactParams {
                    k_p: p.k_p * spread(i, 31),
                    damping: p.damping * spread(i, 59),
                    k_r: p.k_r * spread(i, 83),
                    ..p
                }
                .normalized()
            })
            .collect()
    });

/// The 256 impacts of `PAST_YIELD` (issue 30 item 1: ≤ 1 µs an impact), one by one on the
/// Taylor steps (`single`, `solver::taylor::summary`) and several to a SIMD register
/// (`batch`, `solver::taylor::batch::summaries`: the same bits): divide by 256.
#[divan::bench(args = ["single", "batch"])]
fn elastic_plastic_past_yield_256(b: divan::Bencher, path: &str) {
    let law = ContactLaw::ElasticPlastic;
    let ns = &*PAST_YIELD;
    assert!(ns.iter().all(|n| {
        bouncelab::solver::taylor::summary(n, law).is_some_and(|s| s.permanent_indentation > 0.0)
    }));
    b.bench(|| match path {
        "single" => black_box(ns)
            .iter()
            .map(|n| bouncelab::solver::taylor::summary(n, law).unwrap().cor)
            .sum::<f64>(),
        _ => bouncelab::solver::taylor::batch::summaries(black_box(ns), law)
            .iter()
            .map(|s| s.unwrap().cor)
            .sum::<f64>(),
    });
}

/// 1 000 tennis balls at 2 … 60 m/s (56 of 59 such speeds flatten: tests/physics/rows.rs), the rows
/// `bouncelab.impacts` returns.
static TENNIS_ROWS: std::sync::LazyLock<Vec<ImpactParams>> = std::sync::LazyLock::new(|| {
    let ball = bouncelab::Ball::from_preset("tennis").unwrap().params;
    (0..1000)
        .map(|i| ImpactParams {
            v0: 2.0 + 58.0 * f64::from(i) / 999.0,
            ..ball
        })
        .collect()
});

/// The tennis rows through `api::impact_rows` (issue 30 items 2 and 5: a flattening row from
/// `map::fast::flattening`); run with `RAYON_NUM_THREADS=1` for one core's cost.
#[divan::bench]
fn impact_rows_tennis() -> usize {
    let balls = black_box(&*TENNIS_ROWS);
    bouncelab::api::impact_rows(balls.len(), ContactLaw::Linear, |i| balls[i])
        .unwrap()
        .len()
}

/// The same rows through `simulate`, one by one: the path a flattening row took before, in
/// the same run.
#[divan::bench]
fn simulate_rows_tennis() -> f64 {
    let o = SolveOptions::default();
    black_box(&*TENNIS_ROWS)
        .iter()
        .map(|p| simulate(p, ContactLaw::Linear, &o).unwrap().cor)
        .sum()
}

/// 1 024 flattening cells of the tennis ball's map (normalized (λ, ζ, z̄_p) over λ, ζ =
/// 1e-3 … 1e3 where the ball flattens and the scalar closed form answers), columns λ, ζ, z̄_p.
static TENNIS_FLAT_CELLS: std::sync::LazyLock<[Vec<f64>; 3]> = std::sync::LazyLock::new(|| {
    let ball = bouncelab::Ball::from_preset("tennis").unwrap().params;
    let mut cols = [Vec::new(), Vec::new(), Vec::new()];
    'grid: for i in 0..64 {
        for j in 0..64 {
            let (l, z) = (
                10f64.powf(-3.0 + 6.0 * f64::from(i) / 63.0),
                10f64.powf(-3.0 + 6.0 * f64::from(j) / 63.0),
            );
            let n = ball.with_lambda_zeta(l, z).normalized();
            if bouncelab::map::fast::flattening(n.lambda, n.zeta, n.zp_bar).is_none() {
                continue;
            }
            for (c, x) in cols.iter_mut().zip([n.lambda, n.zeta, n.zp_bar]) {
                c.push(x);
            }
            if cols[0].len() == 1024 {
                break 'grid;
            }
        }
    }
    cols
});

/// The 1 024 tennis flattening cells one by one through the scalar `map::fast::flattening`
/// (issue 30 item 2: ≤ 0.5 µs a cell), the baseline of `flattening_cells_lanes` in the same
/// run: divide by 1 024 for a cell.
#[divan::bench]
fn flattening_cells_scalar() -> f64 {
    let [l, z, zp] = black_box(&*TENNIS_FLAT_CELLS);
    (0..l.len())
        .filter_map(|i| bouncelab::map::fast::flattening(l[i], z[i], zp[i]))
        .map(|s| s.cor)
        .sum()
}

/// The same cells eight at a time through the lanes (`map::fast::lanes::flattenings`, the
/// map's path), on one core.
#[divan::bench]
fn flattening_cells_lanes() -> f64 {
    let [l, z, zp] = black_box(&*TENNIS_FLAT_CELLS);
    let mut out = vec![None; l.len()];
    bouncelab::map::fast::lanes::flattenings(l, z, zp, &mut out);
    out.iter().flatten().map(|s| s.cor).sum()
}

/// `flattening_summary`'s cell alone on one lane (`map::fast::lanes::flattening_one`: the
/// lanes' code on a lane of width one, issue 30 item 2, ≤ 0.5 µs), what `run`, a lone map
/// cell and a row take: against `flattening_summary` (the scalar closed form) in the same run.
#[divan::bench]
fn flattening_one_summary() -> f64 {
    let n = black_box(CASES[3].1).normalized();
    bouncelab::map::fast::lanes::flattening_one(n.lambda, n.zeta, n.zp_bar)
        .unwrap()
        .cor
}

/// The 1 024 tennis flattening cells one by one through `flattening_one` (a lane of width
/// one each), beside `flattening_cells_scalar` and `flattening_cells_lanes`.
#[divan::bench]
fn flattening_cells_one() -> f64 {
    let [l, z, zp] = black_box(&*TENNIS_FLAT_CELLS);
    (0..l.len())
        .filter_map(|i| bouncelab::map::fast::lanes::flattening_one(l[i], z[i], zp[i]))
        .map(|s| s.cor)
        .sum()
}
