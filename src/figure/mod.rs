//! Figures as plain data — the one description of a chart, for paper and screen — and the
//! ways out: an SVG picture ([`svg::render`]), the plotted series as CSV ([`csv::write`]), the
//! terminal explorer's braille widget (`tui::widgets::plot`), and the Markdown report comparing
//! model and experiment ([`report`]). [`paper`] builds the paper's figures (docs/model.md §6)
//! from solver output; [`explorer`] builds the explorer's charts from the same builders, with
//! the pinned curves and this run on top.
//!
//! Nothing here touches the file system or the terminal: rendering returns a `String` and the
//! CSV writer takes any `io::Write`, so the command line and the explorer share one
//! implementation.
//!
//! A new chart or overlay is written once, as data: a [`Figure`] whose series each have a
//! [`Role`] (model, pinned, this run, measured, reference), a [`Style`] and palette colour for
//! the picture, and a [`Look`] for the terminal (colour role, legend key, marker text). The
//! SVG and CSV writers and the explorer's braille widget then all draw it; the explorer shows
//! a chart by adding a [`explorer::Chart`] and a case in [`explorer::figure`].

pub mod chart;
pub mod colormap;
pub mod csv;
pub mod explorer;
pub mod histogram;
pub mod history;
pub mod look;
pub mod overlay;
pub mod paper;
pub mod peers;
pub mod reduce;
pub mod report;
pub mod room;
pub mod shot;
pub mod svg;
pub mod svg_map;
pub mod ticks;

pub use look::{Corner, LegendEntry, Look, Sample, Tone};

/// One axis of a figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Label shown on the figure, with its unit: "t (ms)".
    pub label: String,
    /// CSV column name for this axis' values: "t".
    pub key: String,
    /// Factor from the series' SI values to the unit shown (s → ms: 1e3). Series hold SI
    /// values, as the CSV writes them (like every other output of bouncelab); only the picture
    /// shows convenient units.
    pub scale: f64,
    /// Logarithmic (base 10) axis, with decade ticks.
    pub log: bool,
    /// Range shown, in the unit shown; `None` fits the data (with a small margin).
    pub range: Option<(f64, f64)>,
}

impl Axis {
    /// A linear axis fitted to the data.
    pub fn linear(label: &str, key: &str, scale: f64) -> Axis {
        Axis {
            label: label.into(),
            key: key.into(),
            scale,
            log: false,
            range: None,
        }
    }

    /// A base-10 logarithmic axis over `from..to` (both positive).
    pub fn log(label: &str, key: &str, from: f64, to: f64) -> Axis {
        Axis {
            label: label.into(),
            key: key.into(),
            scale: 1.0,
            log: true,
            range: Some((from, to)),
        }
    }

    /// The same axis over `from..to`, in the unit shown (log axes: the values, not their
    /// logarithms).
    pub fn with_range(mut self, from: f64, to: f64) -> Axis {
        self.range = Some((from, to));
        self
    }

    /// An SI value as drawn: in the unit shown, log10 of it on a log axis; `None` for a value
    /// the axis cannot show (not finite, or not positive on a log axis).
    pub fn drawn(&self, v: f64) -> Option<f64> {
        let v = v * self.scale;
        match (v.is_finite(), self.log) {
            (true, false) => Some(v),
            (true, true) if v > 0.0 => Some(v.log10()),
            _ => None,
        }
    }
}

/// What a series stands for. Its CSV `kind` column says `model`, `measured` or `reference`
/// ([`Role::name`]); the pinned curves and this run's marker are model values too.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Computed by the model.
    Model,
    /// Computed by the model for the pinned setting: drawn dimmed, behind the live curves.
    Pinned,
    /// The current run's point on a sweep's curve.
    ThisRun,
    /// Measured, or a reference value ([`crate::ball::Ball::measured_label`] says which).
    Measured,
    /// A reference line: a threshold or a measured value drawn across the plot.
    Reference,
}

/// The name the CSV and the command line have always used for [`Role`].
pub type Kind = Role;

impl Role {
    /// The CSV `kind` column.
    pub fn name(self) -> &'static str {
        match self {
            Role::Model | Role::Pinned | Role::ThisRun => "model",
            Role::Measured => "measured",
            Role::Reference => "reference",
        }
    }
}

/// Marker shapes, so measured points stay distinct without colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// ●
    Circle,
    /// ■
    Square,
    /// ▲
    Triangle,
    /// ◆
    Diamond,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A solid line through the points.
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// Long dashes with short gaps: a fourth line that differs from the other three without
    /// colour (the explorer's COR–ζ chart draws the current λ and three references).
    LongDashed,
    /// Unconnected markers.
    Markers(Marker),
}

