//! The read-only view of the explorer's state: what drawing, the event loop and tests read.

use super::{App, Ghost, Message, Mode, Overlay, SpeedCurve, SpeedRequest, View, ZetaCurve};
use crate::preset::Preset;
use crate::solver::ImpactResponse;
use crate::tui::param::Param;
use crate::tui::setting::Setting;

impl App {
    /// Sweeps still to come from the background worker (none once it stopped: they wait for
    /// `R`).
    pub fn speed_requests(&self) -> &[SpeedRequest] {
        if self.sweeps.stopped.is_some() {
            return &[];
        }
        &self.sweeps.wanted
    }

    pub fn presets(&self) -> &[Preset] {
        &self.presets
    }
    pub fn preset(&self) -> &Preset {
        &self.presets[self.setting.preset]
    }
    pub fn setting(&self) -> &Setting {
        &self.setting
    }
    pub fn selected(&self) -> Param {
        self.selected
    }
    pub fn coarse(&self) -> bool {
        self.coarse
    }
    pub fn view(&self) -> View {
        self.view
    }
    pub fn overlay(&self) -> &Overlay {
        &self.overlay
    }
    pub fn message(&self) -> Option<&Message> {
        self.message.as_ref()
    }
    pub fn color(&self) -> bool {
        self.color
    }
    /// The colours the terminal shows ([`App::with_color_depth`]).
    pub fn color_depth(&self) -> crate::tui::palette::Depth {
        self.depth
    }
    /// Draw for a terminal that shows `depth` colours (24-bit unless told).
    pub fn with_color_depth(mut self, depth: crate::tui::palette::Depth) -> App {
        self.depth = depth;
        self
    }
    /// The pinned runs, oldest first: `p1` is the first.
    pub fn pins(&self) -> &[Ghost] {
        &self.pins
    }
    /// The latest pin.
    pub fn ghost(&self) -> Option<&Ghost> {
        self.pins.last()
    }
    pub fn undo_depth(&self) -> usize {
        self.undo.len()
    }
    /// The first help line shown.
    pub fn help_scroll(&self) -> u16 {
        self.help_scroll
    }
    pub fn should_quit(&self) -> bool {
        self.quit
    }
    pub fn run(&self) -> Option<&ImpactResponse> {
        self.run.as_ref()
    }
    pub fn zeta_curve(&self) -> Option<&ZetaCurve> {
        self.zeta.as_ref()
    }
    pub fn speed_curve(&self) -> Option<&SpeedCurve> {
        self.sweeps.curve.as_ref()
    }

    /// What the keyboard is talking to.
    pub fn mode(&self) -> Mode {
        if self.too_small() {
            return Mode::TooSmall;
        }
        match self.overlay {
            Overlay::None if self.view == View::Map => Mode::Map,
            Overlay::None if self.crosshair().is_some() => Mode::Crosshair,
            Overlay::None if self.view == View::Oblique => self.oblique_mode(),
            Overlay::None if self.view == View::Flight => crate::tui::action::Mode::Flight,
            Overlay::None => Mode::Normal,
            // the command box closes, and scrolls nothing, like the help
            Overlay::Help | Overlay::Command(_) => Mode::Help,
            Overlay::Input(_) => Mode::Input,
            Overlay::Confirm(_) | Overlay::Ask(_) => Mode::Confirm,
            Overlay::Picker(_) | Overlay::Surfaces(_) => Mode::Picker,
            Overlay::Form(_) => Mode::Form,
            Overlay::Quit(_) => Mode::QuitConfirm,
        }
    }
}
