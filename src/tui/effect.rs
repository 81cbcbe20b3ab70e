//! What `App::update` asks the event loop to do: the explorer's only side effects. `update`
//! returns them; the loop carries them out and reports each outcome back as an action.

use super::compute::SpeedRequest;
use super::export::ExportRequest;
use super::save::SaveRequest;

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
    /// Read the presets for the picker (`g`); the loop answers `Action::PresetsListed`.
    ListPresets,
}
