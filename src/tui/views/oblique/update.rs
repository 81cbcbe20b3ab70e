//! The oblique view's part of `update`: `i` in and out, θ, ω and μ stepped or typed (each
//! checked by the library's one range), the page and the map's quantity, the map's cursor
//! (which moves θ and μ), and the impact, the court pace and the map kept up to date with the
//! ball (src/tui/views/oblique/state.rs says what they are).

use crate::api::ObliqueSpec;
use crate::oblique::court::ITF_COURT_PACE;
use crate::text::number as number_text;
use crate::text::parse::number;
use crate::tui::action::ObliqueKey;
use crate::tui::app::{App, Effect, View};
use crate::tui::export::{ExportRequest, computed};
use crate::tui::state::{Overlay, Purpose};
use crate::tui::views::oblique::export;
use crate::tui::views::oblique::map::{self, ANGLES, FRICTIONS, MapSpec};
use crate::tui::views::oblique::param::ObliqueParam;
use crate::tui::views::oblique::state::{ImpactKey, ObliqueValues, ObliqueView, Page, SAMPLES};
use crate::{Ball, BallError};
use std::sync::atomic::AtomicBool;

impl App {
    /// The oblique view's state.
    pub fn oblique_view(&self) -> &ObliqueView {
        &self.oblique
    }

    /// Whether the (angle, μ) map is out at the worker (the loop then wakes often for it).
    pub fn oblique_pending(&self) -> bool {
        self.oblique.job.out.is_some()
    }

    /// The ball as the library takes it: the preset's with the explorer's parameters, law and
    /// radius (R may be typed in the form), its material's ν and its κ, at the conditions
    /// typed in the form — what `bouncelab oblique --preset NAME` runs with the same numbers
    /// (tests/tui/tui_oblique.rs compares).
    pub fn oblique_ball(&self) -> Ball {
        crate::tui::physical::conditions::library_ball(self.preset(), &self.setting)
    }

    /// The surface the oblique view's ball bounces on: the target's normal give (K_s ∥ c_s on
    /// M) at rest — the surface picked (`G`) or typed in the form; the wall until then. A
    /// target's speed v_t is the impact view's pair's, not a surface's: not used here.
    pub fn oblique_surface(&self) -> crate::target::Target {
        crate::target::Target {
            speed: 0.0,
            ..self.setting.target
        }
    }

    /// The oblique readout's line of the surface: " surface clay: K_s 4e5 N/m, c_s 20 kg/s"
    /// (its name by the library's rule, `App::oblique_surface_used`: the one picked, the steel
    /// plate's when none was, `clay-modified` or `given-surface` once the form or the view
    /// moved a number off it; the numbers the impact runs on, c_t with them), and whether it is
    /// the default plate's (said last: a short readout loses it first).
    pub fn oblique_surface_line(&self) -> (String, bool) {
        let s = &self.setting;
        let t = self.oblique_surface();
        let plain = t == crate::target::Target::wall() && s.tangential_damping.is_none();
        let shown = crate::target::surface::SurfaceMechanics {
            stiffness: t.stiffness,
            damping: t.damping,
            mass: t.mass,
            friction: None,
            tangential_stiffness: None,
            tangential_damping: s.tangential_damping,
        };
        // by the library's rule (issue 53 item 6: every answer names its surface): the one
        // picked, the rigid steel plate when none was, renamed once a number given over it
        // differs (`clay-modified`, `given-surface`), as `y`'s `oblique` line names it
        let name = self.oblique_surface_used().name;
        let line = format!(" surface {name}: {}", crate::tui::surface::numbers(&shown));
        (line, plain && s.surface.is_none())
    }

    /// The keyboard's mode in the oblique view, by its page.
    pub(in crate::tui) fn oblique_mode(&self) -> crate::tui::action::Mode {
        match self.oblique.page {
            Page::Charts => crate::tui::action::Mode::Oblique,
            Page::Map => crate::tui::action::Mode::ObliqueMap,
        }
    }

