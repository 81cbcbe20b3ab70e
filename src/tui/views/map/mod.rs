//! The map view (`Tab` to view 4/4, issue 21): the design map of the current ball over (λ, ζ).
//! Its state in [`state`], the finer passes on [`worker`]'s thread, its panel in [`widget`]
//! (the raster in [`cells`]), `e` writes it through [`export`]; its part of `update` is
//! `update.rs`.

pub mod cells;
pub mod export;
pub mod state;
pub mod targets;
mod update;
pub mod widget;
pub mod worker;
