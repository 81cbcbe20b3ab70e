//! Fits, their intervals and coverage, Monte Carlo, batches, measured files.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

#[path = "../support/common/mod.rs"]
mod common;
#[path = "../support/fit_common/mod.rs"]
mod fit_common;
#[path = "../support/seeded/mod.rs"]
mod seeded;

mod batch_cpk_interval;
mod batch_verdict_interval;
mod fit_answers;
mod fit_coverage;
mod fit_drop_coverage;
mod fit_intervals;
mod fit_joint;
mod fit_oblique;
mod fit_oblique_coverage;
mod fit_oblique_damping;
mod fit_plot_aligned;
mod fit_recovery;
mod fit_stated_sd;
mod fit_work_limit;
mod intervals_physical;
mod mc_conditions;
mod mc_flattening;
mod mc_intervals;
mod mc_watched;
mod measured_bad_files;
mod measured_props;
mod measured_readers;
