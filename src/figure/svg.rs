//! Rendering a [`Figure`] to SVG with plotters' SVG backend: text stays SVG `<text>` (no font
//! files, no system libraries), so the crate builds anywhere.
//!
//! Layout, top to bottom: title, subtitle, the plot with its axes, and the legend in a strip
//! under the plot. The legend sits outside the data so it can never hide a curve, whatever
//! the ball or speed.
//!
//! plotters rounds every coordinate to a whole pixel, which shows as wobble on long straight
//! lines. The picture is therefore drawn `SCALE` times larger and the `<svg>` element's size
//! set back to `WIDTH` × `HEIGHT`: the viewBox keeps the fine coordinates.

use super::room;
use super::ticks::{Room, Ticks, ticks};
use super::{Figure, Marker, PALETTE, Series, Style};
use legend::{LEGEND_ROW_PX, LEGEND_TOP_PX, draw_legend, legend_layout};
use plotters::chart::MeshStyle;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::fmt;

mod aspect;
mod legend;

pub use aspect::{equal_scales, plot_size};

/// Picture size in CSS pixels: the aspect of a journal figure, wide enough for the legend.
pub const WIDTH: u32 = 800;
// the reduction's columns are this picture's pixel columns (`reduce::COLUMNS`)
const _: () = assert!(super::reduce::COLUMNS == WIDTH as usize);
/// Picture height in CSS pixels.
pub const HEIGHT: u32 = 560;
/// Drawing units per CSS pixel.
pub(super) const SCALE: i32 = 4;
/// The page in drawing units: `WIDTH` × `HEIGHT` CSS pixels at `SCALE`.
pub(super) const PAGE: (u32, u32) = (
    (WIDTH as i32 * SCALE) as u32,
    (HEIGHT as i32 * SCALE) as u32,
);

const FONT: &str = "sans-serif";
/// Sizes in CSS pixels (multiplied by `SCALE` when drawn).
const TITLE_PX: i32 = 22;
const SUBTITLE_PX: i32 = 15;
pub(super) const AXIS_DESC_PX: i32 = 17;
pub(super) const TICK_PX: i32 = 15;
pub(super) const LEGEND_PX: i32 = 15;
pub(super) const ANNOTATION_PX: i32 = 13;
const LINE_PX: i32 = 2;
const MARKER_PX: i32 = 5;
/// Around a marker: half its height at its tallest (a triangle's or diamond's apex,
/// `marker`); its text's usual place, up and to the right; the gap beside it.
const SPACING: room::Spacing = room::Spacing {
    half: px(MARKER_PX) * 4 / 3,
    first: (px(MARKER_PX + 4), -px(MARKER_PX + 12)),
    gap: px(3),
};
/// A text farther than this from its marker's centre gets a line to it: the usual place is
/// 39 units away, a place one line (52) further out 77.
const LEADER_FROM: i32 = px(15);
pub(super) const SIDE_PX: i32 = 16;

/// Rendering failed (plotters reported an error; with an in-memory SVG this is not expected).
#[derive(Debug, Clone, PartialEq)]
pub struct RenderError(pub String);

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot render the figure: {}", self.0)
    }
}

impl std::error::Error for RenderError {}

pub(super) fn err<E: fmt::Debug>(e: E) -> RenderError {
    RenderError(format!("{e:?}"))
}

pub(super) const fn px(v: i32) -> i32 {
    v * SCALE
}

/// A font of `size` CSS pixels. plotters writes `font-size` as size/1.24, so undo that here.
pub(super) fn font(size: i32) -> TextStyle<'static> {
    font_in(size, FontStyle::Normal)
}

/// The house's axes on a chart's mesh, every SVG chart's and the map's alike: descriptions
/// and tick labels in the house's fonts, black axes, 5-pixel tick marks.
pub(super) fn house_axes<'m, 'a, 'b, X: Ranged, Y: Ranged, DB: DrawingBackend>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, DB> {
    mesh.axis_desc_style(font(AXIS_DESC_PX))
        .label_style(font(TICK_PX))
        .axis_style(BLACK.stroke_width(px(1) as u32))
        .set_all_tick_mark_size(px(5))
}

fn font_in(size: i32, style: FontStyle) -> TextStyle<'static> {
    (FONT, f64::from(px(size)) * 1.24, style)
        .into_font()
        .color(&BLACK)
}

