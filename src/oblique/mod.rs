//! Oblique impacts: a ball arriving at an angle to the surface and spinning, with friction at
//! the contact (docs/oblique.md). The normal motion is today's impact unchanged, run at the
//! normal speed v_y = v sin θ; the tangential motion is the Cundall–Strack linear_history
//! model: a spring K_t on the contact point's tangential displacement u, capped by Coulomb
//! friction μ F_n, no tangential dashpot.
//!
//! The answer comes from [`solve`]: the exact normal flow of the linear law
//! (`solver::exact::NormalPath`) with the tangential motion in closed form phase by phase
//! (`tangential`): a harmonic oscillator in u while the point sticks, the normal impulse while
//! it slides, the switches root-found. [`mod@reference`] integrates the same model independently
//! (DOP853 with events at every switch); tests/oblique.rs holds the two together.

mod closed;
pub mod court;
mod energy;
mod frictions;
mod modes;
mod normal;
pub mod reference;
mod tangential;
#[cfg(test)]
mod tests;

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::exact::{LocalFlow, NormalPath, PathPoint};
use crate::solver::{Flow, ImpactResponse, SolveError, SolveOptions, simulate_flow};
pub use closed::ClosedPath;
pub use frictions::solve_frictions;
pub use normal::NormalAt;
use serde::Serialize;
use std::fmt;
pub use tangential::{Mode, Phase};

/// Most phases (stick or slip) one impact may switch through before it is called unresolved.
pub const MAX_PHASES: usize = 100_000;

/// The oblique part of an impact, SI units. Build it with [`Oblique::new`] (which checks it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Oblique {
    /// θ, the angle between the incoming path and the surface, degrees: 0 < θ ≤ 90.
    pub angle_deg: f64,
    /// ω, rad/s; positive is topspin for a ball moving in +x (the contact point moves back).
    pub spin: f64,
    /// μ, Coulomb's coefficient of friction, ≥ 0.
    pub friction: f64,
    /// K_t (N/m), > 0: the tangential spring.
    pub tangential_stiffness: f64,
    /// κ = I/(m R²), in (0, 1]: 0.4 for a solid ball, 2/3 for a thin shell.
    pub inertia_factor: f64,
    /// R (m), the undeformed radius.
    pub radius: f64,
}

/// A quantity of an oblique impact that is out of its domain, named as the command line
/// names it: "invalid angle: 0 (must lie in (0, 90] degrees)".
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueInvalid {
    /// `angle`, `spin`, `friction`, `tangential_stiffness`, `inertia_factor` or `radius`.
    pub field: &'static str,
    /// The value given.
    pub value: f64,
    /// Why it is refused.
    pub reason: &'static str,
}

impl fmt::Display for ObliqueInvalid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = crate::text::number(self.value);
        write!(f, "invalid {}: {value} ({})", self.field, self.reason)
    }
}

/// Why an oblique impact has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ObliqueError {
    /// A quantity out of its domain (exit 2).
    #[error("{0}")]
    Invalid(ObliqueInvalid),
    /// The normal impact has no answer (see [`SolveError`]).
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// The normal impact does not rebound (λ = 0 and ζ ≥ 1): there is no outgoing motion.
    #[error("the ball does not rebound (λ = 0, ζ ≥ 1): no outgoing motion to report")]
    NoRebound,
    /// The normal motion asked for is not the linear law's (exit 2). No law is refused since
    /// every law's flow is kept (`solver::Flow`); kept so that callers' matches still hold.
    #[error(
        "invalid law: oblique impacts run the linear law only (its exact normal flow): use --law linear"
    )]
    Law,
    /// The adaptive normal run ended in a creep finished in closed form, which keeps no flow
    /// for the tangential motion to be driven by (exit 1).
    #[error(
        "no answer: the normal impact ends in a slow creep finished in closed form, which keeps no flow to drive the friction by"
    )]
    NoFlow,
    /// A quantity the ball does not carry (a ball that is no preset) and was not given (exit 2).
    #[error("invalid {0}: the ball is no preset and carries none: give it")]
    Missing(&'static str),
    /// The stick/slip switches did not come to an end within [`MAX_PHASES`].
    #[error("no answer: more than 100000 stick/slip phases in one contact")]
    Phases,
}

