//! The explorer's state and [`App::update`], the only place it changes. Curves are computed
//! here, when the state changes, and stored; drawing only reads them. The dialogs (value entry,
//! preset name, overwrite question) are handled in `dialogs`, the COR-vs-speed sweeps'
//! bookkeeping in `sweeps`.

mod dialogs;
mod sweeps;

use super::action::{Action, Mode};
use super::compute::{self, SpeedCurve, SpeedRequest, ZetaCurve};
use super::export::{self, ExportRequest};
use super::format::sig_trim;
use super::param::Param;
use super::save::SaveRequest;
pub use super::state::{Confirm, Ghost, Input, Message, Overlay, Purpose, Setting, Severity, View};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::solver::ImpactResponse;

/// How many changes `u` can undo.
const UNDO_DEPTH: usize = 500;

/// The explorer.
#[derive(Debug, Clone)]
pub struct App {
    presets: Vec<Preset>,
    setting: Setting,
    selected: Param,
    coarse: bool,
    view: View,
    overlay: Overlay,
    message: Option<Message>,
    color: bool,
    ghost: Option<Ghost>,
    undo: Vec<Setting>,
    quit: bool,
    /// The impact for `run_for`.
    run: Option<ImpactResponse>,
    run_for: Option<(ImpactParams, ContactLaw)>,
    /// COR and F̄_m vs ζ at the current λ.
    zeta: Option<ZetaCurve>,
    /// COR vs speed; computed only while the sweeps view shows it.
    speed: Option<SpeedCurve>,
    /// Sweeps to run in the background (see [`App::with_background_sweeps`]).
    speed_wanted: Vec<SpeedRequest>,
    background: bool,
    /// `e` was pressed: export once the view's curves are up to date.
    export_wanted: bool,
    /// An export for the event loop to write (see [`App::export_request`]).
    export: Option<ExportRequest>,
    /// A preset file for the event loop to write (see [`App::save_request`]).
    save: Option<SaveRequest>,
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
            ghost: None,
            undo: Vec::new(),
            quit: false,
            run: None,
            run_for: None,
            zeta: None,
            speed: None,
            speed_wanted: Vec::new(),
            background: false,
            export_wanted: false,
            export: None,
            save: None,
        };
        app.refresh();
        app
    }

    /// Leave the COR-vs-speed sweeps to a background worker: [`App::refresh`] lists them in
    /// [`App::speed_requests`] and the results come back as [`Action::SpeedReady`]. Without
    /// this (tests), `refresh` runs them itself.
    pub fn with_background_sweeps(mut self) -> App {
        self.background = true;
        self
    }

    /// Sweeps waiting for the background worker.
    pub fn speed_requests(&self) -> &[SpeedRequest] {
        &self.speed_wanted
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
    pub fn ghost(&self) -> Option<&Ghost> {
        self.ghost.as_ref()
    }
    pub fn undo_depth(&self) -> usize {
        self.undo.len()
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
        self.speed.as_ref()
    }

    /// An export waiting to be written: the event loop writes it with [`export::write`] and
    /// answers with [`Action::Exported`] or [`Action::ExportFailed`], which clear it.
    pub fn export_request(&self) -> Option<&ExportRequest> {
        self.export.as_ref()
    }

    /// A preset file waiting to be written: the event loop writes it with
    /// [`super::save::write`] and answers with [`Action::Saved`], [`Action::SaveExists`] or
    /// [`Action::SaveFailed`], which clear it.
    pub fn save_request(&self) -> Option<&SaveRequest> {
        self.save.as_ref()
    }

    /// What the keyboard is talking to.
    pub fn mode(&self) -> Mode {
        match self.overlay {
            Overlay::None => Mode::Normal,
            Overlay::Help => Mode::Help,
            Overlay::Input(_) => Mode::Input,
            Overlay::Confirm(_) => Mode::Confirm,
        }
    }

    /// Apply one action and bring the curves up to date.
    pub fn update(&mut self, action: Action) {
        self.apply(action);
        self.refresh();
    }

    /// Apply one action without recomputing: for a batch of queued events, `apply` each, then
    /// [`App::refresh`] once.
    pub fn apply(&mut self, action: Action) {
        if !matches!(action, Action::SpeedReady(..)) {
            self.message = None;
        }
        match action {
            Action::SpeedReady(request, result) => self.receive_speed(&request, result),
            Action::Quit => self.quit = true,
            Action::Step { param, dir, coarse } => {
                self.selected = param;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.set_param(param, value);
            }
            Action::StepSelected { dir, coarse } => {
                let param = self.selected;
                let value = param.step(self.setting.get(param), dir, coarse || self.coarse);
                self.set_param(param, value);
            }
            Action::SelectNext => self.selected = self.selected.next(),
            Action::SelectPrev => self.selected = self.selected.prev(),
            Action::SetCoarse(coarse) => {
                self.coarse = coarse;
                self.info(if coarse { "coarse steps" } else { "fine steps" }.into());
            }
            Action::OpenInput => self.open_input(Purpose::Value(self.selected), String::new()),
            Action::InputChar(c) => self.input_char(c),
            Action::InputBackspace => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.text.pop();
                }
            }
            Action::InputSubmit => self.submit_input(),
            Action::InputCancel => self.cancel_input(),
            Action::CloseHelp => self.overlay = Overlay::None,
            Action::ToggleHelp => {
                self.overlay = match self.overlay {
                    Overlay::Help => Overlay::None,
                    _ => Overlay::Help,
                }
            }
            Action::LoadPreset(i) => match self.presets.get(i) {
                Some(p) => {
                    let name = p.name.clone();
                    self.change(Setting::from_preset(i, p));
                    self.info(format!("loaded {name}"));
                }
                None => self.warn(format!(
                    "no preset {}: 1–{} load one",
                    i + 1,
                    self.presets.len()
                )),
            },
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
            Action::Pin => {
                self.ghost = Some(Ghost {
                    setting: self.setting.clone(),
                    run: self.run.clone(),
                    zeta: self.zeta.clone(),
                    speed: self.speed.clone(),
                });
                self.info("pinned: the current curves stay as a dimmed ghost (P clears)".into());
            }
            Action::Unpin => {
                if self.ghost.take().is_some() {
                    self.info("ghost cleared".into());
                }
            }
            Action::Undo => match self.undo.pop() {
                Some(previous) => {
                    self.setting = previous;
                    self.info("undone".into());
                }
                None => self.warn("nothing to undo".into()),
            },
            Action::NextView | Action::PrevView => self.view = self.view.other(),
            Action::Export => self.export_wanted = true,
            Action::Exported { files } => {
                self.export = None;
                self.info(export::message(&files));
            }
            Action::ExportFailed { msg } => {
                self.export = None;
                self.error(format!("export failed: {msg}"));
            }
            Action::SavePreset => self.open_save(),
            Action::Saved { path, replaced } => self.saved(&path, replaced),
            Action::SaveExists { path, holds } => self.ask_overwrite(path, holds),
            Action::SaveFailed { msg } => {
                self.save = None;
                self.error(format!("save failed: {msg}"));
            }
            Action::ConfirmYes => self.confirm(true),
            Action::ConfirmNo => self.confirm(false),
        }
    }

    /// Recompute what the current state needs and is not up to date: the impact when the
    /// parameters or law changed, the ζ curve when λ changed, the speed sweep when the sweeps
    /// view shows it.
    pub fn refresh(&mut self) {
        let s = &self.setting;
        let key = (s.params, s.law);
        if self.run_for != Some(key) {
            self.run_for = Some(key);
            self.run = compute::impact(&s.params, s.law)
                .map_err(|e| self.error(e))
                .ok();
        }
        let lambda = self.setting.get(Param::Lambda);
        if self.zeta.as_ref().is_none_or(|c| c.lambda != lambda) {
            self.zeta = compute::zeta_curve(lambda).map_err(|e| self.error(e)).ok();
        }
        self.speed_wanted.clear();
        if self.view == View::Sweeps {
            let (current, ghost) = self.speed_targets();
            let stale = |have: Option<&SpeedCurve>, want: &SpeedRequest| {
                have.is_none_or(|c| c.request != *want)
            };
            if stale(self.speed.as_ref(), &current) {
                self.speed_wanted.push(current);
            }
            if let (Some(g), Some(want)) = (&self.ghost, ghost)
                && stale(g.speed.as_ref(), &want)
                && !self.speed_wanted.contains(&want)
            {
                self.speed_wanted.push(want);
            }
            if !self.background {
                for request in std::mem::take(&mut self.speed_wanted) {
                    let result = request.run();
                    self.receive_speed(&request, result);
                }
            }
        }
        if self.export_wanted {
            self.prepare_export();
        }
    }

    /// The export of what is on screen, once it is up to date: while a COR-vs-speed sweep is
    /// still out the export waits for it (and says so).
    fn prepare_export(&mut self) {
        if !self.speed_wanted.is_empty() {
            self.info("export waits for the COR-vs-speed sweep…".into());
            return;
        }
        self.export_wanted = false;
        match export::request(self) {
            Ok(r) => self.export = Some(r),
            Err(e) => self.error(format!("export failed: {e}")),
        }
    }

    /// Set `param` to `value` brought into range; a note when it had to move.
    fn set_param(&mut self, param: Param, value: f64) {
        let Some((v, moved)) = param.clamp(value) else {
            self.warn(format!("{} must be a finite number", param.symbol()));
            return;
        };
        if moved {
            self.warn(format!(
                "{} held at {}{} (range {})",
                param.symbol(),
                sig_trim(v, 4),
                param.unit(),
                param.range_text()
            ));
        }
        let params = param.set(&self.setting.params, v);
        self.change(Setting {
            params,
            ..self.setting.clone()
        });
    }

    /// Move to `next`, remembering the current setting for undo.
    fn change(&mut self, next: Setting) {
        if next != self.setting {
            let previous = std::mem::replace(&mut self.setting, next);
            if self.undo.len() == UNDO_DEPTH {
                self.undo.remove(0);
            }
            self.undo.push(previous);
        }
    }

    fn info(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Info,
        });
    }
    fn warn(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Warning,
        });
    }
    fn error(&mut self, text: String) {
        self.message = Some(Message {
            text,
            severity: Severity::Error,
        });
    }
}
