//! Axes with our own tick placement (ratatui's Chart spreads more than three labels evenly,
//! whatever their values): linear axes with 1-2-2.5-5 steps, and decade axes (log_axis.rs).

use crate::tui::format::{nice_ceil, tick};

/// What a chart asks for; the ticks follow from the room there is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AxisSpec {
    /// From `lo` up to at least `hi` (rounded up to a whole tick).
    Linear { lo: f64, hi: f64 },
    /// log10 of the value from decade `lo` to decade `hi`: the plot runs in log10 units.
    Log { lo: i32, hi: i32 },
}

/// An axis ready to draw: bounds in plot units and labelled ticks.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub bounds: [f64; 2],
    /// (position in plot units, label)
    pub ticks: Vec<(f64, String)>,
}

impl AxisSpec {
    /// Ticks for an axis with room for about `max_ticks` labels.
    pub fn build(self, max_ticks: usize) -> Axis {
        match self {
            AxisSpec::Linear { lo, hi } => linear(lo, hi, max_ticks),
            AxisSpec::Log { lo, hi } => super::log_axis::decades(lo, hi),
        }
    }
}

/// A linear axis over `lo` … `hi` with at most about `max_ticks` round ticks (at least two).
/// The ends snap to whole ticks when that wastes little room, else to a finer grain.
pub fn linear(lo: f64, hi: f64, max_ticks: usize) -> Axis {
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
    let multiples = |bounds: [f64; 2], step: f64| {
        let first = (bounds[0] / step - 1e-9).ceil() as i64;
        let last = (bounds[1] / step + 1e-9).floor() as i64;
        first..=last
    };
    // the finest round step whose ticks, ends included, stay within max_ticks
    let finest = |fits: &dyn Fn(f64) -> bool, mut step: f64| {
        while fits(nice_below(step)) {
            step = nice_below(step);
        }
        step
    };
    let mut step = finest(
        &|s| multiples(snap(s), s).count() <= max_ticks,
        nice_ceil(range),
    );
    let mut bounds = snap(step);
    if bounds[1] - bounds[0] > 1.1 * range {
        // whole ticks would waste room: end on a finer grain, tick as finely as fits
        bounds = snap(nice_ceil(range / 20.0));
        step = finest(&|s| multiples(bounds, s).count() <= max_ticks, step);
    }
    while multiples(bounds, step).count() < 2 {
        step = nice_below(step);
    }
    let ticks = multiples(bounds, step)
        .map(|i| {
            let v = i as f64 * step;
            (v, tick(v, step))
        })
        .collect();
    Axis { bounds, ticks }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round() {
        let a = linear(0.0, 117.3, 6);
        assert_eq!(a.bounds, [0.0, 125.0]);
        let labels: Vec<_> = a.ticks.iter().map(|t| t.1.as_str()).collect();
        assert_eq!(labels, ["0", "25", "50", "75", "100", "125"]);
        let a = linear(0.0, 1.0, 3);
        assert_eq!(a.bounds, [0.0, 1.0]);
        assert_eq!(a.ticks.len(), 3);
        let a = linear(0.0, 2.74, 7);
        assert_eq!(a.bounds, [0.0, 3.0]);
        assert_eq!(a.ticks[1].1, "0.5");
        // little room: few ticks, but the range is not stretched to the next big tick
        let a = linear(0.0, 2.74, 2);
        assert!(a.bounds[0] == 0.0 && (a.bounds[1] - 2.8).abs() < 1e-12);
        let labels: Vec<_> = a.ticks.iter().map(|t| t.1.as_str()).collect();
        assert_eq!(labels, ["0", "2"]);
        let a = linear(0.0, 121.8, 3);
        assert_eq!(a.bounds, [0.0, 130.0]);
        assert_eq!(a.ticks.len(), 3);
    }

    #[test]
    fn degenerate_ranges_still_give_an_axis() {
        for (lo, hi) in [
            (0.0, 0.0),
            (0.0, f64::NAN),
            (f64::NAN, f64::NAN),
            (2.0, 1.0),
        ] {
            let a = linear(lo, hi, 4);
            assert!(a.bounds[1] > a.bounds[0] && a.bounds.iter().all(|b| b.is_finite()));
        }
    }
}