impl ObliqueError {
    /// Whether it is no fault of the input (exit 1) rather than a bad value (exit 2).
    pub fn is_no_answer(&self) -> bool {
        matches!(
            self,
            ObliqueError::NoRebound
                | ObliqueError::Phases
                | ObliqueError::NoFlow
                | ObliqueError::Solve(SolveError::Unresolved { .. })
        )
    }
}

fn invalid(field: &'static str, value: f64, reason: &'static str) -> ObliqueError {
    ObliqueError::Invalid(ObliqueInvalid {
        field,
        value,
        reason,
    })
}

impl Oblique {
    /// The oblique part, checked: the first quantity out of its domain is named.
    pub fn new(
        angle_deg: f64,
        spin: f64,
        friction: f64,
        tangential_stiffness: f64,
        inertia_factor: f64,
        radius: f64,
    ) -> Result<Oblique, ObliqueError> {
        let o = Oblique {
            angle_deg,
            spin,
            friction,
            tangential_stiffness,
            inertia_factor,
            radius,
        };
        o.validate()?;
        Ok(o)
    }

    /// Check every quantity (the fields are public: [`solve`] checks them again).
    pub fn validate(&self) -> Result<(), ObliqueError> {
        let a = self.angle_deg;
        if !(a > 0.0 && a <= 90.0) {
            return Err(invalid("angle", a, "must lie in (0, 90] degrees"));
        }
        if !self.spin.is_finite() || self.spin.abs() > 1e9 {
            return Err(invalid(
                "spin",
                self.spin,
                "must be finite, |ω| ≤ 1e9 rad/s",
            ));
        }
        let mu = self.friction;
        if !(mu.is_finite() && (0.0..=1e6).contains(&mu)) {
            return Err(invalid("friction", mu, "must lie in [0, 1e6]"));
        }
        let k = self.tangential_stiffness;
        if !(k.is_finite() && k > 0.0) {
            return Err(invalid("tangential_stiffness", k, "must be positive"));
        }
        let kappa = self.inertia_factor;
        if !(kappa > 0.0 && kappa <= 1.0) {
            return Err(invalid("inertia_factor", kappa, "must lie in (0, 1]"));
        }
        let r = self.radius;
        if !(r.is_finite() && r > 0.0) {
            return Err(invalid("radius", r, "must be positive"));
        }
        Ok(())
    }
}

/// Mindlin's ratio of tangential to normal stiffness, K_t/K_p = 2(1 − ν)/(2 − ν), for a
/// Poisson ratio ν (docs/oblique.md §1): 2/3 for rubber (ν = 0.5), 6/7 for ν = 0.25.
pub fn mindlin_ratio(poisson: f64) -> f64 {
    2.0 * (1.0 - poisson) / (2.0 - poisson)
}

/// The tangential problem in the normal impact's units (docs/model.md §5 with v0 = v_y):
/// τ = ω0 t, speeds over v_y, u ω0/v_y, forces over m v_y ω0.
#[derive(Debug, Clone, Copy)]
pub struct Scaled {
    /// μ.
    pub mu: f64,
    /// k̃ = K_t/K_p.
    pub kt: f64,
    /// κ.
    pub kappa: f64,
    /// g = 1 + 1/κ: dṽ_c/dτ = g F̃_t.
    pub g: f64,
    /// ω̃_t = √(k̃ g), the sticking oscillation's rate.
    pub omega_t: f64,
}

impl Scaled {
    /// The scaled problem of μ, k̃ = K_t/K_p and κ.
    pub fn new(mu: f64, kt: f64, kappa: f64) -> Scaled {
        let g = 1.0 + 1.0 / kappa;
        Scaled {
            mu,
            kt,
            kappa,
            g,
            omega_t: (kt * g).sqrt(),
        }
    }
}

