//! The sweeps view's part of the explorer's state: the current ball's COR-against-speed curve
//! and the sweeps asked for it and for the pins ([`super::speed`]).

use super::speed::{SpeedCurve, SpeedRequest};

/// The COR-against-speed sweeps: computed only while the sweeps view shows them.
#[derive(Debug, Clone, Default)]
pub struct Sweeps {
    /// COR vs speed of the current ball.
    pub curve: Option<SpeedCurve>,
    /// Sweeps still to come (see `App::with_background_sweeps`).
    pub wanted: Vec<SpeedRequest>,
    /// The sweeps last asked of the background worker (`Effect::Compute`).
    pub asked: Vec<SpeedRequest>,
    /// Why the worker's thread stopped while `asked` was out: they are not asked again until
    /// `R` or a new list of sweeps (src/tui/app/stopped.rs).
    pub stopped: Option<String>,
}