    /// The oblique view's keys.
    pub(in crate::tui) fn oblique_action(&mut self, key: ObliqueKey) {
        if key == ObliqueKey::Toggle {
            self.toggle_view(View::Oblique);
            return;
        }
        if self.view != View::Oblique {
            return;
        }
        let o = &mut self.oblique;
        match key {
            ObliqueKey::Step { param, up, coarse } => {
                o.selected = param;
                let value = param.step(self.oblique_value(param), up, coarse || self.coarse);
                self.oblique_step(param, value);
            }
            ObliqueKey::StepSelected { up, coarse } => {
                let param = o.selected;
                let value = param.step(self.oblique_value(param), up, coarse || self.coarse);
                self.oblique_step(param, value);
            }
            ObliqueKey::Select { next } => {
                o.selected = if next {
                    o.selected.next()
                } else {
                    o.selected.prev()
                }
            }
            ObliqueKey::Type => {
                let p = o.selected;
                self.open_input(Purpose::Oblique(p), String::new());
            }
            ObliqueKey::Page => {
                o.page = match o.page {
                    Page::Charts => Page::Map,
                    Page::Map => Page::Charts,
                };
            }
            ObliqueKey::Quantity => {
                o.quantity = o.quantity.next();
                let label = o.quantity.label();
                if o.page == Page::Charts {
                    o.page = Page::Map;
                }
                self.info(format!("map of {label}"));
            }
            ObliqueKey::Cursor { angle, friction } => self.oblique_cursor(angle, friction),
            ObliqueKey::Toggle => {}
        }
    }

    /// The value of `param` the impact runs on: the view's, or the ball's K_t (Mindlin's) and
    /// κ (the preset's) where the view sets none — as `Ball::oblique` takes them.
    pub fn oblique_value(&self, param: ObliqueParam) -> f64 {
        if let Some(v) = self.oblique.values.get(param) {
            return v;
        }
        let ball = self.oblique_ball();
        match param {
            ObliqueParam::TangentialStiffness => ball.tangential_stiffness().unwrap_or(f64::NAN),
            _ => ball.inertia_factor(),
        }
    }

    /// Change the view's values to `next`, remembering the state for undo (as a change of
    /// the ball is: `u` undoes θ, ω, μ, K_t and κ too).
    fn change_oblique(&mut self, next: ObliqueValues) {
        if next != self.oblique.values {
            self.remember();
            self.oblique.values = next;
        }
    }

    /// The view's values with `param` at `value`.
    fn oblique_with(&self, param: ObliqueParam, value: f64) -> ObliqueValues {
        let mut v = self.oblique.values;
        v.set(param, value);
        v
    }

    /// A step moved `param` to `value`: taken when the library takes it; past a closed bound
    /// it stops there, past an open bound (θ's, κ's, K_t's 0) it stays, and says so.
    fn oblique_step(&mut self, param: ObliqueParam, value: f64) {
        let now = self.oblique_value(param);
        let held = match param.clamp(value) {
            Some(v) if v == value => None,
            Some(v) => Some(v),
            None => Some(now),
        };
        if let Some(at) = held {
            self.warn(format!(
                "{} held at {}{}: the range is {}",
                param.symbol(),
                // as λ, ζ and v0 are held (src/tui/app/edit.rs)
                crate::text::short(at, 4),
                param.unit(),
                param.range_text()
            ));
        }
        let next = self.oblique_with(param, held.unwrap_or(value));
        self.change_oblique(next);
    }

    /// The arrows on the map: θ and μ move to the next cell's (Shift: 8 cells), held inside
    /// the grid.
    fn oblique_cursor(&mut self, angle: i32, friction: i32) {
        let (i, j) = self.oblique.cursor();
        let step = |k: usize, d: i32, n: usize| (k as i64 + i64::from(d)).clamp(0, n as i64 - 1);
        let (i, j) = (step(i, angle, ANGLES), step(j, friction, FRICTIONS));
        let next = ObliqueValues {
            angle: map::angle_at(i as usize),
            friction: map::friction_at(j as usize),
            ..self.oblique.values
        };
        self.change_oblique(next);
    }

