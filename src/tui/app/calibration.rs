//! Whether the answer on screen lies outside the ball's calibration record: the library's own
//! "outside calibration: …" warning ([`crate::Ball::calibration_warning`], issue 52 item 2),
//! which the readouts show beside the model's validity warning.

use super::{App, View};
use crate::tui::state::Severity;

impl App {
    /// The library's "outside calibration: …" warning for the answer the current view shows:
    /// the oblique impact's at its normal speed v sin θ (as `bouncelab oblique` warns,
    /// [`crate::Ball::oblique_warnings`]), the impact's at the explorer's v0 (as `bouncelab
    /// run`) in the views whose readout shows it (impact, sweeps, models, map); `None` inside
    /// the record's range, for a ball with no record, and in the drop and flight views, whose
    /// impacts run at other speeds (not yet checked there).
    pub fn calibration(&self) -> Option<String> {
        let v = match self.view {
            View::Oblique => self.oblique.response()?.vy_in,
            View::Drop | View::Flight => return None,
            View::Impact | View::Sweeps | View::Models | View::Map => self.setting.params.v0,
        };
        let ball = self.oblique_ball();
        ball.calibration_warning(v)
    }

    /// The message line says the calibration warning whole when the explorer opens outside
    /// the record (nothing to undo yet: a change's own message, "λ = 0.31", is not pushed
    /// aside), where the short readouts show it cut to a line. A warning or error already on
    /// the message line stays; the calibration warning said before gives way to the one that
    /// holds now (the oblique view's, at v sin θ, once the explorer opens there), or goes when
    /// none does.
    pub(super) fn say_calibration(&mut self) {
        let now = self.calibration();
        let said = self.message.as_ref().map(|m| &m.text);
        let ours = said.is_some() && said == self.calibration_said.as_ref();
        if ours && now != self.calibration_said {
            match &now {
                Some(w) => self.warn(w.clone()),
                // back inside the record (or in a view whose answer is inside it)
                None => self.message = None,
            }
        }
        let quiet = self
            .message
            .as_ref()
            .is_none_or(|m| m.severity == Severity::Info);
        if let Some(w) = &now
            && self.calibration_said.is_none()
            && self.undo.is_empty()
            && quiet
        {
            self.warn(w.clone());
        }
        self.calibration_said = now;
    }
}
