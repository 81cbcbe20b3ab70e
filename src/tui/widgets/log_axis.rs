//! Decade axes: the plot runs in log10 units and each decade 10^k gets its own label, placed
//! by the same mapping as the curve's dots (plot.rs), not spread evenly.

use super::axis::Axis;

/// The label of 10^k: "0.01", "0.1", "1", "10", "100"; "1e-4", "1e4" beyond three decades.
pub fn decade_label(k: i32) -> String {
    match k {
        -3..=-1 => format!("{:.*}", (-k) as usize, 10f64.powi(k)),
        0..=3 => format!("{}", 10i32.pow(k as u32)),
        _ => format!("1e{k}"),
    }
}

/// An axis over decades `lo` … `hi` (log10 units) with a label at every decade.
pub fn decades(lo: i32, hi: i32) -> Axis {
    let hi = hi.max(lo + 1);
    Axis {
        bounds: [lo as f64, hi as f64],
        ticks: (lo..=hi).map(|k| (k as f64, decade_label(k))).collect(),
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels() {
        let got: Vec<_> = (-4..=4).map(decade_label).collect();
        assert_eq!(
            got,
            [
                "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000", "1e4"
            ]
        );
    }

    #[test]
    fn covering_extends_to_the_values() {
        assert_eq!(covering((-2, 2), [0.16, 0.61]), (-2, 2));
        assert_eq!(covering((-2, 2), [0.005, f64::NAN, 0.0]), (-3, 2));
        assert_eq!(covering((-2, 2), [500.0]), (-2, 3));
        assert_eq!(decades(-2, 2).ticks.len(), 5);
    }
}
