//! Summary statistics of a Monte Carlo's samples (docs/scale.md): mean, standard deviation,
//! extremes and the quantiles of [`PROBS`], each a function of the values in sample order only,
//! so that any split of the same samples (threads, chunks, Dask tasks) gives the same numbers.
//!
//! Quantiles are of type 7 (Hyndman & Fan; numpy's default `linear`): with the values sorted,
//! x₀ ≤ … ≤ x_{n−1}, h = (n − 1) p, q(p) = x_⌊h⌋ + (h − ⌊h⌋)(x_⌈h⌉ − x_⌊h⌋). The order
//! statistics are found without a sort and without a copy of the values (`mc_order`):
//! one pass counts the values in equal bins between the extremes, a second gathers the few
//! bins that hold a rank asked for, and selection (`select_nth_unstable`) within them names
//! each rank's value — the value a full sort puts there (`binned_ranks_are_a_full_sorts`).

use super::mc_interval::{fewest_samples, mean_interval, quantile_ranks};
use super::mc_order::{Bins, unbinned};
#[cfg(test)]
use super::mc_order::{order_statistics, quantiles};
use serde::Serialize;

/// The probabilities of the quantiles reported, in percent.
pub const PROBS: [f64; 9] = [1.0, 2.5, 5.0, 25.0, 50.0, 75.0, 95.0, 97.5, 99.0];

/// The quantiles of [`PROBS`], named as the JSON writes them (`"2.5"`, `"97.5"`, …): their
/// values (`Quantiles`), or their intervals (`Quantiles<[f64; 2]>`, [`Stats::q_ci`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
#[allow(missing_docs)] // each field is the quantile its name says
pub struct Quantiles<T = f64> {
    #[serde(rename = "1")]
    pub q1: T,
    #[serde(rename = "2.5")]
    pub q2_5: T,
    #[serde(rename = "5")]
    pub q5: T,
    #[serde(rename = "25")]
    pub q25: T,
    #[serde(rename = "50")]
    pub q50: T,
    #[serde(rename = "75")]
    pub q75: T,
    #[serde(rename = "95")]
    pub q95: T,
    #[serde(rename = "97.5")]
    pub q97_5: T,
    #[serde(rename = "99")]
    pub q99: T,
}

impl<T: Copy> Quantiles<T> {
    /// The values in the order of [`PROBS`].
    pub fn values(&self) -> [T; 9] {
        [
            self.q1, self.q2_5, self.q5, self.q25, self.q50, self.q75, self.q95, self.q97_5,
            self.q99,
        ]
    }

    fn from_values(v: [T; 9]) -> Quantiles<T> {
        Quantiles {
            q1: v[0],
            q2_5: v[1],
            q5: v[2],
            q25: v[3],
            q50: v[4],
            q75: v[5],
            q95: v[6],
            q97_5: v[7],
            q99: v[8],
        }
    }
}

/// The statistics of one quantity over the samples where it is defined (a contact time only
/// where the ball rebounds); with no such sample every number is NaN (`null` in JSON).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct Stats {
    /// Samples the statistics are over.
    pub n: usize,
    /// Arithmetic mean (compensated sum, in sample order).
    pub mean: f64,
    /// Sample standard deviation (divisor n − 1; NaN for one sample: no spread to estimate).
    pub sd: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Quantiles of type 7 at [`PROBS`].
    pub q: Quantiles,
    /// The mean's standard error s/√n (NaN below two samples): how far the mean of these
    /// samples may be from the run's infinite-sample mean (`mc_interval`).
    #[serde(default = "nan")]
    pub mean_se: f64,
    /// The mean's 95 % interval, x̄ ± t₀.₉₇₅(n − 1) s/√n.
    #[serde(default = "nan_pair")]
    pub mean_ci: [f64; 2],
    /// Each quantile's 95 % interval, [lo, hi], distribution-free from the order statistics
    /// (`mc_interval`); NaN on a side the samples are too few for (below 368 for the 1 %
    /// quantile's lower end).
    #[serde(default = "nan_pairs")]
    pub q_ci: Quantiles<[f64; 2]>,
}

fn nan() -> f64 {
    f64::NAN
}

fn nan_pair() -> [f64; 2] {
    [f64::NAN; 2]
}

