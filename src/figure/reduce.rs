//! Measured data reduced to what a picture can show (issue 54 item 4): `fit --force-time
//! <10⁶ rows> --plot p.svg` wrote a 492 MB SVG (1.29 GB of memory), `figure --measured` 242 MB,
//! one marker or vertex per sample where 800 pixel columns show a few per column. A series of
//! more than [`REDUCE_ABOVE`] points (measured data, or `fit --plot`'s model at each datum) is drawn as its extremes within each run of
//! consecutive points in one of [`COLUMNS`] columns across the x axis — a line as the run's
//! first, lowest, highest and last point (the M4 reduction: the line enters and leaves each
//! column where the data do and spans its extremes), markers as the lowest and highest — and
//! its legend says so. Runs, not columns, so that a loop (force against displacement) keeps
//! both its branches. The CSV of a figure keeps every point. tests/figures/figure_reduced.rs.

use super::ticks::Ticks;
use super::{Figure, Style};

/// Columns across the x axis: the picture's CSS pixel width, `svg::WIDTH` (the plot,
/// narrower, spreads them over its own pixel columns: none holds less than one; `svg.rs`
/// holds the two equal at compile time).
pub const COLUMNS: usize = 800;

/// A measured line is reduced only above this many points: fewer are drawn as they are.
pub const REDUCE_ABOVE: usize = 4 * COLUMNS;

/// `fig` with every series longer than [`REDUCE_ABOVE`] (measured data, or a model drawn at
/// each of their x) reduced across the x axis `tx` (drawing coordinates), its label saying
/// so; `None` when nothing needs it.
pub fn reduced(fig: &Figure, tx: &Ticks) -> Option<Figure> {
    // the measured data, and a model drawn at every one of their x (`fit --plot`'s curve)
    let long = |s: &super::Series| s.annotations.is_empty() && s.points.len() > REDUCE_ABOVE;
    if !fig.series.iter().any(long) {
        return None;
    }
    let mut out = fig.clone();
    for s in out.series.iter_mut().filter(|s| long(s)) {
        let n = s.points.len();
        let line = !matches!(s.style, Style::Markers(_));
        s.points = m4(&s.points, |x| fig.x.drawn(x), tx.lo, tx.hi, line);
        s.label = format!("{} (min/max per pixel column of {n} points)", s.label);
    }
    Some(out)
}

/// The M4 reduction of `points` (module docs) over `COLUMNS` columns of [lo, hi] in the
/// drawing coordinate `drawn(x)` (a `line`'s; markers keep each run's lowest and highest
/// only); points the axis cannot show are left out, as the renderer leaves them.
fn m4(
    points: &[(f64, f64)],
    drawn: impl Fn(f64) -> Option<f64>,
    lo: f64,
    hi: f64,
    line: bool,
) -> Vec<(f64, f64)> {
    let width = (hi - lo).abs().max(f64::MIN_POSITIVE);
    let column = |x: f64| -> Option<i64> {
        let d = drawn(x)?;
        Some(
            (((d - lo) / width) * COLUMNS as f64)
                .floor()
                .clamp(-1.0, COLUMNS as f64) as i64,
        )
    };
    let mut out = Vec::new();
    // the run so far: its column, and the indices of its first, lowest, highest, last point
    let mut run: Option<(i64, [usize; 4])> = None;
    let flush = |run: Option<(i64, [usize; 4])>, out: &mut Vec<(f64, f64)>| {
        if let Some((_, mut idx)) = run {
            if !line {
                // markers: the run's first and last are drawn by nothing but themselves
                (idx[0], idx[3]) = (idx[1], idx[2]);
            }
            idx.sort_unstable();
            let mut last = usize::MAX;
            for i in idx {
                if i != last {
                    out.push(points[i]);
                    last = i;
                }
            }
        }
    };
    for (i, &(x, y)) in points.iter().enumerate() {
        let Some(c) = column(x).filter(|_| y.is_finite()) else {
            continue;
        };
        match &mut run {
            Some((rc, idx)) if *rc == c => {
                if y < points[idx[1]].1 {
                    idx[1] = i;
                }
                if y > points[idx[2]].1 {
                    idx[2] = i;
                }
                idx[3] = i;
            }
            _ => {
                flush(run.take(), &mut out);
                run = Some((c, [i; 4]));
            }
        }
    }
    flush(run, &mut out);
    out
}

#[cfg(test)]
mod tests {
    use super::m4;

    #[test]
    fn m4_keeps_each_columns_extremes_in_order() {
        // 10⁵ points of a noisy sine over 10 columns' worth of x … kept per run
        let pts: Vec<(f64, f64)> = (0..100_000)
            .map(|i| {
                let x = i as f64 / 100_000.0;
                (x, (x * 40.0).sin() + if i % 2 == 0 { 0.01 } else { -0.01 })
            })
            .collect();
        let r = m4(&pts, Some, 0.0, 1.0, true);
        assert!(r.len() <= 4 * super::COLUMNS, "{}", r.len());
        // x never goes back: the order of the data is kept
        assert!(r.windows(2).all(|w| w[0].0 <= w[1].0));
        let max = |v: &[(f64, f64)]| v.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let min = |v: &[(f64, f64)]| v.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        assert_eq!((max(&r), min(&r)), (max(&pts), min(&pts)));
        assert_eq!((r[0], r[r.len() - 1]), (pts[0], pts[pts.len() - 1]));
        // markers: the extremes alone, two a column
        let m = m4(&pts, Some, 0.0, 1.0, false);
        assert!(m.len() <= 2 * super::COLUMNS, "{}", m.len());
        assert_eq!((max(&m), min(&m)), (max(&pts), min(&pts)));
    }
}
