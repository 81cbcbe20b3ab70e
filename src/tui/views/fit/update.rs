//! Measured data and the fit, as part of [`App::update`]: `o` asks for a file's path and the
//! loop reads it; a good file replaces the data on the charts, a bad one changes nothing and
//! says `FILE:LINE:COLUMN: why`. `f` sends the fit of the current ball to the fit worker
//! (the keys go on acting, the pane says "fitting…"); `F` applies the finished fit as one
//! undoable change. A fit whose ball changed meanwhile is kept on show marked stale and is
//! not applied ([`Standing::Stale`]); an answer to a fit superseded by a later `f` (or by
//! `O`, or a new file) is dropped.

use crate::figure::explorer::MeasuredOverlay;
use crate::measured::Data;
use crate::tui::app::{App, Effect, Overlay, Purpose, Setting};
use crate::tui::param::Param;
use crate::tui::views::fit::state::{
    self as measured, FitNews, FitPane, FitStatus, Loaded, Standing,
};
use std::path::PathBuf;

impl App {
    /// `o`: the path entry.
    pub(in crate::tui) fn open_measured(&mut self) {
        self.open_input(Purpose::MeasuredPath, String::new());
    }

    /// Enter in the path entry: the loop is to read the file.
    pub(in crate::tui) fn submit_path(&mut self, text: String) -> Option<Effect> {
        self.overlay = Overlay::None;
        if text.is_empty() {
            return None;
        }
        self.info(format!("reading {text}…"));
        Some(Effect::LoadMeasured(PathBuf::from(text)))
    }

    /// The loop read `data` from `path`: it replaces what was drawn (and any fit to it),
    /// unless it cannot be drawn for the current ball, which changes nothing.
    pub(in crate::tui) fn measured_loaded(&mut self, path: PathBuf, data: Data) {
        let label = crate::measured::file::label(&path);
        let p = self.setting.params;
        match MeasuredOverlay::from_data(&data, &label, p.mass, p.v0) {
            Ok(overlays) => {
                self.info(format!("loaded {label}: a {} (f fits)", data.kind()));
                self.fit.overlays = overlays;
                self.fit.loaded = Some(Loaded { path, label, data });
                self.fit.pane = None;
            }
            Err(e) => self.error(format!("{}:{e}", path.display())),
        }
    }

    /// `--measured FILE` at the start: the data to fit to, besides its overlays.
    pub fn with_loaded(mut self, loaded: Loaded) -> App {
        self.fit.loaded = Some(loaded);
        self
    }

    /// The measured data the explorer holds, if any.
    pub fn loaded(&self) -> Option<&Loaded> {
        self.fit.loaded.as_ref()
    }

    /// The fit pane's content, if a fit was asked for.
    pub fn fit_pane(&self) -> Option<&FitPane> {
        self.fit.pane.as_ref()
    }

    /// Whether a fit is out on the worker.
    pub fn fitting(&self) -> bool {
        self.fit
            .pane
            .as_ref()
            .is_some_and(|f| f.status == FitStatus::Running)
    }

    /// How the fit shown stands to the current ball.
    pub fn fit_standing(&self) -> Option<Standing> {
        let f = self.fit.pane.as_ref()?;
        Some(f.standing(&self.setting.params, self.setting.law))
    }

    /// `O`: no more measured data, nor fit.
    pub(in crate::tui) fn clear_measured(&mut self) {
        if self.fit.loaded.is_none() && self.fit.overlays.is_empty() {
            return self.warn("no measured data to put away (o loads a file)".into());
        }
        let what = crate::tui::app::put_away_what(&self.fit);
        self.overlay = crate::tui::state::Overlay::Ask(crate::tui::state::Ask::PutAway(what));
    }

