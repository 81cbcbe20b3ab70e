//! A solver history read between its samples, for the synthetic force traces of the fit tests
//! (tests/support/fit_common, tests/fit_memory.rs, tests/cli/calibration.rs) and of
//! benches/fit.rs.

use bouncelab::solver::History;

/// The force of `h` at `s` seconds after first contact, linear between its samples (evenly
/// spaced from 0); zero outside the contact (0, `tf`).
pub fn force_at(h: &History, tf: f64, s: f64) -> f64 {
    if s <= 0.0 || s >= tf {
        return 0.0;
    }
    let k = ((s / h.t[1]) as usize).min(h.t.len() - 2);
    let w = (s - h.t[k]) / (h.t[k + 1] - h.t[k]);
    h.force[k] * (1.0 - w) + h.force[k + 1] * w
}
