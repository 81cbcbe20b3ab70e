//! The explorer's views, one folder each: a view's state, its part of `update` (`update.rs`,
//! an `impl App` block), its background worker, its widget and its export live together, so
//! a view is one folder to read (and to delete). `App` (tui/app.rs) holds one state value per
//! view beside the shared setting; its fields are visible within `tui` for these blocks.

pub mod drop;
pub mod fit;
pub mod flight;
pub mod map;
pub mod models;
pub mod oblique;
pub mod sweeps;
