//! The sweeps view (`Tab` to view 2/4): normalized peak force against ζ (the impact view's ζ
//! curves, `tui::compute`) and COR against impact speed, computed in [`speed`] on the
//! background worker and held in [`state`]; its part of `update` is `update.rs`.

pub mod speed;
pub mod state;
mod update;
