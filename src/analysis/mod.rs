//! What users do with single impacts: sweeps (the paper's Figs. 2–4), fits (docs/model.md §4)
//! and Monte Carlo over tolerances (docs/scale.md).

pub mod batch;
mod batch_stats;
pub mod fit;
pub mod mc;
mod mc_conditions;
mod mc_corr;
mod mc_impact;
mod mc_interval;
mod mc_order;
mod mc_rng;
mod mc_samples;
mod mc_spec;
mod mc_stats;
pub mod statics;
pub mod sweep;
pub mod work;
