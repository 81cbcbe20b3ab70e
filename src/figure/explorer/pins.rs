//! How a pin looks: its tag, its labels, its colour, its series.

use super::{Pinned, lambda_zeta_text};
use crate::figure::{GREY, Kind, Look, Marker, Series, Style, Tone};
use crate::text::short;

/// Palette colours of pins 1, 2, … in the picture (grey first, as the one ghost always was;
/// never orange, this run's colour). On screen every pin is dimmed and tagged `p1`, `p2`, ….
const PIN_COLORS: [usize; 7] = [GREY, 5, 3, 2, 0, 1, 6];

/// The line patterns of pins 1, 2, …: each pin its own beside the next without colour
/// (NO_COLOR, greyscale print; issue 51 item 6), the first dotted as the one ghost always was.
const PIN_STYLES: [Style; 3] = [Style::Dotted, Style::Dashed, Style::LongDashed];

impl Pinned<'_> {
    /// "p2": the tag at the pin's curves on screen.
    pub fn tag(&self) -> String {
        format!("p{}", self.number)
    }

    /// The pin as the picture's legend names it: number, ball, parameters, law.
    pub fn label(&self) -> String {
        format!(
            "pinned {}: {} ({}, v0 = {} m/s, {} law)",
            self.number,
            self.ball,
            lambda_zeta_text(&self.params),
            short(self.params.v0, 3),
            self.law
        )
    }

    /// The pin as the terminal legend names it, short enough for a chart's corner: "p2
    /// golf"; the readout's pin table gives its parameters and differences.
    pub fn key(&self) -> String {
        format!("{} {}", self.tag(), self.ball)
    }

    pub(super) fn color(&self) -> usize {
        PIN_COLORS[(self.number.max(1) - 1) % PIN_COLORS.len()]
    }

    /// The pin's curve: dimmed and tagged on screen, a dotted line of its colour in the
    /// picture; `what` ends its CSV id ("model", "displacement", "lambda=0.4").
    pub(super) fn curve(&self, what: &str, points: Vec<(f64, f64)>) -> Series {
        let id = format!("pinned {} {what}", self.number);
        let tag = self.tag();
        Series::new(
            &self.label(),
            &id,
            Kind::Pinned,
            PIN_STYLES[(self.number.max(1) - 1) % PIN_STYLES.len()],
            self.color(),
        )
        .with_points(points)
        .with_look(Look::new(Tone::Ghost, Some(&self.key()), Some(&tag)))
    }

    /// The pin's run on a ζ chart: its number, dimmed, over the point; in the legend under
    /// the pins' one entry there ("pinned"), as the ζ charts' legends are long already.
    pub(super) fn marker(&self, at: (f64, f64)) -> Series {
        let id = format!("pinned {} run", self.number);
        let number = self.number.to_string();
        let look = Look::new(Tone::Ghost, Some("pinned"), Some(&number));
        Series::new(
            &format!("{} run", self.label()),
            &id,
            Kind::Pinned,
            Style::Markers(Marker::Diamond),
            self.color(),
        )
        .with_points(vec![at])
        .with_look(look)
    }
}
