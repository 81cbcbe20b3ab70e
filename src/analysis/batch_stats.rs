//! The summary of a batch against a standard's window (docs/batch.md): how many balls, the
//! mean, sample standard deviation and range of the measured value, how many fail, and the
//! process capability index
//!
//!   Cpk = min(USL − μ, μ − LSL) / (3 s)
//!
//! over the bounds the window has (one-sided windows, like a COR maximum, use the one bound).
//!
//! Both the mean and Cpk are estimates from the balls measured, and carry their 95 %
//! intervals: the mean's Student's t over s/√n, Cpk's Bissell's (1990) normal approximation
//!
//!   Ĉ ± z₀.₉₇₅ √(1/(9n) + Ĉ²/(2(n − 1)))
//!
//! (the lot's values normal; tests/analysis/batch_cpk_interval.rs measures its coverage).

use super::mc_interval::mean_interval;
use serde::Serialize;
use statrs::distribution::{ContinuousCDF, Normal};

/// The statistics of the balls' measured values (SI; `NaN`, written `null` in JSON, where
/// there are too few balls).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BatchStats {
    /// Balls judged (balls without a fit are not counted).
    pub n: usize,
    /// Mean of the measured value.
    pub mean: f64,
    /// Sample standard deviation (n − 1 in the denominator; NaN below two balls).
    pub sd: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Balls outside the window.
    pub failures: usize,
    /// Process capability index against the window (NaN below two balls, or with s = 0, or a
    /// window without bounds).
    pub cpk: f64,
    /// The mean's 95 % interval, x̄ ± t₀.₉₇₅(n − 1) s/√n (NaN below two balls), clipped to
    /// the range the measured value can take (a COR's [0, 1]; see [`stats_in`]).
    pub mean_ci: [f64; 2],
    /// Whether the Student interval left that range and `mean_ci` is its clipped part.
    pub mean_ci_clipped: bool,
    /// Cpk's 95 % interval (Bissell; NaN where Cpk is): how far the lot's capability may be
    /// from what these balls show.
    pub cpk_ci: [f64; 2],
}

/// Cpk's approximate 95 % interval from n values (Bissell 1990, the module's formula).
pub fn cpk_interval(cpk: f64, n: usize) -> [f64; 2] {
    if !cpk.is_finite() || n < 2 {
        return [f64::NAN; 2];
    }
    let z = Normal::standard().inverse_cdf(0.975);
    let nf = n as f64;
    let half = z * (1.0 / (9.0 * nf) + cpk * cpk / (2.0 * (nf - 1.0))).sqrt();
    [cpk - half, cpk + half]
}

/// The statistics of `values` (the measured value of each judged ball; NaN and infinite
/// values are not measurements and are left out) against `window` [lo, hi], for a value
/// without bounds of its own (see [`stats_in`]).
pub fn stats(values: &[f64], window: [Option<f64>; 2]) -> BatchStats {
    stats_in(values, window, [f64::NEG_INFINITY, f64::INFINITY])
}

