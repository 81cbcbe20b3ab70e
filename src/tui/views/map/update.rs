//! The map view's part of `update`: the cursor (which moves the ball), the quantity, the
//! targets, the passes coming back from the worker, and the map kept up to date with the
//! ball and the screen (src/tui/views/map/state.rs says what the map is).

use crate::map::{Map, MapSpec, sensitivity};
use crate::model::contact::ContactLaw;
use crate::text::sig_trim;
use crate::tui::action::Action;
use crate::tui::app::{App, Effect, Setting, View};
use crate::tui::export::{ExportRequest, computed};
use crate::tui::param::Param;
use crate::tui::state::{Overlay, Purpose};
use crate::tui::views::map::export::MapExport;
use crate::tui::views::map::state::{self as map_view, MapView, Window, cell_of, next_quantity};
use crate::tui::views::map::targets;

impl App {
    /// The map view's state.
    pub fn map_view(&self) -> &MapView {
        &self.map
    }

    /// Whether a map is being refined in the background (the loop then wakes often to take
    /// its passes).
    pub fn map_pending(&self) -> bool {
        self.map.job.out.is_some()
    }

    /// The map view's actions.
    pub(in crate::tui) fn map_action(&mut self, action: Action) {
        match action {
            Action::MapCursor { lambda, zeta } => self.move_cursor(lambda, zeta),
            Action::MapQuantity if self.view == View::Map => {
                self.map.quantity = next_quantity(self.map.quantity);
                let (label, _) = map_view::unit(self.map.quantity);
                self.info(format!("map of {label}"));
            }
            Action::MapTargets if self.view == View::Map => {
                let text = self
                    .map
                    .targets
                    .as_ref()
                    .map_or(String::new(), targets::text);
                self.open_input(Purpose::Targets, text);
            }
            Action::MapPass { generation, map } => self.receive_pass(generation, *map),
            _ => {}
        }
    }

    /// Move the cursor by cells: the ball takes the (λ, ζ) of the cell it lands on (both
    /// snapped to the grid, so the cell under the cursor is exactly the ball's impact), one
    /// undoable change. Beyond the window's edge the point is one cell further on the same
    /// spacing, and the window is centred on it again.
    fn move_cursor(&mut self, up: i32, right: i32) {
        if self.view != View::Map {
            return;
        }
        let Some(map) = self.map.map() else {
            self.warn("no map to move on".into());
            return;
        };
        let (l, z) = (
            self.setting.get(Param::Lambda),
            self.setting.get(Param::Zeta),
        );
        let (i, j) = cell_of(map, l, z);
        let to = |axis: &crate::map::Axis, values: &[f64], k: usize, d: i32, now: f64| {
            // λ below the log axis (λ = 0) stays put while only ζ moves
            if d == 0 && (now <= 0.0 || now < axis.from * (1.0 - 1e-12)) {
                return now;
            }
            let k = k as i64 + i64::from(d);
            match usize::try_from(k).ok().and_then(|k| values.get(k)) {
                Some(&v) => v,
                None => axis.at(k as f64),
            }
        };
        let lambda = to(&map.spec.lambda, &map.lambdas, i, up, l);
        let zeta = to(&map.spec.zeta, &map.zetas, j, right, z);
        let mut held = Vec::new();
        let mut clamp = |p: Param, v: f64| match p.clamp(v) {
            Some((v, true)) => {
                held.push(format!(
                    "{} held at {} (range {})",
                    p.symbol(),
                    sig_trim(v, 4),
                    p.range_text()
                ));
                v
            }
            Some((v, false)) => v,
            None => p.get(&self.setting.params),
        };
        let (lambda, zeta) = (clamp(Param::Lambda, lambda), clamp(Param::Zeta, zeta));
        let params = self.setting.params.with_lambda_zeta(lambda, zeta);
        self.change(Setting {
            params,
            ..self.setting.clone()
        });
        if let Some(h) = held.first() {
            self.warn(h.clone());
        }
    }

    /// A pass from the worker: kept when it is of the map held and not coarser than it;
    /// a pass of an older map (the ball or the window changed since) is dropped.
    fn receive_pass(&mut self, generation: u64, map: Map) {
        if generation != self.map.job.generation {
            return;
        }
        let evaluated = |m: &Map| m.cells().iter().filter(|c| c.is_some()).count();
        let keep = self
            .map
            .map()
            .is_none_or(|held| evaluated(&map) >= evaluated(held));
        if keep {
            if map.is_complete() {
                self.map.job.out = None;
            }
            self.map.map = Some(Ok(map));
        }
    }

