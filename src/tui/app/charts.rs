//! `N`, `+`, `-`, `0`: the chart in focus — the crosshair's when it is on (`x`, Tab moves it
//! to the next chart), else the view's first — normalized or zoomed (src/tui/chartview.rs,
//! issue 29 item 10). A view, not a change of the ball: `u` does not undo it.

use super::{App, View};
use crate::tui::action::Action;
use crate::tui::chartview::{ChartView, ChartViews, MAX_ZOOM, normalizable};

impl App {
    /// Every chart's view.
    pub fn chart_views(&self) -> &ChartViews {
        &self.charts
    }

    pub(super) fn chart_view(&mut self, action: Action) {
        let k = self.crosshair().map_or(0, |c| c.chart);
        let Some(&chart) = self.view.charts().get(k) else {
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
    /// What `x`, `N`, `+`, `-` say in a view whose charts they do not read: where the
    /// numbers are instead. The oblique and drop views have charts (drawn with true ticks),
    /// so "no chart to read" was false there (issue 51 item 3;
    /// tests/tui_crosshair.rs: `chart_keys_say_what_works_where_they_do_not_read`).
    pub(super) fn no_chart_keys(&self) -> String {
        match self.view {
            View::Oblique => "x, N, +/- read the impact, sweeps and models views' charts; \
                 here the readout has the impact's numbers and e exports these charts (SVG + CSV)"
                .into(),
            View::Flight => "x, N, +/- read the impact, sweeps and models views' charts; \
                 here the readout has the shot's numbers and e exports the path (SVG + CSV)"
                .into(),
            View::Drop => "x, N, +/- read the impact, sweeps and models views' charts; here \
                 the readout has the rebounds, and `bouncelab drop --format csv` the flight"
                .into(),
            _ => format!(
                "the {} view reads with its cursor (arrows): x, N, +/- read the impact, sweeps \
                 and models views' charts",
                self.view.title()
            ),
        }
    }
}

impl App {
    /// A chart's name as its frame shows it ("COR vs speed", "Force–time"), never the
    /// export's file name ("peers-cor-velocity": issue 51 item 4, no internal names on screen;
    /// tests/tui_crosshair.rs: `chart_keys_say_what_works_where_they_do_not_read`).
    fn chart_name(&self, chart: crate::figure::explorer::Chart) -> String {
        let title = crate::tui::ui::figure(self, chart).screen_title;
        let first = title.split(" · ").next().unwrap_or(&title).trim();
        if first.is_empty() {
            "this chart".into()
        } else {
            first.to_string()
        }
    }
}