pub(super) fn color(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

/// Width of `text` in CSS pixels, estimated: sans-serif glyphs average about 0.5 em. The
/// legend's layout and the markers' texts' places use it, with room to spare (and
/// tests/support/common/room.rs checks the drawn figures with it).
fn text_width(text: &str, size: i32) -> i32 {
    (text.chars().count() as f64 * f64::from(size) * 0.52).ceil() as i32
}

/// A point (SI) in drawing coordinates: scaled to the unit shown, log10 on a log axis; `None`
/// for a value the axis cannot show (not finite, or not positive on a log axis).
fn to_draw(fig: &Figure, (x, y): (f64, f64)) -> Option<(f64, f64)> {
    Some((fig.x.drawn(x)?, fig.y.drawn(y)?))
}

/// A marker of `shape` centred on backend offset (0, 0).
fn marker<DB: DrawingBackend>(
    shape: Marker,
    style: ShapeStyle,
) -> DynElement<'static, DB, (i32, i32)> {
    let s = px(MARKER_PX);
    match shape {
        Marker::Circle => Circle::new((0, 0), s, style).into_dyn(),
        Marker::Square => Rectangle::new([(-s, -s), (s, s)], style).into_dyn(),
        Marker::Triangle => Polygon::new(
            vec![
                (0, -s - s / 3),
                (s + s / 6, s * 5 / 6),
                (-s - s / 6, s * 5 / 6),
            ],
            style,
        )
        .into_dyn(),
        Marker::Diamond => Polygon::new(
            vec![(0, -s - s / 3), (s, 0), (0, s + s / 3), (-s, 0)],
            style,
        )
        .into_dyn(),
    }
}

/// A legend glyph or a line of `style`, from `a` to `b` in backend coordinates.
fn stroke<DB: DrawingBackend>(
    style: Style,
    line: ShapeStyle,
    pts: Vec<(i32, i32)>,
) -> DynElement<'static, DB, (i32, i32)> {
    match style {
        Style::Dashed => DashedPathElement::new(pts, px(8), px(5), line).into_dyn(),
        Style::Dotted => DashedPathElement::new(pts, px(2), px(3), line).into_dyn(),
        Style::LongDashed => DashedPathElement::new(pts, px(16), px(4), line).into_dyn(),
        _ => PathElement::new(pts, line).into_dyn(),
    }
}

type Chart<'a> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<Ticks, Ticks>>;

/// Draw one series into the plot; a marker's text at its offset in `offsets`, by point
/// ([`annotation_offsets`]).
fn draw_series<'a>(
    chart: &mut Chart<'a>,
    fig: &Figure,
    s: &Series,
    offsets: &[(i32, i32)],
) -> Result<(), RenderError> {
    let c = color(s.color);
    let line = c.stroke_width(px(LINE_PX) as u32);
    let pts: Vec<(f64, f64)> = s.points.iter().filter_map(|&p| to_draw(fig, p)).collect();
    match s.style {
        Style::Solid => {
            chart.draw_series(LineSeries::new(pts, line)).map_err(err)?;
        }
        Style::Dashed => {
            chart
                .draw_series(DashedLineSeries::new(pts, px(8), px(5), line))
                .map_err(err)?;
        }
        Style::Dotted => {
            chart
                .draw_series(DashedLineSeries::new(pts, px(2), px(3), line))
                .map_err(err)?;
        }
        Style::LongDashed => {
            chart
                .draw_series(DashedLineSeries::new(pts, px(16), px(4), line))
                .map_err(err)?;
        }
        Style::Markers(shape) => {
            let fill = c.filled();
            let labels = s.annotations.clone();
            // a text moved away from its marker gets a thin grey line to it
            let grey = color(super::GREY).stroke_width(px(1) as u32);
            let leaders = pts.iter().enumerate().filter_map(|(i, &p)| {
                let offset = offsets.get(i).copied().unwrap_or(SPACING.first);
                let end = room::leader(offset, annotation_size(s, i), LEADER_FROM)?;
                Some(EmptyElement::at(p) + PathElement::new(vec![(0, 0), end], grey))
            });
            chart.draw_series(leaders).map_err(err)?;
            chart
                .draw_series(pts.into_iter().enumerate().map(move |(i, p)| {
                    let text = labels.get(i).cloned().unwrap_or_default();
                    let offset = offsets.get(i).copied().unwrap_or(SPACING.first);
                    EmptyElement::at(p)
                        + marker(shape, fill)
                        + Text::new(text, offset, font(ANNOTATION_PX))
                }))
                .map_err(err)?;
        }
    }
    Ok(())
}

