//! The flight view (`h`, outside the `Tab` cycle): a shot (docs/flight.md) of the current
//! ball from a height at a speed, elevation and spin, its path in braille with the bounce
//! marked, and the landing and the bounce's numbers in the readout. Its values and shot in
//! [`state`], the keys' steps in [`param`], its part of `update` in `update.rs`, its panel in
//! [`widget`], `e`'s figure and header in [`export`]. A shot costs some 20 µs (BENCHMARKS.md),
//! so `update` computes it itself, as the oblique view its impact: no worker.

pub mod export;
pub mod param;
pub mod state;
mod update;
pub(in crate::tui) use update::spec;
pub mod widget;
