//! Solving one impact: the exact linear solver and the adaptive numerical one, and the result
//! they both return (docs/model.md §2, Eq. 6).

pub mod audit;
pub(crate) mod dop853;
// the watchers' one solout, public for the tests' own integrations (tests/physics/flight.rs)
#[doc(hidden)]
pub mod each_step;
pub mod exact;
pub(crate) mod modes;
pub mod numeric;
mod outcome;
pub mod propagator;
pub mod roots;
pub(crate) mod series;
pub mod stiff;
pub mod table;
pub mod taylor;

pub(crate) use outcome::to_si;
pub(crate) use outcome::{Outcome, Sample};

use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::{Field, ImpactParams, Normalized, ParamError};
use crate::text::number;
use serde::Serialize;

/// Which integrator runs the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Exact flow of the linearized law (sum of exponentials, root-found events).
    Exact,
    /// Adaptive embedded Runge–Kutta (DOPRI5; Radau5 or BDF when stiff) with event location.
    Numeric,
}

impl Method {
    /// `"exact"` or `"numeric"`, as the JSON and CSV write it.
    pub fn name(self) -> &'static str {
        match self {
            Method::Exact => "exact",
            Method::Numeric => "numeric",
        }
    }
}

/// How to solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Number of evenly spaced history samples over [0, t_f] (0: summary only).
    pub samples: usize,
    /// Relative tolerance of the numerical integrator.
    pub rtol: f64,
    /// Compute the energy audit (dashpot dissipation by quadrature / integration).
    pub energy: bool,
    /// Force a method; `None` picks the exact solver for the linear law.
    pub method: Option<Method>,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            samples: 0,
            rtol: 1e-10,
            energy: false,
            method: None,
        }
    }
}

impl SolveOptions {
    /// The same options with `n` history samples (0: none).
    pub fn with_samples(mut self, n: usize) -> Self {
        self.samples = n;
        self
    }
    /// The same options with the energy audit ([`EnergyBudget`]) switched on.
    pub fn with_energy(mut self) -> Self {
        self.energy = true;
        self
    }
    /// The same options with the method forced (the exact one runs the linear law only).
    pub fn with_method(mut self, m: Method) -> Self {
        self.method = Some(m);
        self
    }
}

/// Where the energy went, SI (J): ½ m v0² − ½ m v_f² = dashpot + contact + spring.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyBudget {
    /// ½ m v0².
    pub initial_kinetic: f64,
    /// ½ m v_f², v_f = e v0 the rebound speed.
    pub final_kinetic: f64,
    /// ∫ c y'² dt, integrated independently of the balance.
    pub dashpot: f64,
    /// Net work into the contact, ∮ F dz, from the contact law's closed forms (flattening).
    pub contact: f64,
    /// ½ K_r y² left in the recoil spring at separation.
    pub spring: f64,
}

impl EnergyBudget {
    /// |loss − (dashpot + contact + spring)| / (½ m v0²).
    pub fn relative_residual(&self) -> f64 {
        let loss = self.initial_kinetic - self.final_kinetic;
        (loss - self.dashpot - self.contact - self.spring).abs() / self.initial_kinetic
    }

    /// `x`, one of this budget's terms, with round-off (|x| < 1e-12 of the initial energy)
    /// shown as 0: how `run` and the explorer print the budget.
    pub fn shown(&self, x: f64) -> f64 {
        if x.abs() < 1e-12 * self.initial_kinetic {
            0.0
        } else {
            x
        }
    }
}

/// A phase switch or the end of contact, in the manner of `solve_ivp`'s `t_events`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PhaseEvent {
    /// Time (s).
    pub t: f64,
    /// What happened.
    pub kind: EventKind,
    /// Indentation at the event (m).
    pub z: f64,
}

/// What a [`PhaseEvent`] marks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EventKind {
    /// z' = 0 while loading: unloading starts.
    Unload,
    /// z reached z_m again while unloading: loading resumes.
    Reload,
    /// z crossed z_p while loading (elastic–plastic law: Hertz → linear).
    Yield,
    /// F = 0 while unloading: the ball leaves the wall.
    Separation,
}

/// Sampled histories, SI units, evenly spaced in time.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct History {
    /// t (s).
    pub t: Vec<f64>,
    /// F(t) (N).
    pub force: Vec<f64>,
    /// z(t) (m).
    pub indentation: Vec<f64>,
    /// α(t) (m).
    pub displacement: Vec<f64>,
}