    /// Enter in θ's, ω's or μ's entry: the number read as the command line reads it and
    /// checked by the library; refused, the entry stays open with the reason.
    pub(in crate::tui) fn submit_oblique(&mut self, param: ObliqueParam, text: &str) {
        if text.is_empty() {
            self.overlay = Overlay::None;
            return;
        }
        let kept = format!("; {} kept", param.symbol());
        let read = number(text)
            .map_err(|e| format!("{e}{kept}"))
            .and_then(|v| param.check(v));
        match read {
            Ok(v) => {
                self.overlay = Overlay::None;
                let next = self.oblique_with(param, v);
                self.change_oblique(next);
                self.oblique.selected = param;
            }
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
            }
        }
    }

    /// Bring the impact, the court pace and the map up to the ball: outside the view, stop
    /// the map's job; in it, the impact when the ball or θ, ω, μ changed, the map (on the
    /// worker, or here without one) when the ball or ω changed.
    pub(in crate::tui) fn refresh_oblique(&mut self) -> Option<Effect> {
        if self.view != View::Oblique {
            // a map stopped before it came back is asked again on the way back in
            if self.oblique.job.out.is_some() {
                self.oblique.map_for = None;
            }
            self.oblique.job.cancel();
            return None;
        }
        let ball = self.oblique_ball();
        let o = &self.oblique;
        // on the surface the form or the surface picker set (issue 53 item 6), at rest, as
        // `bouncelab oblique --surface …` bounces on it; the wall's is the very same answer
        let surface = self.oblique_surface();
        let c_t = self.setting.tangential_damping;
        let v = o.values;
        let key: ImpactKey = (ball.clone(), v, surface, c_t);
        if o.impact_for.as_ref() != Some(&key) {
            let spec = ObliqueSpec {
                v: None,
                angle_deg: v.angle,
                spin: v.spin,
                friction: v.friction,
                tangential_stiffness: v.tangential_stiffness,
                inertia_factor: v.inertia_factor,
            };
            let impact = ball
                .oblique_on(&spec, c_t, SAMPLES, &surface)
                .map_err(|e| e.to_string());
            let tennis = ITF_COURT_PACE.balls.contains(&self.preset().name.as_str());
            // `bouncelab court --friction μ` with the view's K_t and κ, as `court` takes them
            let pace = tennis.then(|| {
                let tangential = (v.tangential_stiffness, v.inertia_factor, c_t);
                ball.court_pace_on(v.friction, tangential, &surface)
                    .map_err(|e: BallError| e.to_string())
            });
            let o = &mut self.oblique;
            (o.impact, o.pace, o.impact_for) = (Some(impact), pace, Some(key));
        }
        self.refresh_oblique_map(ball)
    }

    fn refresh_oblique_map(&mut self, ball: Ball) -> Option<Effect> {
        let spec = MapSpec {
            ball,
            spin: self.oblique.values.spin,
            tangential_stiffness: self.oblique.values.tangential_stiffness,
            inertia_factor: self.oblique.values.inertia_factor,
        };
        if self.oblique.map_for.as_ref() == Some(&spec) {
            return None;
        }
        let o = &mut self.oblique;
        o.job.renew();
        o.map = None;
        o.map_for = Some(spec.clone());
        if !self.background {
            o.map = map::compute(&spec, &AtomicBool::new(false));
            return None;
        }
        Some(Effect::ObliqueMap(Box::new(o.job.hand_out(spec))))
    }

    /// The worker's map: kept when it is of the map asked last.
    pub(in crate::tui) fn receive_oblique_map(
        &mut self,
        generation: u64,
        map: Result<map::ObliqueMap, String>,
    ) {
        if generation == self.oblique.job.generation {
            self.oblique.job.out = None;
            self.oblique.map = Some(map);
        }
    }

    /// The explorer opened on the oblique view at θ, ω, μ (`bouncelab --angle DEG --spin W
    /// --friction MU`; `None`: the view's default), each checked by the library's rule: an
    /// error is `oblique`'s message ("invalid angle: 95 (must lie in (0, 90] degrees)").
    pub fn with_oblique(
        mut self,
        [angle, spin, friction]: [Option<f64>; 3],
    ) -> Result<App, String> {
        let given = [
            (ObliqueParam::Angle, angle),
            (ObliqueParam::Spin, spin),
            (ObliqueParam::Friction, friction),
        ];
        for (param, value) in given {
            if let Some(v) = value {
                let v = param.library_check(v)?;
                self.oblique.values.set(param, v);
            }
        }
        self.view = View::Oblique;
        self.refresh();
        Ok(self)
    }

    /// `e` in the oblique view: the impact's charts and numbers
    /// (src/tui/views/oblique/export.rs), headed by `y`'s `bouncelab oblique` line; the
    /// impact is computed in `update` itself, so there is nothing to wait for. Or why not.
    pub(in crate::tui) fn oblique_export(&self) -> Result<ExportRequest, String> {
        let r = computed(&self.oblique.impact, "impact")?;
        let o = &self.oblique.values;
        let subtitle = format!(
            "{}, {} m/s at {}°, spin {} rad/s, μ = {}",
            self.preset().name,
            number_text(r.v_in),
            number_text(o.angle),
            number_text(o.spin),
            number_text(o.friction)
        );
        let charts = export::figures(r, &subtitle)
            .ok_or_else(|| "export failed: the impact has no history".to_string())?;
        let header = export::header(&self.command_line(), r);
        Ok(ExportRequest::of(&self.preset().name, charts, None, header))
    }
}
