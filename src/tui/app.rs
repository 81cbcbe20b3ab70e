//! The explorer's state and [`App::update`], the only place it changes. Curves are computed
//! here, when the state changes, and stored; drawing only reads them. `update` returns the
//! side effects it wants ([`Effect`]: write an export, write a preset, run sweeps in the
//! background) for the event loop to carry out. Its parts, one file a concern in `app/`:
//! `edit` (the keys that change the setting), `answers` (the loop's answers and the workers'
//! news), `stopped` (a worker gone, and `R`), `refresh` (bringing the curves up to date),
//! `dialogs`, `form`, `picker`, `pins`, `scene` (what the charts are drawn from) and the rest;
//! each view's part is in its folder's `update.rs` (src/tui/views/).

mod answers;
mod ask;
mod calibration;
mod charts;
mod command;
mod crosshair;
mod dialogs;
mod edit;
mod form;
mod getters;
mod picker;
mod pins;
mod quit;
mod refresh;
mod scene;
mod screen;
mod stopped;
mod surface;
mod undone;

use super::action::{Action, Mode};
use super::compute::{self, ZetaCurve};
pub use super::effect::Effect;
use super::export;
use super::param::Param;
use super::save::SaveRequest;
pub use super::state::{
    Ask, Confirm, Ghost, Input, MAX_PINS, Message, Overlay, Purpose, Setting, Severity, View,
};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::solver::ImpactResponse;
use crate::tui::views::drop::state::DropView;
use crate::tui::views::sweeps::speed::{SpeedCurve, SpeedRequest};
pub use ask::put_away_what;
pub use quit::Held;

/// How many changes `u` can undo.
const UNDO_DEPTH: usize = 500;

/// What `u` restores: the setting, the oblique view's θ, ω, μ, K_t, κ and the flight view's
/// launch and μ before a change (issue 57 item 3).
#[derive(Debug, Clone, PartialEq)]
pub(in crate::tui) struct Undoable {
    pub setting: Setting,
    pub oblique: crate::tui::views::oblique::state::ObliqueValues,
    pub flight: crate::tui::views::flight::state::FlightValues,
    /// The measured data and fit `O` put away (`u` puts them back); `None` for a change of
    /// the setting alone.
    pub measured: Option<Box<crate::tui::views::fit::state::FitState>>,
}