/// The answer to one impact, SI units (docs/model.md §2).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactResponse {
    /// The contact law run.
    pub law: ContactLaw,
    /// The solver that ran it.
    pub method: Method,
    /// Coefficient of restitution e = −α'(t_f)/v0 (Eq. 6); 0 when there is no rebound.
    pub cor: f64,
    /// Whether the force returned to zero (the ball left the wall).
    pub rebound: bool,
    /// Peak force F_m (N).
    pub max_force: f64,
    /// Contact time t_f (s); `None` when there is no rebound.
    pub contact_time: Option<f64>,
    /// Time followed (s): t_f, or the bounded horizon after which "no rebound" was concluded.
    pub duration: f64,
    /// Peak indentation z_m (m).
    pub max_indentation: f64,
    /// Permanent indentation z_f (m), Eq. 18.
    pub permanent_indentation: f64,
    /// The recoil element's displacement y (m) where the run ended: at separation, what the
    /// recoil spring still holds (`EnergyBudget::spring` is ½ K_r y²) and, with its sign, which
    /// way it drives the element once the force is gone.
    pub element_displacement: f64,
    /// F̄_m = F_m/(m v0 ω0).
    pub max_force_normalized: f64,
    /// ȳ = y ω0/v0 where the run ended (see `element_displacement`).
    pub element_displacement_normalized: f64,
    /// τ_f = ω0 t_f; `None` when there is no rebound.
    pub contact_time_normalized: Option<f64>,
    /// The ball's normalized numbers λ, ζ, z̄_p, κ (docs/model.md §5).
    pub normalized: Normalized,
    /// Phase switches and the end of contact, in time order.
    pub events: Vec<PhaseEvent>,
    /// Where the energy went, when [`SolveOptions::energy`] asked for it.
    pub energy: Option<EnergyBudget>,
    /// The sampled histories ([`SolveOptions::samples`] points; empty for 0).
    pub history: History,
    /// Solver steps taken: propagator steps (exact) or accepted and rejected integrator steps
    /// (adaptive), over every phase and event re-integration. Bounded by the solvers' budgets.
    pub steps: usize,
    /// Whether a stiff integrator (Radau5 or BDF, possibly at up to 1e4 times the tolerance
    /// asked for) carried some of the run: a stiff dashpot, or a phase too long for DOPRI5.
    /// Its COR and energy audit are good to about 1e-7…1e-4, not to the tolerance asked for.
    pub stiff: bool,
}

/// Why an impact has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// A parameter is out of its domain.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The solver ran out of its step or phase budget before the ball left or came to rest:
    /// rather than pass a truncated run off as "no rebound", it says so.
    #[error(
        "no answer at λ = {}, ζ = {}: {reason} ({steps} steps); a nearby λ or ζ may answer",
        number(*.lambda),
        number(*.zeta)
    )]
    Unresolved {
        /// Which budget ran out.
        reason: Unresolved,
        /// Solver steps taken before it did.
        steps: usize,
        /// The ball's λ.
        lambda: f64,
        /// The ball's ζ.
        zeta: f64,
    },
}

/// Why a run could not be brought to an end: a budget ran out, or the integrators gave up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum Unresolved {
    /// The exact solver's phase budget (`exact::MAX_PHASES`).
    #[error("more than 64 load–unload phases")]
    ExactPhases,
    /// The exact solver's step budget of one phase (`exact::MAX_STEPS`).
    #[error("the step budget of a phase ran out before its end")]
    ExactPhaseSteps,
    /// The adaptive solver's phase budget (`numeric::MAX_PHASES`).
    #[error("more than 4096 load–unload phases")]
    Phases,
    /// The adaptive solver's budget of flips at a turn (`numeric::MAX_FLIPS`).
    #[error("more than 131072 flips between load and unload at a turn")]
    Flips,
    /// The adaptive solver's step budget of one impact (`numeric::TOTAL_STEPS`).
    #[error("the step budget of the impact ran out")]
    Steps,
    /// Every integrator of the cascade gave up on a phase, and no closed form could end it.
    #[error("the integrator gave up before the end of contact")]
    GaveUp,
    /// The horizon came first, with the ball neither gone nor at rest.
    #[error("the ball neither left nor came to rest within the horizon")]
    Horizon,
}

