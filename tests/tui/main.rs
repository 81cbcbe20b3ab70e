//! The explorer: `App::update` and the drawn screen (insta snapshots), and the real binary
//! under a pseudo-terminal.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

#[path = "../support/common/mod.rs"]
mod common;
#[path = "../support/fit_common/mod.rs"]
mod fit_common;
#[path = "../support/pty/mod.rs"]
mod pty;
#[path = "../support/save_flow/mod.rs"]
mod save_flow;
#[path = "../support/seeded/mod.rs"]
mod seeded;
#[path = "../support/tui_common/mod.rs"]
mod tui_common;

mod measured_explorer;
mod tui_app;
mod tui_app_views;
mod tui_calibration;
mod tui_charts;
mod tui_command;
mod tui_command_pty;
mod tui_conditions;
mod tui_crosshair;
mod tui_drop;
mod tui_exit_pty;
mod tui_export;
mod tui_fit;
mod tui_fit_drops;
mod tui_fit_pty;
mod tui_flight;
mod tui_flight_state;
mod tui_form;
mod tui_guards;
mod tui_heavy;
mod tui_issue18;
mod tui_issue18_charts;
mod tui_legend;
mod tui_map;
mod tui_map_state;
mod tui_marks;
mod tui_models;
mod tui_models_export;
mod tui_newcomer_trial;
mod tui_oblique;
mod tui_oblique_export;
mod tui_oblique_state;
mod tui_picker;
mod tui_pins;
mod tui_pty;
mod tui_quit;
mod tui_quit_pty;
mod tui_render;
mod tui_render_axes;
mod tui_render_labels;
mod tui_roundtrip;
mod tui_save;
mod tui_save_overwrite;
mod tui_save_pty;
mod tui_screen_words;
mod tui_session;
mod tui_small;
mod tui_small_pty;
mod tui_surface;
mod tui_surface_form;
mod tui_surface_said;
mod tui_target;
mod tui_ticks;
mod tui_typeahead_pty;
mod tui_typed_numbers;
mod tui_walk;
mod tui_worker_pty;
mod tui_worker_stopped;
