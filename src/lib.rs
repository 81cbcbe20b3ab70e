//! bouncelab computes how a deformable sphere — a sports ball — bounces off a rigid wall: its
//! coefficient of restitution (COR), peak force, contact time and flattening, with the model of
//! A. P. Christoforou and A. S. Yigit, "Inelastic impact and the coefficient of restitution".
//! SI units throughout; equation numbers are the paper's, and `docs/model.md` holds the
//! corrected forms this crate implements.
//!
//! # Five minutes
//!
//! A [`Ball`] is a preset (or the normalized ball, or your own parameters); ask it for an
//! impact:
//!
//! ```
//! use bouncelab::{Ball, ContactLaw};
//!
//! let r = Ball::from_preset("golf")?.with_v0(3.0)?.impact()?;
//! println!("e = {:.4}, F_m = {:.1} N, t_f = {:.3} ms", r.cor, r.max_force,
//!          r.contact_time.unwrap() * 1e3);
//! assert!((r.cor - 0.8404).abs() < 1e-4);
//!
//! // λ = K_r/K_p and ζ = √(m K_p)/(2c) set the response: a softer recoil spring keeps less
//! let soft = Ball::from_preset("golf")?.with_v0(3.0)?.with_lambda(0.2)?;
//! assert!(soft.impact()?.cor < r.cor);
//! // another contact law
//! assert!(soft.with_law(ContactLaw::Hertz).impact()?.rebound);
//!
//! // the recoil spring K_r that gives a measured COR (docs/model.md §4)
//! let fit = Ball::from_preset("superball")?.fit_cor(0.75)?;
//! println!("K_r = {:.0} N/m, λ = {:.4}", fit.k_r, fit.lambda);
//! # Ok::<(), bouncelab::BallError>(())
//! ```
//!
//! Every error is a [`BallError`] whose message is the command line's, one line naming the
//! field at fault. The COR-against-ζ curves of the paper's Figs. 2–3 are [`sweep_zeta`]; COR
//! against speed (Fig. 4) is [`Ball::sweep_velocity`]; a drop test with its bounces is
//! [`Ball::drop_test`]; the presets are listed by [`catalog::Catalog::embedded`] (and, with the
//! user's files, [`catalog::Catalog::load`]).
//!
//! # What is where
//!
//! - [`api`]: the [`Ball`] entry point, built on the modules below ([`ball::Ball`] is the plain
//!   ball record the figures and the explorer share);
//! - [`solver`]: one impact, [`simulate`] (exact linear solver, adaptive numerical one) and its
//!   [`ImpactResponse`];
//! - [`model`]: the parameters ([`ImpactParams`], normalized as λ, ζ, z̄_p, κ), the contact laws
//!   ([`ContactLaw`]) and the material formulas;
//! - [`analysis`]: sweeps, fits of the model to measurements (one COR, COR tables,
//!   force–time traces), and the Monte Carlo over parameter tolerances ([`analysis::mc`],
//!   [`Ball::monte_carlo`]);
//! - [`measured`]: measured data read from text (traces, COR tables, drop tests);
//! - [`peers`]: the field's other contact models (Kelvin–Voigt, Tsuji, Hunt–Crossley)
//!   calibrated to the same ball;
//! - [`mod@drop`]: drop tests and bounce sequences (flight with drag between impacts), and the
//!   sports' standards they are judged by;
//! - [`target`]: two-body impacts — a target of finite mass, moving, with a surface that
//!   gives (bats, rackets, another ball);
//! - [`preset`] and [`catalog`]: the ball presets (TOML) and where they are found.
//!
//! The physics does no I/O: plain data in, plain data out (only [`catalog`] reads preset files).
//!
//! # Cargo features
//!
//! The default features `cli`, `tui` and `svg` build the `bouncelab` program: the command line
//! (clap), the terminal explorer (ratatui) and the SVG figures (plotters). A program that only
//! needs the physics depends on `bouncelab = { version = "…", default-features = false }` and
//! compiles none of them. The Python package (`pip install ./python`) wraps this API; see
//! docs/library.md.

// Every public item of the library is documented (CI's clippy denies warnings). The
// application's modules (`cli`, `tui`, …) are `#[doc(hidden)]`, which the lint skips.
#![warn(missing_docs)]

// the test-support files the unit tests share by `#[path]` with the tests and benches name
// the crate as they do (src/analysis/fit/bins.rs)
#[cfg(test)]
extern crate self as bouncelab;
// the bench ball's file (benches/fit.rs's ball, its fit's start, its fixed noise), one module
// for every unit test that takes it: the binned fit's and src/measured/trace.rs's
#[cfg(test)]
#[path = "../tests/support/fit_common/bench_ball.rs"]
mod bench_ball;
// the tests' one seeded generator (ChaCha8), for the unit tests that draw points
#[cfg(test)]
#[path = "../tests/support/seeded/mod.rs"]
mod seeded;

pub mod analysis;
pub mod api;
#[cfg(feature = "tui")]
#[doc(hidden)]
pub mod atomic;
pub mod ball;
pub mod catalog;
pub mod conditions;
// the command line and the explorer are the application, not the library's API: hidden from
// the docs, and not held to documenting every public item
#[cfg(feature = "cli")]
#[doc(hidden)]
#[allow(missing_docs)]
pub mod cli;
pub mod drop;
#[doc(hidden)]
pub mod fault;
#[cfg(feature = "svg")]
pub mod figure;
pub mod flight;
pub mod map;
pub mod measured;
pub mod model;
pub mod oblique;
pub mod peers;
pub mod preset;
#[doc(hidden)]
pub mod sanitize;
#[cfg(feature = "tui")]
#[doc(hidden)]
pub mod signals;
pub mod solver;
pub mod target;
pub mod text;
#[cfg(feature = "tui")]
#[doc(hidden)]
#[allow(missing_docs)] // the application (the terminal explorer), not the library's API
pub mod tui;

pub use api::{Ball, BallError, sweep_zeta};
pub use model::contact::ContactLaw;
pub use model::params::{Field, ImpactParams, Normalized, ParamError};
pub use solver::{
    ImpactResponse, Method, SolveError, SolveOptions, Unresolved, simulate, simulate_normalized,
};