fn nan_pairs() -> Quantiles<[f64; 2]> {
    Quantiles::from_values([[f64::NAN; 2]; 9])
}

/// Neumaier's compensated sum, in the order given: the same values in the same order give the
/// same bits, and the error does not grow with n.
#[derive(Default)]
struct Sum {
    s: f64,
    c: f64,
}

impl Sum {
    fn add(&mut self, x: f64) {
        let t = self.s + x;
        self.c += if self.s.abs() >= x.abs() {
            (self.s - t) + x
        } else {
            (x - t) + self.s
        };
        self.s = t;
    }

    fn total(&self) -> f64 {
        self.s + self.c
    }
}

#[cfg(test)]
fn sum(values: impl Iterator<Item = f64>) -> f64 {
    let mut s = Sum::default();
    values.for_each(|x| s.add(x));
    s.total()
}

/// The statistics of the finite values of `values` (NaN marks a sample without the quantity),
/// in two passes over them and one or two over the bins (`mc_order`).
pub fn stats(values: &[f64]) -> Stats {
    let (mut n, mut total) = (0usize, Sum::default());
    let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
    for &x in values.iter().filter(|x| x.is_finite()) {
        n += 1;
        total.add(x);
        // (x finite: f64::min and max, as the instructions they compile to, without their NaN
        // checks; of −0 and +0 the first seen, as before)
        min = if x < min { x } else { min };
        max = if x > max { x } else { max };
    }
    if n == 0 {
        let nan = f64::NAN;
        return Stats {
            n,
            mean: nan,
            sd: nan,
            min: nan,
            max: nan,
            q: Quantiles::from_values([nan; 9]),
            mean_se: nan,
            mean_ci: nan_pair(),
            q_ci: nan_pairs(),
        };
    }
    let mean = total.total() / n as f64;
    // the squares' sum and the bins' counts in one more pass
    let mut squares = Sum::default();
    let mut bins = Bins::new(n, (min, max));
    for &x in values.iter().filter(|x| x.is_finite()) {
        squares.add((x - mean) * (x - mean));
        if let Some(b) = &mut bins {
            b.count(x);
        }
    }
    // one sample says nothing of the spread: its sd (over n − 1 = 0) is undefined, not 0 —
    // NaN, null in JSON, as the mean's interval is then (`mc_interval::mean_interval`)
    let sd = if n > 1 {
        (squares.total() / (n - 1) as f64).sqrt()
    } else {
        f64::NAN
    };
    let ranks = order_ranks(n);
    let x = match &bins {
        Some(b) => b.order_statistics(values, &ranks),
        None => unbinned(values, (min, max), &ranks),
    };
    stats_from_order(n, mean, sd, [min, max], &x)
}

/// (⌊h⌋, ⌈h⌉) of the type-7 quantile at h = (n − 1) p/100, clipped to the last rank.
fn type7_pair(n: usize, h: f64) -> [usize; 2] {
    let lo = h.floor() as usize;
    [lo, (lo + 1).min(n - 1)]
}

/// The 0-based ranks of the order statistics [`stats`] reads from `n` ≥ 1 finite values, in
/// increasing order without repeats: each quantile's two (type 7) and each quantile's 95 %
/// interval's ends (`mc_interval::quantile_ranks`). A merge that finds these order
/// statistics its own way (the Dask client's, docs/scale.md) gives them to
/// [`stats_from_order`] and has [`stats`]'s numbers.
pub fn order_ranks(n: usize) -> Vec<usize> {
    let mut ranks: Vec<usize> = PROBS
        .iter()
        .flat_map(|p| type7_pair(n, (n - 1) as f64 * p / 100.0))
        .collect();
    ranks.extend(PROBS.iter().flat_map(|p| {
        let (lo, hi) = quantile_ranks(n, p / 100.0);
        lo.into_iter().chain(hi)
    }));
    ranks.sort_unstable();
    ranks.dedup();
    ranks
}

