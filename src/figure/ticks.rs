//! Axis ticks. Linear axes get "nice" steps (1, 2, 2.5, 5 × 10^k) with every label printed to
//! the same number of decimals; log axes are drawn as log10 of the data on a linear axis, so
//! the ticks sit exactly on the decades (0.01, 0.1, 1, 10, 100) with light grid lines at
//! 2…9 × 10^k.

use super::{Axis, Figure};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use std::ops::Range;

/// Ticks of one axis, in drawing coordinates (log10 of the value on a log axis).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Ticks {
    pub lo: f64,
    pub hi: f64,
    pub major: Vec<f64>,
    pub minor: Vec<f64>,
    /// Decimals printed on a linear axis; `None` on a log axis (decade labels).
    pub decimals: Option<usize>,
}

/// The step among 1, 2, 2.5, 5 × 10^k that gives `target` to 4/3 `target` intervals over
/// `span`.
fn nice_step(span: f64, target: f64) -> f64 {
    let raw = span / target;
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * mag)
        .find(|&s| s >= raw * 0.75)
        .unwrap_or(10.0 * mag)
}

/// Decimals needed to print multiples of `step` exactly (2.5 → 1, 0.25 → 2, 5 → 0).
fn decimals_for(step: f64) -> usize {
    (0..10)
        .find(|&d| {
            let scaled = step * 10f64.powi(d as i32);
            (scaled - scaled.round()).abs() < 1e-6 * scaled.max(1.0)
        })
        .unwrap_or(10)
}

/// Linear ticks over the data extent or the axis' fixed range; a fitted range is widened to
/// the enclosing ticks so the frame starts and ends on a labelled value.
fn linear_ticks(axis: &Axis, extent: Option<(f64, f64)>) -> Ticks {
    let (mut lo, mut hi) = axis.range.or(extent).unwrap_or((0.0, 1.0));
    if hi - lo <= f64::EPSILON * hi.abs().max(1.0) {
        let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        (lo, hi) = (lo - pad, hi + pad);
    }
    if axis.range.is_none() {
        // headroom, so a data maximum sitting on a tick does not touch the frame; a minimum
        // that is zero up to rounding (an indentation of -1e-19 m) stays zero
        let span = hi - lo;
        if lo.abs() < 1e-9 * span {
            lo = 0.0;
        }
        if hi > 0.0 {
            hi += 0.03 * span;
        }
        if lo < 0.0 {
            lo -= 0.03 * span;
        }
    }
    let step = nice_step(hi - lo, 6.0);
    if axis.range.is_none() {
        lo = (lo / step + 1e-9).floor() * step;
        hi = (hi / step - 1e-9).ceil() * step;
    }
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    let major: Vec<f64> = (first..=last).map(|i| i as f64 * step).collect();
    let sub = if [2.0, 2.5]
        .iter()
        .any(|m| (step / m).log10().fract().abs() < 1e-9)
    {
        step / 2.0
    } else {
        step / 5.0
    };
    let minor = (((lo / sub).ceil() as i64)..=((hi / sub).floor() as i64))
        .map(|i| i as f64 * sub)
        .filter(|v| major.iter().all(|m| (m - v).abs() > sub * 1e-6))
        .collect();
    Ticks {
        lo,
        hi,
        major,
        minor,
        decimals: Some(decimals_for(step)),
    }
}

/// Decade ticks of a log axis, in log10 units.
fn log_ticks(axis: &Axis, extent: Option<(f64, f64)>) -> Ticks {
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

/// The axis plotters draws: a linear map of [lo, hi] whose bold key points are our major
/// ticks and light ones our minor ticks (plotters' own combinator for fixed key points does
/// not allow a custom label formatter on f64 axes).
impl Ranged for Ticks {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let f = (v - self.lo) / (self.hi - self.lo);
        limit.0 + (f64::from(limit.1 - limit.0) * f).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.major.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

pub(super) fn ticks(fig: &Figure, x: bool) -> Ticks {
    let axis = if x { &fig.x } else { &fig.y };
    if axis.log {
        log_ticks(axis, fig.data_extent(x))
    } else {
        linear_ticks(axis, fig.data_extent(x))
    }
}

/// A decade label: 0.01, 0.1, 1, 10, 100, then exponent form (1e5) beyond 10^4.
fn decade_label(e: f64) -> String {
    let e = e.round() as i32;
    match e {
        -4..=-1 => format!("{:.*}", (-e) as usize, 10f64.powi(e)),
        0..=4 => format!("{}", 10i64.pow(e as u32)),
        _ => format!("1e{e}"),
    }
}

impl Ticks {
    /// The label of a tick at drawing coordinate `v`.
    pub fn label(&self, v: f64) -> String {
        match self.decimals {
            Some(d) => tick_label(v, d),
            None => decade_label(v),
        }
    }
}

/// A linear tick label with a fixed number of decimals; "-0" prints as "0".
fn tick_label(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(log: bool, range: Option<(f64, f64)>) -> Axis {
        Axis {
            label: "x".into(),
            key: "x".into(),
            scale: 1.0,
            log,
            range,
        }
    }

    #[test]
    fn nice_linear_ticks() {
        let t = linear_ticks(&axis(false, None), Some((0.0, 117.3)));
        assert_eq!((t.lo, t.hi), (0.0, 140.0));
        assert_eq!(
            t.major,
            vec![0.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0, 140.0]
        );
        assert_eq!(t.decimals, Some(0));
        let t = linear_ticks(&axis(false, Some((0.0, 1.05))), None);
        assert_eq!(t.major.len(), 6);
        assert_eq!(t.label(t.major[1]), "0.2");
        let t = linear_ticks(&axis(false, None), Some((0.0, 2.74)));
        assert_eq!(t.hi, 3.0);
        assert_eq!(t.decimals, Some(1));
        assert_eq!(tick_label(-0.0001, 2), "0.00");
    }

    #[test]
    fn decade_ticks() {
        let t = log_ticks(&axis(true, Some((0.01, 100.0))), None);
        assert_eq!(t.major, vec![-2.0, -1.0, 0.0, 1.0, 2.0]);
        assert_eq!(t.minor.len(), 4 * 8);
        let labels: Vec<String> = t.major.iter().map(|&e| decade_label(e)).collect();
        assert_eq!(labels, ["0.01", "0.1", "1", "10", "100"]);
        assert_eq!(decade_label(6.0), "1e6");
    }
}
