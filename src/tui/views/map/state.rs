//! The map view's state (issue 21): the design map of the current ball over (λ, ζ), the
//! quantity shown, the user's targets, and the window of the plane on screen. `App::update`
//! changes it (src/tui/views/map/update.rs); the widget (src/tui/views/map/widget.rs) only reads it.
//!
//! The map is dimensional: the current ball at its v0, flattening included (its m, K_p, z_p
//! and law held, K_r and c varied: [`MapSpec::dimensional`]). Its window is log-spaced on both
//! axes, [`LAMBDA_DECADES`] of λ and [`ZETA_DECADES`] of ζ centred on the current point (kept
//! inside 1e-3 … 1e3, the explorer's ζ range and the positive part of its λ range), and it
//! stays put while the point moves inside it: moving the cursor re-solves one impact, not the
//! map. When the point leaves the window (or the ball, law or v0 change and it lies outside)
//! the window is centred on it again. The grid has one cell per screen cell of the heat map:
//! a column per character, two rows per character (half blocks), one without colour.

use crate::map::{Axis, Map, MapError, MapSpec, Param, Quantity, Scale, Sensitivity, Targets};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::tui::layout;
use crate::tui::worker::JobState;
use ratatui::layout::Rect;

/// Decades of λ the window spans (the presets lie within λ 0.2 … 1.3: one decade each side).
pub const LAMBDA_DECADES: f64 = 2.0;
/// Decades of ζ the window spans (the presets lie within ζ 0.02 … 0.6).
pub const ZETA_DECADES: f64 = 3.0;
/// The window stays within these ends on both axes (log axes: λ = 0 lies below them).
pub const ENDS: (f64, f64) = (1e-3, 1e3);
/// Columns left of the heat map for the λ labels.
pub const GUTTER: u16 = 6;
/// Columns right of the heat map for the colour bar and its numbers.
pub const BAR: u16 = 10;
/// The grid used before the explorer knows its terminal (tests): a 120 × 40 screen's.
const DEFAULT_SIZE: (u16, u16) = (120, 40);

/// The window of the plane on screen: the ends of the λ and ζ axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    pub lambda: (f64, f64),
    pub zeta: (f64, f64),
}

impl Window {
    /// The window centred (in log10) on (λ, ζ), moved inside [`ENDS`].
    pub fn around(lambda: f64, zeta: f64) -> Window {
        Window {
            lambda: span(lambda, LAMBDA_DECADES),
            zeta: span(zeta, ZETA_DECADES),
        }
    }

    /// Whether (λ, ζ) lies in the window (a λ below the log axis counts as in it when the
    /// window sits at the bottom end: the cursor is then drawn on the bottom row).
    pub fn contains(&self, lambda: f64, zeta: f64) -> bool {
        let within = |v: f64, (a, b): (f64, f64)| {
            (v >= a * (1.0 - 1e-12) && v <= b * (1.0 + 1e-12)) || (v < ENDS.0 && a <= ENDS.0)
        };
        within(lambda, self.lambda) && within(zeta, self.zeta)
    }

    /// The two axes for a grid of `rows` λ values and `cols` ζ values.
    pub fn axes(&self, rows: usize, cols: usize) -> Result<(Axis, Axis), MapError> {
        let l = Axis::new(
            Param::Lambda,
            self.lambda.0,
            self.lambda.1,
            rows,
            Scale::Log,
        )?;
        let z = Axis::new(Param::Zeta, self.zeta.0, self.zeta.1, cols, Scale::Log)?;
        Ok((l, z))
    }
}

/// `decades` around `v` in log10, moved inside [`ENDS`].
fn span(v: f64, decades: f64) -> (f64, f64) {
    let (lo, hi) = (ENDS.0.log10(), ENDS.1.log10());
    let c = v.max(ENDS.0).min(ENDS.1).log10();
    let a = (c - decades / 2.0).max(lo).min(hi - decades);
    (10f64.powf(a), 10f64.powf(a + decades))
}

/// Where the map view's parts go inside the chart area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Geometry {
    /// The bordered block.
    pub block: Rect,
    /// The heat map: one character per ζ value, two λ values per character (one without
    /// colour).
    pub plot: Rect,
    /// λ labels, left of the plot.
    pub gutter: Rect,
    /// ζ labels, under the plot.
    pub x_labels: Rect,
    /// The colour bar and its numbers, right of the plot.
    pub bar: Rect,
    /// The lines under the labels: the value under the cursor, sensitivities, targets.
    pub info: Rect,
}

/// The parts for the chart area `area`, or `None` when there is no room for a map.
pub fn geometry(area: Rect) -> Option<Geometry> {
    let inner = Rect::new(
        area.x + 1,
        area.y + 1,
        area.width.saturating_sub(2),
        area.height.saturating_sub(2),
    );
    let info_h = if inner.height >= 14 { 2 } else { 1 };
    if inner.width < GUTTER + BAR + 8 || inner.height < info_h + 1 + 3 {
        return None;
    }
    let plot_h = inner.height - info_h - 1;
    let plot_w = inner.width - GUTTER - BAR;
    let plot = Rect::new(inner.x + GUTTER, inner.y, plot_w, plot_h);
    Some(Geometry {
        block: area,
        plot,
        gutter: Rect::new(inner.x, inner.y, GUTTER, plot_h),
        x_labels: Rect::new(inner.x, plot.bottom(), inner.width, 1),
        bar: Rect::new(plot.right(), inner.y, BAR, plot_h),
        info: Rect::new(inner.x, plot.bottom() + 1, inner.width, info_h),
    })
}

