//! The explorer's state and [`App::update`], the only place it changes. Curves are computed
//! here, when the state changes, and stored; drawing only reads them. `update` returns the
//! side effects it wants ([`Effect`]: write an export, write a preset, run sweeps in the
//! background) for the event loop to carry out. The dialogs (value entry, preset name,
//! overwrite question) are handled in `dialogs`, the COR-vs-speed sweeps' bookkeeping in
//! `sweeps`, and what the charts are drawn from in `scene`.

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
mod scene;
mod screen;

use super::action::{Action, Mode};
use super::compute::{self, ZetaCurve};
pub use super::effect::Effect;
use super::export;
use super::param::Param;
use super::save::SaveRequest;
pub use super::state::{
    Confirm, Ghost, Input, MAX_PINS, Message, Overlay, Purpose, Setting, Severity, View,
};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::solver::ImpactResponse;
use crate::tui::views::drop::state::DropView;
use crate::tui::views::sweeps::speed::{SpeedCurve, SpeedRequest};

/// How many changes `u` can undo.
const UNDO_DEPTH: usize = 500;

/// What `u` restores: the setting and the oblique view's θ, ω, μ, K_t, κ before a change.
#[derive(Debug, Clone, PartialEq)]
pub(in crate::tui) struct Undoable {
    pub setting: Setting,
    pub oblique: crate::tui::views::oblique::state::ObliqueValues,
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
        let mut app = App {
            presets,
            setting,
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
        };
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
        if self.too_small() && !App::acts_when_too_small(&action) {
            return Vec::new();
        }
        if !matches!(
            action,
            Action::SpeedReady(..)
                | Action::ModelsReady(..)
                | Action::Tick(_)
                | Action::Resize(..)
                | Action::FitReady(..)
                | Action::MapPass { .. }
                | Action::ObliqueMapReady { .. }
        ) {
            self.message = None;
        }
        match action {
            Action::Quit => self.ask_to_quit(),
            Action::QuitNow => self.quit = true,
            Action::SaveSession => self.open_input(
                crate::tui::state::Purpose::SessionPath,
                "bouncelab-session.toml".into(),
            ),
            Action::SessionSaved(path) => self.info(format!(
                "session saved to {} (bouncelab --session {} restores it)",
                path.display(),
                path.display()
            )),
            Action::SessionFailed(why) => self.error(format!("session not saved: {why}")),
            Action::Dismiss => self.info("Esc closes dialogs and never quits: q quits".into()),
            Action::Resize(w, h) => self.resize(w, h),
            Action::HelpScroll(how) => self.scroll_help(how),
            Action::NextView => {
                self.view = self.view.next();
                self.crosshair = None;
            }
            Action::PrevView => {
                self.view = self.view.prev();
                self.crosshair = None;
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
            Action::PresetsListed(..) | Action::PickerMove(_) | Action::PickerChoose => {
                self.picker(action)
            }
            Action::SpeedReady(..)
            | Action::ModelsReady(..)
            | Action::Exported { .. }
            | Action::ExportFailed { .. }
            | Action::Saved { .. }
            | Action::SaveExists { .. }
            | Action::SaveFailed { .. } => self.answer(action),
            Action::MeasuredLoaded { path, data } => self.measured_loaded(path, data),
            Action::MeasuredFailed { msg } => self.error(msg),
            Action::FitReady(id, result) => self.fit_ready(id, result),
            Action::ClearMeasured => self.clear_measured(),
            Action::Fit => return self.start_fit().into_iter().collect(),
            Action::ApplyFit => self.apply_fit(),
            Action::OpenInput
            | Action::InputChar(_)
            | Action::InputBackspace
            | Action::InputClear
            | Action::InputDelete
            | Action::InputCursor(_)
            | Action::InputSubmit
            | Action::InputCancel
            | Action::SavePreset
            | Action::ConfirmYes
            | Action::ConfirmNo
            | Action::OpenMeasured
            | Action::ToggleHelp
            | Action::CloseHelp => return self.dialog(action).into_iter().collect(),
            Action::OpenForm | Action::FormMove(_) | Action::FormEdit => self.form(action),
            Action::MapCursor { .. }
            | Action::MapQuantity
            | Action::MapTargets
            | Action::MapPass { .. } => self.map_action(action),
            Action::ShowCommand => return self.show_command(),
            Action::Normalize | Action::Zoom(_) => self.chart_view(action),
            Action::Oblique(key) => self.oblique_action(key),
            Action::ObliqueMapReady { generation, map } => {
                self.receive_oblique_map(generation, *map)
            }
            _ => self.edit(action),
        }
        Vec::new()
    }

