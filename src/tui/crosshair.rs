//! The crosshair (`x`): a point on one chart of the current view, moved by the arrows, that
//! reads (x, y) in the chart's units and, for the chart's live curve, the value of the curve's
//! point nearest in x. Pure: built from the chart's [`Figure`] (the one on screen and in the
//! export), so what it reads is what is drawn.
//!
//! The position is held in the figure's data units (SI, as its series hold them) and moves
//! in steps of a fraction of the data's span — on a logarithmic axis, of its span in decades —
//! clamped to the data's bounds, so it never leaves the chart.

use crate::figure::look::{Look, Tone};
use crate::figure::{Axis, Figure, Kind, Series, Style};
use crate::text::short;

/// Steps across the data's span an arrow moves the crosshair; Shift moves [`LEAP`] steps.
pub const STEPS: f64 = 50.0;
/// Steps a Shift+arrow moves.
pub const LEAP: f64 = 10.0;

/// Where the crosshair is: which chart of the view (its index in `View::charts`), and the
/// point (SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crosshair {
    pub chart: usize,
    pub x: f64,
    pub y: f64,
}

/// The bounds of every finite point of `fig` (positive only on a log axis), or `None`.
fn bounds(fig: &Figure) -> Option<([f64; 2], [f64; 2])> {
    let mut b = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    let ok = |a: &Axis, v: f64| v.is_finite() && (!a.log || v > 0.0);
    for &(x, y) in fig.series.iter().flat_map(|s| &s.points) {
        if ok(&fig.x, x) && ok(&fig.y, y) {
            b.0 = [b.0[0].min(x), b.0[1].max(x)];
            b.1 = [b.1[0].min(y), b.1[1].max(y)];
        }
    }
    (b.0[0] <= b.0[1]).then_some(b)
}

/// The value `v` moved by `steps` steps of the span [lo, hi] (in decades on a log axis),
/// kept inside it.
fn moved(v: f64, [lo, hi]: [f64; 2], log: bool, steps: f64) -> f64 {
    let to = if log {
        let d = (hi / lo).log10() / STEPS;
        v * 10f64.powf(steps * d)
    } else {
        v + steps * (hi - lo) / STEPS
    };
    to.clamp(lo, hi)
}

/// The centre of the data's bounds: where the crosshair starts on `fig`.
pub fn start(chart: usize, fig: &Figure) -> Option<Crosshair> {
    let (bx, by) = bounds(fig)?;
    let mid = |[lo, hi]: [f64; 2], log: bool| {
        if log {
            (lo * hi).sqrt()
        } else {
            (lo + hi) / 2.0
        }
    };
    Some(Crosshair {
        chart,
        x: mid(bx, fig.x.log),
        y: mid(by, fig.y.log),
    })
}

impl Crosshair {
    /// Moved `dx` steps right and `dy` steps up on `fig`, inside its data's bounds.
    pub fn step(self, fig: &Figure, dx: f64, dy: f64) -> Crosshair {
        let Some((bx, by)) = bounds(fig) else {
            return self;
        };
        Crosshair {
            x: moved(self.x, bx, fig.x.log, dx),
            y: moved(self.y, by, fig.y.log, dy),
            ..self
        }
    }
}

/// The chart's live curve: its first line of the current model (the one the readout's values
/// come from), else its first line of any kind.
pub fn live_curve(fig: &Figure) -> Option<&Series> {
    let line = |s: &&Series| !matches!(s.style, Style::Markers(_)) && s.points.len() > 1;
    let current = |s: &&Series| s.look.tone == Tone::Current && s.kind == Kind::Model;
    fig.series
        .iter()
        .filter(line)
        .find(current)
        .or_else(|| fig.series.iter().find(line))
}

/// The point of `curve` nearest to `x` in x (in decades on a log axis).
pub fn nearest(curve: &Series, x: f64, log: bool) -> Option<(f64, f64)> {
    let d = |p: &(f64, f64)| {
        if log {
            (p.0.log10() - x.log10()).abs()
        } else {
            (p.0 - x).abs()
        }
    };
    curve
        .points
        .iter()
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .min_by(|a, b| d(a).total_cmp(&d(b)))
        .copied()
}

/// The unit an axis label names in its last parentheses ("time t (ms)" → "ms"), if any
/// ("COR e (–)" has none).
fn unit(a: &Axis) -> String {
    match (a.label.rfind('('), a.label.rfind(')')) {
        // "(–)" marks a number without unit
        (Some(i), Some(j)) if i < j && !matches!(a.label[i + 1..j].trim(), "–" | "-" | "") => {
            format!(" {}", &a.label[i + 1..j])
        }
        _ => String::new(),
    }
}

/// The symbol an axis label ends with before its unit ("damping factor ζ (–)" → "ζ", "time t
/// (ms)" → "t"): what the screen names the quantity, never the CSV column (`zeta`,
/// `max_force_normalized`: issue 51 item 4, no internal names on screen).
fn symbol(a: &Axis) -> &str {
    let bare = match a.label.rfind('(') {
        Some(i) if a.label.ends_with(')') => &a.label[..i],
        _ => &a.label,
    };
    bare.split_whitespace().last().unwrap_or(&a.key)
}

/// "t 1.2 ms": a value of axis `a` in its unit.
fn value(a: &Axis, v: f64) -> String {
    format!("{} {}{}", symbol(a), short(v * a.scale, 4), unit(a))
}

/// What the crosshair reads on `fig`: "+ t 1.2 ms, force 50 N · model at t 1.21 ms: force
/// 80.3 N".
pub fn reading(c: &Crosshair, fig: &Figure) -> String {
    let mut text = format!("+ {}, {}", value(&fig.x, c.x), value(&fig.y, c.y));
    if let Some(curve) = live_curve(fig)
        && let Some((x, y)) = nearest(curve, c.x, fig.x.log)
    {
        let name = curve.look.key.as_deref().unwrap_or(&curve.id);
        text.push_str(&format!(
            " · {name} at {}: {}",
            value(&fig.x, x),
            value(&fig.y, y)
        ));
    }
    text
}

/// The crosshair drawn on `fig`: a dotted vertical and horizontal line through it across the
/// data's bounds, and its reading in the chart's title. Not in the export: only the screen
/// draws this figure.
pub fn draw_on(c: &Crosshair, fig: &mut Figure) {
    let Some((bx, by)) = bounds(fig) else {
        return;
    };
    let look = Look::new(Tone::Highlight, None, None);
    let line = |id: &str, pts: Vec<(f64, f64)>| {
        Series::new("", id, Kind::Model, Style::Dotted, 4)
            .with_points(pts)
            .with_look(look.clone())
    };
    fig.series
        .push(line("crosshair x", vec![(c.x, by[0]), (c.x, by[1])]));
    fig.series
        .push(line("crosshair y", vec![(bx[0], c.y), (bx[1], c.y)]));
    // first, so that a narrow chart's title keeps it
    fig.screen_title = format!(
        "+({}, {}) · {}",
        short(c.x * fig.x.scale, 4),
        short(c.y * fig.y.scale, 4),
        fig.screen_title
    );
}
