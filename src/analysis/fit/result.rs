//! What a multi-parameter fit takes and gives: the data, each estimate, the fitted ball with
//! how well the data pin it, and why a fit gave no answer.

use super::Param;
use crate::measured::{CorPoint, MeasuredError, Trace};
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, ParamError};
use serde::Serialize;
use std::fmt;

/// What to fit to.
#[derive(Debug, Clone, Copy)]
pub enum FitData<'a> {
    /// A measured force–time pulse: the model's F(t) is fitted to it, with the start of
    /// contact in the data's clock and the force baseline fitted too.
    Trace(&'a Trace),
    /// COR against impact speed (with peak forces and contact times where given): the model's
    /// values at each speed are fitted to them (a drop test becomes such a table).
    Cor(&'a [CorPoint]),
}

/// One fitted quantity: value, standard error and 95 % interval (SI).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Estimate {
    /// Its name in the output ([`Param::name`], or `time_offset`, `baseline`).
    #[serde(skip)]
    pub name: &'static str,
    /// Its SI unit.
    #[serde(skip)]
    pub unit: &'static str,
    /// The fitted value.
    pub value: f64,
    /// Its standard error from cov = s² (JᵀJ)⁻¹ ([`super::stats`]); for a model parameter,
    /// fitted as θ = ln p, by the delta method, p s_θ.
    pub std_error: f64,
    /// The 95 % interval: exp(θ ± t₀.₉₇₅ s_θ) for a model parameter (so it stays positive),
    /// value ± t₀.₉₇₅ std_error for the offset and baseline; the oblique fit's the profile's
    /// (`analysis::fit::profile`: exp of where τ(θ) = ±t₀.₉₇₅, ∞ where the data do not bound
    /// it); Student t at n − p degrees of freedom; NaN when the data leave no degree of
    /// freedom or do not pin the value. A trace that starts with the contact: the hull of the
    /// intervals on both sides of its first row where both fit (`analysis::fit::edge`,
    /// docs/fitting.md).
    pub ci95: [f64; 2],
}

impl Estimate {
    /// `name` (in `unit`) fitted at `value`, its standard error `std_error` and 95 % interval
    /// `ci95`.
    pub fn new(
        name: &'static str,
        unit: &'static str,
        value: f64,
        std_error: f64,
        ci95: [f64; 2],
    ) -> Estimate {
        Estimate {
            name,
            unit,
            value,
            std_error,
            ci95,
        }
    }
}

/// A fitted ball and how well the data pin it.
#[derive(Debug, Clone)]
pub struct MultiFit {
    /// The whole fitted ball (the free parameters moved, the rest as given).
    pub params: ImpactParams,
    /// The contact law fitted under.
    pub law: ContactLaw,
    /// One estimate for each free parameter, in the order given.
    pub fitted: Vec<Estimate>,
    /// Force–time: where the contact starts in the data's clock (s), and the force baseline.
    pub time_offset: Option<Estimate>,
    /// Force–time: the constant force (N) the data read when nothing touches.
    pub baseline: Option<Estimate>,
    /// Correlations between every fitted quantity, in the order of `names`.
    pub names: Vec<&'static str>,
    /// The correlation matrix, one row a quantity of `names`.
    pub correlation: Vec<Vec<f64>>,
    /// RMS of model − data: newtons for a trace, COR for a table.
    pub rms_residual: f64,
    /// Data points fitted (samples of a trace; values of a table).
    pub points: usize,
    /// Levenberg–Marquardt iterations over every start.
    pub iterations: usize,
    /// Whether the best start met a convergence test (not just the iteration budget).
    pub converged: bool,
    /// Condition number of the column-scaled Jacobian (see [`super::stats`]).
    pub condition: f64,
    /// What the caller should know, one line each: no degree of freedom left, a parameter
    /// the data cannot tell from the others, an interval wider than its value, a fit that
    /// stopped on its iteration budget.
    pub warnings: Vec<String>,
    /// The model at each data point: force (N) at each sample, or COR at each speed.
    pub model: Vec<f64>,
    /// Whether the fit answered: it converged and the data pin every free parameter
    /// (`verdict::pinned`). A fit that did not answer still reports what it found,
    /// but the command line exits 1 and refuses to save or plot it.
    pub identified: bool,
    /// The free parameters the data do not pin (an interval wider than a factor
    /// `verdict::PIN_RATIO`, no finite interval, or a value on the search's bound).
    pub not_pinned: Vec<&'static str>,
    /// The free parameters that ran to the bound of their search (±5 decades from the start
    /// for a COR table, ±4 for a trace): the data ask for more than the model gives with the
    /// others held.
    pub on_bound: Vec<&'static str>,
    /// Degrees of freedom were left but every residual is zero: the data show no scatter to
    /// estimate the uncertainty from (`verdict::NO_SCATTER`; no standard error or interval).
    pub no_scatter: bool,
    /// Every row's COR gave its standard deviation (`cor_sd`), taken as known: the intervals
    /// are scaled by those sds, not by the residuals' scatter (`stats::Spread::Stated`).
    pub stated_sd: bool,
    /// A test of whether the model can follow the data at all (systematic residuals); `None`
    /// where no test applies (too few points, no degree of freedom).
    pub lack_of_fit: Option<LackOfFit>,
}

impl MultiFit {
    /// Whether the fit had as many data as quantities fitted (no degree of freedom left), or
    /// residuals all zero ([`MultiFit::no_scatter`]): the values solve the data exactly and
    /// no standard error or interval can be estimated.
    pub fn exact(&self) -> bool {
        self.points <= self.names.len() || self.no_scatter
    }
}

