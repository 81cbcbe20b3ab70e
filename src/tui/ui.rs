//! Layout: header, charts, readout, status line, overlays — adapting to the terminal size.
//! Drawing reads the state and never changes it.

use super::app::{App, Overlay, View};
use super::widgets::plot::Plot;
use super::widgets::{
    confirm, cor_speed, cor_zeta, force_time, force_zeta, help, hysteresis, input, readout, status,
};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Below this the explorer asks for a larger terminal.
pub const MIN_WIDTH: u16 = 50;
pub const MIN_HEIGHT: u16 = 16;
/// From this width the readout is a panel beside the charts.
const SIDE_PANEL_WIDTH: u16 = 80;

/// The charts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Chart {
    ForceTime,
    Hysteresis,
    CorZeta,
    ForceZeta,
    CorSpeed,
}

impl Chart {
    /// The chart's plot for the current state.
    pub fn plot(self, app: &App) -> Plot {
        match self {
            Chart::ForceTime => force_time::plot(app),
            Chart::Hysteresis => hysteresis::plot(app),
            Chart::CorZeta => cor_zeta::plot(app),
            Chart::ForceZeta => force_zeta::plot(app),
            Chart::CorSpeed => cor_speed::plot(app),
        }
    }
}

/// The charts of a view, in screen order (left to right, top to bottom).
pub fn charts(view: View) -> &'static [Chart] {
    match view {
        View::Impact => &[Chart::ForceTime, Chart::Hysteresis, Chart::CorZeta],
        View::Sweeps => &[Chart::ForceZeta, Chart::CorSpeed],
        View::Drop => &[],
    }
}

/// The pieces of a usable screen.
#[derive(Debug, Clone, PartialEq)]
pub struct Screen {
    pub header: Rect,
    pub status: Rect,
    pub readout: Rect,
    /// Whether the readout is the tall side panel (or the compact strip).
    pub side_panel: bool,
    pub charts: Vec<(Chart, Rect)>,
}

/// Where everything goes, or `None` when the area is too small to use.
pub fn screen(app: &App, area: Rect) -> Option<Screen> {
    if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
        return None;
    }
    let [header, body, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(1),
    ])
    .areas(area);
    let side_panel = area.width >= SIDE_PANEL_WIDTH && body.height >= readout::PANEL_HEIGHT;
    let (charts, readout) = if side_panel {
        let w = (area.width * 3 / 10).clamp(32, 40);
        let [c, r] = Layout::horizontal([Constraint::Fill(1), Constraint::Length(w)]).areas(body);
        (c, r)
    } else {
        let [c, r] = Layout::vertical([
            Constraint::Fill(1),
            Constraint::Length(readout::COMPACT_HEIGHT),
        ])
        .areas(body);
        (c, r)
    };
    let charts = match app.view() {
        View::Impact => impact_grid(charts),
        View::Sweeps => sweeps_grid(charts),
        View::Drop => Vec::new(),
    };
    Some(Screen {
        header,
        status,
        readout,
        side_panel,
        charts,
    })
}

/// Force–time and force–displacement above COR vs ζ; all three in a row when short.
fn impact_grid(area: Rect) -> Vec<(Chart, Rect)> {
    if area.height >= 20 {
        let [top, bottom] = Layout::vertical([Constraint::Fill(1); 2]).areas(area);
        let [ft, fd] = Layout::horizontal([Constraint::Fill(1); 2]).areas(top);
        vec![
            (Chart::ForceTime, ft),
            (Chart::Hysteresis, fd),
            (Chart::CorZeta, bottom),
        ]
    } else {
        let [ft, fd, cz] = Layout::horizontal([Constraint::Fill(1); 3]).areas(area);
        vec![
            (Chart::ForceTime, ft),
            (Chart::Hysteresis, fd),
            (Chart::CorZeta, cz),
        ]
    }
}

/// Peak force vs ζ above COR vs speed; side by side when short.
fn sweeps_grid(area: Rect) -> Vec<(Chart, Rect)> {
    let [a, b] = if area.height >= 20 {
        Layout::vertical([Constraint::Fill(1); 2]).areas(area)
    } else {
        Layout::horizontal([Constraint::Fill(1); 2]).areas(area)
    };
    vec![(Chart::ForceZeta, a), (Chart::CorSpeed, b)]
}

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        let Some(s) = screen(self, area) else {
            let text = format!("enlarge the terminal: at least {MIN_WIDTH}×{MIN_HEIGHT}");
            Paragraph::new(Line::raw(text))
                .wrap(Wrap { trim: true })
                .render(area, buf);
            return;
        };
        status::render_header(self, s.header, buf);
        status::render_status(self, s.status, buf);
        if self.view() == View::Drop {
            let body = Rect::new(
                area.x,
                s.header.bottom(),
                area.width,
                s.status.y - s.header.bottom(),
            );
            super::widgets::drop::render(self, body, buf);
        } else if s.side_panel {
            readout::render_panel(self, s.readout, buf);
        } else {
            readout::render_compact(self, s.readout, buf);
        }
        for (chart, rect) in &s.charts {
            chart.plot(self).render(*rect, buf);
        }
        match self.overlay() {
            Overlay::None => {}
            Overlay::Help => help::render(self, area, buf),
            Overlay::Input(i) => input::render(self, i, area, buf),
            Overlay::Confirm(c) => confirm::render(self, c, area, buf),
        }
    }
}