/// The outgoing motion and what happened in contact, SI units (docs/oblique.md §3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ObliqueResponse {
    /// Incoming speed |v| (m/s).
    pub v_in: f64,
    /// Incoming angle to the surface (degrees).
    pub angle_in_deg: f64,
    /// Incoming spin ω (rad/s, > 0 topspin).
    pub spin_in: f64,
    /// v cos θ (m/s).
    pub vx_in: f64,
    /// v sin θ (m/s), toward the surface.
    pub vy_in: f64,
    /// Outgoing speed (m/s).
    pub v_out: f64,
    /// Outgoing angle to the surface, atan2(vy_out, vx_out) (degrees).
    pub angle_out_deg: f64,
    /// Outgoing spin (rad/s).
    pub spin_out: f64,
    /// Outgoing tangential speed (m/s).
    pub vx_out: f64,
    /// Outgoing normal speed (m/s), away from the surface.
    pub vy_out: f64,
    /// vy_out/vy_in: the normal impact's COR.
    pub cor_normal: f64,
    /// Cross's e_x = −v_c,out/v_c,in (v_c = v_x − Rω); `None` when the ball arrives rolling.
    pub cor_tangential: Option<f64>,
    /// |vx_in − vx_out|/(vy_in + vy_out), what a court test measures.
    pub apparent_friction: f64,
    /// Whether the contact point slid from first contact to separation.
    pub slid_throughout: bool,
    /// Time spent sticking (s).
    pub grip_time: f64,
    /// Contact time (s).
    pub contact_time: f64,
    /// Peak normal force (N).
    pub max_normal_force: f64,
    /// Peak |F_t| (N).
    pub max_friction_force: f64,
    /// Where the energy went.
    pub energy: ObliqueEnergy,
    /// The stick and slip phases, in order (τ in the normal impact's units).
    #[serde(skip)]
    pub phases: Vec<Phase>,
    /// The normal impact as `run` gives it at v_y.
    #[serde(skip)]
    pub normal: ImpactResponse,
    /// The sampled histories, when asked for: `t`, `normal_force`, `friction_force`,
    /// `slip_velocity`, `spin` beside the other keys.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub history: Option<ObliqueHistory>,
}

/// The energy of an oblique impact (J): what came in, what went out, and where the rest went;
/// `residual` is |in − out − losses| / in (docs/oblique.md §4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ObliqueEnergy {
    /// ½ m v² at arrival.
    pub translational_in: f64,
    /// ½ I ω² at arrival.
    pub rotational_in: f64,
    /// ½ m v² at separation.
    pub translational_out: f64,
    /// ½ I ω² at separation.
    pub rotational_out: f64,
    /// The normal model's losses: dashpot, contact (flattening) and what the recoil spring
    /// keeps (docs/model.md §8's audit).
    pub normal_dissipation: f64,
    /// Work of friction while sliding.
    pub friction_dissipation: f64,
    /// ½ K_t u² left in the tangential spring at separation.
    pub tangential_spring: f64,
    /// |in − out − losses| / in.
    pub residual: f64,
}

/// The histories of an oblique impact, SI, evenly spaced in time over the contact.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct ObliqueHistory {
    /// t (s).
    pub t: Vec<f64>,
    /// F_n (N).
    pub normal_force: Vec<f64>,
    /// F_t (N), the surface's force on the ball along +x.
    pub friction_force: Vec<f64>,
    /// v_c = v_x − Rω (m/s), the contact point's slip velocity.
    pub slip_velocity: Vec<f64>,
    /// ω (rad/s).
    pub spin: Vec<f64>,
}

/// The normal motion an oblique impact is driven by: the linear law's exact flow, or any
/// law's adaptive run read between its steps (`solver::Flow`).
pub trait NormalMotion {
    /// F̄, F̄' and ᾱ' at τ.
    fn at(&self, tau: f64) -> PathPoint;
    /// τ_f.
    fn end(&self) -> f64;
    /// Where F̄' may jump (phase ends), in order.
    fn kinks(&self) -> Vec<f64>;
    /// The motion at τ_j = j h for j = 0, 1, … while j h < τ_f, then at τ_f: the tangential
    /// search's grid (`tangential::Grid`). Read point by point unless the flow knows better.
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        grid_by_points(self, h)
    }
    /// The motion on [a, b] read with F̄'' for Newton's steps, when the flow has a cheaper
    /// reading there or a closed form (`None`: read `at`).
    fn local(&self, _a: f64, _b: f64) -> Option<Local<'_>> {
        None
    }
}

/// The normal motion on a bracket of the switches' search, read with F̄'': the exact flow's
/// power series from the bracket's start, or the closed form itself.
// a temporary on the stack, one a bracket: boxing the series would allocate for each
#[allow(clippy::large_enum_variant)]
pub enum Local<'a> {
    /// [`NormalPath::local`]'s series.
    Series(LocalFlow),
    /// The closed form (`closed`), turned from the bracket's start.
    Closed(closed::Near<'a>),
}