/// The explorer.
#[derive(Debug, Clone)]
pub struct App {
    pub(in crate::tui) presets: Vec<Preset>,
    pub(in crate::tui) setting: Setting,
    pub(in crate::tui) selected: Param,
    pub(in crate::tui) coarse: bool,
    pub(in crate::tui) view: View,
    pub(in crate::tui) overlay: Overlay,
    pub(in crate::tui) message: Option<Message>,
    pub(in crate::tui) color: bool,
    /// The colours the terminal shows (24-bit ones are brought down to them when drawn).
    pub(in crate::tui) depth: super::palette::Depth,
    /// The pinned runs, oldest first (at most [`MAX_PINS`]).
    pub(in crate::tui) pins: Vec<Ghost>,
    pub(in crate::tui) undo: Vec<Undoable>,
    /// The setting and oblique values as the explorer started or last saved them (`S`):
    /// `q` asks before losing a change from them (src/tui/app/quit.rs).
    pub(in crate::tui) kept: Undoable,
    pub(in crate::tui) quit: bool,
    /// The impact for `run_for`.
    pub(in crate::tui) run: Option<ImpactResponse>,
    pub(in crate::tui) run_for: Option<(ImpactParams, ContactLaw, crate::target::Target)>,
    /// The target's motion in `run`, when it meets a moving or compliant target.
    pub(in crate::tui) target_motion: Option<crate::figure::explorer::TargetMotion>,
    /// COR and F̄_m vs ζ at the current λ.
    pub(in crate::tui) zeta: Option<ZetaCurve>,
    /// COR vs speed, and the sweeps asked; computed only while the sweeps view shows it.
    pub(in crate::tui) sweeps: crate::tui::views::sweeps::state::Sweeps,
    pub(in crate::tui) background: bool,
    /// `e` was pressed: export once the view's curves are up to date.
    pub(in crate::tui) export_wanted: bool,
    /// The save handed to the event loop, until its answer comes back.
    pub(in crate::tui) save_out: Option<SaveRequest>,
    /// The drop view's sequence and animation clock.
    pub(in crate::tui) drop: DropView,
    /// Measured data, the data to fit and the fit pane.
    pub(in crate::tui) fit: crate::tui::views::fit::state::FitState,
    /// The models view's calibrations (src/tui/views/models/state.rs).
    pub(in crate::tui) models: crate::tui::views::models::state::Models,
    /// The first help line shown.
    pub(in crate::tui) help_scroll: u16,
    /// The preset file the explorer started on (`--config FILE`) and its preset's index.
    pub(in crate::tui) config: Option<(usize, std::path::PathBuf)>,
    /// The terminal's width and height, once the loop has said (`Action::Resize`).
    pub(in crate::tui) size: Option<(u16, u16)>,
    /// The map view's map, quantity, targets and window.
    pub(in crate::tui) map: crate::tui::views::map::state::MapView,
    /// The crosshair (`x`), when it is on.
    pub(in crate::tui) crosshair: Option<super::crosshair::Crosshair>,
    /// `y`'s copy: whether the terminal takes OSC 52, and the last line shown (printed on the
    /// main screen when the explorer ends: src/tui/app/command.rs).
    pub(in crate::tui) copy: command::CopyState,
    /// Each chart's normalize toggle and zoom (`N`, `+`, `-`, `0`: src/tui/chartview.rs).
    pub(in crate::tui) charts: super::chartview::ChartViews,
    /// The oblique view's angle, spin, friction, impact and map.
    pub(in crate::tui) oblique: crate::tui::views::oblique::state::ObliqueView,
    /// The flight view's launch, surface and shot.
    pub(in crate::tui) flight: crate::tui::views::flight::state::FlightView,
    /// The calibration warning as the last refresh found it (`App::calibration`): when one
    /// appears the message line says it whole (src/tui/app/calibration.rs).
    pub(in crate::tui) calibration_said: Option<String>,
    /// What the session last saved (`S`) or opened (`--session`) holds: `q` does not ask
    /// for those pins, that measured file and fit (src/tui/app/quit.rs).
    pub(in crate::tui) session_held: Option<Held>,
}

impl App {
    /// The explorer on `preset`; `color: false` draws without colours (NO_COLOR).
    /// The embedded balls are presets 1–3; a start preset that is none of them is the fourth.
    pub fn new(preset: Preset, color: bool) -> App {
        let mut presets = Preset::embedded();
        let index = match presets.iter().position(|p| *p == preset) {
            Some(i) => i,
            None => {
                presets.push(preset);
                presets.len() - 1
            }
        };
        let setting = Setting::from_preset(index, &presets[index]);
        let kept = Undoable {
            setting: setting.clone(),
            oblique: Default::default(),
            flight: Default::default(),
            measured: None,
        };
        let mut app = App {
            presets,
            setting,
            kept,
            selected: Param::Lambda,
            coarse: false,
            view: View::Impact,
            overlay: Overlay::None,
            message: None,
            color,
            depth: super::palette::Depth::TrueColor,
            pins: Vec::new(),
            undo: Vec::new(),
            quit: false,
            run: None,
            run_for: None,
            target_motion: None,
            zeta: None,
            sweeps: Default::default(),
            background: false,
            export_wanted: false,
            save_out: None,
            drop: DropView::new(false),
            fit: Default::default(),
            models: Default::default(),
            help_scroll: 0,
            config: None,
            size: None,
            map: Default::default(),
            crosshair: None,
            copy: Default::default(),
            charts: Default::default(),
            oblique: Default::default(),
            flight: Default::default(),
            calibration_said: None,
            session_held: None,
        };
        app.keep();
        app.refresh();
        app
    }