    /// The actions that change the setting, the selection or the ghost.
    fn edit(&mut self, action: Action) {
        match action {
            Action::Step { param, dir, coarse } => {
                self.selected = param;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.step_param(param, value);
            }
            Action::StepSelected { dir, coarse } => {
                let param = self.selected;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.step_param(param, value);
            }
            Action::SelectNext => self.selected = self.selected.next(),
            Action::SelectPrev => self.selected = self.selected.prev(),
            Action::SetCoarse(coarse) => {
                self.coarse = coarse;
                self.info(if coarse { "coarse steps" } else { "fine steps" }.into());
            }
            Action::LoadPreset(i) => self.load_preset(i),
            Action::CycleLaw => {
                let law = self.setting.law.next();
                self.change(Setting {
                    law,
                    ..self.setting.clone()
                });
                self.info(format!("contact law: {law}"));
            }
            Action::Reset => {
                let i = self.setting.preset;
                self.change(Setting::from_preset(i, &self.presets[i]));
                self.info(format!("reset to the {} preset", self.presets[i].name));
            }
            Action::Pin => self.pin(),
            Action::Unpin => self.unpin(),
            Action::Undo => match self.undo.pop() {
                Some(previous) => {
                    self.setting = previous.setting;
                    self.oblique.set_values(previous.oblique);
                    self.info("undone".into());
                }
                None => self.warn("nothing to undo".into()),
            },
            _ => {}
        }
    }

    /// The event loop's answers: a finished sweep, a written (or failed) export or save.
    fn answer(&mut self, action: Action) {
        match action {
            Action::SpeedReady(request, result) => self.receive_speed(&request, result),
            Action::ModelsReady(request, result) => self.receive_models(request, result),
            Action::Exported { files } => self.info(export::message(&files)),
            Action::ExportFailed { msg } => self.error(format!("export failed: {msg}")),
            Action::Saved { path, replaced } => self.saved(&path, replaced),
            Action::SaveExists { path, holds } => self.ask_overwrite(path, holds),
            Action::SaveFailed { msg } => {
                self.save_out = None;
                self.error(format!("save failed: {msg}"));
            }
            _ => {}
        }
    }

    fn load_preset(&mut self, i: usize) {
        match self.presets.get(i) {
            Some(p) => {
                let name = p.name.clone();
                self.change(Setting::from_preset(i, p));
                self.info(format!("loaded {name}"));
            }
            // 4 loads a start preset that is none of the three; the help offers it, so
            // say why it does nothing here (tests/tui_app.rs: `four_says_why_it_loads_nothing`)
            None if i == 3 => self.warn(format!(
                "4 loads the start preset when it is not one of 1–3: 1–{} load one",
                self.presets.len()
            )),
            None => self.warn(format!(
                "no preset {}: 1–{} load one",
                i + 1,
                self.presets.len()
            )),
        }
    }

    /// Recompute what the current state needs and is not up to date: the impact when the
    /// parameters or law changed, the ζ curve when λ changed, the speed sweep when the sweeps
    /// view shows it. Returns the sweeps to ask of the background worker when they changed,
    /// and an export once one is wanted and the view is up to date.
    pub fn refresh(&mut self) -> Vec<Effect> {
        self.refresh_run();
        if self.view == View::Drop {
            let preset = &self.presets[self.setting.preset];
            self.drop
                .refresh(&self.setting.params, self.setting.law, preset);
        }
        let mut effects: Vec<Effect> = self.refresh_sweeps().into_iter().collect();
        effects.extend(self.refresh_models());
        effects.extend(self.refresh_map());
        effects.extend(self.refresh_oblique());
        if self.export_wanted {
            effects.extend(self.prepare_export());
        }
        effects
    }

    /// Bring the impact and the ζ curve up to the setting (a batch of keys applies several
    /// actions before one refresh: `p` after `2` in one batch must pin golf's run).
    pub(super) fn refresh_run(&mut self) {
        let s = &self.setting;
        // the pair's run: the reduced ball at the closing speed, or on the target's surface
        let key = (s.params, s.law, s.target());
        if self.run_for != Some(key) {
            self.run_for = Some(key);
            (self.run, self.target_motion) = match compute::pair(s) {
                Ok((run, motion)) => (Some(run), motion),
                Err(e) => {
                    self.error(e);
                    (None, None)
                }
            };
        }
        let lambda = self.setting.get(Param::Lambda);
        if self.zeta.as_ref().is_none_or(|c| c.lambda != lambda) {
            self.zeta = compute::zeta_curve(lambda).map_err(|e| self.error(e)).ok();
        }
    }

    /// The export of what is on screen, once it is up to date: while a COR-vs-speed sweep is
    /// still out the export waits for it (and says so).
    fn prepare_export(&mut self) -> Option<Effect> {
        if self.view == View::Map {
            return self.prepare_map_export();
        }
        if self.view == View::Oblique {
            return self.prepare_oblique_export();
        }
        if !self.sweeps.wanted.is_empty() {
            self.info("export waits for the COR-vs-speed sweep…".into());
            return None;
        }
        if self.models.wanted.is_some() {
            self.info("export waits for the models' calibration…".into());
            return None;
        }
        self.export_wanted = false;
        match export::request(&self.scene(), self.view.charts()) {
            Ok(r) => Some(Effect::Export(r.with_header(self.csv_header()))),
            Err(e) => {
                self.error(format!("export failed: {e}"));
                None
            }
        }
    }
}
