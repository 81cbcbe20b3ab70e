//! Drop tests and bounce sequences (docs/drop.md): a ball released from rest with the bottom
//! of the ball at height H falls under gravity and quadratic drag ([`flight`]), hits a rigid
//! plate, and bounces until a bounce count or a minimum rebound height. Each impact is solved
//! by the ball's own contact model ([`crate::simulate`]) at its own impact speed.
//!
//! Assumed between bounces (docs/drop.md, "What is assumed"): the ball flies as a rigid point
//! mass without spin or lift; every impact starts from an undeformed ball (the permanent
//! flattening z_f of one impact, Eq. 18, and the recoil element's displacement recover before
//! the next); gravity and drag act in flight only, not during the millisecond of contact (the
//! paper's model has neither); the ball leaves the plate at the height it touched it (the
//! centre's displacement during contact, a few mm, is not carried into the flight) and the
//! clock advances by the contact time.
//!
//! Pure: no I/O.

pub mod conditions;
pub mod deformation;
pub mod fit;
pub mod flight;
pub mod names;
pub mod standards;
mod trajectory;

pub use flight::{Air, Flight, G};
pub use trajectory::Sample;

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveError, SolveOptions, simulate};
use crate::target::Target;
use crate::text::number;
use serde::Serialize;
use std::fmt;

/// Bounces allowed at most, and by default.
pub const MAX_BOUNCES: usize = 1000;
/// Bounces followed when the caller does not say ([`DropSetup::new`], `drop --bounces`).
pub const DEFAULT_BOUNCES: usize = 10;
/// The sequence stops once a rebound is lower than this (m), by default.
pub const DEFAULT_MIN_REBOUND: f64 = 1e-3;
/// Highest release accepted (m): far above any drop test, low enough that every speed stays
/// in the solver's range.
pub const MAX_HEIGHT: f64 = 1e4;

/// A ball for a drop test: its impact parameters (v0 is replaced by each impact's speed), its
/// contact law, and the radius that sets its drag area and its top-of-ball height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DropBall {
    /// The impact parameters, SI units (each impact runs them at its own v0).
    pub params: ImpactParams,
    /// The contact law of every impact.
    pub law: ContactLaw,
    /// R (m).
    pub radius: f64,
}

/// The conditions of a drop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DropSetup {
    /// H (m): the bottom of the ball above the plate at release.
    pub height: f64,
    /// The air (`None`: vacuum).
    pub air: Option<Air>,
    /// Stop after this many bounces.
    pub bounces: usize,
    /// Stop after a rebound lower than this (m).
    pub min_rebound: f64,
}

impl DropSetup {
    /// A drop from `height` in standard air, 10 bounces, down to 1 mm.
    pub fn new(height: f64) -> DropSetup {
        DropSetup {
            height,
            air: Some(Air::default()),
            bounces: DEFAULT_BOUNCES,
            min_rebound: DEFAULT_MIN_REBOUND,
        }
    }
}

/// One bounce, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Bounce {
    /// Impact speed (m/s).
    pub v_in: f64,
    /// Rebound speed (m/s); 0 when the ball does not leave the plate.
    pub v_out: f64,
    /// e = v_out / v_in at this impact's speed (Eq. 6).
    pub cor: f64,
    /// Apex of the bottom of the ball after this bounce (m).
    pub rebound_height: f64,
    /// Contact time (s); the bounded time followed when there is no rebound.
    pub contact_time: f64,
    /// Peak force (N).
    pub max_force: f64,
    /// Time of first contact since release (s).
    pub t_start: f64,
}

/// Why a sequence ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum End {
    /// The bounce count was reached.
    Count,
    /// A rebound was lower than the minimum.
    MinRebound,
    /// The ball did not leave the plate (e = 0).
    NoRebound,
}

/// A bounce sequence.
#[derive(Debug, Clone, PartialEq)]
pub struct DropRun {
    /// The conditions it ran under.
    pub setup: DropSetup,
    /// The flight between impacts (gravity and the drag of `setup.air`).
    pub flight: Flight,
    /// The bounces, first to last.
    pub bounces: Vec<Bounce>,
    /// Why the sequence stopped.
    pub end: End,
}

/// Why a drop has no answer.
#[derive(Debug, Clone, PartialEq)]
pub enum DropError {
    /// A drop condition is out of its domain.
    Input {
        /// The condition's name (`height`, `air_density`, `drag_coefficient`, …).
        field: &'static str,
        /// The value given.
        value: f64,
        /// Why it is refused ("must be positive", "not a number", …).
        reason: &'static str,
    },
    /// An impact could not be solved.
    Solve(SolveError),
}