    /// Leave the COR-vs-speed sweeps to a background worker: [`App::refresh`] asks for them
    /// with [`Effect::Compute`] and the results come back as [`Action::SpeedReady`]. Without
    /// this (tests), `refresh` runs them itself.
    pub fn with_background_sweeps(mut self) -> App {
        self.background = true;
        self
    }

    /// Draw the user's measured data on the charts it belongs to.
    pub fn with_measured(mut self, m: Vec<crate::figure::explorer::MeasuredOverlay>) -> App {
        self.fit.overlays = m;
        self
    }

    /// Apply one action and bring the curves up to date; returns what the event loop is to
    /// do.
    pub fn update(&mut self, action: Action) -> Vec<Effect> {
        let mut effects = self.apply(action);
        effects.extend(self.refresh());
        effects
    }

    /// Apply one action without recomputing: for a batch of queued events, `apply` each, then
    /// [`App::refresh`] once.
    pub fn apply(&mut self, action: Action) -> Vec<Effect> {
        // `n` leaves `q`'s question on the small screen (and closes nothing else unseen)
        let leaves_question =
            action == Action::CloseHelp && matches!(self.overlay, Overlay::Quit(_));
        if self.too_small() && !App::acts_when_too_small(&action) && !leaves_question {
            return Vec::new();
        }
        if !answers::keeps_message(&action) {
            self.message = None;
        }
        if answers::is_answer(&action) {
            self.answer(action);
            return Vec::new();
        }
        match action {
            Action::Quit => self.ask_to_quit(),
            Action::QuitNow => self.quit = true,
            Action::SaveSession => self.open_input(
                crate::tui::state::Purpose::SessionPath,
                "bouncelab-session.toml".into(),
            ),
            Action::Dismiss => self.info("Esc closes dialogs and never quits: q quits".into()),
            Action::Resize(w, h) => self.resize(w, h),
            Action::HelpScroll(how) => self.scroll_help(how),
            Action::NextView | Action::PrevView => {
                let next = if action == Action::NextView {
                    self.view.next()
                } else {
                    self.view.prev()
                };
                self.show_view(next);
            }
            Action::Crosshair
            | Action::CrosshairNext
            | Action::CrosshairOff
            | Action::CrosshairMove { .. } => self.crosshair_action(action),
            Action::ToggleDrop | Action::DropPause | Action::DropReplay | Action::Tick(_) => {
                self.drop_action(&action)
            }
            Action::Export if self.view == View::Drop => self.warn(
                "the drop view has no export: `bouncelab drop --format csv` writes its data".into(),
            ),
            Action::Export => self.export_wanted = true,
            Action::OpenPicker => return vec![Effect::ListPresets],
            Action::OpenSurfaces => return vec![Effect::ListSurfaces],
            Action::PickerMove(_) | Action::PickerChoose => self.picker(action),
            Action::ClearMeasured => self.clear_measured(),
            Action::Fit => return self.start_fit().into_iter().collect(),
            Action::ApplyFit => self.apply_fit(),
            a if App::is_dialog(&a) => return self.dialog(a).into_iter().collect(),
            Action::OpenForm | Action::FormMove(_) | Action::FormEdit => self.form(action),
            Action::MapCursor { .. } | Action::MapQuantity | Action::MapTargets => {
                self.map_action(action)
            }
            Action::ShowCommand => return self.show_command(),
            Action::Normalize | Action::Zoom(_) => self.chart_view(action),
            Action::Oblique(key) => self.oblique_action(key),
            Action::Flight(key) => self.flight_action(key),
            Action::Retry => self.retry(),
            _ => self.edit(action),
        }
        Vec::new()
    }
}
