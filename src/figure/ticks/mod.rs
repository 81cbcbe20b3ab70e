//! Axis ticks, for the SVG picture and the terminal alike. Linear axes get "nice" steps
//! (1, 2, 2.5, 5 × 10^k) with every label printed to the same number of decimals; log axes are
//! drawn as log10 of the data on a linear axis, so the ticks sit exactly on the decades
//! (0.01, 0.1, 1, 10, 100), with light grid lines at 2…9 × 10^k in the picture; the
//! explorer's map labels its log axes with 1-2-5 or 1-3 × 10^k where they fit ([`log`]).
//!
//! Two kinds of room: a picture ([`Room::Picture`]) has space for about six intervals and
//! pads a fitted range with headroom; a terminal chart ([`Room::Labels`]) fits as many round
//! ticks as it has room for labels, and ends a fitted range on a tick when that wastes little
//! room.

use super::{Axis, Figure};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use std::ops::Range;

pub mod log;
use log::log_ticks;

/// Ticks of one axis, in drawing coordinates (log10 of the value on a log axis).
#[derive(Debug, Clone, PartialEq)]
pub struct Ticks {
    /// Lower end of the axis.
    pub lo: f64,
    /// Upper end of the axis.
    pub hi: f64,
    /// Labelled ticks, increasing.
    pub major: Vec<f64>,
    /// Unlabelled ticks between them (the 2…9 of each decade on a log axis).
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
    let major: Vec<f64> = multiples([lo, hi], step).map(|i| i as f64 * step).collect();
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

/// How much room an axis has for its tick labels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Room {
    /// The SVG picture: about six intervals, a fitted range padded with headroom.
    Picture,
    /// A terminal chart: at most this many labelled ticks (at least two).
    Labels(usize),
}

/// The ticks of the figure's x (`x: true`) or y axis.
pub fn ticks(fig: &Figure, x: bool, room: Room) -> Ticks {
    let axis = if x { &fig.x } else { &fig.y };
    let extent = fig.data_extent(x);
    match (axis.log, room) {
        (true, Room::Picture) => log_ticks(axis, extent),
        // a terminal has no room for the 2…9 × 10^k grid
        (true, Room::Labels(_)) => Ticks {
            minor: Vec::new(),
            ..log_ticks(axis, extent)
        },
        (false, Room::Picture) => linear_ticks(axis, extent),
        (false, Room::Labels(n)) => labelled_ticks(axis, extent, n),
    }
}

/// A terminal's linear axis: a fixed range as it is, a fitted one from zero (or the data's
/// negative minimum) to the data's maximum.
fn labelled_ticks(axis: &Axis, extent: Option<(f64, f64)>, max_ticks: usize) -> Ticks {
    match axis.range {
        Some((lo, hi)) => within(lo, hi, max_ticks),
        None => {
            let (lo, hi) = extent.unwrap_or((0.0, 1.0));
            let span = (hi - lo).abs();
            let lo = if lo < -1e-9 * span { lo } else { 0.0 };
            fitted(lo, hi, max_ticks)
        }
    }
}

/// Ticks over `lo` … `hi` (a fitted range: the ends snap to whole ticks when that wastes
/// little room, else to a finer grain) with at most about `max_ticks` round ticks, at least
/// two.
pub fn fitted(lo: f64, hi: f64, max_ticks: usize) -> Ticks {
    let (lo, hi) = if lo.is_finite() && hi.is_finite() && hi > lo {
        (lo, hi)
    } else if lo.is_finite() {
        (lo, lo + 1.0)
    } else {
        (0.0, 1.0)
    };
    let range = hi - lo;
    let max_ticks = max_ticks.max(2);
    let snap = |g: f64| [(lo / g + 1e-9).floor() * g, (hi / g - 1e-9).ceil() * g];
    let mut step = finest_step(
        &|s| multiples(snap(s), s).count() <= max_ticks,
        nice_ceil(range),
    );
    let mut bounds = snap(step);
    if bounds[1] - bounds[0] > 1.1 * range {
        // whole ticks would waste room: end on a finer grain, tick as finely as fits
        bounds = snap(nice_ceil(range / 20.0));
        step = finest_step(&|s| multiples(bounds, s).count() <= max_ticks, step);
    }
    while multiples(bounds, step).count() < 2 {
        step = nice_below(step);
    }
    labelled(bounds, step)
}

/// Ticks inside the fixed range `lo` … `hi`, as finely as `max_ticks` allows.
fn within(lo: f64, hi: f64, max_ticks: usize) -> Ticks {
    let bounds = [lo, hi];
    let mut step = finest_step(
        &|s| multiples(bounds, s).count() <= max_ticks.max(2),
        nice_ceil(hi - lo),
    );
    while multiples(bounds, step).count() < 2 && step > (hi - lo) * 1e-6 {
        step = nice_below(step);
    }
    labelled(bounds, step)
}

