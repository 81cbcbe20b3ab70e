//! The library's physics: closed forms, the solvers, maps, oblique impacts, drops, flights,
//! peers, targets, standards, the rows Python reads.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

#[path = "../support/common/mod.rs"]
mod common;
#[path = "../support/domain/mod.rs"]
mod domain;
#[path = "../support/flight_ode/mod.rs"]
mod flight_ode;
#[path = "../support/seeded/mod.rs"]
mod seeded;
#[path = "../support/spread/mod.rs"]
mod spread;

mod closed_forms;
mod conditions;
mod conditions_bounds;
mod conditions_spread;
mod conditions_squash;
mod drop;
mod drop_flight;
mod drop_presets;
mod flight;
mod flight_anchors;
mod flight_mc;
mod flight_net;
mod fuzz_regressions;
mod golf_driver;
mod hertz_table;
mod map;
mod map_flatten;
mod map_flatten_lanes;
mod map_lanes;
mod map_precision;
mod map_stiff;
mod oblique;
mod oblique_bounded;
mod oblique_damping;
mod oblique_laws;
mod oblique_scan;
mod peers;
mod peers_calibration;
mod peers_export;
mod peers_figures;
mod presets;
mod properties;
mod rows;
mod rows_columns;
mod rows_wide;
mod run_summary;
mod solver_agreement;
mod solver_creeps;
mod standards;
mod surfaces;
mod target_pair;
mod taylor;
mod taylor_batch;
