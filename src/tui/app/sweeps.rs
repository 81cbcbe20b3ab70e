//! Which COR-vs-speed sweeps the state needs, and where a finished one goes.

use super::{App, Setting};
use crate::tui::compute::{SpeedCurve, SpeedRequest};

impl App {
    /// The sweeps the current setting and the ghost need.
    pub(super) fn speed_targets(&self) -> (SpeedRequest, Option<SpeedRequest>) {
        let request =
            |s: &Setting| SpeedRequest::new(&s.params, s.law, self.presets[s.preset].measured.v0);
        (
            request(&self.setting),
            self.ghost.as_ref().map(|g| request(&g.setting)),
        )
    }

    /// A finished sweep goes wherever it is (still) wanted. A failed one leaves an empty curve
    /// for its request, so it is not asked for again.
    pub(super) fn receive_speed(
        &mut self,
        request: &SpeedRequest,
        result: Result<SpeedCurve, String>,
    ) {
        let curve = result.unwrap_or_else(|e| {
            self.error(e);
            SpeedCurve {
                request: request.clone(),
                points: Vec::new(),
            }
        });
        let (current, ghost) = self.speed_targets();
        if *request == current {
            self.speed = Some(curve.clone());
        }
        if let (Some(g), Some(want)) = (&mut self.ghost, ghost)
            && *request == want
        {
            g.speed = Some(curve);
        }
        self.speed_wanted.retain(|r| r != request);
    }
}
