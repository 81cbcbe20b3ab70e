//! One file per chart or panel. Charts build a [`plot::Plot`] from the state (SI → N, ms, mm
//! here, when drawing) and render it; nothing here changes the state or runs the model.

pub mod axis;
pub mod confirm;
pub mod cor_speed;
pub mod cor_zeta;
pub mod drop;
pub mod force_time;
pub mod force_zeta;
pub mod help;
pub mod hysteresis;
pub mod input;
pub mod log_axis;
pub mod plot;
pub mod readout;
pub mod status;

use ratatui::style::Style;
use ratatui::text::{Line, Span};

/// A legend entry: a coloured sample and its text.
/// With an empty sample the text itself takes the style.
pub(crate) fn legend(sample: &'static str, style: Style, text: impl Into<String>) -> Line<'static> {
    if sample.is_empty() {
        return Line::styled(text.into(), style);
    }
    Line::from(vec![
        Span::styled(sample, style),
        Span::raw(" "),
        Span::raw(text.into()),
    ])
}

/// The letter that marks a ball's measured point: its name's initial.
pub(crate) fn initial(name: &str) -> String {
    name.chars()
        .next()
        .map_or("?".into(), |c| c.to_uppercase().collect())
}
