//! Layout: header, charts, readout, status line, overlays — adapting to the terminal size.
//! Drawing reads the state and never changes it: each panel gets the few things it shows,
//! each chart its figure, built from the state's [`crate::figure::explorer::Scene`].

mod render;

use super::app::{App, View};
use super::param::Param;
use super::theme::Theme;
use super::widgets::pins::PinView;
use super::widgets::readout::{self, Readout};
use super::widgets::status::message_lines;
pub use crate::figure::explorer::Chart;
use crate::figure::{Figure, explorer};
use crate::tui::views::fit::widget::FitView;
use crate::tui::views::map::widget::MapPanel;
use crate::tui::views::models::widget::ModelsTable;
use ratatui::layout::{Constraint, Layout, Rect};

pub use super::layout::SIDE_PANEL_WIDTH;
pub use super::state::{MIN_HEIGHT, MIN_WIDTH};
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
    /// The fit pane under the charts, while there is a fit (`f`).
    pub fit: Option<Rect>,
    /// The whole chart area (the map view draws its heat map there).
    pub chart_area: Rect,
}

/// Where everything goes, or `None` when the area is too small to use.
pub fn screen(app: &App, area: Rect) -> Option<Screen> {
    // the models view's table always goes beside its charts; the compact readout grows a line
    // for the pins' table; messages take their own rows above the key hints
    let compact = readout::compact_height(app.pins().len());
    let message_rows = message_lines(app.message(), area.width).len() as u16;
    let b = super::layout::body(area, app.view() == View::Models, compact, message_rows)?;
    let (charts, readout, fit) = if !b.side_panel && app.view() == View::Impact {
        // narrow: two panes a row, the readout the fourth (legends and units keep their room)
        let (body, fit) = split_fit(app, b.charts.union(b.readout));
        let (charts, readout) = narrow_impact_grid(body);
        (charts, readout, fit)
    } else {
        let (charts, fit) = split_fit(app, b.charts);
        let charts = match app.view() {
            View::Impact => impact_grid(charts),
            View::Sweeps => sweeps_grid(charts),
            View::Models => models_grid(charts),
            View::Drop | View::Map | View::Oblique | View::Flight => Vec::new(),
        };
        (charts, b.readout, fit)
    };
    Some(Screen {
        header: b.header,
        message: b.message,
        status: b.status,
        readout,
        side_panel: b.side_panel,
        charts,
        fit,
        chart_area: b.charts,
    })
}

/// The fit pane's view, while there is a fit and the view has charts (not the map's raster).
fn fit_view(app: &App, theme: Theme) -> Option<FitView<'_>> {
    // the map view's grid is sized by `update` from the whole chart area (layout::body)
    if matches!(
        app.view(),
        View::Drop | View::Map | View::Oblique | View::Flight
    ) {
        return None;
    }
    Some(FitView {
        pane: app.fit_pane()?,
        standing: app.fit_standing()?,
        theme,
    })
}

/// The charts' area less the fit pane's rows at its bottom (at most half of it).
fn split_fit(app: &App, charts: Rect) -> (Rect, Option<Rect>) {
    let Some(v) = fit_view(app, Theme::new(false)) else {
        return (charts, None);
    };
    let h = v.height(charts.width).min(charts.height / 2);
    let [c, f] = Layout::vertical([Constraint::Fill(1), Constraint::Length(h)]).areas(charts);
    (c, Some(f))
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

/// COR vs speed above force–time and force–displacement; all three in a row when short. (The
/// table beside them leaves the charts narrow on small terminals: stacked, each keeps a plot
/// down to 12 rows.)
fn models_grid(area: Rect) -> Vec<(Chart, Rect)> {
    let [cor, ft, fd] = if area.height >= 12 {
        let [top, bottom] = Layout::vertical([Constraint::Fill(1); 2]).areas(area);
        let [ft, fd] = Layout::horizontal([Constraint::Fill(1); 2]).areas(bottom);
        [top, ft, fd]
    } else {
        Layout::horizontal([Constraint::Fill(1); 3]).areas(area)
    };
    vec![
        (Chart::ModelsCorSpeed, cor),
        (Chart::ModelsForceTime, ft),
        (Chart::ModelsForceDisplacement, fd),
    ]
}

/// The models view's table of the state.
fn models_table(app: &App, theme: Theme) -> ModelsTable<'_> {
    let s = app.setting();
    ModelsTable {
        data: app.models(),
        error: app.models_error(),
        no_rebound: app.run().is_some_and(|r| !r.rebound),
        setting: (s.get(Param::Lambda), s.get(Param::Zeta), s.get(Param::V0)),
        theme,
    }
}

/// The pins as the readout's table shows them.
fn pin_views(app: &App) -> Vec<PinView<'_>> {
    app.pins()
        .iter()
        .map(|g| PinView {
            ball: app.presets()[g.setting.preset].name.as_str(),
            setting: &g.setting,
            run: g.run.as_ref(),
        })
        .collect()
}

/// The readout's view of the state.
fn readout<'a>(app: &'a App, pins: &'a [PinView<'a>], tall: bool, theme: Theme) -> Readout<'a> {
    Readout {
        preset: app.preset(),
        setting: app.setting(),
        selected: app.selected(),
        coarse: app.coarse(),
        run: app.run(),
        validity: app.validity(),
        calibration: app.calibration(),
        surface_warnings: app.surface_warnings(),
        pins,
        tall,
        theme,
    }
}

/// The map view's panel: the map, the current point, the other presets by their key.
fn map_panel(app: &App, theme: Theme) -> MapPanel<'_> {
    let s = app.setting();
    let presets = app
        .presets()
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != s.preset)
        .map(|(i, p)| {
            let n = p.params().normalized();
            (i + 1, n.lambda, n.zeta)
        })
        .collect();
    MapPanel {
        view: app.map_view(),
        point: (s.get(Param::Lambda), s.get(Param::Zeta)),
        presets,
        about: format!(
            "{} at v0 = {} m/s, {} law",
            app.preset().name,
            crate::text::sig_trim(s.params.v0, 4),
            s.law
        ),
        theme,
    }
}
