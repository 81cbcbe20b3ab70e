//! One step of the Radau IIA collocation method with [`S`] stages (order 2S − 1 = 9, stiffly
//! accurate, L-stable) for a three-state system, the implicit step the stiff phases take
//! (`stiff`): where the dashpot is stiff an explicit step (the Taylor series of `power`) must
//! stay within the inverse of the fastest rate, an L-stable one only within the slow motion's
//! scale (Hairer & Wanner, *Solving ODEs II*, IV.5 and VI.3: on a singularly perturbed
//! problem the error stays O(h^{2S−1}) + O(ε h^{S})).
//!
//! Why hand-written: the `differential-equations` crate's Radau5 (order 5, the adaptive
//! solver's cascade) needs some 10× the steps at the 1e-12 the map holds, and a step here is a
//! 15 × 15 simplified Newton on a polynomial right-hand side, with no allocation.
//!
//! The tableau is computed once (`TABLEAU`): the nodes are the roots of
//! d^{S−1}/dx^{S−1} [x^{S−1} (x − 1)^S] (c_S = 1), A_ij = ∫₀^{c_i} ℓ_j (Lagrange basis on the
//! nodes); `radau_tableau_meets_the_order_conditions` checks B(2S − 1) and C(S).

use nalgebra::{SMatrix, SVector};
use std::sync::LazyLock;

/// Stages.
pub(super) const S: usize = 5;
/// Unknowns of the stage equations: S stages of three states.
const M: usize = 3 * S;

/// A three-state system x' = f(x), its Jacobian, and the rate dτ/dσ of the phase's time τ
/// in the variable σ it is integrated in.
pub(super) trait System {
    fn f(&self, x: [f64; 3]) -> [f64; 3];
    fn jac(&self, x: [f64; 3]) -> [[f64; 3]; 3];
    /// dτ/dσ, a function of the state alone (τ is then a quadrature of the stages).
    fn dtau(&self, x: [f64; 3]) -> f64;
}

/// The Radau IIA coefficients and the collocation polynomial's weights.
pub(super) struct Tableau {
    pub c: [f64; S],
    pub a: [[f64; S]; S],
    /// 1 / Π_{m≠j} (t_j − t_m) over the nodes t = (0, c_1, …, c_S): the leading coefficient
    /// of the collocation polynomial is Σ_j w_j X_j.
    pub lead: [f64; S + 1],
}

/// A polynomial's coefficients, lowest first.
fn mul(p: &[f64], q: &[f64]) -> Vec<f64> {
    let mut r = vec![0.0; p.len() + q.len() - 1];
    for (i, pi) in p.iter().enumerate() {
        for (j, qj) in q.iter().enumerate() {
            r[i + j] += pi * qj;
        }
    }
    r
}

fn value(p: &[f64], x: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, &c| acc * x + c)
}

