//! The design map as an SVG heat map: one quantity over (ζ, λ) in viridis
//! ([`super::colormap`]) with a colour bar and its numbers, labelled iso-lines, the iso-line of
//! each COR target, the feasible region outlined, and the preset's own (λ, ζ) marked. Same
//! page, fonts and frame as the paper's figures ([`super::svg`]).

use crate::figure::svg::{
    ANNOTATION_PX, HEIGHT, PAGE, RenderError, SIDE_PX, WIDTH, draw_titles, err, finish, font,
    house_axes, px,
};
use crate::figure::ticks::{Room, Ticks, fitted, ticks};
use crate::figure::{Axis, Figure, PALETTE, Role, Series, Style, colormap::viridis};
use crate::map::{Contour, Map, Quantity, Scale, Targets};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

mod legend;

/// What to draw over the map.
pub struct View<'a> {
    /// The quantity coloured in.
    pub quantity: Quantity,
    /// The targets whose feasible region is outlined.
    pub targets: Option<&'a Targets>,
    /// The ball's own (λ, ζ), marked.
    pub own: Option<(f64, f64)>,
    /// Which ball, for the subtitle: "superball at v0 = 3.12 m/s".
    pub title_ball: String,
    /// The cells past the ball's radius (`api::map_radius_note`), a note line of the
    /// subtitle as on the impact figures (`figure::history::OUTSIDE`); stderr and JSON give
    /// the warnings in full.
    pub radius_note: Option<String>,
    /// What moved from the ball's preset and record (`api::Ball::moved_notes`): after the
    /// law, before the targets.
    pub notes: Vec<String>,
}

/// Room for the colour bar at the right of the plot, CSS pixels.
const BAR_PX: i32 = 110;
/// Height of the legend strip under the plot.
pub(super) const LEGEND_H: i32 = 34;

/// (label, factor from the map's values to the unit shown) of the quantity (the explorer's
/// map view shows the same).
pub fn unit(q: Quantity, normalized: bool) -> (&'static str, f64) {
    match (q, normalized) {
        (Quantity::Cor, _) => ("e (COR)", 1.0),
        (Quantity::MaxForce, true) => ("F̄_m", 1.0),
        (Quantity::MaxForce, false) => ("F_m (N)", 1.0),
        (Quantity::ContactTime, true) => ("τ_f", 1.0),
        (Quantity::ContactTime, false) => ("t_f (ms)", 1e3),
    }
}

fn axis_of(a: &crate::map::Axis, label: &str, key: &str) -> Axis {
    match a.scale {
        Scale::Log => Axis::log(label, key, a.from, a.to),
        Scale::Linear => Axis::linear(label, key, 1.0).with_range(a.from, a.to),
    }
}

/// The figure frame (axes, titles) the page is drawn around.
fn frame(map: &Map, v: &View) -> Figure {
    let (label, _) = unit(v.quantity, map.spec.normalized);
    let targets = v.targets.map_or(String::new(), |t| format!("; where {t}"));
    let note = v.radius_note.as_ref().map_or(String::new(), |n| {
        format!("; {}{n}", crate::figure::history::OUTSIDE)
    });
    let moved: String = v.notes.iter().map(|n| format!("; {n}")).collect();
    Figure::new(
        format!("Design map: {label} over (λ, ζ)"),
        format!(
            "{}, {} law{moved}{targets}{note}",
            v.title_ball,
            map.spec.law.name()
        ),
        axis_of(&map.spec.zeta, "ζ = √(m K_p)/(2c)", "zeta"),
        axis_of(&map.spec.lambda, "λ = K_r/K_p", "lambda"),
        layers(v),
    )
}

/// What the picture holds, named in its `<desc>` (no points: the layers are drawn here, not
/// by the figure renderer).
fn layers(v: &View) -> Vec<Series> {
    let mut names = vec![(v.quantity.name(), Role::Model), ("iso-lines", Role::Model)];
    if let Some(t) = v.targets {
        if t.0.iter().any(|k| k.quantity == Quantity::Cor) {
            names.push(("target-cor", Role::Reference));
        }
        names.push(("feasible-outline", Role::Reference));
    }
    if v.own.is_some() {
        names.push(("ball", Role::ThisRun));
    }
    names
        .into_iter()
        .map(|(id, role)| Series::new("", id, role, Style::Solid, 0))
        .collect()
}

/// A value on an axis as drawn (log10 on a log axis).
fn drawn(a: &crate::map::Axis, v: f64) -> f64 {
    match a.scale {
        Scale::Log => v.log10(),
        Scale::Linear => v,
    }
}

/// The cell edges along an axis, as drawn: halfway between values, the ends at the axis ends.
fn edges(a: &crate::map::Axis) -> Vec<f64> {
    let mut e = vec![drawn(a, a.from)];
    e.extend((1..a.n).map(|k| drawn(a, a.at(k as f64 - 0.5))));
    e.push(drawn(a, a.to));
    e
}

