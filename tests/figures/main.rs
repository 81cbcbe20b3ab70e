//! The SVG figures and their CSV data.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

#[path = "../support/common/mod.rs"]
mod common;
#[path = "../support/tui_common/mod.rs"]
mod tui_common;

mod figure_map_radius;
mod figure_measured_once;
mod figure_numbers;
mod figure_placement;
mod figure_radius;
mod figure_reduced;
mod figure_room;
mod figures;