/// The statistics of `n` ≥ 1 finite values from their `mean`, `sd`, extremes `[min, max]` and
/// their order statistics `x` at [`order_ranks`]`(n)` (in that order): [`stats`]'s quantiles
/// and intervals, the same arithmetic. Panics if `x` is not one value a rank.
pub fn stats_from_order(n: usize, mean: f64, sd: f64, extremes: [f64; 2], x: &[f64]) -> Stats {
    let ranks = order_ranks(n);
    assert_eq!(ranks.len(), x.len(), "one order statistic a rank");
    let hs = PROBS.map(|p| (n - 1) as f64 * p / 100.0);
    let value = |r: usize| x[ranks.binary_search(&r).expect("a rank asked for")];
    let q = hs.map(|h| {
        let [lo, hi] = type7_pair(n, h);
        let (x_lo, x_hi) = (value(lo), value(hi));
        x_lo + (h - lo as f64) * (x_hi - x_lo)
    });
    let side = |r: Option<usize>| r.map_or(f64::NAN, value);
    let q_ci = PROBS.map(|p| {
        let (lo, hi) = quantile_ranks(n, p / 100.0);
        [side(lo), side(hi)]
    });
    let (mean_se, mean_ci) = mean_interval(n, mean, sd);
    Stats {
        n,
        mean,
        sd,
        min: extremes[0],
        max: extremes[1],
        q: Quantiles::from_values(q),
        mean_se,
        mean_ci,
        q_ci: Quantiles::from_values(q_ci),
    }
}

