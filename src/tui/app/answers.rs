//! The event loop's answers, as part of `update`: what comes back from an effect (a written
//! or failed export, save or session, a measured file read, the presets listed) and the
//! workers' news (a sweep, a calibration, a fit's progress or outcome, a map's pass, a worker
//! gone). No key makes these.

use super::App;
use crate::tui::action::Action;
use crate::tui::export;

/// Whether `action` is one of the loop's answers ([`App::answer`] takes it).
pub(super) fn is_answer(action: &Action) -> bool {
    matches!(
        action,
        Action::SessionSaved(_)
            | Action::SessionExists { .. }
            | Action::SessionFailed { .. }
            | Action::PresetsListed(..)
            | Action::SurfacesListed(..)
            | Action::SpeedReady(..)
            | Action::ModelsReady(..)
            | Action::Exported { .. }
            | Action::ExportFailed { .. }
            | Action::Saved { .. }
            | Action::SaveExists { .. }
            | Action::SaveFailed { .. }
            | Action::MeasuredLoaded { .. }
            | Action::MeasuredFailed { .. }
            | Action::FitReady(..)
            | Action::MapPass { .. }
            | Action::ObliqueMapReady { .. }
            | Action::WorkerStopped { .. }
    )
}

/// Whether the message line stays as it is through `action`: the workers' news and the
/// clock, which come whatever the user does (every other action clears it first, and may
/// say something of its own).
pub(super) fn keeps_message(action: &Action) -> bool {
    matches!(
        action,
        Action::SpeedReady(..)
            | Action::ModelsReady(..)
            | Action::Tick(_)
            | Action::Resize(..)
            | Action::FitReady(..)
            | Action::MapPass { .. }
            | Action::ObliqueMapReady { .. }
    )
}

impl App {
    /// One of the loop's answers ([`is_answer`]).
    pub(super) fn answer(&mut self, action: Action) {
        match action {
            Action::SessionSaved(path) => {
                self.keep();
                self.session_held = Some(self.held());
                self.info(format!(
                    "session saved to {} (bouncelab --session {} restores it)",
                    path.display(),
                    path.display()
                ))
            }
            Action::SessionExists { path, text } => self.ask_session_overwrite(path, text),
            Action::SessionFailed { path, why } => self.session_failed(&path, why),
            Action::PresetsListed(..) => self.picker(action),
            Action::SurfacesListed(entries, error) => self.surfaces_listed(entries, error),
            Action::SpeedReady(request, result) => self.receive_speed(&request, result),
            Action::ModelsReady(request, result) => self.receive_models(request, result),
            Action::Exported { files } => self.info(export::message(&files)),
            Action::ExportFailed { msg } => self.error(format!("export failed: {msg}")),
            Action::Saved { path, replaced } => {
                // the ball is kept in its preset file: `q` need not ask for it (the oblique
                // inputs, which a preset does not hold, still count)
                self.kept.setting = self.setting.clone();
                self.saved(&path, replaced)
            }
            Action::SaveExists { path, holds } => self.ask_overwrite(path, holds),
            Action::SaveFailed { msg } => {
                self.save_out = None;
                self.error(format!("save failed: {msg}"));
            }
            Action::MeasuredLoaded { path, data } => self.measured_loaded(path, data),
            Action::MeasuredFailed { msg } => self.error(msg),
            Action::FitReady(id, result) => self.fit_ready(id, result),
            Action::MapPass { .. } => self.map_action(action),
            Action::ObliqueMapReady { generation, map } => {
                self.receive_oblique_map(generation, *map)
            }
            Action::WorkerStopped { work, why } => self.worker_stopped(work, why),
            _ => {}
        }
    }
}