fn labelled(bounds: [f64; 2], step: f64) -> Ticks {
    Ticks {
        lo: bounds[0],
        hi: bounds[1],
        major: multiples(bounds, step).map(|i| i as f64 * step).collect(),
        minor: Vec::new(),
        decimals: Some(decimals_for(step)),
    }
}

/// The indices i of the multiples i·step inside `bounds`.
fn multiples(bounds: [f64; 2], step: f64) -> std::ops::RangeInclusive<i64> {
    let first = (bounds[0] / step - 1e-9).ceil() as i64;
    let last = (bounds[1] / step + 1e-9).floor() as i64;
    first..=last
}

/// The finest round step below `start` (and `start` itself) that still `fits`.
fn finest_step(fits: &dyn Fn(f64) -> bool, mut step: f64) -> f64 {
    while fits(nice_below(step)) {
        step = nice_below(step);
    }
    step
}

/// The next of 1, 2, 2.5, 5 × 10^k below `x`.
fn nice_below(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    [5.0, 2.5, 2.0, 1.0, 0.5]
        .into_iter()
        .map(|m| m * p)
        .find(|&v| v < x * (1.0 - 1e-9))
        .unwrap_or(x / 2.0)
}

/// Smallest of 1, 2, 2.5, 5 × 10^k not below `x`; 1 for a non-positive or non-finite `x`.
pub fn nice_ceil(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&v| v >= x * (1.0 - 1e-12))
        .unwrap_or(10.0 * p)
}

/// The decades that cover `base` and every finite positive value in `values`.
pub fn covering(base: (i32, i32), values: impl IntoIterator<Item = f64>) -> (i32, i32) {
    values
        .into_iter()
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold(base, |(lo, hi), v| {
            let l = v.log10();
            (lo.min(l.floor() as i32), hi.max(l.ceil() as i32))
        })
}

/// A decade label: 0.001 … 1000, then exponent form (1e-4, 1e4) beyond three decades.
pub fn decade_label(e: f64) -> String {
    let e = e.round() as i32;
    match e {
        -3..=-1 => format!("{:.*}", (-e) as usize, 10f64.powi(e)),
        0..=3 => format!("{}", 10i64.pow(e as u32)),
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

    /// The major ticks with their labels.
    pub fn labels(&self) -> Vec<(f64, String)> {
        self.major.iter().map(|&v| (v, self.label(v))).collect()
    }

    /// The power of ten a terminal writes a linear axis' labels in when its values are too
    /// large or too small to read as they are (tests/tui/tui_render.rs:
    /// `extreme_speeds_get_scaled_tick_labels`): a multiple of 3, as SI prefixes go, when the
    /// largest tick lies outside 0.001 … 100 000; `None` otherwise and on a log axis.
    pub fn label_exponent(&self) -> Option<i32> {
        self.decimals?;
        let m = self.major.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        if !(m.is_finite() && m > 0.0) || (1e-3..1e5).contains(&m) {
            return None;
        }
        Some(3 * (m.log10() / 3.0).floor() as i32)
    }

    /// The major ticks with their labels written in units of 10^`label_exponent` (the
    /// exponent returned with them), with the decimals their step needs at that scale.
    pub fn scaled_labels(&self) -> (Option<i32>, Vec<(f64, String)>) {
        let Some(e) = self.label_exponent() else {
            return (None, self.labels());
        };
        let unit = 10f64.powi(e);
        let step = match self.major.as_slice() {
            [a, b, ..] => (b - a) / unit,
            _ => 1.0,
        };
        let d = decimals_for(step);
        let labels = self
            .major
            .iter()
            .map(|&v| (v, tick_label(v / unit, d)))
            .collect();
        (Some(e), labels)
    }
}

/// "×10⁻¹⁵": the factor a scaled axis' labels are in.
pub fn factor_label(exponent: i32) -> String {
    const SUPER: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits: String = exponent
        .unsigned_abs()
        .to_string()
        .chars()
        .filter_map(|c| c.to_digit(10).map(|d| SUPER[d as usize]))
        .collect();
    let sign = if exponent < 0 { "⁻" } else { "" };
    format!("×10{sign}{digits}")
}

/// The label of `x` on an axis whose ticks are `step` apart; "—" when either is not a
/// finite number (or the step not positive).
pub fn step_label(x: f64, step: f64) -> String {
    if !(x.is_finite() && step.is_finite() && step > 0.0) {
        return "—".into();
    }
    tick_label(x, decimals_for(step))
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
mod tests;
