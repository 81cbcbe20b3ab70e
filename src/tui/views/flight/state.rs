//! The flight view's state: the launch and the surface it sets, which value the arrows move,
//! and the shot of the current ball for them (or why there is none). `App::update` changes it
//! (update.rs); the widget only reads it.

use crate::api::ShotReport;
use crate::tui::views::flight::param::FlightParam;

/// Trajectory samples drawn (and exported).
pub const SAMPLES: usize = 400;

/// What the user sets: docs/flight.md §6's serve by default (2.8 m, 50 m/s, 6° down,
/// 200 rad/s of topspin, μ = 0.6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlightValues {
    pub speed: f64,
    pub elevation: f64,
    pub spin: f64,
    pub height: f64,
    pub friction: f64,
}

impl Default for FlightValues {
    fn default() -> FlightValues {
        FlightValues {
            speed: 50.0,
            elevation: -6.0,
            spin: 200.0,
            height: 2.8,
            friction: 0.6,
        }
    }
}

impl FlightValues {
    pub fn get(&self, p: FlightParam) -> f64 {
        match p {
            FlightParam::Speed => self.speed,
            FlightParam::Elevation => self.elevation,
            FlightParam::Spin => self.spin,
            FlightParam::Height => self.height,
            FlightParam::Friction => self.friction,
        }
    }

    pub fn with(mut self, p: FlightParam, v: f64) -> FlightValues {
        match p {
            FlightParam::Speed => self.speed = v,
            FlightParam::Elevation => self.elevation = v,
            FlightParam::Spin => self.spin = v,
            FlightParam::Height => self.height = v,
            FlightParam::Friction => self.friction = v,
        }
        self
    }
}

/// The shot for a ball and the values: the key it was computed for.
pub type ShotKey = (crate::Ball, FlightValues);

/// The flight view's state.
#[derive(Debug, Clone, Default)]
pub struct FlightView {
    pub values: FlightValues,
    /// What the arrows step.
    pub selected: FlightParamSel,
    /// The shot, or the library's refusal.
    pub shot: Option<Result<ShotReport, String>>,
    pub(in crate::tui) key: Option<ShotKey>,
}

/// The selected value (a newtype so that the view's state has a default).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FlightParamSel(pub FlightParam);

impl Default for FlightParamSel {
    fn default() -> FlightParamSel {
        FlightParamSel(FlightParam::Speed)
    }
}

impl FlightView {
    /// The shot, when there is one.
    pub fn report(&self) -> Option<&ShotReport> {
        self.shot.as_ref().and_then(|r| r.as_ref().ok())
    }
}
