//! Each chart's own view (issue 29 item 10): pins of very different balls — a 26 N
//! table-tennis ball beside a 5 900 N softball — flatten each other on a shared scale. `N`
//! normalizes the chart: every run by its own peak force and contact time (F/F_m against
//! t/t_f; against the displacement, α/α_max), so their shapes lie over each other; `+` / `-`
//! zoom it in and out by two from the data's lower-left corner (where every pulse starts),
//! `0` brings it back. Pure: a [`Figure`] in, the figure as drawn out; the export keeps SI
//! (docs/explorer.md, "Normalize and zoom").

use crate::figure::explorer::Chart;
use crate::figure::{Figure, Role, Series, Style};

/// The most a chart zooms in: 2¹⁰, a thousandth of its span.
pub const MAX_ZOOM: u8 = 10;

/// How one chart is drawn.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ChartView {
    /// Each run by its own scales (F/F_m, t/t_f).
    pub normalized: bool,
    /// Zoomed in 2^zoom times from the data's lower-left corner.
    pub zoom: u8,
}

/// A chart on screen: one of the figure layer's (impact, sweeps and models views), or one a
/// view draws itself — the oblique view's three time charts, the drop view's height chart —
/// which `x`, `N`, `+`, `-` read as they do the others (issue 51 item 3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartId {
    Explorer(Chart),
    /// F_n and F_t against time.
    ObliqueForces,
    /// v_c against time.
    ObliqueSlip,
    /// ω against time.
    ObliqueSpin,
    /// Height against time.
    DropHeight,
}

impl From<Chart> for ChartId {
    fn from(c: Chart) -> Self {
        ChartId::Explorer(c)
    }
}

/// Every chart's view; a chart not listed is drawn as it is.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ChartViews(Vec<(ChartId, ChartView)>);

impl ChartViews {
    pub fn get(&self, chart: impl Into<ChartId>) -> ChartView {
        let chart = chart.into();
        self.0
            .iter()
            .find(|(c, _)| *c == chart)
            .map_or(ChartView::default(), |(_, v)| *v)
    }

    pub fn set(&mut self, chart: impl Into<ChartId>, view: ChartView) {
        let chart = chart.into();
        self.0.retain(|(c, _)| *c != chart);
        if view != ChartView::default() {
            self.0.push((chart, view));
        }
    }
}

/// Whether `chart` can be normalized: force against time or displacement, both linear.
pub fn normalizable(chart: impl Into<ChartId>) -> bool {
    x_name(chart.into()).is_some()
}

/// The normalized x axis' name.
fn x_name(chart: ChartId) -> Option<&'static str> {
    match chart {
        ChartId::Explorer(Chart::ForceTime | Chart::ModelsForceTime) => Some("t/t_f"),
        ChartId::Explorer(Chart::Hysteresis) => Some("α/α_max"),
        ChartId::Explorer(Chart::ModelsForceDisplacement) => Some("δ/δ_max"),
        // F_n and F_t by the contact's largest force and its duration
        ChartId::ObliqueForces => Some("t/t_c"),
        _ => None,
    }
}

/// `fig` (of `chart`) as `view` draws it.
pub fn apply(view: ChartView, chart: impl Into<ChartId>, fig: &mut Figure) {
    if view.normalized
        && let Some(x) = x_name(chart.into())
    {
        normalize(fig);
        fig.x.label = x.into();
        fig.y.label = "F/F_m".into();
        fig.screen_title = format!("F/F_m vs {x} · each run by its own (N: absolute)");
    }
    if view.zoom > 0 {
        zoom(fig, view.zoom);
        fig.screen_title = with_zoom(&fig.screen_title, 1u32 << view.zoom);
    }
}

/// The title with `×k` on its axes part: the part a narrow frame keeps
/// (src/tui/widgets/title.rs), so the zoom shows at every size.
fn with_zoom(title: &str, k: u32) -> String {
    let mut parts: Vec<String> = title.split(" · ").map(String::from).collect();
    let axes = parts.iter().position(|p| p.contains(" vs ")).unwrap_or(0);
    parts[axes] = format!("{} ×{k}", parts[axes]);
    parts.join(" · ")
}

/// The run a series belongs to: a pin's number, the measured data, or the live run (its
/// curves and their labelled marks) — each normalized by its own scales.
fn group(s: &Series) -> String {
    match s.kind {
        Role::Pinned => s.id.split(' ').take(2).collect::<Vec<_>>().join(" "),
        Role::Measured | Role::Reference => "measured".into(),
        Role::Model | Role::ThisRun => "live".into(),
    }
}

/// A run's scales from its curves (its marks follow them): the largest force F_m, and the
/// largest x where the force is positive — t_f on force–time (the contact ends as F returns
/// to 0), α_max against the displacement.
fn scales(series: &[&Series]) -> Option<(f64, f64)> {
    let lines: Vec<&&Series> = series
        .iter()
        .filter(|s| !matches!(s.style, Style::Markers(_)))
        .collect();
    let pts = || {
        let from: Box<dyn Iterator<Item = &(f64, f64)>> = if lines.is_empty() {
            Box::new(series.iter().flat_map(|s| &s.points))
        } else {
            Box::new(lines.iter().flat_map(|s| &s.points))
        };
        from.filter(|(x, y)| x.is_finite() && y.is_finite())
    };
    let f_m = pts().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let x_m = pts()
        .filter(|p| p.1 > 0.0)
        .map(|p| p.0)
        .fold(f64::NEG_INFINITY, f64::max);
    (f_m > 0.0 && x_m > 0.0 && f_m.is_finite() && x_m.is_finite()).then_some((x_m, f_m))
}

