//! The flight view's part of `update`: `h` in and out, the launch and μ stepped (each taken
//! only where the library takes it: a refused value leaves the last one and says why; a
//! taken one is a change `u` undoes), and the shot kept up to date with the ball (state.rs
//! says what it is).

use crate::api::ShotSpec;
use crate::text::number;
use crate::tui::action::FlightKey;
use crate::tui::app::{App, View};
use crate::tui::export::{ExportRequest, computed};
use crate::tui::views::flight::export;
use crate::tui::views::flight::state::{FlightValues, FlightView, SAMPLES};

/// The shot the view shows for `v`: one bounce, to the landing after it, the ball's own
/// aerodynamic models in standard air, and its net (as `bouncelab shot` with the same
/// numbers and `--net`).
pub fn spec(v: &FlightValues) -> ShotSpec {
    let mut s = ShotSpec::new(v.height, v.speed, v.elevation, v.spin, v.friction);
    s.samples = SAMPLES;
    s.net = v.net;
    s
}

impl App {
    /// The flight view's state.
    pub fn flight_view(&self) -> &FlightView {
        &self.flight
    }

    /// The flight view's keys.
    pub(in crate::tui) fn flight_action(&mut self, key: FlightKey) {
        if key == FlightKey::Toggle {
            self.toggle_view(View::Flight);
            self.refresh_flight();
            return;
        }
        if self.view != View::Flight {
            return;
        }
        let coarse = self.coarse;
        let f = &mut self.flight;
        let (param, up, big) = match key {
            FlightKey::Step { param, up, coarse } => (param, up, coarse),
            FlightKey::StepSelected { up, coarse } => (f.selected.0, up, coarse),
            FlightKey::Select { next } => {
                let p = f.selected.0;
                f.selected.0 = if next { p.next() } else { p.prev() };
                return;
            }
            FlightKey::Toggle => return,
        };
        f.selected.0 = param;
        let next = f
            .values
            .with(param, param.step(f.values.get(param), up, big || coarse));
        let ball = self.oblique_ball();
        match ball.shot(&spec(&next)) {
            Ok(r) => {
                // a step `u` undoes, as the ball's and the oblique view's (issue 57 item 3)
                if next != self.flight.values {
                    self.remember();
                }
                self.flight.values = next;
                self.flight.key = Some((ball, next));
                self.flight.shot = Some(Ok(r));
            }
            Err(e) => self.error(format!("{}: {e}", param.option())),
        }
    }

    /// Compute the shot again when the ball or the values changed.
    pub(in crate::tui) fn refresh_flight(&mut self) {
        let ball = self.oblique_ball();
        let key = (ball, self.flight.values);
        if self.flight.key.as_ref() == Some(&key) {
            return;
        }
        self.flight.shot = Some(key.0.shot(&spec(&key.1)).map_err(|e| e.to_string()));
        self.flight.key = Some(key);
    }

    /// `e` in the flight view: the path as a figure (SVG and CSV), the CSV headed by `y`'s
    /// line and the landing's and the bounce's numbers; nothing recomputed. Or why not.
    pub(in crate::tui) fn flight_export(&self) -> Result<ExportRequest, String> {
        let r = computed(&self.flight.shot, "shot")?;
        let v = &self.flight.values;
        let subtitle = format!(
            "{}, from {} m at {} m/s, {}°, {} rad/s; μ = {}",
            self.preset().name,
            number(v.height),
            number(v.speed),
            number(v.elevation),
            number(v.spin),
            number(v.friction)
        );
        let radius = self.setting.radius;
        let charts = vec![("flight-path", export::path_figure(r, radius, &subtitle))];
        let header = export::header(&self.command_line(), r);
        Ok(ExportRequest::of(&self.preset().name, charts, None, header))
    }
}
