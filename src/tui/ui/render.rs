//! The explorer drawn whole (`impl Widget for &App`): the header, message and key-hint rows,
//! the view's body, the charts and the fit pane, then the overlay on top.

use super::{Screen, fit_view, map_panel, models_table, pin_views, readout, screen};
use crate::tui::app::{App, Overlay, View};
use crate::tui::chartview::ChartId;
use crate::tui::state::{MIN_HEIGHT, MIN_WIDTH};
use crate::tui::theme::Theme;
use crate::tui::views::oblique::param::ObliqueParam;
use crate::tui::widgets::command::CommandBox;
use crate::tui::widgets::confirm::ConfirmDialog;
use crate::tui::widgets::help::Help;
use crate::tui::widgets::input::InputDialog;
use crate::tui::widgets::picker::PickerBox;
use crate::tui::widgets::plot::Plot;
use crate::tui::widgets::status::{Header, KeyHints, MessageLine, surface_words};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};

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
        Overlay::Ask(ask) => {
            crate::tui::widgets::confirm::AskDialog { ask, theme }.render(area, buf)
        }
        Overlay::Command(line) => CommandBox {
            line,
            copied: app.osc52(),
            theme,
        }
        .render(area, buf),
        Overlay::Quit(lost) => {
            crate::tui::widgets::quit::QuitDialog { lost, theme }.render(area, buf)
        }
        Overlay::Picker(picker) => PickerBox { picker, theme }.render(area, buf),
        Overlay::Surfaces(picker) => {
            crate::tui::widgets::surfaces::SurfacesBox { picker, theme }.render(area, buf)
        }
        Overlay::Form(form) => crate::tui::widgets::form::FormBox {
            form: *form,
            setting: app.setting(),
            surface: app.form_surface(),
            warning: app.validity(),
            theme,
        }
        .render(area, buf),
    }
}

/// A terminal too small to use: what size it needs (and `q`'s question, when asked).
fn render_too_small(app: &App, area: Rect, buf: &mut Buffer) {
    let mut text = format!("enlarge the terminal: at least {MIN_WIDTH}×{MIN_HEIGHT}");
    // `q` asked, with no room for its dialog: the question here
    if let Overlay::Quit(lost) = app.overlay() {
        text = format!("Quit and lose {lost}? q or y quits · n stays. {text}");
    }
    Paragraph::new(Line::raw(text))
        .wrap(Wrap { trim: true })
        .render(area, buf);
}

/// The header, the message line and the key hints.
fn render_bars(app: &App, s: &Screen, theme: Theme, buf: &mut Buffer) {
    // the compact readout has no row for the surface: the header names it
    let surface = (!s.side_panel).then(|| surface_words(app.setting()));
    Header {
        ball: &app.preset().name,
        surface: surface.as_deref(),
        law: app.setting().law,
        view: app.view(),
        theme,
    }
    .render(s.header, buf);
    MessageLine {
        message: app.message(),
        theme,
    }
    .render(s.message, buf);
    KeyHints {
        theme,
        map: app.view() == View::Map,
        drop: app.view() == View::Drop,
        drop_paused: app.view() == View::Drop && app.drop_view().paused(),
        oblique: (app.view() == View::Oblique).then(|| app.oblique_view().page),
        flight: app.view() == View::Flight,
    }
    .render(s.status, buf);
}

/// The drop, flight and oblique views in the whole `body`; the others' readout (or the
/// models view's table) in its place.
fn render_body(app: &App, s: &Screen, body: Rect, theme: Theme, buf: &mut Buffer) {
    if app.view() == View::Drop {
        let chart = app
            .screen_figure(ChartId::DropHeight)
            .unwrap_or_else(|| crate::tui::views::drop::widget::height_figure(app.drop_view()));
        crate::tui::views::drop::widget::DropPanel {
            drop: app.drop_view(),
            ball: &app.preset().name,
            chart: &chart,
            theme,
        }
        .render(body, buf);
    } else if app.view() == View::Flight {
        crate::tui::views::flight::widget::FlightPanel {
            view: app.flight_view(),
            ball: &app.preset().name,
            radius: app.setting().radius,
            theme,
        }
        .render(body, buf);
    } else if app.view() == View::Oblique {
        render_oblique(app, body, theme, buf);
    } else if app.view() == View::Models {
        models_table(app, theme).render(s.readout, buf);
    } else {
        let pins = pin_views(app);
        readout(app, &pins, s.side_panel, theme).render(s.readout, buf);
    }
}

/// The oblique view's panel, with its three time charts when all are at hand.
fn render_oblique(app: &App, body: Rect, theme: Theme, buf: &mut Buffer) {
    let time = [
        ChartId::ObliqueForces,
        ChartId::ObliqueSlip,
        ChartId::ObliqueSpin,
    ]
    .map(|id| app.screen_figure(id));
    let time = match time {
        [Some(a), Some(b), Some(c)] => Some([a, b, c]),
        _ => None,
    };
    let surface = app.oblique_surface_line();
    let calibration = app.calibration();
    let surface_warnings = app.oblique_surface_warnings();
    crate::tui::views::oblique::widget::ObliquePanel {
        view: app.oblique_view(),
        time: time.as_ref(),
        ball: &app.preset().name,
        v0: app.setting().params.v0,
        tangential: [
            app.oblique_value(ObliqueParam::TangentialStiffness),
            app.oblique_value(ObliqueParam::InertiaFactor),
        ],
        surface: (&surface.0, surface.1),
        calibration: calibration.as_deref(),
        surface_warnings: &surface_warnings,
        theme,
    }
    .render(body, buf);
}

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        let Some(s) = screen(self, area) else {
            render_too_small(self, area, buf);
            return;
        };
        let theme = Theme::new(self.color());
        render_bars(self, &s, theme, buf);
        // the drop, flight and oblique views take the whole body, between the header and the
        // message line (src/tui/views/{drop,flight,oblique}/widget.rs)
        let body = Rect::new(
            area.x,
            s.header.bottom(),
            area.width,
            s.message.y - s.header.bottom(),
        );
        render_body(self, &s, body, theme, buf);
        if self.view() == View::Map {
            map_panel(self, theme).render(s.chart_area, buf);
        }
        for (chart, rect) in &s.charts {
            if let Some(fig) = self.screen_figure(ChartId::Explorer(*chart)) {
                Plot::new(&fig, theme).render(*rect, buf);
            }
        }
        if let (Some(rect), Some(v)) = (s.fit, fit_view(self, theme)) {
            v.render(rect, buf);
        }
        render_overlay(self, theme, area, buf);
        // the map's 24-bit cells in colours the terminal shows
        crate::tui::palette::bring_down(buf, area, self.color_depth());
    }
}
