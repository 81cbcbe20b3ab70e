//! The side view of a shot (`bouncelab shot --svg-out`, docs/flight.md): the centre's path,
//! the surface, the launch, each bounce and the end marked.

use super::{Axis, BLACK, Figure, GREY, Kind, Marker, Series, Style};
use crate::api::ShotReport;
use crate::text::given;

/// The figure of `shot` of a ball of radius `r` (the path drawn from its trajectory samples),
/// titled `title` and subtitled `subtitle`.
pub fn side_view(shot: &ShotReport, r: f64, title: String, subtitle: String) -> Figure {
    let path: Vec<(f64, f64)> = shot.trajectory.iter().map(|s| (s.x, s.y)).collect();
    let x_end = path.iter().map(|p| p.0).fold(0.0_f64, f64::max);
    let x_start = path.iter().map(|p| p.0).fold(0.0_f64, f64::min);
    let surface = Series::new(
        "surface (centre at y = R)",
        "surface",
        Kind::Reference,
        Style::Solid,
        GREY,
    )
    .with_points(vec![(x_start, r), (x_end, r)]);
    let line =
        Series::new("path of the centre", "path", Kind::Model, Style::Solid, 0).with_points(path);
    let mut bounces = Series::new(
        "bounce",
        "bounce",
        Kind::Model,
        Style::Markers(Marker::Circle),
        1,
    )
    .with_points(shot.bounces.iter().map(|b| (b.x, r)).collect());
    bounces.annotations = shot
        .bounces
        .iter()
        .map(|b| format!("{} m/s at {}°", given(b.v_in, 3), given(b.angle_in, 3)))
        .collect();
    let e = shot.end.state;
    let mut end = Series::new(
        "end",
        "end",
        Kind::Model,
        Style::Markers(Marker::Square),
        BLACK,
    )
    .with_points(vec![(e.x, e.y)]);
    end.annotations = vec![format!("x = {} m", given(e.x, 4))];
    Figure::new(
        title,
        subtitle,
        Axis::linear("x (m)", "x", 1.0),
        Axis::linear("height of the centre (m)", "y", 1.0),
        vec![surface, line, bounces, end],
    )
}
