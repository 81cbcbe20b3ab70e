//! bouncelab — the Christoforou–Yigit model of the inelastic impact of a deformable sphere on a
//! rigid surface (A. P. Christoforou and A. S. Yigit, "Inelastic impact and the coefficient of
//! restitution"). Equation numbers in comments are the paper's; `docs/model.md` holds the
//! corrected forms this crate implements.
//!
//! The physics core (`model`, `solver`) does no I/O: plain data in, plain data out.

pub mod analysis;
pub mod atomic;
pub mod ball;
pub mod catalog;
pub mod cli;
pub mod drop;
#[doc(hidden)]
pub mod fault;
pub mod figure;
pub mod measured;
pub mod model;
pub mod peers;
pub mod preset;
pub mod sanitize;
pub mod signals;
pub mod solver;
pub mod text;
pub mod tui;

pub use model::contact::ContactLaw;
pub use model::params::{Field, ImpactParams, Normalized, ParamError};
pub use solver::{
    ImpactResponse, Method, SolveError, SolveOptions, Unresolved, simulate, simulate_normalized,
};