/// The box of point `i`'s text in `s`, drawn (empty without one).
fn annotation_size(s: &Series, i: usize) -> (i32, i32) {
    let text = s.annotations.get(i).map_or("", String::as_str);
    (px(text_width(text, ANNOTATION_PX)), px(ANNOTATION_PX))
}

/// Where each marker's text goes, as an offset from its marker, per series and point
/// ([`room::offsets`]: the usual place when it has room, else one clear of every marker and
/// of the texts before it).
fn annotation_offsets(chart: &Chart, fig: &Figure) -> Vec<Vec<(i32, i32)>> {
    let at = |p| to_draw(fig, p).map(|p| chart.backend_coord(&p));
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let plot = room::Rect {
        x0: xs.start,
        y0: ys.start,
        x1: xs.end,
        y1: ys.end,
    };
    room::offsets(&fig.series, at, annotation_size, plot, SPACING)
}

/// The width (CSS pixels) left of the plot for the y axis' tick labels and its rotated
/// description: 70, or wider where the widest tick label needs it (`fit --plot`'s residuals,
/// "-0.0005", keep clear of the description "e − model": tests/figures/figure_radius.rs). The
/// description, its gap, the tick mark and the labels' gap take 31 of it, which leaves room
/// for labels up to 39 wide ("0.025"; every figure of tests/figures/figure_room.rs).
fn y_label_area(ty: &Ticks) -> i32 {
    let widest = ty
        .labels()
        .iter()
        .map(|(_, l)| text_width(l, TICK_PX))
        .max()
        .unwrap_or(0);
    70.max(widest + 31)
}

/// The subtitle on one line when it fits; else broken after its first "; ", and the rest,
/// where it still would not fit, at each further "; " that ends a full line (`fit --plot`'s
/// values with their intervals, tests/cli/cli_fit_reports.rs).
fn subtitle_lines(text: &str) -> Vec<&str> {
    let fits = |s: &str| text_width(s, SUBTITLE_PX) <= WIDTH as i32 - 2 * SIDE_PX;
    if text.is_empty() {
        return vec![];
    }
    if fits(text) {
        return vec![text];
    }
    let Some((first, mut rest)) = text.split_once("; ") else {
        return vec![text];
    };
    let mut lines = vec![first];
    while !fits(rest) {
        let cut = rest
            .match_indices("; ")
            .map(|(i, _)| i)
            .take_while(|&i| fits(&rest[..i]))
            .last();
        let Some(i) = cut else { break };
        lines.push(&rest[..i]);
        rest = &rest[i + 2..];
    }
    lines.push(rest);
    lines
}

/// Text for XML character data.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The picture drawn at `SCALE`, shown at `WIDTH` × `HEIGHT`, with a `<title>` and a `<desc>`
/// naming the series (for screen readers, and for tools that list a figure's content).
pub(super) fn finish(svg: String, fig: &Figure) -> String {
    let (w, h) = (WIDTH as i32 * SCALE, HEIGHT as i32 * SCALE);
    let open = format!("<svg width=\"{w}\" height=\"{h}\" ");
    let names: Vec<String> = fig
        .series
        .iter()
        .map(|s| format!("{} ({})", s.id, s.kind.name()))
        .collect();
    let head = format!("<svg width=\"{WIDTH}\" height=\"{HEIGHT}\" font-family=\"{FONT}\" ");
    let meta = format!(
        "<title>{}</title>\n<desc>{}. Series: {}.</desc>\n",
        escape(&fig.title),
        escape(&fig.subtitle),
        escape(&names.join("; "))
    );
    let svg = svg.replacen(&open, &head, 1);
    match svg.find(">\n") {
        Some(i) => format!("{}{}{}", &svg[..i + 2], meta, &svg[i + 2..]),
        None => svg,
    }
}

