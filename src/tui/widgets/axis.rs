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

/// A linear axis from `lo` to a whole tick at or above `hi`, about `max_ticks` ticks.
pub fn linear(lo: f64, hi: f64, max_ticks: usize) -> Axis {
    let (lo, hi) = if lo.is_finite() && hi.is_finite() && hi > lo {
        (lo, hi)
    } else if lo.is_finite() {
        (lo, lo + 1.0)
    } else {
        (0.0, 1.0)
    };
    let intervals = max_ticks.max(2) - 1;
    let step = nice_ceil((hi - lo) / intervals as f64);
    let first = (lo / step + 1e-9).floor();
    let last = (hi / step - 1e-9).ceil();
    let bounds = [first * step, last * step];
    let ticks = (0..=(last - first) as usize)
        .map(|i| {
            let v = (first + i as f64) * step;
            (v, tick(v, step))
        })
        .collect();
    Axis { bounds, ticks }
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
