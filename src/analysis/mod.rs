//! What users do with single impacts: sweeps (the paper's Figs. 2–4) and fits (docs/model.md §4).

pub mod fit;
pub mod sweep;
pub mod work;