    /// `Enter` in the targets entry: empty clears them; a text that does not read keeps the
    /// entry open with the reason (one line naming the part at fault).
    pub(in crate::tui) fn submit_targets(&mut self, text: &str) {
        if text.is_empty() {
            self.overlay = Overlay::None;
            if self.map.targets.take().is_some() {
                self.info("targets cleared".into());
            }
            return;
        }
        match targets::parse(text) {
            Ok(t) => {
                self.overlay = Overlay::None;
                self.info(format!(
                    "targets: {} (contact_time in ms)",
                    targets::text(&t)
                ));
                self.map.targets = Some(t);
            }
            Err(e) => {
                let why = targets::refusal(&e);
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
            }
        }
    }

    /// Bring the map up to date: outside the map view, stop the work out; in it, the map of
    /// the window for the current ball (a new one when the ball, law, v0, window or grid
    /// changed: its first, coarse pass here, within the frame, when the law is linear; the
    /// rest on the worker), and the sensitivities at the current point.
    pub(in crate::tui) fn refresh_map(&mut self) -> Option<Effect> {
        if self.view != View::Map {
            self.map.job.cancel();
            return None;
        }
        let (rows, cols) = map_view::grid(self.size, self.color, self.pins().len())?;
        let (l, z) = (
            self.setting.get(Param::Lambda),
            self.setting.get(Param::Zeta),
        );
        let window = match self.map.window {
            Some(w) if w.contains(l, z) => w,
            _ => Window::around(l, z),
        };
        self.map.window = Some(window);
        let (params, law) = (self.setting.params, self.setting.law);
        let spec = window.axes(rows, cols).and_then(|(la, za)| {
            Ok(MapSpec::dimensional(params, law, la, za)?
                .with_fast(true)
                .with_fast_laws(true))
        });
        let spec = match spec {
            Ok(s) => s,
            Err(e) => {
                self.map.job.cancel();
                self.map.map = Some(Err(e.to_string()));
                return None;
            }
        };
        if !self.map.holds(&spec) {
            self.map.job.renew();
            let mut map =
                Map::new(spec.clone()).first_cells_at_most(map_view::first_pass_cells(law));
            if !self.background {
                while map.refine().is_some() {}
            } else if law == ContactLaw::Linear {
                map.refine();
            }
            self.map.map = Some(Ok(map));
        }
        self.refresh_sensitivity(&spec);
        let map = self.map.map()?;
        // a map whose worker stopped waits for `R` (src/tui/app/stopped.rs)
        let stopped = self.map.job.stopped.is_some();
        if !self.background || map.is_complete() || self.map.job.out.is_some() || stopped {
            return None;
        }
        let map = map.clone();
        Some(Effect::Map(self.map.job.hand_out(map)))
    }

    /// ∂e/∂ln λ and ∂e/∂ln ζ at the current point, when the ball changed.
    fn refresh_sensitivity(&mut self, spec: &MapSpec) {
        let key = (self.setting.params, self.setting.law);
        if self.map.sens_for == Some(key) {
            return;
        }
        self.map.sens_for = Some(key);
        let (l, z) = (
            self.setting.get(Param::Lambda),
            self.setting.get(Param::Zeta),
        );
        self.map.sensitivity = Some(sensitivity(spec, l, z).map_err(|e| e.to_string()));
    }
}

impl App {
    /// `e` in the map view: the map on screen once it has full detail, or why not; `None`
    /// while the worker refines it (the export waits, and says so).
    pub(in crate::tui) fn map_export(&mut self) -> Option<Result<ExportRequest, String>> {
        let map = match computed(&self.map.map, "map") {
            Ok(m) => m,
            Err(why) => return Some(Err(why)),
        };
        if !map.is_complete() {
            if let Some(why) = &self.map.job.stopped {
                let why = format!("export failed: the map's refinement stopped: {why} (R retries)");
                return Some(Err(why));
            }
            self.info("export waits for the map's full detail…".into());
            return None;
        }
        let s = &self.setting;
        let export = MapExport {
            map: map.clone(),
            quantity: self.map.quantity,
            targets: self.map.targets.clone(),
            own: (s.get(Param::Lambda), s.get(Param::Zeta)),
            title_ball: format!(
                "{} at v0 = {} m/s",
                self.preset().name,
                sig_trim(s.params.v0, 4)
            ),
            radius: s.radius,
        };
        let header = self.csv_header();
        let request = ExportRequest::of(&self.preset().name, Vec::new(), Some(export), header);
        Some(Ok(request))
    }
}