/// Run one impact with dimensional parameters.
pub fn simulate(
    params: &ImpactParams,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Result<ImpactResponse, SolveError> {
    params.validate()?;
    if !(opts.rtol > 0.0 && opts.rtol < 1e-2) {
        return Err(ParamError {
            field: Field::Rtol,
            value: opts.rtol,
            reason: "must lie in (0, 1e-2)",
        }
        .into());
    }
    let n = params.normalized();
    let contact = Contact {
        law,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let method = match (opts.method, law) {
        (Some(Method::Exact), ContactLaw::Linear) | (None, ContactLaw::Linear) => Method::Exact,
        (Some(Method::Exact), _) => {
            return Err(ParamError {
                field: Field::Method,
                value: f64::NAN,
                reason: "the exact solver runs the linear law only",
            }
            .into());
        }
        _ => Method::Numeric,
    };
    let out = match method {
        Method::Exact => exact::solve(&n, &contact, opts),
        Method::Numeric => numeric::solve(&n, &contact, opts),
    };
    answer(params, n, law, method, out)
}

/// The outcome as the answer in SI units, or [`SolveError::Unresolved`] where the run could
/// not be brought to an end: never a truncated run passed off as an answer.
fn answer(
    params: &ImpactParams,
    n: Normalized,
    law: ContactLaw,
    method: Method,
    out: Outcome,
) -> Result<ImpactResponse, SolveError> {
    if let Some(reason) = out.unresolved {
        return Err(SolveError::Unresolved {
            reason,
            steps: out.steps,
            lambda: n.lambda,
            zeta: n.zeta,
        });
    }
    Ok(to_si(params, n, law, method, out))
}

/// Run one impact of the linear law with the exact solver, and keep its flow, which
/// [`exact::NormalPath`] reads at any τ (the oblique impact's normal motion, src/oblique/).
pub fn simulate_path(
    params: &ImpactParams,
    opts: &SolveOptions,
) -> Result<(ImpactResponse, exact::NormalPath), SolveError> {
    params.validate()?;
    let n = params.normalized();
    let contact = Contact {
        law: ContactLaw::Linear,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let (out, path) = exact::solve_path(&n, &contact, opts);
    let response = answer(params, n, ContactLaw::Linear, Method::Exact, out)?;
    Ok((response, path))
}

/// The flow of a solved impact, read at any τ: the exact solver's for the linear law, the
/// adaptive solver's steps for any other (docs/oblique.md §2).
pub enum Flow {
    /// The linear law's exact flow.
    Exact(exact::NormalPath),
    /// The adaptive run's steps, interpolated.
    Numeric(numeric::NumericPath),
}

impl Flow {
    /// F̄, F̄' and ᾱ' at τ (clamped to [0, τ_f]).
    pub fn at(&self, tau: f64) -> exact::PathPoint {
        match self {
            Flow::Exact(p) => p.at(tau),
            Flow::Numeric(p) => p.at(tau),
        }
    }

    /// τ_f.
    pub fn end(&self) -> f64 {
        match self {
            Flow::Exact(p) => p.end(),
            Flow::Numeric(p) => p.end(),
        }
    }

    /// ᾱ_max = α_max ω0/v0, the peak of the ball's displacement toward the wall (the zero of
    /// ᾱ': [`exact::NormalPath::peak_displacement`]).
    pub fn peak_displacement(&self) -> f64 {
        match self {
            Flow::Exact(p) => p.peak_displacement(),
            Flow::Numeric(p) => p.peak_displacement(),
        }
    }

    /// Where F̄' may jump (the exact flow's phase ends) or F̄'' may (the adaptive run's steps).
    pub fn boundaries(&self) -> Vec<f64> {
        match self {
            Flow::Exact(p) => p.boundaries().collect(),
            Flow::Numeric(p) => p.boundaries().collect(),
        }
    }
}

/// Run one impact of any law as [`simulate`] does (the same solver, the same integration: the
/// same answer to the last bit) and keep its flow. `Ok((response, None))` when the adaptive
/// run finished a creep in closed form, which keeps no flow to read.
pub fn simulate_flow(
    params: &ImpactParams,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Result<(ImpactResponse, Option<Flow>), SolveError> {
    if law == ContactLaw::Linear && opts.method != Some(Method::Numeric) {
        let (r, path) = simulate_path(params, opts)?;
        return Ok((r, Some(Flow::Exact(path))));
    }
    params.validate()?;
    let n = params.normalized();
    let contact = Contact {
        law,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let (out, path) = numeric::solve_path(
        &n,
        &contact,
        &SolveOptions {
            samples: 0,
            ..*opts
        },
    );
    let response = answer(params, n, law, Method::Numeric, out)?;
    Ok((response, path.map(Flow::Numeric)))
}

/// Run one impact from λ, ζ alone (m = K_p = v0 = 1, no flattening).
pub fn simulate_normalized(
    lambda: f64,
    zeta: f64,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Result<ImpactResponse, SolveError> {
    crate::model::params::validate_lambda_zeta(lambda, zeta)?;
    simulate(
        &ImpactParams::from_normalized(lambda, zeta, f64::INFINITY),
        law,
        opts,
    )
}
