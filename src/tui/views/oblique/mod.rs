//! The oblique view (`i`, outside the Tab cycle, issue 31): one oblique impact of the current
//! ball (docs/oblique.md) with the angle θ, the spin ω and the friction μ adjustable, its
//! forces and slip against time, its paths over the surface and a readout (the ITF court pace
//! for the tennis ball), and an (angle, μ) map. Its state in [`state`] (the parameters and
//! their one range in [`param`]), the map in [`map`] (computed on [`worker`]'s thread), its
//! part of `update` in `update.rs`, the panel in [`widget`] (the charts in [`charts`], the map's
//! raster in [`map_widget`]); `e` exports its charts ([`export`]). Everything is asked of the library's front door, `Ball::oblique`
//! and `Ball::court_pace` (src/api/oblique.rs), as `bouncelab oblique` and `court` ask it.

pub mod charts;
pub mod export;
pub mod map;
pub mod map_widget;
pub mod param;
pub mod state;
mod update;
pub mod widget;
pub mod worker;
