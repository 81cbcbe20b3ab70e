//! Where the screen's parts go for a terminal area: header, body (charts and readout), status
//! line. Pure geometry of a `Rect`, below `App`: `update` needs it too (the map view's grid
//! has one cell per half character of the chart area), and the drawing uses the same numbers.

use super::state::{MIN_HEIGHT, MIN_WIDTH};
use super::widgets::readout;
use ratatui::layout::{Constraint, Layout, Rect};

/// From this width the readout is a panel beside the charts.
pub const SIDE_PANEL_WIDTH: u16 = 80;

/// The parts of a usable screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Body {
    pub header: Rect,
    /// The message line(s) above the key hints (no rows without a message).
    pub message: Rect,
    pub status: Rect,
    pub readout: Rect,
    /// Whether the readout is the tall side panel (or the compact strip).
    pub side_panel: bool,
    /// Where the view's charts go.
    pub charts: Rect,
}

/// The parts for `area`, or `None` below the minimum size; `side` puts the readout beside the
/// charts whatever the size (the models view's table), `compact` is the readout strip's
/// height when it is not beside them (`readout::compact_height`), `message` the rows of the
/// message above the key hints (`status::message_lines`).
pub fn body(area: Rect, side: bool, compact: u16, message: u16) -> Option<Body> {
    if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
        return None;
    }
    let [header, body, message, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(message),
        Constraint::Length(1),
    ])
    .areas(area);
    let side_panel =
        (area.width >= SIDE_PANEL_WIDTH && body.height >= readout::PANEL_HEIGHT) || side;
    let w = (area.width * 3 / 10).clamp(32, 40);
    let (charts, readout) = charts_and_readout(body, side_panel, w, compact);
    Some(Body {
        header,
        message,
        status,
        readout,
        side_panel,
        charts,
    })
}

/// `area` split into the charts and their readout: a column `width` wide on the right when
/// `beside`, else a strip `rows` high below — the screen's body, and the drop and flight
/// views within it.
pub fn charts_and_readout(area: Rect, beside: bool, width: u16, rows: u16) -> (Rect, Rect) {
    let [charts, readout] = if beside {
        Layout::horizontal([Constraint::Fill(1), Constraint::Length(width)]).areas(area)
    } else {
        Layout::vertical([Constraint::Fill(1), Constraint::Length(rows)]).areas(area)
    };
    (charts, readout)
}
