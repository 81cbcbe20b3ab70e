//! How far a Monte Carlo's numbers may be from the run's infinite-sample values: 95 %
//! intervals of the mean and of each quantile (docs/scale.md, "How many samples").
//!
//! **The mean**: x̄ ± t₀.₉₇₅(n − 1) s/√n (the central limit theorem; s the sample sd).
//!
//! **A quantile** ξ_p, distribution-free (Conover, *Practical Nonparametric Statistics*, 3rd ed.,
//! §3.2; Hahn & Meeker, *Statistical Intervals*, §5.2): of n samples, the number B below ξ_p is
//! Binomial(n, p), so the order statistics X₍ₗ₎ ≤ X₍ᵤ₎ (1-based) enclose ξ_p with probability
//! P(l ≤ B ≤ u − 1). Taking the largest l with P(B ≤ l − 1) ≤ α/2 and the smallest u with
//! P(B ≥ u) ≤ α/2 leaves at most α/2 out on each side: the coverage is at least 1 − α whatever
//! the distribution (continuous), and close to it once n p (1 − p) is large. Where no such l
//! or u exists — too few samples for the tail, fewer than 368 for the 1 % quantile — the interval is
//! absent (NaN; `null` in JSON), and the report says so.
//!
//! Held by `mc_interval_tests` (tests/analysis/mc_intervals.rs): over 2 000 seeded runs of known
//! distributions each interval covers its true value 95 % of the time, within the binomial
//! scatter.

use statrs::distribution::{Binomial, ContinuousCDF, DiscreteCDF, StudentsT};

/// The probability left out of each interval: 95 % intervals.
pub const ALPHA: f64 = 0.05;

/// The mean's standard error s/√n, and its 95 % interval x̄ ± t₀.₉₇₅(n − 1) s/√n; NaN below
/// two samples.
pub fn mean_interval(n: usize, mean: f64, sd: f64) -> (f64, [f64; 2]) {
    if n < 2 {
        return (f64::NAN, [f64::NAN; 2]);
    }
    let se = sd / (n as f64).sqrt();
    (se, [mean - t975(n - 1) * se, mean + t975(n - 1) * se])
}

/// Degrees of freedom from which t₀.₉₇₅ is the Cornish–Fisher series in 1/ν
/// (`fit::stats::t975`, Abramowitz & Stegun 26.7.5, four terms: its error O(ν⁻⁵) is below
/// 1e-19 here) rather than statrs' `inverse_cdf`, whose search does not end from about
/// ν = 1.5·10⁷ and drifts before that: 6.5e-7
/// above the series at ν = 3·10⁴, 7e-6 at 10⁵ (the series matches the tables, 1.962339081 at
/// ν = 1000, to 1e-12). `the_means_interval_answers_at_any_n`.
pub const SERIES_DOF: usize = 10_000;

/// t₀.₉₇₅(ν): statrs' below [`SERIES_DOF`], the series from it (the two agree to 2e-13 there).
fn t975(dof: usize) -> f64 {
    if dof >= SERIES_DOF {
        return super::fit::stats::t975(dof);
    }
    StudentsT::new(0.0, 1.0, dof as f64)
        .map(|d| d.inverse_cdf(1.0 - ALPHA / 2.0))
        .unwrap_or(f64::NAN)
}

/// The 0-based ranks (lo, hi) of the order statistics whose span is the 95 % interval of the
/// p-quantile (0 < p < 1) of `n` samples, each side missing ξ_p with probability ≤ α/2;
/// `None` on a side where even the extreme sample does not reach that confidence.
pub fn quantile_ranks(n: usize, p: f64) -> (Option<usize>, Option<usize>) {
    let Ok(b) = Binomial::new(p, n as u64) else {
        return (None, None);
    };
    let half = ALPHA / 2.0;
    // lower: the largest l ≥ 1 with P(B ≤ l − 1) ≤ α/2 — cdf rises with l, so the l that
    // pass are 1 … l*; rank l − 1
    let lo = last_true(1, n as u64, |l| b.cdf(l - 1) <= half).map(|l| (l - 1) as usize);
    // upper: the smallest u ≤ n with P(B ≥ u) = P(B > u − 1) ≤ α/2 — sf falls as u rises,
    // so the u that pass are u* … n; rank u − 1
    let hi = first_true(1, n as u64, |u| b.sf(u - 1) <= half).map(|u| (u - 1) as usize);
    (lo, hi)
}

/// The fewest samples for which the p-quantile's 95 % interval has both ends: the extreme
/// order statistic must miss ξ_p with probability ≤ α/2, (1 − p′)ⁿ ≤ α/2 with
/// p′ = min(p, 1 − p) — 368 for the 1 % and 99 % quantiles, 146 for 2.5 % and 97.5 %.
pub fn fewest_samples(p: f64) -> usize {
    ((ALPHA / 2.0).ln() / (1.0 - p.min(1.0 - p)).ln()).ceil() as usize
}

/// The largest k in [a, b] where `pred` holds, `pred` true up to some point and false after;
/// `None` where it holds nowhere. (A bisection on integers: statrs' `inverse_cdf` answers
/// the cdf's inequality the other way round, ≥ rather than ≤, and this states it directly.)
fn last_true(a: u64, b: u64, pred: impl Fn(u64) -> bool) -> Option<u64> {
    if a > b || !pred(a) {
        return None;
    }
    let (mut yes, mut no) = (a, b + 1);
    while no - yes > 1 {
        let mid = yes + (no - yes) / 2;
        if pred(mid) {
            yes = mid;
        } else {
            no = mid;
        }
    }
    Some(yes)
}

