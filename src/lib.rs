//! bouncelab — the Christoforou–Yigit model of the inelastic impact of a deformable sphere on a
//! rigid surface (A. P. Christoforou and A. S. Yigit, "Inelastic impact and the coefficient of
//! restitution"). Equation numbers in comments are the paper's; `MODEL.md` holds the corrected
//! forms this crate implements.
//!
//! The physics core (`model`, `solver`) does no I/O: plain data in, plain data out.

pub mod analysis;
pub mod catalog;
pub mod cli;
#[doc(hidden)]
pub mod fault;
pub mod figure;
pub mod model;
pub mod peers;
pub mod preset;
pub mod solver;
pub mod tui;

pub use model::contact::ContactLaw;
pub use model::params::{ImpactParams, Normalized, ParamError};
pub use solver::{ImpactResponse, Method, SolveError, SolveOptions, simulate, simulate_normalized};
