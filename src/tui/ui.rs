//! Layout: header, charts, readout, status line, overlays — adapting to the terminal size.
//! Drawing reads the state and never changes it: each panel gets the few things it shows,
//! each chart its figure, built from the state's [`crate::figure::explorer::Scene`].

use super::app::{App, Overlay, View};
use super::theme::Theme;
use super::widgets::confirm::ConfirmDialog;
use super::widgets::help::Help;
use super::widgets::input::InputDialog;
use super::widgets::plot::Plot;
use super::widgets::readout::{self, Readout};
use super::widgets::status::{Header, KeyHints, MessageLine, message_lines};
pub use crate::figure::explorer::Chart;
use crate::figure::{Figure, explorer};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};

pub use super::state::{MIN_HEIGHT, MIN_WIDTH};
/// From this width the readout is a panel beside the charts.
const SIDE_PANEL_WIDTH: u16 = 80;

/// The figure a chart shows for the current state (the one `e` exports).
pub fn figure(app: &App, chart: Chart) -> Figure {
    explorer::figure(chart, &app.scene())
}

/// The pieces of a usable screen.
#[derive(Debug, Clone, PartialEq)]
pub struct Screen {
    pub header: Rect,
    /// The message line(s) above the key hints.
    pub message: Rect,
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
    let message_rows = message_lines(app.message(), area.width).len() as u16;
    let [header, body, message, status] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Fill(1),
        Constraint::Length(message_rows),
        Constraint::Length(1),
    ])
    .areas(area);
    let side_panel = area.width >= SIDE_PANEL_WIDTH && body.height >= readout::PANEL_HEIGHT;
    let (charts, readout) = if side_panel {
        let w = (area.width * 3 / 10).clamp(32, 40);
        let [c, r] = Layout::horizontal([Constraint::Fill(1), Constraint::Length(w)]).areas(body);
        (
            match app.view() {
                View::Impact => impact_grid(c),
                View::Sweeps => sweeps_grid(c),
                View::Drop => Vec::new(),
            },
            r,
        )
    } else if app.view() == View::Impact {
        narrow_impact_grid(body)
    } else {
        let [c, r] = Layout::vertical([
            Constraint::Fill(1),
            Constraint::Length(readout::COMPACT_HEIGHT),
        ])
        .areas(body);
        (
            match app.view() {
                View::Sweeps => sweeps_grid(c),
                _ => Vec::new(),
            },
            r,
        )
    };
    Some(Screen {
        header,
        message,
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

/// Without room for the side panel (80×24, 60×20): two panes a row, so each chart keeps half
/// the width (its legend and units) — force–time and force–displacement above, COR vs ζ and
/// the compact readout below — rather than three charts and the panel in a row.
fn narrow_impact_grid(body: Rect) -> (Vec<(Chart, Rect)>, Rect) {
    let [top, bottom] = Layout::vertical([Constraint::Fill(1); 2]).areas(body);
    let [ft, fd] = Layout::horizontal([Constraint::Fill(1); 2]).areas(top);
    let [cz, r] = Layout::horizontal([Constraint::Fill(1); 2]).areas(bottom);
    let charts = vec![
        (Chart::ForceTime, ft),
        (Chart::Hysteresis, fd),
        (Chart::CorZeta, cz),
    ];
    (charts, r)
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

/// The readout's view of the state.
fn readout(app: &App, tall: bool, theme: Theme) -> Readout<'_> {
    let pinned = app
        .ghost()
        .map(|g| (&g.setting, app.presets()[g.setting.preset].name.as_str()));
    Readout {
        preset: app.preset(),
        setting: app.setting(),
        selected: app.selected(),
        coarse: app.coarse(),
        run: app.run(),
        pinned,
        tall,
        theme,
    }
}

/// The overlay on top of everything, if any.
fn render_overlay(app: &App, theme: Theme, area: Rect, buf: &mut Buffer) {
    match app.overlay() {
        Overlay::None => {}
        Overlay::Help => Help {
            theme,
            scroll: app.help_scroll(),
        }
        .render(area, buf),
        Overlay::Input(input) => InputDialog {
            input,
            setting: app.setting(),
            theme,
        }
        .render(area, buf),
        Overlay::Confirm(confirm) => ConfirmDialog { confirm, theme }.render(area, buf),
    }
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
        let theme = Theme::new(self.color());
        Header {
            ball: &self.preset().name,
            law: self.setting().law,
            view: self.view(),
            theme,
        }
        .render(s.header, buf);
        MessageLine {
            message: self.message(),
            theme,
        }
        .render(s.message, buf);
        KeyHints { theme }.render(s.status, buf);
        if self.view() == View::Drop {
            // the drop view takes the whole body (src/tui/widgets/drop.rs)
            let body = Rect::new(
                area.x,
                s.header.bottom(),
                area.width,
                s.message.y - s.header.bottom(),
            );
            super::widgets::drop::render(self, body, buf);
        } else {
            readout(self, s.side_panel, theme).render(s.readout, buf);
        }
        let scene = self.scene();
        for (chart, rect) in &s.charts {
            let fig = explorer::figure(*chart, &scene);
            Plot::new(&fig, theme).render(*rect, buf);
        }
        render_overlay(self, theme, area, buf);
    }
}
