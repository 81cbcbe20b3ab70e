//! The crosshair (`x`) as part of [`App::update`]: on, moved, to the next chart, off. Each
//! move says what it reads (src/tui/crosshair.rs) on the message row.

use super::{App, View};
use crate::tui::action::Action;
use crate::tui::crosshair::{self, Crosshair};

impl App {
    /// Show `view`: a crosshair belongs to the charts it was put on, so it goes (Tab,
    /// Shift+Tab and the drop, oblique and flight views' own keys).
    pub(in crate::tui) fn show_view(&mut self, view: View) {
        self.view = view;
        self.crosshair = None;
    }

    /// A view's own key (`d`, `i`, `h`): open the view `own`, or leave it for the impact view,
    /// as [`App::show_view`] does.
    pub(in crate::tui) fn toggle_view(&mut self, own: View) {
        self.show_view(self.view.toggled(own));
    }

    pub(super) fn crosshair_action(&mut self, action: Action) {
        match action {
            Action::Crosshair if self.crosshair.is_some() => self.crosshair_chart(1),
            Action::Crosshair => self.crosshair_chart(0),
            Action::CrosshairNext => self.crosshair_chart(1),
            Action::CrosshairOff => {
                self.crosshair = None;
                self.info("crosshair off".into());
            }
            Action::CrosshairMove { dx, dy } => {
                let Some(c) = self.crosshair else { return };
                let Some(fig) = self.crosshair_figure(c.chart) else {
                    return;
                };
                let c = c.step(&fig, f64::from(dx), f64::from(dy));
                self.crosshair = Some(c);
                self.info(crosshair::reading(&c, &fig));
            }
            _ => {}
        }
    }

    /// Put the crosshair on the chart `ahead` charts after the current one (0: the first),
    /// at the centre of its data; past the last chart it is off.
    fn crosshair_chart(&mut self, ahead: usize) {
        let n = self.chart_ids().len();
        if n == 0 {
            self.crosshair = None;
            return self.warn(self.no_chart_keys());
        }
        let k = match (self.crosshair, ahead) {
            (Some(c), a) if a > 0 => c.chart + a,
            _ => 0,
        };
        if k >= n {
            self.crosshair = None;
            self.info("crosshair off".into());
            return;
        }
        match self
            .crosshair_figure(k)
            .and_then(|f| crosshair::start(k, &f).map(|c| (c, f)))
        {
            Some((c, fig)) => {
                self.crosshair = Some(c);
                self.info(crosshair::reading(&c, &fig));
            }
            None => {
                self.crosshair = None;
                self.warn("nothing drawn yet to read".into());
            }
        }
    }

    /// The figure of chart `k` of the current view, as drawn.
    pub(super) fn crosshair_figure(&mut self, k: usize) -> Option<crate::figure::Figure> {
        self.refresh_run();
        let chart = *self.chart_ids().get(k)?;
        self.drawn_figure(chart)
    }

    /// The crosshair, when it is on a chart of the view shown.
    pub fn crosshair(&self) -> Option<&Crosshair> {
        self.crosshair
            .as_ref()
            .filter(|c| self.view != View::Map && c.chart < self.chart_ids().len())
    }
}
