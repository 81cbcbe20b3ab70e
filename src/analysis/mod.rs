//! What users do with single impacts: sweeps (the paper's Figs. 2–4) and fits (MODEL.md §4).

pub mod fit;
pub mod sweep;