/// As [`stats`], for a measured value that lies in `range` (a COR in [0, 1], a rebound
/// height in [0, ∞)): the mean's Student interval is clipped to `range`. Clipping keeps its
/// coverage exactly — the lot's true mean lies in `range`, so the clipped interval holds it
/// whenever the Student interval does — where a rescaled (e.g. logit) interval would need
/// every value inside the open range and change what the interval means.
pub fn stats_in(values: &[f64], window: [Option<f64>; 2], range: [f64; 2]) -> BatchStats {
    let v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    let n = v.len();
    let mean = if n == 0 {
        f64::NAN
    } else {
        v.iter().sum::<f64>() / n as f64
    };
    let sd = if n < 2 {
        f64::NAN
    } else {
        (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
    };
    let [lo, hi] = window;
    let outside = |x: &&f64| lo.is_some_and(|l| **x < l) || hi.is_some_and(|h| **x > h);
    let failures = v.iter().filter(outside).count();
    let room = [lo.map(|l| mean - l), hi.map(|h| h - mean)]
        .into_iter()
        .flatten()
        .fold(f64::INFINITY, f64::min);
    let cpk = if sd > 0.0 && room.is_finite() {
        room / (3.0 * sd)
    } else {
        f64::NAN
    };
    let student = mean_interval(n, mean, sd).1;
    // f64::max would turn a NaN end (too few balls) into the range's bound: clip numbers only
    let clip = |x: f64| {
        if x.is_nan() {
            x
        } else {
            x.clamp(range[0], range[1])
        }
    };
    let mean_ci = student.map(clip);
    let mean_ci_clipped = student[0] < range[0] || student[1] > range[1];
    let min = v.iter().copied().fold(f64::INFINITY, f64::min);
    let max = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    BatchStats {
        n,
        mean,
        sd,
        min: if n == 0 { f64::NAN } else { min },
        max: if n == 0 { f64::NAN } else { max },
        failures,
        cpk,
        mean_ci,
        mean_ci_clipped,
        cpk_ci: cpk_interval(cpk, n),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values 1, 2, 3: mean 2, s = 1; window [0.5, 4]: Cpk = min(1.5, 2)/3 = 0.5.
    #[test]
    fn cpk_by_hand() {
        let s = stats(&[1.0, 2.0, 3.0], [Some(0.5), Some(4.0)]);
        assert_eq!((s.n, s.failures), (3, 0));
        assert!((s.mean - 2.0).abs() < 1e-15 && (s.sd - 1.0).abs() < 1e-15);
        assert!((s.cpk - 0.5).abs() < 1e-15, "{s:?}");
        assert_eq!((s.min, s.max), (1.0, 3.0));
        // a maximum only (a COR class): (USL − μ)/3s = (2.5 − 2)/3
        let s = stats(&[1.0, 2.0, 3.0], [None, Some(2.5)]);
        assert!(
            (s.cpk - 0.5 / 3.0).abs() < 1e-15 && s.failures == 1,
            "{s:?}"
        );
        // the mean outside the window: Cpk negative
        let s = stats(&[5.0, 6.0, 7.0], [Some(0.5), Some(4.0)]);
        assert!(s.cpk < 0.0 && s.failures == 3, "{s:?}");
    }

    /// Bissell's half-width by hand: Ĉ = 1, n = 50: 1.959964 √(1/450 + 1/98) = 0.21846.
    #[test]
    fn cpk_interval_by_hand() {
        let [lo, hi] = cpk_interval(1.0, 50);
        let half = 1.959964 * (1.0 / 450.0 + 1.0 / 98.0f64).sqrt();
        assert!((hi - 1.0 - half).abs() < 1e-6 && (1.0 - lo - half).abs() < 1e-6);
        assert!(cpk_interval(f64::NAN, 50)[0].is_nan() && cpk_interval(1.0, 1)[1].is_nan());
    }

    /// Two CORs 0.576 and 0.683: x̄ = 0.6295, s = 0.075660, t₀.₉₇₅(1) = 12.7062, so Student
    /// gives 0.6295 ± 0.67980 = −0.0503 … 1.3093; a COR's mean lies in [0, 1], so 0 … 1.
    #[test]
    fn a_cor_mean_interval_stays_in_zero_one() {
        let open = stats(&[0.576, 0.683], [None, Some(0.7)]);
        assert!(open.mean_ci[0] < 0.0 && open.mean_ci[1] > 1.0 && !open.mean_ci_clipped);
        assert!((open.mean_ci[0] + 0.0503).abs() < 1e-4, "{open:?}");
        let cor = stats_in(&[0.576, 0.683], [None, Some(0.7)], [0.0, 1.0]);
        assert_eq!(cor.mean_ci, [0.0, 1.0]);
        assert!(cor.mean_ci_clipped);
        // an interval inside the range is left as it is
        let v = [0.70, 0.71, 0.72, 0.70, 0.71];
        let inside = stats_in(&v, [None, Some(0.8)], [0.0, 1.0]);
        assert_eq!(inside.mean_ci, stats(&v, [None, Some(0.8)]).mean_ci);
        assert!(!inside.mean_ci_clipped);
        // one side only: a height's interval cut at 0, its upper end kept
        let h = stats_in(&[0.05, 0.6], [Some(0.2), None], [0.0, f64::INFINITY]);
        assert!(
            h.mean_ci[0] == 0.0 && h.mean_ci[1] > 3.0 && h.mean_ci_clipped,
            "{h:?}"
        );
    }

    #[test]
    fn too_few_balls_give_no_spread() {
        let s = stats_in(&[1.2], [Some(1.0), Some(2.0)], [0.0, 2.0]);
        assert!(s.sd.is_nan() && s.cpk.is_nan() && s.n == 1 && s.mean_ci[0].is_nan());
        let s = stats(&[], [Some(1.0), Some(2.0)]);
        assert!(s.mean.is_nan() && s.min.is_nan() && s.n == 0);
        let s = stats(&[1.5, 1.5], [Some(1.0), Some(2.0)]);
        assert!(s.sd == 0.0 && s.cpk.is_nan());
    }
}
