//! Extrapolation of the linearly implicit Euler method (Deuflhard's LIMEX, Hairer and Wanner's
//! SEULEX: E. Hairer, G. Wanner, *Solving Ordinary Differential Equations II*, §IV.9) on a
//! four-state system with its Jacobian written out.
//!
//! One macro step H from x₀ takes, for j = 1 … `COLUMNS`, n_j = j substeps h = H/n_j of
//!
//! ```text
//!     (I − h J) Δ = h f(x_i),   x_{i+1} = x_i + Δ,    J = f'(x₀)
//! ```
//!
//! and extrapolates the ends T_{j,1} to h → 0 by the Aitken–Neville scheme in powers of h
//! (the method is one-step with a smooth increment for a fixed J, so its error has an
//! expansion in h): T_{j,k+1} = T_{j,k} + (T_{j,k} − T_{j−1,k}) / (n_j/n_{j−k} − 1). The
//! step is taken at T_{K,K} (order K) where ‖T_{K,K} − T_{K,K−1}‖ (the error of the order
//! K − 1 value) is within the tolerance. Each substep solves with I − hJ, so the stiff mode
//! (the dashpot's 2ζ(k + λ), docs/model.md §8) decays in it whatever the step: the method is
//! stable at any stiffness. Its steps are not free of the stiffness, though: the expansion in
//! h holds only for h·rate small, and at 1e-12 the Prothero–Robinson test below takes 33 steps
//! at rate 1 but some 1 400–1 700 at 10³ and 10⁶ (the unit test prints them) — accurate, not
//! fast, which is why it is a reference (`super`).
//!
//! Why by hand: the reference must be independent of the adaptive solver, whose stiff
//! integrators are the `differential-equations` crate's Radau5 and BDF (their runs in the
//! map's stiff corner close their energy balance loosely and are run again by DOPRI5,
//! docs/numerics.md). `russell_ode` (Radau5) needs a system BLAS/LAPACK and `diffsol` brings a
//! large tree; neither was tried here. For a 4 × 4 system with its Jacobian written out and
//! no dense output the method is the few lines below, its solves nalgebra's 4 × 4 LU.

use nalgebra::{Matrix4, Vector4};

/// The state: four components.
pub(super) type X = [f64; 4];

/// A system x' = f(x) (autonomous) with its Jacobian.
pub(super) trait System {
    fn f(&self, x: &X) -> X;
    fn jacobian(&self, x: &X) -> [[f64; 4]; 4];
}

/// Columns of the extrapolation table: the order of the step taken.
const COLUMNS: usize = 7;

/// The tolerance of the steps: each component's error against `atol + rtol |x|`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Tolerance {
    pub rtol: f64,
    pub atol: f64,
}

/// One macro step's outcome: its end (T_{K,K}) and its error in units of the tolerance.
pub(super) struct Step {
    pub x: X,
    pub err: f64,
}

/// One macro step of length `h` from `x0`; `None` where a solve fails (I − hJ singular) or
/// the values are not finite.
pub(super) fn step<S: System>(sys: &S, x0: &X, h: f64, tol: Tolerance) -> Option<Step> {
    let rows = sys.jacobian(x0);
    let jac = Matrix4::from_fn(|i, j| rows[i][j]);
    let mut table: [X; COLUMNS] = [[0.0; 4]; COLUMNS];
    let mut err = 0.0;
    for j in 0..COLUMNS {
        let n = j + 1;
        let sub = h / n as f64;
        let lu = (Matrix4::identity() - jac * sub).lu();
        // the increment from x0, not the state, is extrapolated: its rounding is relative to
        // the step's motion, not to |x|, and the table's weights (hundreds at seven columns)
        // amplify it
        let mut x = [0.0; 4];
        for _ in 0..n {
            let at: X = std::array::from_fn(|i| x0[i] + x[i]);
            let f = sys.f(&at);
            let rhs = Vector4::from_fn(|i, _| sub * f[i]);
            let d = lu.solve(&rhs)?;
            x = std::array::from_fn(|i| x[i] + d[i]);
        }
        // Aitken–Neville: table[k] holds T_{j+1, k+1} after the sweep (n_{j−k} = j − k + 1)
        let mut prev = x;
        for (k, row) in table.iter_mut().enumerate().take(j) {
            let ratio = n as f64 / (n - k - 1) as f64 - 1.0;
            let next: X = std::array::from_fn(|i| prev[i] + (prev[i] - row[i]) / ratio);
            *row = prev;
            prev = next;
        }
        table[j] = prev;
        if j == COLUMNS - 1 {
            err = norm(&table[j], &table[j - 1], x0, tol);
        }
    }
    let x: X = std::array::from_fn(|i| x0[i] + table[COLUMNS - 1][i]);
    (x.iter().all(|v| v.is_finite()) && err.is_finite()).then_some(Step { x, err })
}

/// The largest |a_i − b_i| / (atol + rtol max(|x0_i + a_i|, |x0_i|)), `a` and `b` increments
/// from `x0`.
fn norm(a: &X, b: &X, x0: &X, tol: Tolerance) -> f64 {
    (0..4).fold(0.0f64, |m, i| {
        let scale = tol.atol + tol.rtol * (x0[i] + a[i]).abs().max(x0[i].abs());
        m.max((a[i] - b[i]).abs() / scale)
    })
}

/// The next step after one whose error was `err` (in tolerances): the error of the order
/// K − 1 value goes as h^K.
pub(super) fn next_step(h: f64, err: f64) -> f64 {
    let factor = if err <= 0.0 {
        4.0
    } else {
        (0.9 * err.powf(-1.0 / COLUMNS as f64)).clamp(0.2, 4.0)
    };
    h * factor
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x' = −k (x − cos t) + ..., written autonomous: a stiff linear test problem
    /// (Prothero–Robinson), x = cos t exactly, with t the third state.
    struct Prothero(f64);

    impl System for Prothero {
        fn f(&self, x: &X) -> X {
            let t = x[2];
            [-self.0 * (x[0] - t.cos()) - t.sin(), 0.0, 1.0, 0.0]
        }
        fn jacobian(&self, x: &X) -> [[f64; 4]; 4] {
            let t = x[2];
            let mut j = [[0.0; 4]; 4];
            j[0][0] = -self.0;
            j[0][2] = -self.0 * t.sin() - t.cos();
            j
        }
    }

    /// The answer holds its tolerance at every stiffness; the steps it takes say where the
    /// method pays (the module's introduction, `super`'s: a mildly stiff problem, the rate
    /// some hundreds to thousands, takes the most).
    #[test]
    fn a_stiff_problem_is_followed_to_its_tolerance() {
        let tol = Tolerance {
            rtol: 1e-12,
            atol: 1e-12,
        };
        for stiffness in [1.0, 1e3, 1e6] {
            let sys = Prothero(stiffness);
            let (mut x, mut h, mut steps) = ([1.0, 0.0, 0.0, 0.0], 0.1f64, 0);
            while x[2] < 3.0 {
                let h_now = h.min(3.0 - x[2]);
                let s = step(&sys, &x, h_now, tol).unwrap();
                h = next_step(h_now, s.err);
                if s.err <= 1.0 {
                    x = s.x;
                }
                steps += 1;
                assert!(steps < 100_000, "{stiffness}: {steps} steps");
            }
            eprintln!("stiffness {stiffness}: {steps} steps");
            assert!((x[0] - 3f64.cos()).abs() < 1e-10, "{stiffness}: {}", x[0]);
        }
    }
}
