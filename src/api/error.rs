//! [`BallError`]: why a ball cannot be built or run, one line each, the command line's words.

use super::MAX_SAMPLES;
use crate::analysis::fit::{FitError, MultiFitError};
use crate::analysis::mc::McError;
use crate::analysis::work::TooMuchWork;
use crate::catalog::CatalogError;
use crate::drop::DropError;
use crate::model::params::{Field, ParamError};
use crate::oblique::ObliqueError;
use crate::solver::SolveError;
use crate::text::number as display_number;
use std::fmt;

/// Why a ball cannot be built or run. Each message is one line, the command line's own
/// (without its `bouncelab: error: ` prefix).
#[derive(Debug, Clone, PartialEq)]
pub enum BallError {
    /// No preset of that name, or a preset file that does not load.
    Catalog(CatalogError),
    /// A preset whose own parameter set is out of its domain (at the speed asked for).
    Preset {
        /// The preset's name.
        name: String,
        /// `"adopted"` or `"materials"`.
        source: &'static str,
        /// The parameter at fault.
        error: ParamError,
    },
    /// A value given (v0, λ, ζ, a parameter, a number of samples) is out of its domain.
    Param(ParamError),
    /// A λ or ζ given is in its domain but the K_r or c it gives for this ball is not.
    Derived {
        /// [`Field::Lambda`] or [`Field::Zeta`].
        field: Field,
        /// The value given.
        value: f64,
        /// `"K_r"` or `"c"`.
        gives: &'static str,
        /// The K_r or c it gives.
        derived: f64,
        /// Its unit.
        unit: &'static str,
        /// Why the derived value is refused.
        reason: &'static str,
    },
    /// A number of history samples outside 2 … [`MAX_SAMPLES`].
    Samples(usize),
    /// A list that needs at least one value (the λ values of a ζ sweep) is empty.
    NoValue(&'static str),
    /// The impact has no answer (see [`SolveError`]).
    Solve(SolveError),
    /// The fit has no answer (see [`FitError`]).
    Fit(FitError),
    /// The drop test has no answer (see [`DropError`]).
    Drop(DropError),
    /// A quantity that is none of the model's parameters (a drop height, the air) is out of
    /// its domain.
    Invalid {
        /// Its name (`drop_height`, `rebound_height`, `drag_coefficient`, `air_density`).
        field: &'static str,
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: String,
    },
    /// The multi-parameter fit has no answer (see [`MultiFitError`]).
    MultiFit(MultiFitError),
    /// A sweep asks for more work than the limit ([`crate::analysis::work::LIMIT`]).
    Work(TooMuchWork),
    /// A Monte Carlo that cannot run (see [`McError`]).
    MonteCarlo(McError),
    /// Long work stopped by its watch ([`crate::analysis::work::Watch`]: Ctrl-C in Python).
    Interrupted,
    /// An oblique impact with no answer (see [`ObliqueError`]: no rebound, endless switching).
    Oblique(ObliqueError),
}

impl fmt::Display for BallError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BallError::Catalog(e) => write!(f, "{e}"),
            BallError::Preset {
                name,
                source,
                error,
            } => write!(f, "preset '{name}' ({source} parameters): {error}"),
            BallError::Param(e) => write!(f, "{e}"),
            BallError::Derived {
                field,
                value,
                gives,
                derived,
                unit,
                reason,
            } => write!(
                f,
                "invalid {field}: {} (gives {gives} = {} {unit}: {reason})",
                display_number(*value),
                display_number(*derived)
            ),
            BallError::Samples(n) => {
                write!(f, "invalid samples: {n} (must lie in 2 … {MAX_SAMPLES})")
            }
            BallError::NoValue(field) => write!(f, "invalid {field}: no value given"),
            BallError::Solve(e) => write!(f, "{e}"),
            BallError::Fit(e) => write!(f, "{e}"),
            BallError::Drop(e) => write!(f, "{e}"),
            BallError::Work(e) => write!(f, "{e}"),
            BallError::Invalid {
                field,
                value,
                reason,
            } => write!(f, "invalid {field}: {} ({reason})", display_number(*value)),
            BallError::MultiFit(e) => write!(f, "{e}"),
            BallError::MonteCarlo(e) => write!(f, "{e}"),
            BallError::Interrupted => write!(f, "interrupted"),
            BallError::Oblique(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for BallError {}

impl BallError {
    /// Whether the error is no fault of the input: an impact (of a run, or of a drop's
    /// bounce) the solver could not bring to an end within its budgets, or a fit no start of
    /// which the solver answered for (the command line's
    /// exit code 1; every other error is bad input, exit 2).
    pub fn is_no_answer(&self) -> bool {
        matches!(
            self,
            BallError::Solve(SolveError::Unresolved { .. })
                | BallError::Drop(DropError::Solve(SolveError::Unresolved { .. }))
                | BallError::MultiFit(MultiFitError::NoAnswer)
                | BallError::MonteCarlo(McError::Solve(SolveError::Unresolved { .. }))
        ) || matches!(self, BallError::Oblique(e) if e.is_no_answer())
    }
}

/// `From<E> for BallError` for each error that a variant wraps as it is: one line a pair.
macro_rules! wraps {
    ($($error:ty => $variant:ident),+ $(,)?) => {$(
        impl From<$error> for BallError {
            fn from(e: $error) -> Self {
                BallError::$variant(e)
            }
        }
    )+};
}

wraps! {
    CatalogError => Catalog,
    ParamError => Param,
    SolveError => Solve,
    FitError => Fit,
    MultiFitError => MultiFit,
    TooMuchWork => Work,
    DropError => Drop,
    McError => MonteCarlo,
}

/// An oblique impact's bad input and solver failure are the run's own errors; only its
/// own failures (no rebound, endless switching) stay [`BallError::Oblique`].
impl From<ObliqueError> for BallError {
    fn from(e: ObliqueError) -> Self {
        match e {
            ObliqueError::Invalid(i) => BallError::Invalid {
                field: i.field,
                value: i.value,
                reason: i.reason.into(),
            },
            ObliqueError::Solve(e) => BallError::Solve(e),
            e => BallError::Oblique(e),
        }
    }
}
