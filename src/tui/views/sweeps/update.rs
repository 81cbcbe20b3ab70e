//! Which COR-vs-speed sweeps the state needs, and where a finished one goes.

use crate::tui::app::{App, Effect, Setting, View};
use crate::tui::views::sweeps::speed::{SpeedCurve, SpeedRequest};

impl App {
    /// List the sweeps the sweeps view needs and does not have; run them here, or, with a
    /// background worker, ask for them when the list changed (not again after its worker
    /// stopped: src/tui/app/stopped.rs).
    pub(in crate::tui) fn refresh_sweeps(&mut self) -> Option<Effect> {
        self.sweeps.wanted.clear();
        if self.view == View::Sweeps {
            let (current, pins) = self.speed_targets();
            // a curve still being refined is wanted until its last point
            let stale = |have: Option<&SpeedCurve>, want: &SpeedRequest| {
                have.is_none_or(|c| c.request != *want || c.refining)
            };
            if stale(self.sweeps.curve.as_ref(), &current) {
                self.sweeps.wanted.push(current);
            }
            for (g, want) in self.pins.iter().zip(pins) {
                if stale(g.speed.as_ref(), &want) && !self.sweeps.wanted.contains(&want) {
                    self.sweeps.wanted.push(want);
                }
            }
        }
        if !self.background {
            for request in std::mem::take(&mut self.sweeps.wanted) {
                let result = request.run();
                self.receive_speed(&request, result);
            }
            return None;
        }
        // after a stop the same list waits for `R`; a new one goes to a new thread
        (self.sweeps.wanted != self.sweeps.asked).then(|| {
            self.sweeps.stopped = None;
            self.sweeps.asked = self.sweeps.wanted.clone();
            Effect::Compute(self.sweeps.wanted.clone())
        })
    }

    /// The sweeps the current setting and each pin (in order) need. They reach the measured
    /// file's fastest row too (a COR table or drop test): the sweep ends at 1.5 × the speed
    /// it is given at least, rounded up (`SpeedRequest::new`), so it is given 1/1.5 of that
    /// row's speed (a cannon's table to 50 m/s showed 2 of its 5 rows on a chart that ended
    /// at 20 m/s; tests/tui/tui_walk.rs).
    pub(in crate::tui) fn speed_targets(&self) -> (SpeedRequest, Vec<SpeedRequest>) {
        let fastest = self
            .fit
            .overlays
            .iter()
            .filter(|m| m.chart == crate::figure::explorer::Chart::CorSpeed)
            .flat_map(|m| m.points.iter().map(|p| p.0))
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max);
        let request = |s: &Setting| {
            let measured = self.presets[s.preset].measured.v0;
            SpeedRequest::new(&s.params, s.law, measured.max(fastest / 1.5))
        };
        (
            request(&self.setting),
            self.pins.iter().map(|g| request(&g.setting)).collect(),
        )
    }

    /// A finished sweep goes wherever it is (still) wanted. A failed one leaves an empty curve
    /// for its request, so it is not asked for again. A coarse one (`refining`) is drawn and
    /// stays wanted.
    pub(in crate::tui) fn receive_speed(
        &mut self,
        request: &SpeedRequest,
        result: Result<SpeedCurve, String>,
    ) {
        let refining = result.as_ref().is_ok_and(|c| c.refining);
        let curve = result.unwrap_or_else(|e| {
            self.error(e);
            SpeedCurve {
                request: request.clone(),
                points: Vec::new(),
                refining: false,
            }
        });
        let (current, pins) = self.speed_targets();
        if *request == current {
            self.sweeps.curve = Some(curve.clone());
        }
        for (g, want) in self.pins.iter_mut().zip(pins) {
            if *request == want {
                g.speed = Some(curve.clone());
            }
        }
        if !refining {
            self.sweeps.wanted.retain(|r| r != request);
        }
    }
}
