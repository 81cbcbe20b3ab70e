//! Which calibration the models view needs, and where a finished one goes: kept only when it
//! is for the ball as it is now (a late answer for a ball the user has changed is dropped).

use crate::figure::explorer::models::ModelsData;
use crate::tui::app::{App, Effect, View};
use crate::tui::views::models::state::ModelsRequest;

impl App {
    /// The calibration the current ball needs: its Christoforou–Yigit COR at v0 as the target,
    /// the ball's radius (the preset's, or typed in the form). `None` without an impact to
    /// calibrate to, nor without a rebound (e 0: the peers take a COR in (0, 1]; the table
    /// says so in words).
    pub fn models_target(&self) -> Option<ModelsRequest> {
        let run = self.run.as_ref().filter(|r| r.rebound)?;
        let s = &self.setting;
        let radius = s.radius;
        Some(ModelsRequest::new(&s.params, s.law, radius, run.cor))
    }

    /// The calibration still to come from the background worker, if any.
    pub fn models_request(&self) -> Option<&ModelsRequest> {
        self.models.wanted.as_ref()
    }

    /// The calibrations for the current ball, once they are here.
    pub fn models(&self) -> Option<&ModelsData> {
        self.models.for_request(self.models_target().as_ref())
    }

    /// Why the calibration for the current ball failed, if it did.
    pub fn models_error(&self) -> Option<&str> {
        self.models.error_for(self.models_target().as_ref())
    }

    /// While the models view shows: ask for the calibration the ball needs and does not have;
    /// run it here, or, with a background worker, ask for it when that changed.
    pub(in crate::tui) fn refresh_models(&mut self) -> Option<Effect> {
        let target = self.models_target().filter(|_| self.view == View::Models);
        let held = self.models.held.as_ref().map(|h| &h.0);
        let wanted = target.filter(|t| held != Some(t));
        self.models.wanted = wanted;
        if !self.background {
            if let Some(request) = self.models.wanted.clone() {
                let result = request.run();
                self.receive_models(request, result);
            }
            return None;
        }
        (self.models.wanted != self.models.asked).then(|| {
            self.models.asked = self.models.wanted.clone();
            Effect::ComputeModels(self.models.wanted.iter().cloned().collect())
        })
    }

    /// A finished calibration is kept when it is for the ball as it is now, dropped otherwise.
    pub(in crate::tui) fn receive_models(
        &mut self,
        request: ModelsRequest,
        result: Result<ModelsData, String>,
    ) {
        if self.models_target().as_ref() != Some(&request) {
            return;
        }
        if let Err(e) = &result {
            let e = crate::tui::views::models::widget::human_names(e);
            self.error(format!("models: {e}"));
        }
        self.models.wanted = None;
        self.models.held = Some((request, result));
    }
}
