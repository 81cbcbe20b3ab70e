//! The user's measured data on the explorer's charts (`bouncelab --measured FILE`), and the
//! speed it was measured at: a force trace belongs to one impact speed only.

use super::explorer::Chart;
use super::{Kind, Look, Marker, Series, Style, Tone};

/// Measured data on one chart (`bouncelab --measured FILE`), labelled by its file name;
/// points in SI on the chart's axes ([`crate::measured::overlay`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredOverlay {
    /// The legend's label (the file's name).
    pub label: String,
    /// The chart the points belong on.
    pub chart: Chart,
    /// (x, y) in the chart's SI units.
    pub points: Vec<(f64, f64)>,
    /// The impact speed it was measured at (m/s), for data of one impact (a force trace):
    /// drawn only while the explorer runs at that speed. `None`: data across speeds.
    pub v0: Option<f64>,
}

/// Whether `v0` is the speed `at` a measurement was taken: the tolerance of
/// [`crate::ball::Ball::measured_at`].
pub fn same_speed(at: f64, v0: f64) -> bool {
    (at - v0).abs() <= 1e-9 * at
}

impl MeasuredOverlay {
    /// The charts `data` can be drawn on: a trace on force–time and (with the ball's `mass`
    /// and `v0`) force–displacement, a COR table or drop test on COR against speed.
    pub fn from_data(
        data: &crate::measured::Data,
        label: &str,
        mass: f64,
        v0: f64,
    ) -> Result<Vec<MeasuredOverlay>, crate::measured::MeasuredError> {
        use crate::measured::{Data, overlay};
        let one = |chart, points, at| MeasuredOverlay {
            label: label.to_string(),
            chart,
            points,
            v0: at,
        };
        Ok(match data {
            Data::Trace(t) => vec![
                one(Chart::ForceTime, overlay::aligned(t)?, Some(v0)),
                one(
                    Chart::Hysteresis,
                    overlay::displacement(t, mass, v0)?,
                    Some(v0),
                ),
            ],
            _ => vec![one(
                Chart::CorSpeed,
                overlay::cor_points(data).unwrap_or_default(),
                None,
            )],
        })
    }

    pub(super) fn series(&self) -> Series {
        Series::new(
            &self.label,
            &format!("measured {}", self.label),
            Kind::Measured,
            Style::Markers(Marker::Circle),
            super::BLACK,
        )
        .with_points(self.points.clone())
        .with_look(Look::new(Tone::Measured, Some(&self.label), Some("+")))
    }
}
