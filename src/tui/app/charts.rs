//! `N`, `+`, `-`, `0`: the chart in focus — the crosshair's when it is on (`x`, Tab moves it
//! to the next chart), else the view's first — normalized or zoomed (src/tui/chartview.rs,
//! issue 29 item 10). A view, not a change of the ball: `u` does not undo it.

use super::{App, View};
use crate::figure::Figure;
use crate::tui::action::Action;
use crate::tui::chartview::{ChartId, ChartView, ChartViews, MAX_ZOOM, normalizable};
use crate::tui::views::oblique::state::Page;

impl App {
    /// Every chart's view.
    pub fn chart_views(&self) -> &ChartViews {
        &self.charts
    }

    /// The charts of the view shown, in the order `x` and Tab visit them: the figure layer's
    /// (impact, sweeps, models), the oblique view's F_n F_t, v_c and ω on its charts page once
    /// its impact is computed, the drop view's height chart (issue 51 item 3).
    pub fn chart_ids(&self) -> Vec<ChartId> {
        match self.view {
            View::Oblique => {
                let ov = self.oblique_view();
                if ov.page == Page::Charts && ov.response().is_some() {
                    vec![
                        ChartId::ObliqueForces,
                        ChartId::ObliqueSlip,
                        ChartId::ObliqueSpin,
                    ]
                } else {
                    Vec::new()
                }
            }
            View::Drop => vec![ChartId::DropHeight],
            v => v.charts().iter().map(|&c| ChartId::Explorer(c)).collect(),
        }
    }

    /// Chart `id`'s figure as drawn: with its normalize and zoom (`N`, `+`, `-`), without the
    /// crosshair.
    pub fn drawn_figure(&self, id: ChartId) -> Option<Figure> {
        let mut fig = self.chart_figure(id)?;
        crate::tui::chartview::apply(self.charts.get(id), id, &mut fig);
        Some(fig)
    }

    /// Chart `id`'s figure, whole and absolute (the one `e` exports).
    fn chart_figure(&self, id: ChartId) -> Option<Figure> {
        use crate::tui::views::{drop::widget::height_figure, oblique::charts::time_figures};
        let oblique = |i: usize| {
            let figs = time_figures(self.oblique_view().response()?)?;
            figs.into_iter().nth(i)
        };
        match id {
            ChartId::Explorer(chart) => Some(crate::tui::ui::figure(self, chart)),
            ChartId::ObliqueForces => oblique(0),
            ChartId::ObliqueSlip => oblique(1),
            ChartId::ObliqueSpin => oblique(2),
            ChartId::DropHeight => Some(height_figure(self.drop_view())),
        }
    }

    /// Chart `id`'s figure as the screen shows it: [`App::drawn_figure`] with the crosshair
    /// when it is on this chart.
    pub fn screen_figure(&self, id: ChartId) -> Option<Figure> {
        let mut fig = self.drawn_figure(id)?;
        if let Some(c) = self.crosshair()
            && self.chart_ids().get(c.chart) == Some(&id)
        {
            crate::tui::crosshair::draw_on(c, &mut fig);
        }
        Some(fig)
    }

    pub(super) fn chart_view(&mut self, action: Action) {
        let k = self.crosshair().map_or(0, |c| c.chart);
        let Some(&chart) = self.chart_ids().get(k) else {
            return self.warn(self.no_chart_keys());
        };
        let now = self.charts.get(chart);
        let name = self.chart_name(chart);
        let next = match action {
            Action::Normalize if !normalizable(chart) => {
                return self.warn(format!(
                    "{name}: only force charts normalize (F/F_m against t/t_f or α/α_max); \
                     x then Tab picks another chart"
                ));
            }
            Action::Normalize => ChartView {
                normalized: !now.normalized,
                ..now
            },
            Action::Zoom(0) => ChartView { zoom: 0, ..now },
            Action::Zoom(d) if d > 0 && now.zoom >= MAX_ZOOM => {
                return self.warn(format!("{name}: zoomed in as far as it goes (×1024)"));
            }
            Action::Zoom(d) => ChartView {
                zoom: now.zoom.saturating_add_signed(d.signum()),
                ..now
            },
            _ => return,
        };
        self.charts.set(chart, next);
        // the crosshair stays on this chart, at the centre of what it now shows
        if self.crosshair.is_some() {
            self.crosshair = self
                .crosshair_figure(k)
                .and_then(|fig| crate::tui::crosshair::start(k, &fig));
        }
        let what = match (next.normalized, next.zoom) {
            (true, 0) => "normalized: each run by its own F_m and t_f (N: absolute)".to_string(),
            (n, 0) => format!("whole data{}", if n { ", normalized" } else { "" }),
            (n, z) => format!(
                "zoom ×{} from the lower-left corner{} (0: whole data)",
                1u32 << z,
                if n { ", normalized" } else { "" }
            ),
        };
        self.info(format!("{name}: {what}"));
    }
}

impl App {
    /// What `x`, `N`, `+`, `-` say where no chart is drawn to read: the map's cursor reads
    /// the map; the oblique view's map page (and a failed impact) has none.
    pub(super) fn no_chart_keys(&self) -> String {
        match self.view {
            View::Oblique => "x, N, +/- read the oblique view's charts: t shows them \
                 (the readout has the impact's numbers)"
                .into(),
            View::Flight => "x, N, +/- read the impact, sweeps and models views' charts; \
                 here the readout has the shot's numbers and e exports the path (SVG + CSV)"
                .into(),
            _ => format!(
                "the {} view reads with its cursor (arrows): x, N, +/- read the charts of \
                 the other views",
                self.view.title()
            ),
        }
    }
}

impl App {
    /// A chart's name as its frame shows it ("COR vs speed", "Force–time"), never the
    /// export's file name ("peers-cor-velocity": issue 51 item 4, no internal names on screen;
    /// tests/tui/tui_crosshair.rs: `chart_keys_say_what_works_where_they_do_not_read`).
    fn chart_name(&self, chart: ChartId) -> String {
        let title = self
            .chart_figure(chart)
            .map(|f| f.screen_title)
            .unwrap_or_default();
        let first = title.split(" · ").next().unwrap_or(&title).trim();
        if first.is_empty() {
            "this chart".into()
        } else {
            first.to_string()
        }
    }
}