/// What the reader of `stats` should know about its intervals: the quantiles whose 95 %
/// interval lacks an end (NaN: too few samples for that tail), and how many samples they
/// need; nothing when every interval is whole. Only quantities with samples count (a contact
/// time without rebounds has no statistics at all).
pub fn interval_warnings(stats: &[&Stats]) -> Vec<String> {
    let mut open = Vec::new();
    let mut need = 0;
    for (k, p) in PROBS.iter().enumerate() {
        let open_end = |s: &Stats| s.n > 0 && s.q_ci.values()[k].iter().any(|x| x.is_nan());
        if stats.iter().any(|s| open_end(s)) {
            open.push(format!("{p} %"));
            need = need.max(fewest_samples(p / 100.0));
        }
    }
    if open.is_empty() {
        return Vec::new();
    }
    let n = stats
        .iter()
        .map(|s| s.n)
        .filter(|&n| n > 0)
        .min()
        .unwrap_or(0);
    let few = if n == 1 {
        "1 sample is".to_string()
    } else {
        format!("{n} samples are")
    };
    vec![format!(
        "{few} too few for a 95 % interval of the {} quantiles (an open end; {need} needed)",
        open.join(", ")
    )]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On 0, 1, …, n−1 (any order) the type-7 quantile at p is (n−1)p exactly, the mean
    /// (n−1)/2 and the sd √(n(n+1)/12).
    #[test]
    fn closed_forms_on_an_even_grid() {
        let n = 1001usize;
        // a fixed permutation: i·7919 mod n (7919 is prime to 1001)
        let v: Vec<f64> = (0..n).map(|i| ((i * 7919) % n) as f64).collect();
        let s = stats(&v);
        assert_eq!(s.n, n);
        assert_eq!((s.min, s.max), (0.0, 1000.0));
        assert!((s.mean - 500.0).abs() < 1e-12);
        let sd = ((n * (n + 1)) as f64 / 12.0).sqrt();
        assert!((s.sd - sd).abs() < 1e-10, "{} vs {sd}", s.sd);
        for (q, p) in s.q.values().iter().zip(PROBS) {
            assert!((q - 10.0 * p).abs() < 1e-9, "{q} at {p} %");
        }
    }

    /// Interpolation between two order statistics: four values, p = 50 % lies halfway.
    #[test]
    fn interpolates_between_order_statistics() {
        let mut v = vec![4.0, 1.0, 3.0, 2.0];
        let [q25, q50, q99] = quantiles(&mut v.clone(), &[25.0, 50.0, 99.0]);
        assert_eq!(q50, 2.5);
        assert_eq!(q25, 1.75);
        assert!((q99 - 3.97).abs() < 1e-12);
        let [q0, q100] = quantiles(&mut v, &[0.0, 100.0]);
        assert_eq!((q0, q100), (1.0, 4.0));
    }

    /// The selected order statistics are those of a full sort, on values with ties.
    #[test]
    fn selection_matches_a_full_sort() {
        let v: Vec<f64> = (0..9973u64)
            .map(|i| ((i * 7919) % 1013) as f64 * 0.5)
            .collect();
        let mut sorted = v.clone();
        sorted.sort_by(f64::total_cmp);
        let got = quantiles(&mut v.clone(), &PROBS);
        for (q, p) in got.iter().zip(PROBS) {
            let h = (v.len() - 1) as f64 * p / 100.0;
            let lo = h.floor() as usize;
            let want = sorted[lo] + (h - lo as f64) * (sorted[lo + 1] - sorted[lo]);
            assert_eq!(*q, want, "{p} %");
        }
    }

    #[test]
    fn undefined_samples_are_left_out_and_none_left_is_nan() {
        let s = stats(&[f64::NAN, 2.0, f64::NAN, 4.0]);
        assert_eq!(
            (s.n, s.mean, s.min, s.max, s.q.q50),
            (2, 3.0, 2.0, 4.0, 3.0)
        );
        assert!((s.sd - 2f64.sqrt()).abs() < 1e-15);
        let none = stats(&[f64::NAN]);
        assert_eq!(none.n, 0);
        assert!(none.mean.is_nan() && none.q.q99.is_nan());
        // one sample: no spread to estimate (it read 0, "no spread", before)
        let one = stats(&[7.0]);
        assert_eq!((one.q.q1, one.q.q99), (7.0, 7.0));
        assert!(one.sd.is_nan());
    }

    /// The order statistics by bins are a full sort's, bit for bit, with ties, signed zeros,
    /// NaN and infinities left out, a heavy tail that crowds most values into one bin, and
    /// the statistics are those of the values kept (a copy, sorted).
    #[test]
    fn binned_ranks_are_a_full_sorts() {
        let lcg = |i: u64| {
            (i.wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407)
                >> 11) as f64
                / (1u64 << 53) as f64
        };
        let sets: Vec<Vec<f64>> = vec![
            (0..100_003u64)
                .map(|i| (lcg(i) * 50.0).floor() * 0.25 - 3.0)
                .collect(),
            (0..70_001u64).map(|i| 1.0 / (lcg(i) + 1e-9)).collect(),
            (0..5_000u64)
                .map(|i| match i % 7 {
                    0 => f64::NAN,
                    1 => -0.0,
                    2 => 0.0,
                    3 => f64::INFINITY,
                    _ => lcg(i) - 0.5,
                })
                .collect(),
            vec![2.5; 1000],
            vec![1.0, 1.0 + f64::EPSILON],
            vec![
                f64::MIN_POSITIVE,
                2.0 * f64::MIN_POSITIVE,
                3.0 * f64::MIN_POSITIVE,
            ],
            // a range too narrow to divide (subnormal), and one too wide (max − min = ∞)
            vec![1e-323, 0.0, 5e-324, 0.0],
            vec![f64::MAX, -f64::MAX, 0.0, 1.0],
        ];
        for v in sets {
            let mut kept: Vec<f64> = v.iter().copied().filter(|x| x.is_finite()).collect();
            kept.sort_by(f64::total_cmp);
            let s = stats(&v);
            assert_eq!(
                (s.n, s.min, s.max),
                (kept.len(), kept[0], kept[kept.len() - 1])
            );
            assert_eq!(s.mean, sum(kept.iter().copied()) / kept.len() as f64);
            let want = quantiles(&mut kept.clone(), &PROBS);
            for (q, w) in s.q.values().iter().zip(want) {
                assert_eq!(q.to_bits(), w.to_bits(), "{} values", v.len());
            }
            let ranks: Vec<usize> = (0..kept.len()).step_by(kept.len() / 97 + 1).collect();
            let got = order_statistics(&v, kept.len(), (kept[0], kept[kept.len() - 1]), &ranks);
            for (r, x) in ranks.iter().zip(got) {
                assert_eq!(x.to_bits(), kept[*r].to_bits(), "rank {r}");
            }
        }
    }

    /// The compensated sum keeps what a plain one loses: 1 + 1e-16 × 10⁴ − 1.
    #[test]
    fn the_sum_is_compensated() {
        let v = std::iter::once(1.0)
            .chain(std::iter::repeat_n(1e-16, 10_000))
            .chain(std::iter::once(-1.0));
        assert!((sum(v) - 1e-12).abs() < 1e-24);
    }
}