/// Edge `k`, or a quarter of the next cell beyond it (the last edge stays).
fn reach(e: &[f64], k: usize) -> f64 {
    match e.get(k + 1) {
        Some(next) => e[k] + 0.25 * (next - e[k]),
        None => e[k],
    }
}

type Chart<'a> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<Ticks, Ticks>>;

/// The cells, a run of equal colours along ζ drawn as one rectangle (a 200 × 120 map is some
/// thousands of rectangles, not 24 000).
fn draw_cells(chart: &mut Chart, map: &Map, field: &[f64], bar: &Ticks) -> Result<(), RenderError> {
    let (ez, el) = (edges(&map.spec.zeta), edges(&map.spec.lambda));
    let nz = map.zetas.len();
    let colour = |x: f64| {
        if x.is_nan() {
            RGBColor(205, 205, 205)
        } else {
            let (r, g, b) = viridis((x - bar.lo) / (bar.hi - bar.lo));
            RGBColor(r, g, b)
        }
    };
    let mut rects = Vec::new();
    for i in 0..map.lambdas.len() {
        let mut j = 0;
        while j < nz {
            let c = colour(field[i * nz + j]);
            let mut k = j + 1;
            while k < nz && colour(field[i * nz + k]) == c {
                k += 1;
            }
            // each rectangle reaches a quarter cell into the next row and run, which are
            // drawn after it: no anti-aliased seam shows between cells
            let (top, right) = (reach(&el, i + 1), reach(&ez, k));
            rects.push(Rectangle::new([(ez[j], el[i]), (right, top)], c.filled()));
            j = k;
        }
    }
    chart.draw_series(rects).map_err(err)?;
    Ok(())
}

/// The polylines of contours as drawn (x = ζ, y = λ).
fn paths(map: &Map, lines: &[Contour]) -> Vec<Vec<(f64, f64)>> {
    let (l, z) = (&map.spec.lambda, &map.spec.zeta);
    lines
        .iter()
        .map(|c| {
            c.points
                .iter()
                .map(|&(a, b)| (drawn(z, b), drawn(l, a)))
                .collect()
        })
        .collect()
}

/// Iso-lines at the colour bar's inner ticks, thin black, each labelled at its middle vertex.
fn draw_iso(
    chart: &mut Chart,
    map: &Map,
    q: Quantity,
    bar: &Ticks,
    scale: f64,
) -> Result<(), RenderError> {
    let style = BLACK.mix(0.7).stroke_width(px(1) as u32);
    for &level in bar.major.iter().filter(|&&m| m > bar.lo && m < bar.hi) {
        let lines = map.contours(q, level / scale);
        for p in paths(map, &lines) {
            if p.len() < 2 {
                continue;
            }
            let mid = p[p.len() / 2];
            chart
                .draw_series(std::iter::once(PathElement::new(p, style)))
                .map_err(err)?;
            let text = font(ANNOTATION_PX).pos(Pos::new(HPos::Center, VPos::Bottom));
            chart
                .draw_series(std::iter::once(Text::new(bar.label(level), mid, text)))
                .map_err(err)?;
        }
    }
    Ok(())
}

/// The feasible region's outline (dashed white over black, visible on every colour of the
/// map) and the COR targets' iso-lines (vermillion) over it.
fn draw_targets(chart: &mut Chart, map: &Map, t: &Targets) -> Result<(), RenderError> {
    let outline = paths(map, &map.feasible_outline(t));
    let under = BLACK.stroke_width(px(5) as u32);
    let over = WHITE.stroke_width(px(3) as u32);
    chart
        .draw_series(outline.iter().map(|p| PathElement::new(p.clone(), under)))
        .map_err(err)?;
    chart
        .draw_series(
            outline
                .into_iter()
                .map(|p| DashedPathElement::new(p, px(6), px(4), over)),
        )
        .map_err(err)?;
    // the target's iso-line on top: where it bounds the region it runs inside the outline
    let (r, g, b) = PALETTE[1];
    let target = RGBColor(r, g, b).stroke_width(px(2) as u32);
    for k in t.0.iter().filter(|k| k.quantity == Quantity::Cor) {
        let lines = map.contours(Quantity::Cor, k.value);
        chart
            .draw_series(
                paths(map, &lines)
                    .into_iter()
                    .map(|p| PathElement::new(p, target)),
            )
            .map_err(err)?;
    }
    Ok(())
}

