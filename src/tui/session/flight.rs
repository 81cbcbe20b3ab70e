//! The flight view in a session file (issue 57 item 3): the launch's speed, elevation, spin
//! and height, the surface's μ and the value the arrows move. Absent from a version-1 or -2
//! file: the view's defaults (docs/flight.md §6's serve).

use crate::tui::views::flight::param::FlightParam;
use crate::tui::views::flight::spec;
use crate::tui::views::flight::state::{FlightParamSel, FlightValues, FlightView};
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FlightState {
    /// |v| at launch, m/s.
    pub speed: f64,
    /// Degrees above the horizontal (negative: down).
    pub elevation: f64,
    /// ω, rad/s (> 0 topspin).
    pub spin: f64,
    /// Height of the ball's centre at launch, m.
    pub height: f64,
    /// The surface's μ.
    pub friction: f64,
    /// speed, elevation, spin, height or friction: `bouncelab shot`'s option without `--`.
    pub selected: String,
}

fn name(p: FlightParam) -> &'static str {
    p.option().trim_start_matches('-')
}

impl FlightState {
    pub fn of(view: &FlightView) -> FlightState {
        let v = &view.values;
        FlightState {
            speed: v.speed,
            elevation: v.elevation,
            spin: v.spin,
            height: v.height,
            friction: v.friction,
            selected: name(view.selected.0).into(),
        }
    }

    /// Set `view` from the file, the launch checked as the view's steps check it: the shot of
    /// `ball` from it, which `bouncelab shot` computes with the same numbers, must be one the
    /// library takes (it names a refused value); or why not (`flight: …`).
    pub fn restore(&self, view: &mut FlightView, ball: &crate::Ball) -> Result<(), String> {
        let values = FlightValues {
            speed: self.speed,
            elevation: self.elevation,
            spin: self.spin,
            height: self.height,
            friction: self.friction,
            // the net: the view's, which no key moves (not in the file)
            ..FlightValues::default()
        };
        ball.shot(&spec(&values))
            .map_err(|e| format!("flight: {e}"))?;
        let selected = FlightParam::ALL
            .into_iter()
            .find(|&p| name(p) == self.selected)
            .ok_or_else(|| format!("flight: selected: unknown value '{}'", self.selected))?;
        view.values = values;
        view.selected = FlightParamSel(selected);
        Ok(())
    }
}
