//! The sweeps view (`Tab` to view 2/4): normalized peak force against ζ (the impact view's ζ
//! curves, `tui::compute`) and COR against impact speed, computed in [`speed`] on the
//! background worker; its part of `update` is `tui/app/sweeps.rs`.

pub mod speed;