/// A colour-blind-safe palette (Okabe & Ito), darkest first-use colours first; index with
/// [`Series::color`] (taken modulo its length).
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0, 114, 178),   // blue
    (213, 94, 0),    // vermillion
    (0, 158, 115),   // bluish green
    (204, 121, 167), // reddish purple
    (230, 159, 0),   // orange
    (86, 180, 233),  // sky blue
    (0, 0, 0),       // black
    (120, 120, 120), // grey
];

/// Index of black and grey in [`PALETTE`], for measured values and reference lines.
pub const BLACK: usize = 6;
/// Index of grey in [`PALETTE`].
pub const GREY: usize = 7;

/// One plotted series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text of the picture (may hold Greek letters and units).
    pub label: String,
    /// Name in the CSV `series` column: ASCII, stable, easy to filter on.
    pub id: String,
    /// What it stands for (the CSV `kind` column).
    pub kind: Kind,
    /// How it is drawn in the SVG.
    pub style: Style,
    /// Index into [`PALETTE`].
    pub color: usize,
    /// (x, y), SI units.
    pub points: Vec<(f64, f64)>,
    /// Text placed next to each point (markers only); empty for none.
    pub annotations: Vec<String>,
    /// How a terminal draws it.
    pub look: Look,
}

impl Series {
    /// An empty series with its legend label, CSV id, kind, style and colour index; its
    /// terminal look follows its kind ([`Look::of`]).
    pub fn new(label: &str, id: &str, kind: Kind, style: Style, color: usize) -> Series {
        Series {
            label: label.into(),
            id: id.into(),
            kind,
            style,
            color,
            points: Vec::new(),
            annotations: Vec::new(),
            look: Look::of(kind),
        }
    }

    /// The series with these (x, y) points, SI units.
    pub fn with_points(mut self, points: Vec<(f64, f64)>) -> Series {
        self.points = points;
        self
    }

    /// The series with a terminal look.
    pub fn with_look(mut self, look: Look) -> Series {
        self.look = look;
        self
    }
}

/// A figure: what to draw, independent of how.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// First line above the plot (SVG).
    pub title: String,
    /// Second line under the title: which ball, parameters, law, speed.
    pub subtitle: String,
    /// The horizontal axis.
    pub x: Axis,
    /// The vertical axis.
    pub y: Axis,
    /// Drawn in this order; the legend lists those with a label, under the plot.
    pub series: Vec<Series>,
    /// The title of the chart in a terminal, shorter than `title`, with the units.
    pub screen_title: String,
    /// Where a terminal puts the legend, inside the plot.
    pub legend_corner: Corner,
}

impl Figure {
    /// A figure with a terminal title equal to `title` and the legend top right; builders
    /// for the explorer set both.
    pub fn new(title: String, subtitle: String, x: Axis, y: Axis, series: Vec<Series>) -> Figure {
        Figure {
            screen_title: title.clone(),
            title,
            subtitle,
            x,
            y,
            series,
            legend_corner: Corner::TopRight,
        }
    }

    /// Add `notes` to the subtitle after its first part (the ball, its law and speed), before
    /// the figure's own notes (its flattening, its radius), each after a "; " the SVG may
    /// break it at: what moved from the ball's preset and record (`api::Ball::moved_notes`),
    /// said on every picture of a ball the same way.
    pub fn push_notes(&mut self, notes: &[String]) {
        if notes.is_empty() {
            return;
        }
        let at = self.subtitle.find("; ").unwrap_or(self.subtitle.len());
        let added: String = notes.iter().map(|n| format!("; {n}")).collect();
        self.subtitle.insert_str(at, &added);
    }

    /// Add `series` after the model curves, before the measured values (which are drawn last,
    /// and listed last in the legend), so that a measured marker at the same place stays
    /// visible.
    pub fn insert_before_measured(&mut self, series: Series) {
        let i = self
            .series
            .iter()
            .position(|s| s.kind == Kind::Measured)
            .unwrap_or(self.series.len());
        self.series.insert(i, series);
    }

    /// The terminal legend: one entry per distinct key, in series order (see [`look`]).
    pub fn legend(&self) -> Vec<LegendEntry> {
        look::legend(&self.series)
    }

    /// (min, max) over every point of every series along one axis, in the unit shown,
    /// ignoring non-finite values (and non-positive ones on a log axis); `None` when there is
    /// nothing to show.
    pub fn data_extent(&self, axis_x: bool) -> Option<(f64, f64)> {
        let axis = if axis_x { &self.x } else { &self.y };
        let mut it = self
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .map(|&(x, y)| axis.scale * if axis_x { x } else { y })
            .filter(|v| v.is_finite() && (!axis.log || *v > 0.0));
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), v| (lo.min(v), hi.max(v))))
    }
}
