//! Dotted and dashed lines on the braille canvas: the dots of a line, and a pattern kept
//! running across a series' points (a curve of 121 points has segments shorter than a dash).

/// The plot's x and y bounds, in plot units.
pub type Bounds = ([f64; 2], [f64; 2]);

/// Points from `a` to `b` (plot units) for a dotted line: `n` over the whole span of the
/// plot, as many in proportion over a shorter segment.
pub fn dots(a: (f64, f64), b: (f64, f64), n: f64, bounds: Bounds) -> Vec<(f64, f64)> {
    let ([x0, x1], [y0, y1]) = bounds;
    let span = ((b.0 - a.0) / (x1 - x0))
        .abs()
        .max(((b.1 - a.1) / (y1 - y0)).abs());
    let k = (n * span).ceil().max(1.0) as usize;
    (0..=k)
        .map(|i| {
            let t = i as f64 / k as f64;
            (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
        })
        .collect()
}

/// A line drawn in dots on the braille canvas; each looks different without colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pattern {
    /// Every third dot.
    Dotted,
    /// Three dots on, three off.
    Dashed,
    /// Six dots on, two off.
    LongDashed,
}

impl Pattern {
    /// Whether the `k`-th dot along the line is drawn.
    fn keeps(self, k: usize) -> bool {
        match self {
            Pattern::Dotted => k.is_multiple_of(3),
            Pattern::Dashed => (k / 3).is_multiple_of(2),
            Pattern::LongDashed => k % 8 < 6,
        }
    }
}

/// The dots of a series in `pattern`, the pattern running on across its points so short
/// segments keep it. `n`: dots a dotted line has over the plot's span. `points`: in plot
/// units, `None` where the axes cannot show one.
pub fn patterned(
    points: &[Option<(f64, f64)>],
    pattern: Pattern,
    n: f64,
    bounds: Bounds,
) -> Vec<(f64, f64)> {
    let every = 3.0 * n;
    let keep = |k: usize| pattern.keeps(k);
    let mut out = Vec::new();
    let mut k = 0;
    for w in points.windows(2) {
        let (Some(a), Some(b)) = (w[0], w[1]) else {
            continue;
        };
        let pts = dots(a, b, every, bounds);
        for p in &pts[..pts.len() - 1] {
            if keep(k) {
                out.push(*p);
            }
            k += 1;
        }
    }
    out
}
