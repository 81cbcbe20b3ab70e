//! The summary of a batch against a standard's window (docs/batch.md): how many balls, the
//! mean, sample standard deviation and range of the measured value, how many fail, and the
//! process capability index
//!
//!   Cpk = min(USL − μ, μ − LSL) / (3 s)
//!
//! over the bounds the window has (one-sided windows, like a COR maximum, use the one bound).

use serde::Serialize;

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
}

/// The statistics of `values` (the measured value of each judged ball; NaN and infinite
/// values are not measurements and are left out) against `window` [lo, hi].
pub fn stats(values: &[f64], window: [Option<f64>; 2]) -> BatchStats {
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

    #[test]
    fn too_few_balls_give_no_spread() {
        let s = stats(&[1.2], [Some(1.0), Some(2.0)]);
        assert!(s.sd.is_nan() && s.cpk.is_nan() && s.n == 1);
        let s = stats(&[], [Some(1.0), Some(2.0)]);
        assert!(s.mean.is_nan() && s.min.is_nan() && s.n == 0);
        let s = stats(&[1.5, 1.5], [Some(1.0), Some(2.0)]);
        assert!(s.sd == 0.0 && s.cpk.is_nan());
    }
}
