//! The flight view's state: the launch and the surface it sets, which value the arrows move,
//! and the shot of the current ball for them (or why there is none). `App::update` changes it
//! (update.rs); the widget only reads it.

use crate::api::{Net, ShotReport, TENNIS_NET_HEIGHT};
use crate::tui::views::flight::param::FlightParam;

/// Trajectory samples drawn (and exported).
pub const SAMPLES: usize = 400;

/// Where the view's net stands (m from the launch): a serve's from the baseline, half the
/// court's 23.77 m (ITF Rules of Tennis, Rule 1; docs/flight.md §6).
pub const SERVE_NET_X: f64 = 11.89;

/// What the user sets: docs/flight.md §6's serve that clears the net by default (2.8 m,
/// 50 m/s, 5° down, 200 rad/s of topspin, μ = 0.6; the serve 6° down is in the net), and the
/// tennis net before it (11.89 m out, 0.914 m high), which the view draws and judges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlightValues {
    pub speed: f64,
    pub elevation: f64,
    pub spin: f64,
    pub height: f64,
    pub friction: f64,
    /// The net in the path (`bouncelab shot --net`); no key moves it.
    pub net: Option<Net>,
}

impl Default for FlightValues {
    fn default() -> FlightValues {
        FlightValues {
            speed: 50.0,
            elevation: -5.0,
            spin: 200.0,
            height: 2.8,
            friction: 0.6,
            net: Some(Net {
                x: SERVE_NET_X,
                height: TENNIS_NET_HEIGHT,
            }),
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

    /// `bouncelab shot`'s words for the net (`--net X,HEIGHT`), none without one.
    pub fn net_words(&self) -> Vec<String> {
        use crate::text::number;
        self.net
            .iter()
            .flat_map(|n| {
                [
                    "--net".into(),
                    format!("{},{}", number(n.x), number(n.height)),
                ]
            })
            .collect()
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
