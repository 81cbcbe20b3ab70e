//! Speed of the Monte Carlo (issue 32: 1e7 linear-law samples ≤ 5 s on one core; medians in
//! BENCHMARKS.md). Run: `cargo bench --bench mc`. The golf ball with K_p, c and K_r spread by
//! 5 % (normal), as docs/scale.md's first example.

use bouncelab::Ball;
use bouncelab::analysis::mc::{Dist, McSpec, Sampler, impact, parse_vary};
use divan::black_box;

fn main() {
    divan::main();
}

fn sampler(correlate: bool) -> Sampler {
    let golf = Ball::from_preset("golf").unwrap();
    let mut spec = McSpec::new(
        parse_vary("k_p=5%,c=5%,k_r=5%").unwrap(),
        Dist::Normal,
        10_000_000,
        1,
    )
    .unwrap();
    if correlate {
        let pairs = bouncelab::analysis::mc::parse_correlate("k_p:c=0.5").unwrap();
        spec = spec.with_correlation(pairs).unwrap();
    }
    golf.sampler(&spec)
}

/// One sample: its draws (ChaCha8 on the sample's stream, three normals), its ball checked,
/// and its impact.
#[divan::bench]
fn one_sample(b: divan::Bencher) {
    let s = sampler(false);
    sample_by_sample(b, |i| s.outcome(i).unwrap().cor);
}

/// `of` samples 1, 2, 3, …, one a call.
fn sample_by_sample<T>(b: divan::Bencher, mut of: impl FnMut(u64) -> T) {
    let mut i = 0u64;
    b.bench_local(|| {
        i += 1;
        of(black_box(i))
    });
}

/// The draws and the checked ball alone (no impact).
#[divan::bench]
fn draws_only(b: divan::Bencher) {
    let s = sampler(false);
    sample_by_sample(b, |i| s.params(i).unwrap().k_p);
}

/// The impact alone, at the nominal golf ball (the closed form of `map::fast`).
#[divan::bench]
fn impact_only(b: divan::Bencher) {
    let golf = Ball::from_preset("golf").unwrap();
    b.bench_local(|| impact(black_box(&golf.params), golf.law).unwrap().cor);
}

/// One sample with a correlation (the Cholesky product added).
#[divan::bench]
fn one_sample_correlated(b: divan::Bencher) {
    let s = sampler(true);
    sample_by_sample(b, |i| s.outcome(i).unwrap().cor);
}

/// 100,000 samples on one thread, through `Sampler::samples` (blocks, ordering, the columns):
/// per sample, the median / 1e5; 1e7 samples take 100 × the median.
#[divan::bench(sample_count = 10)]
fn block_1e5_one_thread(b: divan::Bencher) {
    let s = sampler(false);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    b.bench_local(|| pool.install(|| s.samples(0, 100_000).unwrap().len()));
}

/// The (λ, ζ) of the golf samples 0 … 10⁵.
fn golf_points() -> (Vec<f64>, Vec<f64>) {
    let s = sampler(false);
    (0..100_000u64)
        .map(|i| {
            let n = s.params(i).unwrap().normalized();
            (n.lambda, n.zeta)
        })
        .unzip()
}

/// The closed form alone over the 10⁵ golf samples, one at a time (`map::fast::summary`, the
/// scalar path): the baseline of `closed_form_1e5_lanes` in the same run. Per sample: the
/// median / 1e5.
#[divan::bench(sample_count = 20)]
fn closed_form_1e5_scalar(b: divan::Bencher) {
    let (l, z) = golf_points();
    b.bench_local(|| {
        l.iter()
            .zip(&z)
            .map(|(&l, &z)| bouncelab::map::fast::summary(black_box(l), z).map_or(0.0, |s| s.cor))
            .sum::<f64>()
    });
}

/// The same four at a time through the lanes (`map::fast::lanes::summaries`, what `mc` runs).
#[divan::bench(sample_count = 20)]
fn closed_form_1e5_lanes(b: divan::Bencher) {
    let (l, z) = golf_points();
    let mut out = vec![None; l.len()];
    b.bench_local(|| {
        bouncelab::map::fast::lanes::summaries(black_box(&l), &z, &mut out);
        out.iter().map(|s| s.map_or(0.0, |s| s.cor)).sum::<f64>()
    });
}