    /// `f`: the fit of the current ball to the loaded data, for the fit worker.
    pub(in crate::tui) fn start_fit(&mut self) -> Option<Effect> {
        let Some(loaded) = &self.fit.loaded else {
            self.warn("no measured data to fit to: o loads a file".into());
            return None;
        };
        self.fit.id += 1;
        let drops = matches!(loaded.data, crate::measured::Data::Drop(_));
        let s = &self.setting;
        match measured::request(self.fit.id, loaded, &s.params, s.law) {
            Ok(r) => {
                self.fit.pane = Some(FitPane {
                    id: r.id,
                    label: r.label.clone(),
                    base: r.base,
                    law: r.law,
                    free: r.free.clone(),
                    status: FitStatus::Running,
                    armed: false,
                    progress: None,
                    drops,
                });
                self.info(format!("fitting {} to {}…", names(&r.free), r.label));
                Some(Effect::Fit(r))
            }
            Err(e) => {
                self.error(e);
                None
            }
        }
    }

    /// News of a fit: its progress shown while it runs, its outcome once back; news of a fit
    /// superseded is dropped.
    pub(in crate::tui) fn fit_ready(&mut self, id: u64, news: FitNews) {
        let Some(pane) = self.fit.pane.as_mut().filter(|p| p.id == id) else {
            return;
        };
        let result = match news {
            FitNews::Progress(p) => {
                if pane.status == FitStatus::Running {
                    pane.progress = Some(p);
                }
                return;
            }
            FitNews::Done(result) => result,
        };
        pane.status = FitStatus::Done(result);
        match self.fit_standing() {
            Some(Standing::Stale) => {
                self.warn("fit done, but the ball changed meanwhile: stale (f fits again)".into())
            }
            _ => match &self.fit.pane.as_ref().map(|p| &p.status) {
                Some(FitStatus::Done(Err(e))) => self.error(format!("fit failed: {e}")),
                Some(FitStatus::Done(Ok(o))) if !o.identified => self.warn(
                    "fit done, but it gave no answer (see the pane): F twice applies it".into(),
                ),
                _ => self.info("fit done: F applies it (u undoes)".into()),
            },
        }
    }

    /// `F`: the fitted ball in place of the current one, as one change `u` undoes.
    pub(in crate::tui) fn apply_fit(&mut self) {
        let standing = self.fit_standing();
        let Some(pane) = &self.fit.pane else {
            return self.warn("no fit to apply: f fits the ball to the measured data".into());
        };
        let outcome = match &pane.status {
            FitStatus::Running => return self.warn("the fit is still running".into()),
            FitStatus::Done(Err(_)) => return self.warn("the fit failed: nothing to apply".into()),
            FitStatus::Done(Ok(o)) => o.clone(),
        };
        // a fit that did not answer (docs/fitting.md) is applied only when asked twice
        // (tests/tui/tui_fit.rs, an_unpinned_parameter_is_said_so)
        if !outcome.identified && !pane.armed && standing != Some(Standing::Applied) {
            if let Some(p) = &mut self.fit.pane {
                p.armed = true;
            }
            let why = crate::analysis::fit::verdict::no_answer_reasons(
                outcome.converged,
                &outcome.not_pinned,
            );
            return self.warn(format!(
                "the fit gave no answer ({}): F again applies it anyway",
                why.join("; ")
            ));
        }
        match standing {
            Some(Standing::Applied) => return self.info("the fit is already applied".into()),
            Some(Standing::Stale) => {
                return self.warn("stale fit: the ball changed since f; f fits again".into());
            }
            _ => {}
        }
        let n = outcome.params.normalized();
        for (param, v) in [(Param::Lambda, n.lambda), (Param::Zeta, n.zeta)] {
            if let Err(why) = param.check(v, &outcome.params) {
                return self.warn(format!("fit not applied: {why}"));
            }
        }
        self.change(Setting {
            params: outcome.params,
            ..self.setting.clone()
        });
        self.info("fit applied (u undoes)".into());
    }
}

/// "k_p, c, k_r".
fn names(free: &[crate::analysis::fit::Param]) -> String {
    free.iter().map(|p| p.name()).collect::<Vec<_>>().join(", ")
}
