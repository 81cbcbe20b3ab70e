//! Summary statistics of a Monte Carlo's samples (docs/scale.md): mean, standard deviation,
//! extremes and the quantiles of [`PROBS`], each a function of the values in sample order only,
//! so that any split of the same samples (threads, chunks, Dask tasks) gives the same numbers.
//!
//! Quantiles are of type 7 (Hyndman & Fan; numpy's default `linear`): with the values sorted,
//! x₀ ≤ … ≤ x_{n−1}, h = (n − 1) p, q(p) = x_⌊h⌋ + (h − ⌊h⌋)(x_⌈h⌉ − x_⌊h⌋). The order
//! statistics are found by selection (`select_nth_unstable`), not a full sort: O(n) each.

use serde::Serialize;

/// The probabilities of the quantiles reported, in percent.
pub const PROBS: [f64; 9] = [1.0, 2.5, 5.0, 25.0, 50.0, 75.0, 95.0, 97.5, 99.0];

/// The quantiles of [`PROBS`], named as the JSON writes them (`"2.5"`, `"97.5"`, …).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
#[allow(missing_docs)] // each field is the quantile its name says
pub struct Quantiles {
    #[serde(rename = "1")]
    pub q1: f64,
    #[serde(rename = "2.5")]
    pub q2_5: f64,
    #[serde(rename = "5")]
    pub q5: f64,
    #[serde(rename = "25")]
    pub q25: f64,
    #[serde(rename = "50")]
    pub q50: f64,
    #[serde(rename = "75")]
    pub q75: f64,
    #[serde(rename = "95")]
    pub q95: f64,
    #[serde(rename = "97.5")]
    pub q97_5: f64,
    #[serde(rename = "99")]
    pub q99: f64,
}

impl Quantiles {
    /// The values in the order of [`PROBS`].
    pub fn values(&self) -> [f64; 9] {
        [
            self.q1, self.q2_5, self.q5, self.q25, self.q50, self.q75, self.q95, self.q97_5,
            self.q99,
        ]
    }

    fn from_values(v: [f64; 9]) -> Quantiles {
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
    /// Sample standard deviation (divisor n − 1; 0 for one sample).
    pub sd: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Quantiles of type 7 at [`PROBS`].
    pub q: Quantiles,
}

/// Neumaier's compensated sum, in the order given: the same values in the same order give the
/// same bits, and the error does not grow with n.
fn sum(values: impl Iterator<Item = f64>) -> f64 {
    let (mut s, mut c) = (0.0f64, 0.0f64);
    for x in values {
        let t = s + x;
        c += if s.abs() >= x.abs() {
            (s - t) + x
        } else {
            (x - t) + s
        };
        s = t;
    }
    s + c
}

/// The statistics of the finite values of `values` (NaN marks a sample without the quantity).
pub fn stats(values: &[f64]) -> Stats {
    let mut kept: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    let n = kept.len();
    if n == 0 {
        let nan = f64::NAN;
        return Stats {
            n,
            mean: nan,
            sd: nan,
            min: nan,
            max: nan,
            q: Quantiles::from_values([nan; 9]),
        };
    }
    let mean = sum(kept.iter().copied()) / n as f64;
    let sd = if n > 1 {
        (sum(kept.iter().map(|x| (x - mean) * (x - mean))) / (n - 1) as f64).sqrt()
    } else {
        0.0
    };
    let min = kept.iter().copied().fold(f64::INFINITY, f64::min);
    let max = kept.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let q = Quantiles::from_values(quantiles(&mut kept, &PROBS));
    Stats {
        n,
        mean,
        sd,
        min,
        max,
        q,
    }
}

/// Type-7 quantiles at `percents` (ascending) of `values` (finite, not empty), which are
/// reordered. The order statistics needed are selected by divide and conquer: the middle
/// rank first, then the ranks below it in the part left of it and those above in the part
/// right of it, so the work is O(n log k) for k ranks, not O(n k).
pub fn quantiles<const K: usize>(values: &mut [f64], percents: &[f64; K]) -> [f64; K] {
    debug_assert!(
        percents.windows(2).all(|w| w[0] <= w[1]),
        "ascending percents"
    );
    let n = values.len();
    let hs: Vec<f64> = percents
        .iter()
        .map(|p| (n - 1) as f64 * p / 100.0)
        .collect();
    let mut ranks: Vec<usize> = hs
        .iter()
        .flat_map(|h| {
            let lo = h.floor() as usize;
            [lo, (lo + 1).min(n - 1)]
        })
        .collect();
    ranks.sort_unstable();
    ranks.dedup();
    select_ranks(values, &ranks, 0);
    let mut out = [0.0; K];
    for (k, h) in hs.iter().enumerate() {
        let lo = h.floor() as usize;
        let (x_lo, x_hi) = (values[lo], values[(lo + 1).min(n - 1)]);
        out[k] = x_lo + (h - lo as f64) * (x_hi - x_lo);
    }
    out
}

/// Put the order statistic of each rank in `ranks` (ascending, relative to `values`' start
/// plus `offset`) at its index.
fn select_ranks(values: &mut [f64], ranks: &[usize], offset: usize) {
    if ranks.is_empty() {
        return;
    }
    let mid = ranks.len() / 2;
    let r = ranks[mid] - offset;
    values.select_nth_unstable_by(r, f64::total_cmp);
    let (left, right) = values.split_at_mut(r);
    select_ranks(left, &ranks[..mid], offset);
    select_ranks(&mut right[1..], &ranks[mid + 1..], offset + r + 1);
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
        let one = stats(&[7.0]);
        assert_eq!((one.sd, one.q.q1, one.q.q99), (0.0, 7.0, 7.0));
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