/// The colour bar: the map's colours from the bar's low to high end, numbered at its ticks.
fn draw_bar(
    area: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    bar: &Ticks,
    label: &str,
) -> Result<(), RenderError> {
    let x = fitted(0.0, 1.0, 2);
    let x = Ticks {
        lo: 0.0,
        hi: 1.0,
        major: Vec::new(),
        minor: Vec::new(),
        ..x
    };
    let mut c = ChartBuilder::on(area)
        .margin_top(px(6))
        .margin_left(px(12))
        .margin_right(px(8))
        .x_label_area_size(px(52))
        .set_label_area_size(LabelAreaPosition::Right, px(58))
        .build_cartesian_2d(x, bar.clone())
        .map_err(err)?;
    let fy = |v: &f64| bar.label(*v);
    house_axes(
        c.configure_mesh()
            .disable_x_mesh()
            .disable_y_mesh()
            .y_label_formatter(&fy)
            .y_desc(label),
    )
    .draw()
    .map_err(err)?;
    let n = 128;
    let step = (bar.hi - bar.lo) / n as f64;
    c.draw_series((0..n).map(|k| {
        let (r, g, b) = viridis((k as f64 + 0.5) / n as f64);
        let y0 = bar.lo + step * k as f64;
        // a quarter slice into the next (drawn after it): no seam between slices
        let top = if k + 1 < n { y0 + 1.25 * step } else { bar.hi };
        Rectangle::new([(0.0, y0), (1.0, top)], RGBColor(r, g, b).filled())
    }))
    .map_err(err)?;
    c.draw_series(std::iter::once(Rectangle::new(
        [(0.0, bar.lo), (1.0, bar.hi)],
        BLACK.stroke_width(px(1) as u32),
    )))
    .map_err(err)?;
    Ok(())
}

/// The plot: cells, axes, iso-lines, targets, the ball's mark and the frame.
fn draw_plot(
    plot: &DrawingArea<SVGBackend, plotters::coord::Shift>,
    fig: &Figure,
    map: &Map,
    v: &View,
    (field, bar, scale): (&[f64], &Ticks, f64),
) -> Result<(), RenderError> {
    let (tx, ty) = (
        ticks(fig, true, Room::Picture),
        ticks(fig, false, Room::Picture),
    );
    let mut chart = ChartBuilder::on(plot)
        .margin_left(px(SIDE_PX))
        .margin_right(px(8))
        .margin_top(px(6))
        .x_label_area_size(px(52))
        .y_label_area_size(px(70))
        .build_cartesian_2d(tx.clone(), ty.clone())
        .map_err(err)?;
    draw_cells(&mut chart, map, field, bar)?;
    let (fx, fy) = (|v: &f64| tx.label(*v), |v: &f64| ty.label(*v));
    house_axes(
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(fig.x.label.as_str())
            .y_desc(fig.y.label.as_str())
            .x_label_formatter(&fx)
            .y_label_formatter(&fy),
    )
    .draw()
    .map_err(err)?;
    draw_iso(&mut chart, map, v.quantity, bar, scale)?;
    if let Some(t) = v.targets {
        draw_targets(&mut chart, map, t)?;
    }
    if let Some((l, z)) = v.own {
        let p = (drawn(&map.spec.zeta, z), drawn(&map.spec.lambda, l));
        let inside = p.0 >= tx.lo && p.0 <= tx.hi && p.1 >= ty.lo && p.1 <= ty.hi;
        if inside {
            let mark = EmptyElement::at(p)
                + Circle::new((0, 0), px(6), WHITE.filled())
                + Circle::new((0, 0), px(6), BLACK.stroke_width(px(2) as u32));
            chart.draw_series(std::iter::once(mark)).map_err(err)?;
        }
    }
    let frame = Rectangle::new(
        [(tx.lo, ty.lo), (tx.hi, ty.hi)],
        BLACK.stroke_width(px(1) as u32),
    );
    chart.draw_series(std::iter::once(frame)).map_err(err)?;
    Ok(())
}

/// The map as an SVG document of `WIDTH` × `HEIGHT` CSS pixels.
pub fn render(map: &Map, v: &View) -> Result<String, RenderError> {
    let fig = frame(map, v);
    let (label, scale) = unit(v.quantity, map.spec.normalized);
    let field: Vec<f64> = map.field(v.quantity).iter().map(|x| x * scale).collect();
    let (lo, hi) = field
        .iter()
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let bar = if lo.is_finite() {
        fitted(lo, hi, 6)
    } else {
        fitted(0.0, 1.0, 6)
    };
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, PAGE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let head = draw_titles(&root, &fig)?;
        let (_, rest) = root.split_vertically(px(head));
        let (body, legend) = rest.split_vertically(px(HEIGHT as i32 - head - LEGEND_H));
        let (plot, bar_area) = body.split_horizontally(px(WIDTH as i32 - BAR_PX));
        draw_plot(&plot, &fig, map, v, (&field, &bar, scale))?;
        draw_bar(&bar_area, &bar, label)?;
        legend::draw(&legend, v)?;
        root.present().map_err(err)?;
    }
    Ok(crate::sanitize::text(&finish(buf, &fig)).into_owned())
}
