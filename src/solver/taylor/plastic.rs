//! The elastic–plastic impact's fast paths (issue 30 item 1), phase by phase.
//!
//! The law is Hertz up to z̄_p, a straight line past it, and a 3/2-power unloading from the
//! peak (docs/model.md §3, Eqs. 10–12, 18–19). Measured by callgrind (BENCHMARKS.md, "Fourth
//! session (ep5)" and "Fifth session (ep6)"): on the Taylor steps an impact past yield costs
//! some 73 000 instructions (series of order 28, `POWER_LEN`), nearly all of them the
//! 3/2-power steps (the Hertz loading to z̄_p, then the unloading); the straight stretch (1–6
//! linear steps of ≈ 1 600) is the rest.
//!
//! **No yield.** Where the Hertz impact at the same (λ, ζ, κ) turns below z̄_p the
//! elastic–plastic impact *is* the Hertz impact: the loading is Eq. 10 throughout, and with
//! z̄_m ≤ z̄_p Eqs. 18–19 give z̄_r = z̄_m, z̄_f = 0, so the unloading of Eq. 12 is
//! F̄_m (z̄/z̄_m)^{3/2} = κ z̄^{3/2}, the loading curve again. [`below_yield`] takes the Hertz
//! table's answer (`solver::table`, good to its `TOLERANCE`, 1e-12 of each output) there,
//! with the margin [`YIELD_MARGIN`] between its z̄_m and z̄_p; tests/physics/taylor.rs holds it to
//! the Taylor steps and the adaptive solver (`elastic_plastic_below_yield_is_the_hertz_impact`,
//! `elastic_plastic_near_yield`).
//!
//! Past yield the Taylor steps answer (`super::summary`).

use super::Summary;
use crate::model::params::Normalized;

/// How far below z̄_p the tabulated Hertz z̄_m must turn for the table to answer: 10⁴ times
/// the table's error (`solver::table::TOLERANCE`, 1e-12 relative), so that the true z̄_m is
/// below z̄_p too. Between, the Taylor steps decide (they find yield as an event).
pub const YIELD_MARGIN: f64 = 1e-8;

/// The elastic–plastic impact of `n` from `hertz`, the Hertz impact of the same `n` (the
/// table's, in the units of the run), where that impact turns below yield with
/// [`YIELD_MARGIN`] to spare; `None` otherwise (the Taylor steps then answer).
pub fn below_yield(n: &Normalized, hertz: Summary) -> Option<Summary> {
    let margin = n.zp_bar * (1.0 - YIELD_MARGIN);
    (hertz.max_indentation.is_finite() && hertz.max_indentation < margin).then_some(Summary {
        permanent_indentation: 0.0,
        ..hertz
    })
}