/// The smallest k in [a, b] where `pred` holds, `pred` false up to some point and true after;
/// `None` where it holds nowhere.
fn first_true(a: u64, b: u64, pred: impl Fn(u64) -> bool) -> Option<u64> {
    if a > b || !pred(b) {
        return None;
    }
    let (mut no, mut yes) = (a as i128 - 1, b as i128);
    while yes - no > 1 {
        let mid = no + (yes - no) / 2;
        if pred(mid as u64) {
            yes = mid;
        } else {
            no = mid;
        }
    }
    Some(yes as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ranks by brute force: every l and u tried, the binomial's tails summed term by term.
    #[test]
    fn ranks_are_the_binomial_tails_by_brute_force() {
        for &(n, p) in &[
            (20usize, 0.5f64),
            (100, 0.25),
            (400, 0.01),
            (1000, 0.975),
            (367, 0.01),
        ] {
            let pmf = |k: usize| {
                let ln = (1..=n).map(|i| (i as f64).ln()).sum::<f64>()
                    - (1..=k).map(|i| (i as f64).ln()).sum::<f64>()
                    - (1..=n - k).map(|i| (i as f64).ln()).sum::<f64>();
                (ln + k as f64 * p.ln() + (n - k) as f64 * (1.0 - p).ln()).exp()
            };
            let cdf = |k: usize| (0..=k).map(pmf).sum::<f64>();
            let lo = (1..=n)
                .rev()
                .find(|&l| cdf(l - 1) <= ALPHA / 2.0)
                .map(|l| l - 1);
            let hi = (1..=n)
                .find(|&u| 1.0 - cdf(u - 1) <= ALPHA / 2.0)
                .map(|u| u - 1);
            assert_eq!(quantile_ranks(n, p), (lo, hi), "n {n}, p {p}");
        }
    }

    /// The smallest n with a lower bound for the 1 % quantile: (0.99)^n ≤ 0.025, n ≥ 368 (0.99^367 = 0.02501).
    #[test]
    fn the_one_percent_quantile_needs_368_samples() {
        assert_eq!(quantile_ranks(367, 0.01).0, None);
        assert_eq!(quantile_ranks(368, 0.01).0, Some(0));
        assert!(quantile_ranks(367, 0.01).1.is_some());
        assert_eq!(quantile_ranks(367, 0.99).1, None);
        assert_eq!(quantile_ranks(368, 0.99).1, Some(367));
    }

    /// `fewest_samples` is where `quantile_ranks` first gives both ends, at every probability
    /// the Monte Carlo reports.
    #[test]
    fn fewest_samples_is_where_both_ends_appear() {
        for p in [0.01, 0.025, 0.05, 0.25, 0.5, 0.75, 0.95, 0.975, 0.99] {
            let n = fewest_samples(p);
            let both = |n| matches!(quantile_ranks(n, p), (Some(_), Some(_)));
            assert!(both(n) && !both(n - 1), "p {p}: {n}");
        }
        assert_eq!((fewest_samples(0.01), fewest_samples(0.975)), (368, 146));
    }

    /// The mean's interval: t₀.₉₇₅(9) = 2.262157 (tables), s/√n.
    #[test]
    fn the_means_interval_is_students() {
        let (se, [lo, hi]) = mean_interval(10, 1.0, 2.0);
        assert!((se - 2.0 / 10f64.sqrt()).abs() < 1e-15);
        assert!((hi - 1.0 - 2.262157 * se).abs() < 1e-6 * se);
        assert!((1.0 - lo - 2.262157 * se).abs() < 1e-6 * se);
        assert!(mean_interval(1, 1.0, 0.0).0.is_nan());
    }

    /// statrs' t quantile does not return from about 1.5·10⁷ samples up; from `SERIES_DOF`
    /// the series answers, continuous with statrs at the switch, falling toward z₀.₉₇₅ = 1.959964.
    #[test]
    fn the_means_interval_answers_at_any_n() {
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let t = |n: usize| {
                let (se, [_, hi]) = mean_interval(n, 0.0, 1.0);
                hi / se
            };
            let ns = [
                2 * 10usize.pow(7),
                10usize.pow(8),
                10usize.pow(12),
                usize::MAX,
            ];
            let _ = tx.send(ns.map(t));
        });
        let ts = rx
            .recv_timeout(std::time::Duration::from_secs(20))
            .expect("answers within 20 s");
        let z = 1.959_963_984_540_054;
        let mut last = f64::INFINITY;
        for t in ts {
            assert!(t >= z && t <= last && t - z < 1e-6, "{t}");
            last = t;
        }
        // continuous at the switch: statrs just below, the series from it
        let below = t975(SERIES_DOF - 1);
        let from = t975(SERIES_DOF);
        let statrs_there = StudentsT::new(0.0, 1.0, SERIES_DOF as f64)
            .unwrap()
            .inverse_cdf(1.0 - ALPHA / 2.0);
        assert!(
            (from - statrs_there).abs() < 1e-12,
            "{from} vs {statrs_there}"
        );
        // at 10⁵ the series is its first order z + (z³ + z)/(4ν) to its second (3e-10);
        // (statrs' answer there is 7e-6 off it)
        let first = z + (z * z * z + z) / 4e5;
        assert!((t975(100_000) - first).abs() < 1e-9, "{}", t975(100_000));
        // one degree of freedom apart: dt/dν = −(z³ + z)/(4ν²) = −2.4e-8 at 10⁴
        let step = (z * z * z + z) / (4.0 * 1e8);
        assert!(((below - from) - step).abs() < 1e-11, "{below} {from}");
    }
}