impl Local<'_> {
    /// The normal motion at τ.
    pub fn at(&self, tau: f64) -> PathPoint {
        self.at_with_curvature(tau).0
    }

    /// The normal motion at τ and F̄'' there.
    pub fn at_with_curvature(&self, tau: f64) -> (PathPoint, f64) {
        match self {
            Local::Series(l) => l.at_with_curvature(tau),
            Local::Closed(c) => c.with_curvature(tau),
        }
    }
}

/// [`NormalMotion::grid`] read point by point.
fn grid_by_points<M: NormalMotion + ?Sized>(m: &M, h: f64) -> Vec<PathPoint> {
    let tf = m.end();
    let n = (tf / h).ceil().max(1.0) as usize;
    (0..=n)
        .map(|j| m.at(if j == n { tf } else { j as f64 * h }))
        .collect()
}

impl NormalMotion for NormalPath {
    fn at(&self, tau: f64) -> PathPoint {
        NormalPath::at(self, tau)
    }
    fn end(&self) -> f64 {
        NormalPath::end(self)
    }
    fn kinks(&self) -> Vec<f64> {
        self.boundaries().collect()
    }
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        NormalPath::grid(self, h)
    }
    fn local(&self, a: f64, b: f64) -> Option<Local<'_>> {
        NormalPath::local(self, a, b).map(Local::Series)
    }
}

impl NormalMotion for Flow {
    fn at(&self, tau: f64) -> PathPoint {
        Flow::at(self, tau)
    }
    fn end(&self) -> f64 {
        Flow::end(self)
    }
    fn kinks(&self) -> Vec<f64> {
        self.boundaries()
    }
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        match self {
            Flow::Exact(p) => p.grid(h),
            Flow::Numeric(_) => grid_by_points(self, h),
        }
    }
    fn local(&self, a: f64, b: f64) -> Option<Local<'_>> {
        match self {
            Flow::Exact(p) => p.local(a, b).map(Local::Series),
            Flow::Numeric(_) => None,
        }
    }
}

/// One oblique impact of a ball with parameters `params` (their `v0` is ignored: the speed is
/// `v`), on the linear law, with `samples` history samples (0: none).
pub fn solve(
    params: &ImpactParams,
    v: f64,
    oblique: &Oblique,
    samples: usize,
) -> Result<ObliqueResponse, ObliqueError> {
    solve_law(params, ContactLaw::Linear, v, oblique, samples)
}

/// One oblique impact as [`solve`], on any contact law: the normal motion is `run`'s (the
/// exact flow for the linear law, the adaptive solver for the others, docs/oblique.md §2).
pub fn solve_law(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    samples: usize,
) -> Result<ObliqueResponse, ObliqueError> {
    let opts = SolveOptions::default().with_energy();
    solve_with(params, law, v, oblique, samples, &opts)
}

/// [`solve_law`] with the normal solver's options (tests run the linear law adaptively).
pub(crate) fn solve_with(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    samples: usize,
    opts: &SolveOptions,
) -> Result<ObliqueResponse, ObliqueError> {
    oblique.validate()?;
    NormalAt::with_options(params, law, v, oblique.angle_deg, opts)?.solve(oblique, samples)
}

/// What the reference integration starts from: the components of the arrival, the normal
/// flow and the scaled tangential problem.
pub(crate) struct Prepared {
    pub vx: f64,
    pub vy: f64,
    pub path: Flow,
    pub scaled: Scaled,
}

pub(crate) fn prepare(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
) -> Result<Prepared, ObliqueError> {
    oblique.validate()?;
    let theta = oblique.angle_deg.to_radians();
    // at 90° the normal impact is the very one `run` solves: v_y = v, not v sin(π/2)
    let (vy, vx) = if oblique.angle_deg == 90.0 {
        (v, 0.0)
    } else {
        (v * theta.sin(), v * theta.cos())
    };
    let normal_params = ImpactParams { v0: vy, ..*params };
    let opts = SolveOptions::default().with_energy();
    let (normal, path) = simulate_flow(&normal_params, law, &opts)?;
    if !normal.rebound {
        return Err(ObliqueError::NoRebound);
    }
    let path = path.ok_or(ObliqueError::NoFlow)?;
    let scaled = Scaled::new(
        oblique.friction,
        oblique.tangential_stiffness / params.k_p,
        oblique.inertia_factor,
    );
    Ok(Prepared {
        vx,
        vy,
        path,
        scaled,
    })
}
