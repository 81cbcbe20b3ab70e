//! The oblique view's state: θ, ω and μ, which of them the arrows move, the page shown
//! (charts or the (angle, μ) map), the impact and the court pace for the current ball, and the
//! map with its job at the worker. `App::update` changes it (update.rs); the widgets only read
//! it.

use crate::api::CourtPace;
use crate::oblique::ObliqueResponse;
use crate::tui::views::oblique::map::{self, MapSpec, ObliqueMap, Quantity};
use crate::tui::views::oblique::param::ObliqueParam;
use crate::tui::worker::JobState;

/// History samples of the charts (as `bouncelab oblique --history`'s default).
pub const SAMPLES: usize = 400;

/// What the view shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Page {
    /// F_n and F_t, v_c and ω against time, the paths and the readout.
    Charts,
    /// The (angle, μ) map and the readout.
    Map,
}

/// The key the impact was computed for: the ball (as the library takes it), the view's
/// values, the surface it bounces on (at rest) and the tangential dashpot c_t.
pub type ImpactKey = (
    crate::Ball,
    ObliqueValues,
    crate::target::Target,
    Option<f64>,
);

/// What the user sets in the view: θ, ω, μ and the tangential model's K_t and κ (`None`: the
/// ball's own, Mindlin's K_t and the preset's κ). The undo history and a session keep these
/// (src/tui/app/edit.rs, src/tui/session.rs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObliqueValues {
    pub angle: f64,
    pub spin: f64,
    pub friction: f64,
    pub tangential_stiffness: Option<f64>,
    pub inertia_factor: Option<f64>,
}

impl Default for ObliqueValues {
    /// The ITF court pace test's arrival (16°, no spin) on a μ = 0.6 court, the ball's K_t, κ.
    fn default() -> ObliqueValues {
        ObliqueValues {
            angle: 16.0,
            spin: 0.0,
            friction: 0.6,
            tangential_stiffness: None,
            inertia_factor: None,
        }
    }
}

impl ObliqueValues {
    /// The value of `p`; `None` for K_t or κ left to the ball.
    pub fn get(&self, p: ObliqueParam) -> Option<f64> {
        match p {
            ObliqueParam::Angle => Some(self.angle),
            ObliqueParam::Spin => Some(self.spin),
            ObliqueParam::Friction => Some(self.friction),
            ObliqueParam::TangentialStiffness => self.tangential_stiffness,
            ObliqueParam::InertiaFactor => self.inertia_factor,
        }
    }

    pub fn set(&mut self, p: ObliqueParam, v: f64) {
        match p {
            ObliqueParam::Angle => self.angle = v,
            ObliqueParam::Spin => self.spin = v,
            ObliqueParam::Friction => self.friction = v,
            ObliqueParam::TangentialStiffness => self.tangential_stiffness = Some(v),
            ObliqueParam::InertiaFactor => self.inertia_factor = Some(v),
        }
    }
}

/// The oblique view's state.
#[derive(Debug, Clone)]
pub struct ObliqueView {
    /// θ (degrees to the surface), ω (rad/s, > 0 topspin), μ, and K_t (N/m) and κ when set
    /// in the view (`None`: the ball's): what undo and a session keep.
    pub values: ObliqueValues,
    /// The parameter ↑ ↓ and `=` act on.
    pub selected: ObliqueParam,
    pub page: Page,
    pub quantity: Quantity,
    /// The impact, with its history, or why there is none (the command line's message).
    pub impact: Option<Result<ObliqueResponse, String>>,
    /// The ITF court pace at μ, for the tennis ball (`None` for other balls).
    pub pace: Option<Result<CourtPace, String>>,
    pub impact_for: Option<ImpactKey>,
    /// The map, or why there is none.
    pub map: Option<Result<ObliqueMap, String>>,
    /// What the map held or asked is of.
    pub map_for: Option<MapSpec>,
    /// The map's job at the worker: an answer of an older map is stale; when the worker
    /// stopped while computing the map of `map_for` (`map` then says so), it is not asked
    /// again until `R` or another map.
    pub job: JobState,
}

impl Default for ObliqueView {
    /// The ITF court pace test's arrival (16°, no spin) on a μ = 0.6 court.
    fn default() -> ObliqueView {
        ObliqueView {
            values: ObliqueValues::default(),
            selected: ObliqueParam::Angle,
            page: Page::Charts,
            quantity: Quantity::AngleOut,
            impact: None,
            pace: None,
            impact_for: None,
            map: None,
            map_for: None,
            job: JobState::default(),
        }
    }
}

impl ObliqueView {
    /// The impact, when there is one.
    pub fn response(&self) -> Option<&ObliqueResponse> {
        self.impact.as_ref()?.as_ref().ok()
    }

    /// The map, when there is one for the current ball and spin.
    pub fn held_map(&self) -> Option<&ObliqueMap> {
        self.map.as_ref()?.as_ref().ok()
    }

    /// The map's cell under (θ, μ).
    pub fn cursor(&self) -> (usize, usize) {
        map::cell_of(self.values.angle, self.values.friction)
    }
}
