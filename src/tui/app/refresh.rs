//! Bringing what the state shows up to date after actions (`App::refresh`): the impact and the
//! ζ curve here, each view's background work through its own part (`refresh_sweeps`,
//! `refresh_models`, `refresh_map`, `refresh_oblique`), and an export once it is wanted and
//! what it writes is ready.

use super::{App, Effect, View, compute, export};
use crate::tui::param::Param;

impl App {
    /// Recompute what the current state needs and is not up to date: the impact when the
    /// parameters or law changed, the ζ curve when λ changed, the speed sweep when the sweeps
    /// view shows it. Returns the sweeps to ask of the background worker when they changed,
    /// and an export once one is wanted and the view is up to date.
    pub fn refresh(&mut self) -> Vec<Effect> {
        self.refresh_run();
        if self.view == View::Drop {
            let preset = &self.presets[self.setting.preset];
            self.drop
                .refresh(&self.setting.params, self.setting.law, preset);
        }
        let mut effects: Vec<Effect> = self.refresh_sweeps().into_iter().collect();
        effects.extend(self.refresh_models());
        effects.extend(self.refresh_map());
        effects.extend(self.refresh_oblique());
        if self.view == View::Flight {
            self.refresh_flight();
        }
        if self.export_wanted {
            effects.extend(self.prepare_export());
        }
        self.say_calibration();
        effects
    }

    /// Bring the impact and the ζ curve up to the setting (a batch of keys applies several
    /// actions before one refresh: `p` after `2` in one batch must pin golf's run).
    pub(super) fn refresh_run(&mut self) {
        let s = &self.setting;
        // the pair's run: the reduced ball at the closing speed, or on the target's surface
        let key = (s.params, s.law, s.target);
        if self.run_for != Some(key) {
            self.run_for = Some(key);
            (self.run, self.target_motion) = match compute::pair(s) {
                Ok((run, motion)) => (Some(run), motion),
                Err(e) => {
                    self.error(e);
                    (None, None)
                }
            };
        }
        let lambda = self.setting.get(Param::Lambda);
        if self.zeta.as_ref().is_none_or(|c| c.lambda != lambda) {
            self.zeta = compute::zeta_curve(lambda).map_err(|e| self.error(e)).ok();
        }
    }

    /// The export of what is on screen, once it is up to date (while a sweep, the models'
    /// calibration or the map's refinement is still out the export waits, and says so); once
    /// there is a request or a reason why not, the export is no longer wanted.
    fn prepare_export(&mut self) -> Option<Effect> {
        let request = match self.view {
            View::Map => self.map_export(),
            // the flight and oblique views compute in `update` itself: nothing to wait for
            View::Flight => Some(self.flight_export()),
            View::Oblique => Some(self.oblique_export()),
            _ => self.charts_export(),
        }?;
        self.export_wanted = false;
        match request {
            Ok(r) => Some(Effect::Export(r)),
            Err(why) => {
                self.error(why);
                None
            }
        }
    }

    /// The export of the view's charts, or why not; `None` while a sweep or the models'
    /// calibration it draws is still out (the export waits, and says so).
    fn charts_export(&mut self) -> Option<Result<export::ExportRequest, String>> {
        if !self.sweeps.wanted.is_empty() {
            if let Some(why) = &self.sweeps.stopped {
                let why =
                    format!("export failed: the COR-vs-speed sweep stopped: {why} (R retries)");
                return Some(Err(why));
            }
            self.info("export waits for the COR-vs-speed sweep…".into());
            return None;
        }
        if self.models.wanted.is_some() {
            self.info("export waits for the models' calibration…".into());
            return None;
        }
        let request = export::request(&self.scene(), self.view.charts());
        Some(
            request
                .map(|r| r.with_header(self.csv_header()))
                .map_err(|e| format!("export failed: {e}")),
        )
    }
}
