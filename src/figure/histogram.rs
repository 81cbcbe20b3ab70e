//! A histogram as a figure: the counts per bin drawn as a step outline, with vertical lines
//! at marked values (a Monte Carlo's 2.5 % and 97.5 % points, a standard's window): the SVG of
//! `bouncelab mc --svg-out` and `bouncelab batch --svg-out` (docs/scale.md).

use super::{Axis, BLACK, Figure, GREY, Kind, Series, Style};

/// Counts of the finite `values` in `bins` equal bins over [lo, hi] (the last bin closed):
/// (left edge, count) of each, and the bin width. A single value (lo = hi) gets one bin of
/// width 1e-9 of it (or 1e-12 at 0), so that it still shows.
pub fn bins(values: &[f64], bins: usize, lo: f64, hi: f64) -> (Vec<(f64, usize)>, f64) {
    let bins = bins.max(1);
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        let pad = (lo.abs() * 1e-9).max(1e-12);
        (lo - pad, hi + pad)
    };
    let width = (hi - lo) / bins as f64;
    let mut counts = vec![0usize; bins];
    for &v in values
        .iter()
        .filter(|v| v.is_finite() && (lo..=hi).contains(*v))
    {
        let i = (((v - lo) / width) as usize).min(bins - 1);
        counts[i] += 1;
    }
    let edges = (0..bins).map(|i| lo + i as f64 * width);
    (edges.zip(counts).collect(), width)
}

/// The histogram of `values` over their range widened to take the `marks`, with a dashed line
/// at each mark (legend label, CSV id, x); `x` is the axis of the values (its unit and scale).
pub fn figure(
    title: &str,
    subtitle: &str,
    x: Axis,
    values: &[f64],
    nbins: usize,
    marks: &[(&str, &str, f64)],
) -> Figure {
    let finite = || values.iter().copied().filter(|v| v.is_finite());
    let lo = finite()
        .chain(marks.iter().map(|m| m.2))
        .fold(f64::INFINITY, f64::min);
    let hi = finite()
        .chain(marks.iter().map(|m| m.2))
        .fold(f64::NEG_INFINITY, f64::max);
    let (counts, width) = if lo.is_finite() {
        bins(values, nbins, lo, hi)
    } else {
        (Vec::new(), 0.0)
    };
    let mut outline = Vec::with_capacity(2 * counts.len() + 2);
    if let Some(&(first, _)) = counts.first() {
        outline.push((first, 0.0));
    }
    for &(edge, n) in &counts {
        outline.push((edge, n as f64));
        outline.push((edge + width, n as f64));
    }
    if let Some(&(last, _)) = counts.last() {
        outline.push((last + width, 0.0));
    }
    let top = counts.iter().map(|c| c.1).max().unwrap_or(1).max(1) as f64;
    let mut series = vec![
        Series::new("samples", "histogram", Kind::Model, Style::Solid, 0).with_points(outline),
    ];
    for (i, (label, id, at)) in marks.iter().enumerate() {
        let color = if i % 2 == 0 { BLACK } else { GREY };
        series.push(
            Series::new(label, id, Kind::Reference, Style::Dashed, color)
                .with_points(vec![(*at, 0.0), (*at, top)]),
        );
    }
    let y = Axis::linear("samples per bin", "count", 1.0);
    Figure::new(title.into(), subtitle.into(), x, y, series)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_finite_value_in_range_is_counted_once() {
        let v = [0.0, 0.1, 0.5, 0.99, 1.0, f64::NAN];
        let (c, w) = bins(&v, 4, 0.0, 1.0);
        assert_eq!(w, 0.25);
        let counts: Vec<usize> = c.iter().map(|b| b.1).collect();
        assert_eq!(counts, [2, 0, 1, 2]); // 1.0 falls in the last, closed bin
        let (one, _) = bins(&[3.0, 3.0], 5, 3.0, 3.0);
        assert_eq!(one.iter().map(|b| b.1).sum::<usize>(), 2);
    }

    #[test]
    fn the_outline_encloses_the_counts_and_marks_span_it() {
        let f = figure(
            "t",
            "s",
            Axis::linear("e", "cor", 1.0),
            &[0.1, 0.2, 0.2, 0.3],
            2,
            &[("lo", "lo", 0.0)],
        );
        // the mark at 0 widens the range to [0, 0.3]: bins [0, 0.15) and [0.15, 0.3]
        let outline = &f.series[0].points;
        let expected = [
            (0.0, 0.0),
            (0.0, 1.0),
            (0.15, 1.0),
            (0.15, 3.0),
            (0.3, 3.0),
            (0.3, 0.0),
        ];
        assert_eq!(outline.len(), expected.len());
        for (p, e) in outline.iter().zip(expected) {
            assert!((p.0 - e.0).abs() < 1e-15 && p.1 == e.1, "{p:?} vs {e:?}");
        }
        assert_eq!(f.series[1].points, vec![(0.0, 0.0), (0.0, 3.0)]);
    }
}