impl fmt::Display for DropError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DropError::Input {
                field,
                value,
                reason,
            } => write!(f, "invalid {field}: {} ({reason})", number(*value)),
            DropError::Solve(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for DropError {}

impl From<SolveError> for DropError {
    fn from(e: SolveError) -> Self {
        DropError::Solve(e)
    }
}

fn input(field: &'static str, value: f64, reason: &'static str) -> DropError {
    DropError::Input {
        field,
        value,
        reason,
    }
}

/// A number in [1e-9, max] (`zero`: [0, max]), or an error naming `field`.
pub(crate) fn check_range(
    field: &'static str,
    value: f64,
    zero: bool,
    max: f64,
) -> Result<(), DropError> {
    if value.is_nan() {
        return Err(input(field, value, "not a number"));
    }
    if !(value > 0.0 || (zero && value == 0.0)) {
        let reason = if zero {
            "must not be negative"
        } else {
            "must be positive"
        };
        return Err(input(field, value, reason));
    }
    // a length below a nanometre is no drop; a vanishing drag is (the C_d → 0 limit)
    if value > max || (!zero && value < 1e-9) {
        return Err(input(field, value, "out of the range this model covers"));
    }
    Ok(())
}

impl DropSetup {
    /// Every condition checked; the first bad one named.
    pub fn validate(&self) -> Result<(), DropError> {
        check_range("height", self.height, false, MAX_HEIGHT)?;
        if let Some(a) = self.air {
            check_range("air_density", a.density, true, 1e4)?;
            check_range("drag_coefficient", a.drag_coefficient, true, 100.0)?;
        }
        if !(1..=MAX_BOUNCES).contains(&self.bounces) {
            return Err(input(
                "bounces",
                self.bounces as f64,
                "must lie in 1 … 1000",
            ));
        }
        check_range("min_rebound", self.min_rebound, false, MAX_HEIGHT)
    }
}

/// One impact of `ball` at speed `v` (m/s).
pub fn impact(ball: &DropBall, v: f64) -> Result<crate::ImpactResponse, SolveError> {
    let params = ImpactParams {
        v0: v,
        ..ball.params
    };
    simulate(&params, ball.law, &SolveOptions::default())
}

/// What a drop reads off one impact.
struct Hit {
    cor: f64,
    rebound: bool,
    contact_time: f64,
    max_force: f64,
}

/// One impact of `ball` at `v` on `surface` (at rest): on the rigid plate [`impact`]'s, else
/// the ball against the surface (docs/targets.md), its COR the ball's rebound over its arrival
/// (the apparent COR; a surface that moves off with the ball leaves none: no rebound).
fn hit(ball: &DropBall, v: f64, surface: &Target) -> Result<Hit, SolveError> {
    if surface.is_rigid() && surface.mass == f64::INFINITY && surface.speed == 0.0 {
        let r = impact(ball, v)?;
        return Ok(Hit {
            cor: r.cor,
            rebound: r.rebound,
            contact_time: r.contact_time.unwrap_or(r.duration),
            max_force: r.max_force,
        });
    }
    let c = crate::target::collide(&ball.params, ball.law, surface, v, None)?;
    Ok(Hit {
        cor: c.apparent_cor.max(0.0),
        rebound: c.rebound && c.apparent_cor > 0.0,
        contact_time: c.contact_time.unwrap_or(f64::NAN),
        max_force: c.max_force,
    })
}

/// Release `ball` from `setup.height` and follow its bounces (module docs for what is
/// assumed). Ends after `setup.bounces` bounces, after a rebound below `setup.min_rebound`,
/// or when the ball stays on the plate: never more than [`MAX_BOUNCES`] impacts.
pub fn drop(ball: &DropBall, setup: &DropSetup) -> Result<DropRun, DropError> {
    let run = drop_watched(ball, setup, &crate::analysis::work::Unwatched)?;
    Ok(run.expect("an unwatched drop is never stopped"))
}

/// [`drop`], the bounces done reported to `watch` before each impact; `None` when the watch
/// stops it (Python's Ctrl-C, issue 28; tests/analysis/mc_watched.rs).
pub fn drop_watched(
    ball: &DropBall,
    setup: &DropSetup,
    watch: &dyn crate::analysis::work::Watch,
) -> Result<Option<DropRun>, DropError> {
    drop_on_watched(ball, setup, &Target::wall(), watch)
}

/// [`drop_watched`] onto `surface` (at rest; `Target::wall()`: the rigid plate, the same
/// answer to the last bit): each bounce is the ball against it (docs/surfaces.md).
pub fn drop_on_watched(
    ball: &DropBall,
    setup: &DropSetup,
    surface: &Target,
    watch: &dyn crate::analysis::work::Watch,
) -> Result<Option<DropRun>, DropError> {
    setup.validate()?;
    check_range("radius", ball.radius, false, 1e3)?;
    ball.params.validate().map_err(SolveError::from)?;
    let flight = Flight::new(ball.params.mass, ball.radius, setup.air);
    let (mut t, mut h) = (0.0, setup.height);
    let mut bounces = Vec::with_capacity(setup.bounces);
    let mut end = End::Count;
    while bounces.len() < setup.bounces {
        if !watch.step(bounces.len() as u64) {
            return Ok(None);
        }
        let v_in = flight.fall_speed(h);
        t += flight.fall_time(h);
        let r = hit(ball, v_in, surface)?;
        let contact_time = r.contact_time;
        let v_out = r.cor * v_in;
        let rebound_height = if r.rebound {
            flight.rise_height(v_out)
        } else {
            0.0
        };
        bounces.push(Bounce {
            v_in,
            v_out,
            cor: r.cor,
            rebound_height,
            contact_time,
            max_force: r.max_force,
            t_start: t,
        });
        if !r.rebound || v_out == 0.0 {
            end = End::NoRebound;
            break;
        }
        t += contact_time + flight.rise_time(v_out);
        h = rebound_height;
        if h < setup.min_rebound {
            end = End::MinRebound;
            break;
        }
    }
    Ok(Some(DropRun {
        setup: *setup,
        flight,
        bounces,
        end,
    }))
}

impl DropRun {
    /// Whether air drag acted.
    pub fn drag(&self) -> bool {
        self.setup.air.is_some()
    }

    /// "quadratic drag ½ρC_dAv², ρ = 1.204 kg/m³, C_d = 0.47" or "no drag (vacuum)".
    pub fn drag_model(&self) -> String {
        match self.setup.air {
            Some(a) => format!(
                "quadratic drag ½ρC_dAv², ρ = {} kg/m³, C_d = {}",
                number(a.density),
                number(a.drag_coefficient)
            ),
            None => "no drag (vacuum)".into(),
        }
    }
}