/// The title and subtitle lines, centred; returns the height they take, in CSS pixels.
pub(super) fn draw_titles<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    fig: &Figure,
) -> Result<i32, RenderError> {
    let centre = px(WIDTH as i32 / 2);
    let top = Pos::new(HPos::Center, VPos::Top);
    let title = font_in(TITLE_PX, FontStyle::Bold).pos(top);
    root.draw(&Text::new(fig.title.as_str(), (centre, px(10)), title))
        .map_err(err)?;
    let mut head = 44;
    for line in subtitle_lines(&fig.subtitle) {
        let sub = font(SUBTITLE_PX).color(&RGBColor(70, 70, 70)).pos(top);
        root.draw(&Text::new(line, (centre, px(head - 4)), sub))
            .map_err(err)?;
        head += SUBTITLE_PX + 5;
    }
    Ok(head + 2)
}

/// The width (CSS pixels) `fig`'s y tick labels and description take left of its plot
/// (`y_label_area`: 70, or wider for wide tick labels).
pub fn label_area(fig: &Figure) -> i32 {
    y_label_area(&ticks(fig, false, Room::Picture))
}

/// The figure as an SVG document of `WIDTH` × `HEIGHT` CSS pixels.
pub fn render(fig: &Figure) -> Result<String, RenderError> {
    render_aligned(fig, 0)
}

/// [`render`] with at least `left` CSS pixels left of the plot: figures stacked one above
/// the other (`fit --plot`) take the widest of their [`label_area`]s, so that their plots
/// start at one x and share the x axis (tests/figures/figure_room.rs).
pub fn render_aligned(fig: &Figure, left: i32) -> Result<String, RenderError> {
    // long measured lines drawn as what the picture can show, saying so (`reduce`)
    let reduced = super::reduce::reduced(fig, &ticks(fig, true, Room::Picture));
    let fig = reduced.as_ref().unwrap_or(fig);
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, PAGE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let head = draw_titles(&root, fig)?;
        let legend_h = legend_layout(fig).1.len() as i32 * LEGEND_ROW_PX + LEGEND_TOP_PX + 6;
        let (_, rest) = root.split_vertically(px(head));
        let (plot, legend) = rest.split_vertically(px(HEIGHT as i32 - head - legend_h));
        let (tx, ty) = (
            ticks(fig, true, Room::Picture),
            ticks(fig, false, Room::Picture),
        );
        let mut chart = ChartBuilder::on(&plot)
            .margin_left(px(SIDE_PX))
            .margin_right(px(30))
            .margin_top(px(6))
            .x_label_area_size(px(52))
            .y_label_area_size(px(y_label_area(&ty).max(left)))
            .build_cartesian_2d(tx.clone(), ty.clone())
            .map_err(err)?;
        let (fx, fy) = (|v: &f64| tx.label(*v), |v: &f64| ty.label(*v));
        house_axes(
            chart
                .configure_mesh()
                .x_desc(fig.x.label.as_str())
                .y_desc(fig.y.label.as_str())
                .x_label_formatter(&fx)
                .y_label_formatter(&fy)
                .bold_line_style(RGBColor(218, 218, 218).stroke_width(px(1) as u32))
                .light_line_style(RGBColor(242, 242, 242).stroke_width(px(1) as u32)),
        )
        .draw()
        .map_err(err)?;
        let offsets = annotation_offsets(&chart, fig);
        // this run's marker last, over everything: never hidden under a measured marker at
        // its place (the legend keeps the series' order; issue 51 item 7)
        let this_run = |s: &Series| s.kind == super::Kind::ThisRun;
        let (last, first): (Vec<_>, Vec<_>) = fig
            .series
            .iter()
            .zip(&offsets)
            .partition(|(s, _)| this_run(s));
        for (s, offsets) in first.into_iter().chain(last) {
            draw_series(&mut chart, fig, s, offsets)?;
        }
        // a full frame, as journals print it (plotters draws the left and bottom axes only)
        let frame = Rectangle::new(
            [(tx.lo, ty.lo), (tx.hi, ty.hi)],
            BLACK.stroke_width(px(1) as u32),
        );
        chart.draw_series(std::iter::once(frame)).map_err(err)?;
        draw_legend(&legend, fig)?;
        root.present().map_err(err)?;
    }
    // labels may hold control characters, which XML 1.0 forbids: shown as text instead
    // (crate::sanitize; tests/cli/escaping.rs)
    Ok(crate::sanitize::text(&finish(buf, fig)).into_owned())
}