/// Why a multi-parameter fit gave no answer; each message is one line.
#[derive(Debug, Clone, PartialEq)]
pub enum MultiFitError {
    /// The starting parameters are invalid.
    Params(ParamError),
    /// No parameter was freed.
    NoFree,
    /// A parameter was freed twice.
    Repeated(Param),
    /// K_h and K_p are tied by Eq. 16: one of them at a time.
    Tied,
    /// Fewer data points than quantities to fit.
    TooFew {
        /// Data points given.
        points: usize,
        /// Quantities to fit (free parameters, and a trace's offset and baseline).
        parameters: usize,
    },
    /// The trace holds no pulse to fit.
    NoPulse(MeasuredError),
    /// No start led to parameters the solver answers for.
    NoAnswer,
    /// The trace's impulse contradicts the impact speed and mass: I = m v0 (1 + e) needs
    /// 0 ≤ e ≤ 1, so v0 must lie in [I/(2m), I/m].
    Contradicts {
        /// The restitution the impulse implies at the given v0.
        implied: f64,
        /// The impact speed given (m/s).
        v0: f64,
        /// The impulse of the pulse (N s).
        impulse: f64,
        /// The speeds the impulse allows (m/s): I/(2m) and I/m.
        allowed: [f64; 2],
    },
    /// As many data as parameters, and no parameters of the model reproduce them (the miss of
    /// the best, or a parameter pressed on its bound): the message says what is reachable.
    OutOfReach(String),
    /// The fit ran but gave no answer (did not converge, or the data do not pin a
    /// parameter): the reason. Not the input's fault alone: the command line exits 1.
    Unanswered(String),
    /// `v0` is free but the data carry their own speeds (a COR table or drop tests).
    SpeedNotFree,
    /// A value that is not a finite number came up on the way (data or parameters far outside
    /// any ball's range).
    NonFinite,
    /// The fit's work is beyond the work limit ([`crate::analysis::work`]), refused before it
    /// started.
    TooMuchWork(crate::analysis::work::TooMuchWork),
    /// The fit's watch stopped it ([`crate::analysis::work::Watch`]: Ctrl-C, KeyboardInterrupt).
    Interrupted,
}

impl From<crate::analysis::work::TooMuchWork> for MultiFitError {
    fn from(e: crate::analysis::work::TooMuchWork) -> Self {
        MultiFitError::TooMuchWork(e)
    }
}

impl fmt::Display for MultiFitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MultiFitError::Params(e) => write!(f, "{e}"),
            MultiFitError::NoFree => write!(f, "no free parameter to fit"),
            MultiFitError::Repeated(p) => write!(f, "free parameter {} given twice", p.name()),
            MultiFitError::Tied => write!(
                f,
                "k_h and k_p are tied (K_p = 1.5 K_h √z_p, Eq. 16): free one of them"
            ),
            MultiFitError::TooFew { points, parameters } => write!(
                f,
                "{}, fewer than the {} fitted",
                crate::text::counted(*points, "data point"),
                crate::text::counted(*parameters, "parameter")
            ),
            MultiFitError::NoPulse(e) => write!(f, "{e}"),
            MultiFitError::NoAnswer => write!(
                f,
                "no starting point gave parameters the solver answers for"
            ),
            MultiFitError::Contradicts {
                implied,
                v0,
                impulse,
                allowed,
            } => write!(
                f,
                "the pulse's impulse {} N s implies e = {} at v0 = {} m/s (I = m v0 (1 + e)), \
                 outside 0 … 1: the trace allows v0 from {} to {} m/s (give --v0, or --free v0 \
                 to fit it)",
                crate::text::sig(*impulse, 4),
                crate::text::sig(*implied, 3),
                crate::text::number(*v0),
                crate::text::sig(allowed[0], 4),
                crate::text::sig(allowed[1], 4)
            ),
            MultiFitError::OutOfReach(m) => write!(f, "{m}"),
            MultiFitError::Unanswered(why) => write!(f, "the fit gave no answer: {why}"),
            MultiFitError::SpeedNotFree => write!(
                f,
                "v0 can be fitted from a force-time trace only: a COR table or drop test gives \
                 each row's speed"
            ),
            MultiFitError::NonFinite => write!(
                f,
                "the fit met a value that is not a finite number: the data lie far outside \
                 any ball's range"
            ),
            MultiFitError::TooMuchWork(e) => write!(f, "{e}"),
            MultiFitError::Interrupted => write!(f, "interrupted: the fit was stopped"),
        }
    }
}

impl std::error::Error for MultiFitError {}

/// A test of the residuals for a model that cannot follow the data.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LackOfFit {
    /// `"runs"` (Wald–Wolfowitz runs test of the residuals' signs, in data order: too few
    /// runs means the misses are systematic) or `"chi2"` (Σ(r/σ)² against χ² at n − p
    /// degrees of freedom, when every point carries its standard deviation).
    pub test: &'static str,
    /// The runs test's z (negative: fewer runs than chance), or χ².
    pub statistic: f64,
    /// One-sided p-value: the chance of residuals this systematic (this large) from noise.
    pub p_value: f64,
}

impl LackOfFit {
    /// Whether the test says the model cannot follow the data.
    pub fn significant(&self) -> bool {
        self.p_value < LACK_OF_FIT_P
    }
}

/// Below this p-value the residuals are called systematic: the model cannot follow the data.
pub const LACK_OF_FIT_P: f64 = 1e-3;