fn tableau() -> Tableau {
    // x^{S−1} (x − 1)^S, differentiated S − 1 times
    let mut p = vec![1.0];
    for _ in 0..S - 1 {
        p = mul(&p, &[0.0, 1.0]);
    }
    for _ in 0..S {
        p = mul(&p, &[-1.0, 1.0]);
    }
    for _ in 0..S - 1 {
        p = (1..p.len()).map(|k| k as f64 * p[k]).collect();
    }
    // the S − 1 roots inside (0, 1) by bisection on a fine grid's sign changes, then c_S = 1
    let mut c = [1.0; S];
    let mut found = 0;
    let grid = 4000;
    for i in 0..grid - 1 {
        let (mut lo, mut hi) = (i as f64 / grid as f64, (i + 1) as f64 / grid as f64);
        if value(&p, lo) * value(&p, hi) > 0.0 || found == S - 1 {
            continue;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if value(&p, lo) * value(&p, mid) <= 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        c[found] = 0.5 * (lo + hi);
        found += 1;
    }
    let mut a = [[0.0; S]; S];
    for j in 0..S {
        // ℓ_j, then its integral from 0
        let mut l = vec![1.0];
        for m in (0..S).filter(|&m| m != j) {
            l = mul(&l, &[-c[m] / (c[j] - c[m]), 1.0 / (c[j] - c[m])]);
        }
        let integral: Vec<f64> = std::iter::once(0.0)
            .chain(l.iter().enumerate().map(|(k, lk)| lk / (k + 1) as f64))
            .collect();
        for (i, row) in a.iter_mut().enumerate() {
            row[j] = value(&integral, c[i]);
        }
    }
    let t: Vec<f64> = std::iter::once(0.0).chain(c).collect();
    let mut lead = [0.0; S + 1];
    for (j, w) in lead.iter_mut().enumerate() {
        *w = 1.0
            / (0..=S)
                .filter(|&m| m != j)
                .map(|m| t[j] - t[m])
                .product::<f64>();
    }
    Tableau { c, a, lead }
}

pub(super) static TABLEAU: LazyLock<Tableau> = LazyLock::new(tableau);

/// One accepted implicit step: the stages, the end state, and τ's increment.
#[derive(Debug, Clone, Copy)]
pub(super) struct Step {
    pub h: f64,
    pub x0: [f64; 3],
    pub stages: [[f64; 3]; S],
    /// dτ over the step: h Σ_j a_Sj dτ/dσ(Z_j).
    pub dtau: f64,
}

impl Step {
    pub fn end(&self) -> [f64; 3] {
        self.stages[S - 1]
    }
    /// The collocation polynomial at θ ∈ [0, 1] of the step (order S + 1: a first guess of
    /// where an event is, never its answer).
    pub fn dense(&self, theta: f64) -> [f64; 3] {
        let tab = &*TABLEAU;
        let t: [f64; S + 1] = std::array::from_fn(|i| if i == 0 { 0.0 } else { tab.c[i - 1] });
        let mut out = [0.0; 3];
        for j in 0..=S {
            let w: f64 = (0..=S)
                .filter(|&m| m != j)
                .map(|m| (theta - t[m]) / (t[j] - t[m]))
                .product();
            let xj = if j == 0 { self.x0 } else { self.stages[j - 1] };
            for (o, v) in out.iter_mut().zip(xj) {
                *o += w * v;
            }
        }
        out
    }
    /// max_i (|d_S,i| / scale_i)^{1/S}, d_S the collocation polynomial's leading coefficient
    /// in θ: about h / ρ, ρ the radius of convergence of the solution's series.
    pub fn ratio(&self) -> f64 {
        let lead = &TABLEAU.lead;
        (0..3)
            .map(|i| {
                let d: f64 = lead[0] * self.x0[i]
                    + (0..S).map(|j| lead[j + 1] * self.stages[j][i]).sum::<f64>();
                let scale = self.x0[i].abs().max(self.end()[i].abs()).max(1.0);
                (d.abs() / scale).powf(1.0 / S as f64)
            })
            .fold(0.0, f64::max)
    }
}

/// Newton's increments, scaled by the state (max(|x|, 1)).
fn norm(dz: &SVector<f64, M>, scale: &[f64; 3]) -> f64 {
    dz.iter()
        .enumerate()
        .map(|(k, d)| d.abs() / scale[k % 3])
        .fold(0.0, f64::max)
}

/// The step of size `h` from `x0`: the stage equations z = h (A ⊗ I) F(x0 + z) by simplified
/// Newton (the Jacobian at x0) to the rounding of the state; `None` where Newton does not
/// contract (the caller shortens the step).
pub(super) fn step<Sys: System>(sys: &Sys, x0: [f64; 3], h: f64) -> Option<Step> {
    let tab = &*TABLEAU;
    let j = sys.jac(x0);
    let mut m = SMatrix::<f64, M, M>::identity();
    for (si, row) in tab.a.iter().enumerate() {
        for (sj, &aij) in row.iter().enumerate() {
            for r in 0..3 {
                for col in 0..3 {
                    m[(3 * si + r, 3 * sj + col)] -= h * aij * j[r][col];
                }
            }
        }
    }
    let lu = m.lu();
    let scale = x0.map(|v| v.abs().max(1.0));
    let mut z = SVector::<f64, M>::zeros();
    let mut last = f64::INFINITY;
    for _ in 0..20 {
        let fz: [[f64; 3]; S] =
            std::array::from_fn(|si| sys.f(std::array::from_fn(|r| x0[r] + z[3 * si + r])));
        let mut g = SVector::<f64, M>::zeros();
        for si in 0..S {
            for r in 0..3 {
                let hf: f64 = (0..S).map(|sj| tab.a[si][sj] * fz[sj][r]).sum();
                g[3 * si + r] = h * hf - z[3 * si + r];
            }
        }
        let dz = lu.solve(&g)?;
        z += dz;
        let size = norm(&dz, &scale);
        if !size.is_finite() {
            return None;
        }
        // converged: the increments contract (θ < 1) and what is left of them,
        // θ/(1 − θ) · |Δ|, is below the state's rounding; or they stall at the rounding
        // floor of the ill-conditioned stiff system (below 1e-12)
        let theta = size / last;
        let done = size <= 4.0 * f64::EPSILON
            || (theta < 1.0 && theta / (1.0 - theta) * size <= f64::EPSILON)
            || (theta >= 0.5 && size <= 1e-12);
        if done {
            let stages = std::array::from_fn(|si| std::array::from_fn(|r| x0[r] + z[3 * si + r]));
            let dtau = h
                * (0..S)
                    .map(|sj| tab.a[S - 1][sj] * sys.dtau(stages[sj]))
                    .sum::<f64>();
            return Some(Step {
                h,
                x0,
                stages,
                dtau,
            });
        }
        if theta >= 1.0 {
            return None;
        }
        last = size;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radau_tableau_meets_the_order_conditions() {
        let t = &*TABLEAU;
        // B(2S − 1): Σ b_j c_j^{k−1} = 1/k, b the last row
        for k in 1..2 * S {
            let q: f64 = (0..S)
                .map(|j| t.a[S - 1][j] * t.c[j].powi(k as i32 - 1))
                .sum();
            assert!((q - 1.0 / k as f64).abs() < 1e-14, "B({k}): {q}");
        }
        // C(S): Σ_j a_ij c_j^{k−1} = c_i^k / k
        for i in 0..S {
            for k in 1..=S {
                let q: f64 = (0..S).map(|j| t.a[i][j] * t.c[j].powi(k as i32 - 1)).sum();
                assert!((q - t.c[i].powi(k as i32) / k as f64).abs() < 1e-14);
            }
        }
        assert_eq!(t.c[S - 1], 1.0);
    }

    /// y' = −1000 (y − cos σ) − sin σ (stiff; y = cos σ from y(0) = 1), and the slow
    /// x' = −x: one step of 0.3 (300 times the fast rate's time) holds x to 1e-13 and y to
    /// the O(ε h^S) of a singularly perturbed problem (ε = 1e-3: 2.4e-6 h^S-units; 1.2e-10
    /// found) against their closed forms.
    struct Prothero;
    impl System for Prothero {
        fn f(&self, x: [f64; 3]) -> [f64; 3] {
            [-1000.0 * (x[0] - x[2].cos()) - x[2].sin(), -x[1], 1.0]
        }
        fn jac(&self, x: [f64; 3]) -> [[f64; 3]; 3] {
            [
                [-1000.0, 0.0, -1000.0 * x[2].sin() - x[2].cos()],
                [0.0, -1.0, 0.0],
                [0.0, 0.0, 0.0],
            ]
        }
        fn dtau(&self, _: [f64; 3]) -> f64 {
            1.0
        }
    }

    #[test]
    fn a_stiff_step_far_past_the_fast_rate_holds_the_slow_solution() {
        let s = step(&Prothero, [1.0, 1.0, 0.0], 0.3).unwrap();
        let e = s.end();
        assert!((e[0] - 0.3f64.cos()).abs() < 1e-9, "{e:?}");
        assert!((e[1] - (-0.3f64).exp()).abs() < 1e-13, "{e:?}");
        assert!((s.dtau - 0.3).abs() < 1e-15);
        assert!((s.dense(0.5)[1] - (-0.15f64).exp()).abs() < 1e-7);
    }
}
