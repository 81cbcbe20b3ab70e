//! A worker that stopped (its thread gone: a panic in a sweep, calibration, fit or map job),
//! as part of `update`: the view whose computation it was stops saying "computing" and says
//! that it stopped and why, the message line too, and nothing is handed to a worker for it
//! again until `R` (or a new request: another ball, a new map), which the event loop gives to
//! a new thread (src/tui/event.rs). Asking again by itself could panic again forever.

use super::App;
use crate::tui::background::Work;
use crate::tui::views::fit::state::FitStatus;

impl App {
    /// `work`'s worker is gone (`why`: "it panicked: …").
    pub(in crate::tui) fn worker_stopped(&mut self, work: Work, why: String) {
        let again = match work {
            Work::Sweeps => {
                self.sweeps.stopped = Some(why.clone());
                "R retries"
            }
            Work::Models => {
                if let Some(request) = self.models.wanted.take() {
                    let text = format!("stopped: {why} (R retries)");
                    self.models.held = Some((request, Err(text)));
                }
                self.models.stopped = Some(why.clone());
                "R retries"
            }
            Work::Fit => {
                if let Some(pane) = self.fit.pane.as_mut()
                    && pane.status == FitStatus::Running
                {
                    pane.status = FitStatus::Done(Err(format!("stopped: {why}")));
                }
                "f fits again"
            }
            Work::Map => {
                self.map.job.out = None;
                self.map.job.stopped = Some(why.clone());
                "R retries"
            }
            Work::ObliqueMap => {
                self.oblique.job.out = None;
                self.oblique.map = Some(Err(format!("stopped: {why} (R retries)")));
                self.oblique.job.stopped = Some(why.clone());
                "R retries"
            }
        };
        self.error(format!("{} stopped: {why} ({again})", work.name()));
    }

    /// `R`: every computation that stopped is asked for again (by the view that shows it, at
    /// the refresh after this), each on a new thread.
    pub(in crate::tui) fn retry(&mut self) {
        let mut again = Vec::new();
        if self.sweeps.stopped.take().is_some() {
            self.sweeps.asked.clear();
            again.push(Work::Sweeps);
        }
        if self.models.stopped.take().is_some() {
            (self.models.held, self.models.asked) = (None, None);
            again.push(Work::Models);
        }
        if self.map.job.stopped.take().is_some() {
            again.push(Work::Map);
        }
        if self.oblique.job.stopped.take().is_some() {
            (self.oblique.map, self.oblique.map_for) = (None, None);
            again.push(Work::ObliqueMap);
        }
        if again.is_empty() {
            return self.warn("nothing stopped to retry (a stopped fit: f fits again)".into());
        }
        let names: Vec<&str> = again.iter().map(|w| w.name()).collect();
        self.info(format!("retrying {}", names.join(", ")));
    }
}
