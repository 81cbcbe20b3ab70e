//! The Monte Carlo's 95 % intervals are honest (src/analysis/mc_interval.rs, docs/scale.md):
//! over many seeded runs of distributions whose quantiles and mean are known, each interval
//! holds its true value about 95 % of the time — not less (the binomial construction leaves at
//! most 2.5 % out on each side), and not much more (an interval as wide as the samples' range
//! would also "cover").

use crate::seeded;

use bouncelab::analysis::mc::{PROBS, Samples, Stats, summarize};
use seeded::Seeded;
use statrs::distribution::{ContinuousCDF, Normal};

/// Runs of 400 samples: above the 368 the 1 % quantile's lower end needs.
const N: usize = 400;
/// Runs per distribution; the coverage's binomial sd is √(0.95·0.05/2000) = 0.49 %.
const RUNS: u64 = 2000;

/// The statistics of `values` (as the COR column: `summarize` treats the three alike).
fn stats_of(values: Vec<f64>) -> Stats {
    let n = values.len();
    summarize(&Samples {
        start: 0,
        cor: values,
        max_force: vec![1.0; n],
        contact_time: vec![1.0; n],
    })
    .cor
}

/// The share of `RUNS` runs in which each interval held its true value: the nine quantiles',
/// then the mean's.
fn coverage(draw: impl Fn(&mut Seeded) -> f64, truth: impl Fn(f64) -> f64, mean: f64) -> [f64; 10] {
    let mut held = [0u32; 10];
    for seed in 0..RUNS {
        let mut rng = Seeded::new(90_000 + seed);
        let s = stats_of((0..N).map(|_| draw(&mut rng)).collect());
        for (k, (ci, p)) in s.q_ci.values().iter().zip(PROBS).enumerate() {
            let x = truth(p / 100.0);
            assert!(
                ci[0] <= s.q.values()[k] && s.q.values()[k] <= ci[1],
                "{p} %: {ci:?}"
            );
            held[k] += u32::from(ci[0] <= x && x <= ci[1]);
        }
        held[9] += u32::from(s.mean_ci[0] <= mean && mean <= s.mean_ci[1]);
    }
    held.map(|h| f64::from(h) / RUNS as f64)
}

/// 95 % less three binomial sds: a sound interval falls below it once in some 700 checks.
const LEAST: f64 = 0.935;

fn check(name: &str, cover: [f64; 10]) {
    for (k, c) in cover.iter().enumerate() {
        let what = PROBS
            .get(k)
            .map_or("the mean".to_string(), |p| format!("{p} %"));
        // the quantiles' discreteness can only raise the coverage (≤ 2.5 % out each side): at
        // n = 400 the 1 % quantile's is some 97–98 %; an interval spanning the samples' range
        // would cover 100 %
        assert!(*c >= LEAST && *c <= 0.985, "{name}, {what}: covered {c}");
    }
}

#[test]
fn intervals_cover_the_normals_quantiles_and_mean() {
    let normal = Normal::new(0.0, 1.0).unwrap();
    let cover = coverage(|r| r.normal(), |p| normal.inverse_cdf(p), 0.0);
    check("normal", cover);
}

/// A skewed distribution: the quantiles' intervals are distribution-free; the mean's leans
/// on the central limit theorem, which 400 exponential samples satisfy.
#[test]
fn intervals_cover_the_exponentials_quantiles_and_mean() {
    let cover = coverage(|r| -(1.0 - r.uniform()).ln(), |p| -(1.0 - p).ln(), 1.0);
    check("exponential", cover);
}

/// Below 368 samples the 1 % quantile has no lower end (0.99³⁶⁷ > 2.5 %), nor the 99 % an
/// upper one: NaN, `null` in JSON; the middle quantiles keep theirs.
#[test]
fn too_few_samples_leave_the_tails_open() {
    let mut rng = Seeded::new(7);
    let s = stats_of((0..200).map(|_| rng.normal()).collect());
    let ci = s.q_ci.values();
    assert!(ci[0][0].is_nan() && ci[0][1].is_finite(), "{:?}", ci[0]);
    assert!(ci[8][1].is_nan() && ci[8][0].is_finite(), "{:?}", ci[8]);
    assert!(ci[4].iter().all(|x| x.is_finite()));
    assert!((s.mean_se - s.sd / 200f64.sqrt()).abs() < 1e-15);
}