/// Every run divided by its own scales; the axes then show plain ratios.
fn normalize(fig: &mut Figure) {
    let groups: Vec<String> = fig.series.iter().map(group).collect();
    let mut seen: Vec<&String> = Vec::new();
    let mut found = Vec::new();
    for g in &groups {
        if !seen.contains(&g) {
            seen.push(g);
            let members: Vec<&Series> = fig
                .series
                .iter()
                .zip(&groups)
                .filter(|(_, h)| *h == g)
                .map(|(s, _)| s)
                .collect();
            found.push((g.clone(), scales(&members)));
        }
    }
    for (s, g) in fig.series.iter_mut().zip(&groups) {
        if let Some((_, Some((xm, fm)))) = found.iter().find(|(h, _)| h == g) {
            for p in &mut s.points {
                *p = (p.0 / xm, p.1 / fm);
            }
        }
    }
    for a in [&mut fig.x, &mut fig.y] {
        a.scale = 1.0;
        a.range = None;
    }
}

/// The axes' ranges cut to 1/2^k of the data's span from its lower-left corner (on a log
/// axis, of its span in decades).
fn zoom(fig: &mut Figure, k: u8) {
    let f = 1.0 / f64::from(1u32 << k.min(MAX_ZOOM));
    for x in [true, false] {
        let axis = if x { &fig.x } else { &fig.y };
        let shown = fig.series.iter().flat_map(|s| &s.points).filter_map(|p| {
            let v = if x { p.0 } else { p.1 };
            axis.drawn(v)
        });
        let (lo, hi) = shown.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        // no span (one point, or none finite): nothing to zoom along this axis
        if lo.partial_cmp(&hi) != Some(std::cmp::Ordering::Less) {
            continue;
        }
        let top = lo + (hi - lo) * f;
        let range = if axis.log {
            (10f64.powf(lo), 10f64.powf(top))
        } else {
            (lo, top)
        };
        if x {
            fig.x.range = Some(range);
        } else {
            fig.y.range = Some(range);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Axis, Corner};

    fn series(id: &str, kind: Role, pts: Vec<(f64, f64)>) -> Series {
        Series::new(id, id, kind, Style::Solid, 0).with_points(pts)
    }

    /// Two half-sines, 26 N over 1 ms and 5 900 N over 4 ms (a table-tennis ball's pulse
    /// beside a softball's), in SI.
    fn two_balls() -> Figure {
        let pulse = |f_m: f64, t_c: f64| -> Vec<(f64, f64)> {
            (0..=100)
                .map(|i| {
                    let t = t_c * f64::from(i) / 100.0;
                    (t, f_m * (std::f64::consts::PI * t / t_c).sin().max(0.0))
                })
                .collect()
        };
        Figure {
            title: String::new(),
            subtitle: String::new(),
            x: Axis::linear("t (ms)", "t", 1e3),
            y: Axis::linear("F (N)", "force", 1.0),
            series: vec![
                series("model", Role::Model, pulse(26.0, 1e-3)),
                series("pinned 1 model", Role::Pinned, pulse(5900.0, 4e-3)),
            ],
            screen_title: "F [N] vs t [ms]".into(),
            legend_corner: Corner::TopRight,
        }
    }

    /// Normalized, each run peaks at F/F_m = 1 and ends at t/t_f = 1: the table-tennis
    /// pulse, 0.4 % of the softball's on the shared scale, now spans the chart as it does.
    #[test]
    fn normalized_runs_each_peak_at_one_and_end_at_one() {
        let mut fig = two_balls();
        let view = ChartView {
            normalized: true,
            zoom: 0,
        };
        apply(view, Chart::ForceTime, &mut fig);
        for s in &fig.series {
            let f = s.points.iter().map(|p| p.1).fold(0.0, f64::max);
            let t = s.points.iter().map(|p| p.0).fold(0.0, f64::max);
            assert!(
                (f - 1.0).abs() < 1e-3 && (t - 1.0).abs() < 1e-12,
                "{}: {f} {t}",
                s.id
            );
        }
        assert_eq!((fig.x.scale, fig.y.scale), (1.0, 1.0));
        assert!(fig.screen_title.starts_with("F/F_m vs t/t_f"));
        // the COR chart is not a force chart: left as it is
        let mut cor = two_balls();
        apply(view, Chart::CorZeta, &mut cor);
        assert_eq!(cor, two_balls());
    }

    /// Zoom ×4 from the lower-left corner: the ranges are a quarter of the data's span.
    #[test]
    fn zoom_cuts_the_ranges_from_the_lower_left_corner() {
        let mut fig = two_balls();
        apply(
            ChartView {
                normalized: false,
                zoom: 2,
            },
            Chart::ForceTime,
            &mut fig,
        );
        let (x0, x1) = fig.x.range.unwrap();
        let (y0, y1) = fig.y.range.unwrap();
        assert!(x0.abs() < 1e-12 && (x1 - 1.0).abs() < 1e-9, "{x0} {x1} ms");
        assert!(y0.abs() < 1e-9 && (y1 - 1475.0).abs() < 1e-6, "{y0} {y1} N");
        assert_eq!(fig.screen_title, "F [N] vs t [ms] ×4");
    }

    #[test]
    fn views_are_kept_per_chart() {
        let mut v = ChartViews::default();
        let n = ChartView {
            normalized: true,
            zoom: 0,
        };
        v.set(Chart::ForceTime, n);
        assert_eq!(v.get(Chart::ForceTime), n);
        assert_eq!(v.get(Chart::Hysteresis), ChartView::default());
        v.set(Chart::ForceTime, ChartView::default());
        assert_eq!(v, ChartViews::default());
    }
}
