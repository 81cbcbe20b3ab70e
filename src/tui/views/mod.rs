//! The explorer's views, one folder each: a view's state, its background worker, its widget
//! and its export live together, so a view is one folder to read (and to delete). Its part of
//! `update` is in `tui/app/<view>.rs`, where `App`'s fields are.

pub mod drop;
pub mod fit;
pub mod map;
pub mod models;
pub mod sweeps;
