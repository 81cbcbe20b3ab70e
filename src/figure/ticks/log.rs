//! A log axis's ticks, both rules in one place: the picture's and the terminal charts' decades
//! (0.01, 0.1, 1 …, with 2…9 × 10^k between them in the picture), and the labels the
//! explorer's map fits on its short axes — the richest of 1-2-5, 1-3 or the decades alone
//! whose neighbours stand far enough apart (`tests/tui/tui_map.rs` reads them).

use super::{Axis, Ticks};

/// The sets of mantissas a log axis is labelled with, richest first; the last, the decades,
/// is used however close they stand.
pub const MANTISSAS: [&[f64]; 3] = [&[1.0, 2.0, 5.0], &[1.0, 3.0], &[1.0]];

/// m × 10^k for each m of `mantissas` and every decade k, inside [`from`, `to`] (ends taken
/// with a relative slack of 1e-9), in increasing order for an increasing set of mantissas.
pub fn marks(from: f64, to: f64, mantissas: &[f64]) -> Vec<f64> {
    let (k0, k1) = (from.log10().floor() as i32, to.log10().ceil() as i32);
    (k0..=k1)
        .flat_map(|k| mantissas.iter().map(move |&m| m * 10f64.powi(k)))
        .filter(|&v| v >= from * (1.0 - 1e-9) && v <= to * (1.0 + 1e-9))
        .collect()
}

/// The labelled values of a log axis over [`from`, `to`]: the marks of the richest set of
/// [`MANTISSAS`] that `fit` (the caller's test: their places on the axis far enough apart),
/// or the decades.
pub fn labels(from: f64, to: f64, fit: impl Fn(&[f64]) -> bool) -> Vec<f64> {
    let [richer @ .., decades] = MANTISSAS;
    richer
        .iter()
        .map(|set| marks(from, to, set))
        .find(|values| fit(values))
        .unwrap_or_else(|| marks(from, to, decades))
}

/// Decade ticks of a log axis, in log10 units.
pub(super) fn log_ticks(axis: &Axis, extent: Option<(f64, f64)>) -> Ticks {
    let (a, b) = axis.range.or(extent).unwrap_or((1.0, 10.0));
    let (mut lo, mut hi) = (a.max(f64::MIN_POSITIVE).log10(), b.max(a).log10());
    if axis.range.is_none() {
        (lo, hi) = (lo.floor(), hi.ceil());
    }
    if hi - lo < 1e-9 {
        (lo, hi) = (lo - 1.0, hi + 1.0);
    }
    let (first, last) = ((lo - 1e-9).ceil() as i32, (hi + 1e-9).floor() as i32);
    let major = (first..=last).map(f64::from).collect();
    let minor = ((lo.floor() as i32)..=(hi.ceil() as i32))
        .flat_map(|d| (2..10).map(move |k| (f64::from(k)).log10() + f64::from(d)))
        .filter(|&v| v > lo && v < hi)
        .collect();
    Ticks {
        lo,
        hi,
        major,
        minor,
        decimals: None,
    }
}
