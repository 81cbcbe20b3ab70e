//! The user's measured data on the explorer's charts (`bouncelab --measured FILE`), and the
//! speed it was measured at: a force trace belongs to one impact speed only.

use super::chart::Chart;
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

    /// The `i`th file's data (from 0): a trace (hundreds of samples of one impact) as a dotted
    /// line, which leaves the model's curve visible under it; a few points across speeds (a
    /// COR table) as `+` markers. A second file's trace is in long dashes (its points `×`), a
    /// third's points `*`, each file in a colour of its own: files told apart without colour
    /// (issue 51 item 6; a third trace is dotted again, in its own colour: the terminal's
    /// dashed pattern is the measured thresholds').
    pub(super) fn series(&self, i: usize) -> Series {
        const LINES: [Style; 2] = [Style::Dotted, Style::LongDashed];
        const MARKS: [&str; 3] = ["+", "×", "*"];
        const COLORS: [usize; 3] = [super::BLACK, 1, 2];
        let trace = matches!(self.chart, Chart::ForceTime | Chart::Hysteresis);
        let (style, text) = if trace {
            (LINES[i % LINES.len()], None)
        } else {
            (Style::Markers(Marker::Circle), Some(MARKS[i % MARKS.len()]))
        };
        Series::new(
            &self.label,
            &format!("measured {}", self.label),
            Kind::Measured,
            style,
            COLORS[i % COLORS.len()],
        )
        .with_points(self.points.clone())
        .with_look(Look::new(Tone::Measured, Some(&self.label), text))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::overlay::pulse_text;
    use crate::measured::parse_any;

    /// A trace of hundreds of samples is a dotted line (markers would cover the model's curve
    /// under them); a COR table's few points are `+` markers.
    #[test]
    fn a_trace_is_a_line_and_a_cor_table_markers() {
        let text = pulse_text(|k| 100.0 * (std::f64::consts::PI * k / 200.0).sin());
        let trace =
            MeasuredOverlay::from_data(&parse_any(&text).unwrap(), "t.csv", 0.0459, 1.47).unwrap();
        assert_eq!(trace.len(), 2);
        for o in &trace {
            let s = o.series(0);
            assert_eq!(s.style, Style::Dotted, "{:?}", o.chart);
            assert_eq!(s.look.text, None);
        }
        let table = parse_any("v0,cor\n1,0.8\n2,0.78\n3,0.75\n").unwrap();
        let cor = MeasuredOverlay::from_data(&table, "c.csv", 0.0459, 1.47).unwrap();
        let s = cor[0].series(0);
        assert_eq!(s.style, Style::Markers(Marker::Circle));
        assert_eq!(s.look.text.as_deref(), Some("+"));
        // issue 51 item 6: a second file has its own glyph and colour (all were `+`/dotted
        // and black)
        let second = cor[0].series(1);
        assert_eq!(second.look.text.as_deref(), Some("×"));
        assert_ne!(second.color, s.color);
        let second_trace = trace[0].series(1);
        assert_eq!(second_trace.style, Style::LongDashed);
        assert_ne!(second_trace.color, trace[0].series(0).color);
    }
}
