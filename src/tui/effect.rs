//! What `App::update` asks the event loop to do: the explorer's only side effects. `update`
//! returns them; the loop carries them out and reports each outcome back as an action.

use super::export::ExportRequest;
use super::save::SaveRequest;
use crate::tui::views::map::state::MapJob;
use crate::tui::views::sweeps::speed::SpeedRequest;

#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// Write these figures (`e`); the loop answers `Action::Exported` or
    /// `Action::ExportFailed`.
    Export(ExportRequest),
    /// Write this preset file (`s`); the loop answers `Action::Saved`, `Action::SaveExists`
    /// or `Action::SaveFailed`.
    Save(SaveRequest),
    /// Run exactly these COR-vs-speed sweeps in the background, dropping any other that is
    /// out; each finished one comes back as `Action::SpeedReady`.
    Compute(Vec<SpeedRequest>),
    /// Read this measured file (`o`); the loop answers `Action::MeasuredLoaded` or
    /// `Action::MeasuredFailed`.
    LoadMeasured(std::path::PathBuf),
    /// Run this fit on the fit worker (`f`), replacing any not yet started; it comes back as
    /// `Action::FitReady`.
    Fit(crate::tui::views::fit::state::FitRequest),
    /// Run exactly these calibrations of the models view in the background (none: drop the
    /// one that is out); a finished one comes back as `Action::ModelsReady`.
    ComputeModels(Vec<crate::tui::views::models::state::ModelsRequest>),
    /// Refine this map in the background, pass by pass (a job before it stops on its own:
    /// `update` set its cancel flag); each pass comes back as `Action::MapPass`.
    Map(MapJob),
    /// Compute the oblique view's (angle, μ) map in the background (a job before it stops on
    /// its own: `update` set its cancel flag); it comes back as `Action::ObliqueMapReady`.
    // boxed: the job holds a whole ball (`api::Ball`), the largest variant by far
    ObliqueMap(Box<crate::tui::views::oblique::map::MapJob>),
    /// Read the presets for the picker (`g`); the loop answers `Action::PresetsListed`.
    ListPresets,
    /// Read the surfaces for the surface picker (`G`); the loop answers
    /// `Action::SurfacesListed`.
    ListSurfaces,
    /// Write this session file (`S`) atomically, over an existing file only with `replace`
    /// (the user said y); the loop answers `Action::SessionSaved`, `Action::SessionExists` or
    /// `Action::SessionFailed`.
    SaveSession {
        path: std::path::PathBuf,
        text: String,
        replace: bool,
    },
    /// Copy this text to the terminal's clipboard with OSC 52 (`y`,
    /// [`crate::tui::clipboard::osc52`]); a terminal without it ignores the sequence. No answer.
    Copy(String),
}

impl Effect {
    /// Whether the loop answers this effect itself and the answer can change what the next
    /// key does: the picker's list opens the picker, a measured file or a write may ask a
    /// question. Keys queued behind it wait for the answer (`G` with `↓ Enter` typed ahead
    /// picked nothing: the picker was still empty; tests/tui/tui_typeahead_pty.rs).
    pub fn answered_before_next_key(&self) -> bool {
        matches!(
            self,
            Effect::ListPresets
                | Effect::ListSurfaces
                | Effect::LoadMeasured(_)
                | Effect::Save(_)
                | Effect::SaveSession { .. }
                | Effect::Export(_)
        )
    }
}
