//! The command line's contract, run through the `bouncelab` binary: subcommands, goldens, exit
//! codes, bad input, outputs, signals.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

#[path = "../support/common/mod.rs"]
mod common;
#[path = "../support/fit_common/mod.rs"]
mod fit_common;
#[path = "../support/hostile/mod.rs"]
mod hostile;
#[path = "../support/pty/mod.rs"]
mod pty;
#[path = "../support/seeded/mod.rs"]
mod seeded;
#[path = "../support/tui_common/mod.rs"]
mod tui_common;

mod answer_keys;
mod answer_reach;
mod answer_reach_map;
mod answer_warnings;
mod calibration;
mod calibration_outputs;
mod cli;
mod cli_aerodynamics;
mod cli_bad_input;
mod cli_batch;
mod cli_batch_bound;
mod cli_batch_cor_interval;
mod cli_batch_csv;
mod cli_batch_readings;
mod cli_collide_pair;
mod cli_drop;
mod cli_explorer_oblique;
mod cli_figure_presets;
mod cli_figures;
mod cli_fit;
mod cli_fit_air;
mod cli_fit_joint;
mod cli_fit_oblique;
mod cli_fit_reports;
mod cli_formats_name;
mod cli_golden;
mod cli_golden_batch;
mod cli_golden_map;
mod cli_golden_oblique;
mod cli_golden_shot;
mod cli_golden_targets;
mod cli_guarantees;
mod cli_map;
mod cli_mc;
mod cli_mc_correlated;
mod cli_oblique;
mod cli_odd_inputs;
mod cli_outputs;
mod cli_peers;
mod cli_peers_case;
mod cli_presets;
mod cli_progress_pty;
mod cli_reproduce;
mod cli_runout_trial;
mod cli_shot_net;
mod cli_shot_surface;
mod cli_size;
mod cli_small;
mod cli_standards_ball;
mod cli_static;
mod cli_surface_header;
mod cli_surface_names;
mod cli_surface_warnings;
mod cli_tangential_damping;
mod cli_target_pair;
mod cli_targets;
mod court_assumed;
mod escaping;
mod field_names;
mod hostile_generators;
mod hostile_unreadable;
mod issue52_messages;
mod issue52_trial;
mod numbers_as_typed;
mod outputs_regular_only;
mod session_file;
mod signals_early;
mod signals_prompt;
mod suspend_pty;
