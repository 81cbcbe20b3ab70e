//! How a figure's series look in a terminal, as plain data: a colour role ([`Tone`]) the
//! explorer's theme turns into a colour (or none, under NO_COLOR), the short legend key, and
//! the text a marker prints. The SVG picture uses the series' palette colour and label instead.
//!
//! The terminal legend is derived from the series ([`legend`]): one entry per key, in series
//! order, so a chart's legend cannot disagree with what it draws.

use super::{Role, Series, Style};

/// A colour role on screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tone {
    /// The live model curve.
    Current,
    /// A second live curve (force against the contact indentation).
    Secondary,
    /// The i-th fixed reference curve (λ = 0, 0.4, 1).
    Reference(usize),
    /// Measured values.
    Measured,
    /// Pinned curves, dimmed.
    Ghost,
    /// This run's marker, and the permanent indentation.
    Highlight,
    /// Thresholds drawn as rules, in the axes' colour.
    Rule,
}

/// How one series looks in a terminal.
#[derive(Debug, Clone, PartialEq)]
pub struct Look {
    /// Its colour role.
    pub tone: Tone,
    /// The legend key; `None`: not in the terminal legend.
    pub key: Option<String>,
    /// Markers: the text printed at each point. Lines: a tag printed at the line's last
    /// point (a threshold's name). `None`: a marker prints "●", a line no tag.
    pub text: Option<String>,
}

impl Look {
    /// The look of a series of `role` before a builder names it: no legend key, no text.
    pub fn of(role: Role) -> Look {
        let tone = match role {
            Role::Model => Tone::Current,
            Role::Pinned => Tone::Ghost,
            Role::ThisRun => Tone::Highlight,
            Role::Measured => Tone::Measured,
            Role::Reference => Tone::Rule,
        };
        Look {
            tone,
            key: None,
            text: None,
        }
    }

    /// A look with its tone, legend key and text given.
    pub fn new(tone: Tone, key: Option<&str>, text: Option<&str>) -> Look {
        Look {
            tone,
            key: key.map(String::from),
            text: text.map(String::from),
        }
    }
}

/// Where the terminal legend goes inside the plot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Upper left.
    TopLeft,
    /// Upper right.
    TopRight,
    /// Lower left.
    BottomLeft,
    /// Lower right.
    BottomRight,
}

/// The sample in front of a legend key.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Sample {
    /// A curve: "━".
    Line,
    /// A measured value or threshold, or a curve drawn dotted: "┄".
    Dotted,
    /// A curve drawn dashed: "╍".
    Dashed,
    /// A curve drawn in long dashes: "═".
    LongDashed,
    /// Markers: their texts, e.g. "◆", or "S G B" for the balls' letters (then the whole
    /// entry takes the tone).
    Marks(Vec<String>),
}

/// One line of the terminal legend.
#[derive(Debug, Clone, PartialEq)]
pub struct LegendEntry {
    /// What is drawn in front of the key.
    pub sample: Sample,
    /// Its colour role.
    pub tone: Tone,
    /// The text.
    pub key: String,
    /// The series' colour ([`crate::figure::PALETTE`] index): a pin's or a measured file's
    /// own, which the terminal draws too (issue 51 item 6).
    pub color: usize,
}

/// Whether a terminal draws the series as a dotted line: thresholds, measured values (but a
/// second measured file, which the figure draws in long dashes), and model and pinned curves
/// the figure draws dotted.
pub fn dotted(s: &Series) -> bool {
    match s.kind {
        Role::Reference => !matches!(s.style, Style::Markers(_)),
        Role::Measured => !matches!(s.style, Style::Markers(_) | Style::LongDashed),
        Role::Model | Role::Pinned => s.style == Style::Dotted,
        Role::ThisRun => false,
    }
}

/// Whether a terminal draws the series dashed: model and pinned curves the figure draws
/// dashed, so that curves stay apart without colour (NO_COLOR), as in the SVG picture
/// (measured values the figure draws dashed, its thresholds, stay dotted on screen).
pub fn dashed(s: &Series) -> bool {
    matches!(s.kind, Role::Model | Role::Pinned) && s.style == Style::Dashed
}

/// Whether a terminal draws the series in long dashes (model, pinned and measured curves the
/// figure draws so).
pub fn long_dashed(s: &Series) -> bool {
    matches!(s.kind, Role::Model | Role::Pinned | Role::Measured) && s.style == Style::LongDashed
}

/// The legend of `series`: one entry per distinct (key, tone), in series order. Markers that
/// share a key gather their texts in one entry ("S G B measured"); a line and a marker that
/// share one ("pinned") keep the first's sample.
pub fn legend(series: &[Series]) -> Vec<LegendEntry> {
    let mut out: Vec<LegendEntry> = Vec::new();
    for s in series {
        let Some(key) = &s.look.key else { continue };
        let sample = match s.style {
            Style::Markers(_) => {
                Sample::Marks(vec![s.look.text.clone().unwrap_or_else(|| "●".into())])
            }
            _ if dotted(s) => Sample::Dotted,
            _ if dashed(s) => Sample::Dashed,
            _ if long_dashed(s) => Sample::LongDashed,
            _ => Sample::Line,
        };
        let same = out
            .iter_mut()
            .find(|e| e.key == *key && e.tone == s.look.tone);
        match (same, sample) {
            (Some(e), Sample::Marks(new)) => {
                if let Sample::Marks(have) = &mut e.sample {
                    have.extend(
                        new.into_iter()
                            .filter(|t| !have.contains(t))
                            .collect::<Vec<_>>(),
                    );
                }
            }
            (Some(_), _) => {}
            (None, sample) => out.push(LegendEntry {
                sample,
                tone: s.look.tone,
                key: key.clone(),
                color: s.color,
            }),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Marker, Series};

    fn marker(text: &str) -> Series {
        Series::new("", "", Role::Measured, Style::Markers(Marker::Circle), 0).with_look(Look::new(
            Tone::Measured,
            Some("measured"),
            Some(text),
        ))
    }

    #[test]
    fn legend_gathers_markers_and_keeps_series_order() {
        let model = Series::new("", "", Role::Model, Style::Solid, 0).with_look(Look::new(
            Tone::Current,
            Some("model"),
            None,
        ));
        let line = Series::new("", "", Role::Measured, Style::Dashed, 0).with_look(Look::new(
            Tone::Measured,
            Some("measured"),
            None,
        ));
        let unnamed = Series::new("", "", Role::Model, Style::Solid, 0);
        let got = legend(&[model, unnamed, marker("S"), marker("G"), marker("S"), line]);
        assert_eq!(got.len(), 2);
        assert_eq!(
            (got[0].sample.clone(), got[0].key.as_str()),
            (Sample::Line, "model")
        );
        assert_eq!(got[1].sample, Sample::Marks(vec!["S".into(), "G".into()]));
    }
}