/// (λ rows, ζ columns) of the grid for a terminal of `size` (`None`: not known yet), drawn
/// with colour (two rows per character) or without, with `pins` runs pinned (the compact
/// readout grows with them). A message of more than one row is left out: while one shows, the
/// map is drawn a row or two shorter, each row of the plot the nearest λ of the grid
/// (`views::map::widget`).
pub fn grid(size: Option<(u16, u16)>, color: bool, pins: usize) -> Option<(usize, usize)> {
    let (w, h) = size.unwrap_or(DEFAULT_SIZE);
    let compact = crate::tui::widgets::readout::compact_height(pins);
    // the message row kept when there is no message; a longer message shortens the drawing
    let quiet = crate::tui::widgets::status::message_lines(None, w).len() as u16;
    let g = geometry(layout::body(Rect::new(0, 0, w, h), false, compact, quiet)?.charts)?;
    let per_char = if color { 2 } else { 1 };
    Some((
        usize::from(g.plot.height) * per_char,
        usize::from(g.plot.width),
    ))
}

/// The work of a map's first, coarse pass, in linear-law impacts (`analysis::work::cost`):
/// about 1 000, some 2–7 ms on one core at the exact solver's 2–7 µs an impact
/// (BENCHMARKS.md), so that the whole map shows coarse within 50 ms of a key under any law
/// (issue 29 item 13), then refines pass by pass on the worker.
pub const FIRST_PASS_WORK: u64 = 1_000;

/// The most cells of a map's first pass under `law`: [`FIRST_PASS_WORK`] at the law's cost
/// (the Hertz law's impacts cost 40 linear ones: 25 cells, a lattice of 32 at 200 × 60). The
/// linear law keeps `Map::new`'s (about 80 cells, of the closed form's 0.3 µs).
pub fn first_pass_cells(law: ContactLaw) -> usize {
    (FIRST_PASS_WORK / crate::analysis::work::cost(law)) as usize
}

/// A map handed to the background worker to refine, pass by pass. Its `cancel` flag is set by
/// `update` once the map is stale (the ball or the view changed): the worker then stops inside
/// the pass ([`Map::refine_until`]).
pub type MapJob = crate::tui::worker::Cancellable<Map>;

/// The map view's state.
#[derive(Debug, Clone)]
pub struct MapView {
    pub quantity: Quantity,
    /// The targets set with `t` (none: no feasible region drawn).
    pub targets: Option<Targets>,
    pub window: Option<Window>,
    /// The map of the window, refined as passes come in; `Err`: why it cannot be made.
    pub map: Option<Result<Map, String>>,
    /// The map's refinement at the worker: a pass of an older map is stale; a map whose
    /// worker stopped is not handed out again until `R` or a new map.
    pub job: JobState,
    /// ∂e/∂ln λ and ∂e/∂ln ζ at the current point (for `sens_for`).
    pub sensitivity: Option<Result<Sensitivity, String>>,
    pub sens_for: Option<(ImpactParams, ContactLaw)>,
}

impl Default for MapView {
    fn default() -> MapView {
        MapView {
            quantity: Quantity::Cor,
            targets: None,
            window: None,
            map: None,
            job: JobState::default(),
            sensitivity: None,
            sens_for: None,
        }
    }
}

impl MapView {
    /// The map, when there is one.
    pub fn map(&self) -> Option<&Map> {
        self.map.as_ref().and_then(|m| m.as_ref().ok())
    }

    /// Whether `spec` is the one of the map held (same ball apart from K_r and c, same law,
    /// same axes).
    pub fn holds(&self, spec: &MapSpec) -> bool {
        self.map().is_some_and(|m| {
            let s = &m.spec;
            s.law == spec.law
                && s.lambda == spec.lambda
                && s.zeta == spec.zeta
                && s.params_at(1.0, 1.0) == spec.params_at(1.0, 1.0)
        })
    }
}

/// The next quantity `n` shows: COR, peak force, contact time, COR …
pub fn next_quantity(q: Quantity) -> Quantity {
    let k = Quantity::ALL.iter().position(|&x| x == q).unwrap_or(0);
    Quantity::ALL[(k + 1) % Quantity::ALL.len()]
}

/// The quantity's name and unit on screen, and the factor from the map's SI values to it:
/// the SVG heat map's, so the screen and the export agree.
pub fn unit(q: Quantity) -> (&'static str, f64) {
    crate::figure::svg_map::unit(q, false)
}

/// The cell (i along λ, j along ζ) nearest to (λ, ζ) on the map's axes, clamped to the grid.
pub fn cell_of(map: &Map, lambda: f64, zeta: f64) -> (usize, usize) {
    let near = |a: &Axis, v: f64| {
        let k = if v > 0.0 { a.index_of(v).round() } else { 0.0 };
        (k.max(0.0) as usize).min(a.n - 1)
    };
    (near(&map.spec.lambda, lambda), near(&map.spec.zeta, zeta))
}
