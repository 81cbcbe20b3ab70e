//! The normal motion of a ball against a surface that gives or moves, for the tangential
//! model (docs/oblique.md §11): the chain's force F̄(τ), sampled on an even grid of the contact
//! by the compliant solvers (`target::history`), read between the samples on the natural cubic
//! spline through them. F̄' is the spline's derivative, and the ball's own normal speed
//! ṽ = 1 − ∫₀^τ F̄ its integral in closed form (m dv/dt = −F acts on the ball whatever the
//! surface does, so the impulse the slides take is the ball's).
//!
//! Written by hand: a natural cubic spline on an even grid is one tridiagonal solve (Thomas's
//! algorithm) and four closed forms; no crate of the tree has one.

use super::NormalMotion;
use crate::solver::exact::PathPoint;

/// F̄ on an even grid τ_j = j h (j = 0 … n, τ_n = τ_f), with the spline's second derivatives
/// and the running integral of F̄ at the grid's points.
pub(super) struct Tabulated {
    h: f64,
    force: Vec<f64>,
    /// The spline's F̄'' at each point (0 at both ends: the natural spline).
    second: Vec<f64>,
    /// ∫₀^τ_j F̄ dτ.
    integral: Vec<f64>,
}

impl Tabulated {
    /// The spline through `force` sampled at τ_j = j τ_f/(n − 1); at least 3 samples.
    pub(super) fn new(tau_end: f64, force: Vec<f64>) -> Tabulated {
        let n = force.len();
        assert!(n >= 3, "a tabulated motion needs 3 samples");
        let h = tau_end / (n - 1) as f64;
        // M_{j−1} + 4 M_j + M_{j+1} = 6 (F_{j−1} − 2F_j + F_{j+1})/h², M_0 = M_{n−1} = 0
        let mut diag = vec![4.0; n];
        let mut rhs: Vec<f64> = (0..n)
            .map(|j| {
                if j == 0 || j == n - 1 {
                    0.0
                } else {
                    6.0 * (force[j - 1] - 2.0 * force[j] + force[j + 1]) / (h * h)
                }
            })
            .collect();
        for j in 2..n - 1 {
            let w = 1.0 / diag[j - 1];
            diag[j] -= w;
            rhs[j] -= w * rhs[j - 1];
        }
        let mut second = vec![0.0; n];
        for j in (1..n - 1).rev() {
            second[j] = (rhs[j] - second[j + 1]) / diag[j];
        }
        let mut t = Tabulated {
            h,
            force,
            second,
            integral: vec![0.0; n],
        };
        for j in 1..n {
            t.integral[j] = t.integral[j - 1] + t.piece(j - 1, h).2;
        }
        t
    }

    /// On the interval from point j, at x = τ − τ_j ∈ [0, h]: (F̄, F̄', ∫_{τ_j}^τ F̄).
    fn piece(&self, j: usize, x: f64) -> (f64, f64, f64) {
        let (h, f0, f1) = (self.h, self.force[j], self.force[j + 1]);
        let (m0, m1) = (self.second[j], self.second[j + 1]);
        let (a, b) = (f0 / h - m0 * h / 6.0, f1 / h - m1 * h / 6.0);
        let y = h - x;
        let f = m0 * y.powi(3) / (6.0 * h) + m1 * x.powi(3) / (6.0 * h) + a * y + b * x;
        let rate = -m0 * y * y / (2.0 * h) + m1 * x * x / (2.0 * h) - a + b;
        let area = m0 * (h.powi(4) - y.powi(4)) / (24.0 * h)
            + m1 * x.powi(4) / (24.0 * h)
            + a * (h * h - y * y) / 2.0
            + b * x * x / 2.0;
        (f, rate, area)
    }
}

impl NormalMotion for Tabulated {
    fn at(&self, tau: f64) -> PathPoint {
        let last = self.force.len() - 2;
        let j = ((tau / self.h).floor().max(0.0) as usize).min(last);
        let (f, rate, area) = self.piece(j, tau - j as f64 * self.h);
        PathPoint {
            force: f.max(0.0),
            rate,
            velocity: 1.0 - self.integral[j] - area,
        }
    }
    fn end(&self) -> f64 {
        self.h * (self.force.len() - 1) as f64
    }
    fn kinks(&self) -> Vec<f64> {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A half sine, F̄ = sin τ on [0, π]: the spline, its slope and its integral to the
    /// sampling's accuracy (h⁴ for F̄, h² near the natural ends for F̄').
    #[test]
    fn a_half_sine_is_read_back() {
        let n = 2001;
        let tf = std::f64::consts::PI;
        let f = (0..n)
            .map(|j| (tf * j as f64 / (n - 1) as f64).sin())
            .collect();
        let t = Tabulated::new(tf, f);
        for k in 0..=37 {
            let tau = tf * k as f64 / 37.0;
            let p = t.at(tau);
            assert!((p.force - tau.sin()).abs() < 1e-9, "F at {tau}");
            assert!((p.rate - tau.cos()).abs() < 1e-6, "F' at {tau}");
            assert!((p.velocity - tau.cos()).abs() < 1e-9, "v at {tau}");
        }
        assert!((t.end() - tf).abs() < 1e-15);
    }
}
