//! The trace fit's Jacobian in one pass with the solution (issue 30, item 4): exact
//! derivatives of the linear law's force history with respect to the ball's parameters, where
//! the contact stays below the flattening threshold (z_m ≤ z_p: the unloading line is the
//! loading line, docs/model.md §3, so the whole contact is one linear phase).
//!
//! In that phase the state x = (α, α', y) follows x' = A x (docs/model.md §2, F = K_p (α − y)):
//!
//! ```text
//!     A = [   0      1      0         ]
//!         [ −K_p/m   0    K_p/m       ]
//!         [  K_p/c   0  −(K_p+K_r)/c  ]      x(0) = (0, v0, 0)
//! ```
//!
//! and its sensitivity S_b = ∂x/∂θ_b to θ_b = ln p_b (p_b one of K_p, c, K_r, v0) follows the
//! forward sensitivity equation S_b' = A S_b + A_b x, A_b = ∂A/∂θ_b, S_b(0) = ∂x(0)/∂θ_b. The
//! pair (x, S_b) is again a linear system with constant coefficients, so one step h of it is
//! exact: exp([[A, 0], [A_b, A]] h) = [[E, 0], [G_b, E]] with E = exp(A h) (Van Loan's block
//! exponential). Stepping it over the solver's uniform history grid gives ∂F/∂θ_b =
//! (∂K_p/∂θ_b)(α − y) + K_p (S_b,α − S_b,y) at every sample, to rounding — against the forward
//! differences' one solver run per parameter and their truncation error
//! (`tests::exact_jacobian_matches_central_differences`).
//!
//! Flattening (the unloading line's slope then depends on z_m, and the phase switch moves with
//! the parameters) and the Hertz and elastic–plastic laws keep forward differences.

use super::Param;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::ImpactResponse;
use nalgebra::{Matrix3, Matrix6, Vector3};

/// The parameters the linear phase depends on (ln K_p, ln c, ln K_r, ln v0), in the order of
/// [`chain`]'s entries and [`matrices`]' derivatives.
const BASIS: usize = 4;

/// ∂(ln K_p, ln c, ln K_r, ln v0)/∂(ln p) for the free parameter `p`, as [`super::apply`]
/// sets the ball: K_h moves K_p in proportion (K_p = 1.5 K_h √z_p, Eq. 16); z_p moves K_p as
/// its square root when K_h is free beside it, else not at all (below flattening, F does not
/// depend on z_p).
fn chain(p: Param, free: &[Param]) -> [f64; BASIS] {
    match p {
        Param::KP | Param::KH => [1.0, 0.0, 0.0, 0.0],
        Param::C => [0.0, 1.0, 0.0, 0.0],
        Param::KR => [0.0, 0.0, 1.0, 0.0],
        Param::V0 => [0.0, 0.0, 0.0, 1.0],
        Param::ZP if free.contains(&Param::KH) => [0.5, 0.0, 0.0, 0.0],
        Param::ZP => [0.0; BASIS],
    }
}

/// Whether the run is one linear phase, so that [`force_sensitivities`] is exact for it.
pub(super) fn exact_applies(law: ContactLaw, p: &ImpactParams, run: &ImpactResponse) -> bool {
    law == ContactLaw::Linear && run.max_indentation <= p.z_p && run.history.t.len() >= 2
}

/// The system matrix A of the linear phase and its derivatives A_b = ∂A/∂(ln p_b).
fn matrices(p: &ImpactParams) -> (Matrix3<f64>, [Matrix3<f64>; BASIS]) {
    let (m, k, c, r) = (p.mass, p.k_p, p.damping, p.k_r);
    #[rustfmt::skip]
    let a = Matrix3::new(
        0.0,    1.0, 0.0,
        -k / m, 0.0, k / m,
        k / c,  0.0, -(k + r) / c,
    );
    #[rustfmt::skip]
    let d_kp = Matrix3::new(
        0.0,    0.0, 0.0,
        -k / m, 0.0, k / m,
        k / c,  0.0, -k / c,
    );
    // c ∂/∂c of the third row, which alone holds c: minus that row
    #[rustfmt::skip]
    let d_c = Matrix3::new(
        0.0,    0.0, 0.0,
        0.0,    0.0, 0.0,
        -k / c, 0.0, (k + r) / c,
    );
    #[rustfmt::skip]
    let d_kr = Matrix3::new(
        0.0, 0.0, 0.0,
        0.0, 0.0, 0.0,
        0.0, 0.0, -r / c,
    );
    (a, [d_kp, d_c, d_kr, Matrix3::zeros()])
}

/// E = exp(A h) and G_b, the lower-left block of exp([[A, 0], [A_b, A]] h), for each b.
fn steps(
    a: &Matrix3<f64>,
    d: &[Matrix3<f64>; BASIS],
    h: f64,
) -> (Matrix3<f64>, [Matrix3<f64>; BASIS]) {
    let mut e = Matrix3::identity();
    let g = d.map(|db| {
        let mut big = Matrix6::zeros();
        big.fixed_view_mut::<3, 3>(0, 0).copy_from(&(a * h));
        big.fixed_view_mut::<3, 3>(3, 3).copy_from(&(a * h));
        big.fixed_view_mut::<3, 3>(3, 0).copy_from(&(db * h));
        let x = big.exp();
        e = x.fixed_view::<3, 3>(0, 0).into_owned();
        x.fixed_view::<3, 3>(3, 0).into_owned()
    });
    (e, g)
}

/// ∂F/∂(ln p) on the history grid of `run` (uniform, from t = 0), one column per parameter of
/// `free`, for the ball `p` whose linear, unflattened run `run` is ([`exact_applies`]).
pub(super) fn force_sensitivities(
    p: &ImpactParams,
    free: &[Param],
    run: &ImpactResponse,
) -> Vec<Vec<f64>> {
    let n = run.history.t.len();
    let h = run.history.t[1];
    let (a, d) = matrices(p);
    let (e, g) = steps(&a, &d, h);
    let mut x = Vector3::new(0.0, p.v0, 0.0);
    // S_b(0): only v0 moves the start
    let mut s = [Vector3::zeros(); BASIS];
    s[3] = Vector3::new(0.0, p.v0, 0.0);
    let mut basis: [Vec<f64>; BASIS] = std::array::from_fn(|_| Vec::with_capacity(n));
    for _ in 0..n {
        let z = x[0] - x[2];
        for b in 0..BASIS {
            let own = if b == 0 { z } else { 0.0 };
            basis[b].push(p.k_p * (own + s[b][0] - s[b][2]));
        }
        for b in 0..BASIS {
            s[b] = e * s[b] + g[b] * x;
        }
        x = e * x;
    }
    free.iter()
        .map(|&q| {
            let w = chain(q, free);
            (0..n)
                .map(|i| (0..BASIS).map(|b| w[b] * basis[b][i]).sum())
                .collect()
        })
        .collect()
}

/// The state at every sample of the grid by the same steps, for the tests that the steps are
/// the solver's solution.
#[cfg(test)]
fn states(p: &ImpactParams, run: &ImpactResponse) -> Vec<Vector3<f64>> {
    let (a, d) = matrices(p);
    let (e, _) = steps(&a, &d, run.history.t[1]);
    let mut x = Vector3::new(0.0, p.v0, 0.0);
    (0..run.history.t.len())
        .map(|_| {
            let now = x;
            x = e * x;
            now
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::{SolveOptions, simulate};

    use super::super::bins::tests::truth as ball;

    fn run(p: &ImpactParams) -> ImpactResponse {
        simulate(
            p,
            ContactLaw::Linear,
            &SolveOptions::default().with_samples(2001),
        )
        .unwrap()
    }

    #[test]
    fn the_steps_are_the_solvers_solution() {
        // two paths: the exact solver's history and exp(A h) stepped over its grid
        let p = ball();
        let run = run(&p);
        assert!(exact_applies(ContactLaw::Linear, &p, &run));
        let worst = states(&p, &run)
            .iter()
            .zip(&run.history.force)
            .map(|(x, f)| (p.k_p * (x[0] - x[2]) - f).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-9 * run.max_force, "{worst}");
    }

    #[test]
    fn the_contact_time_moves_as_the_sensitivities_say() {
        // F(t_f; θ) = 0 gives ∂t_f/∂θ = −(∂F/∂θ)(t_f)/F'(t_f); against central differences of
        // the exact solver's contact time (its own closed form, docs/model.md §8), δ = 1e-4 in
        // ln p: truncation ≈ δ² ≈ 1e-8 relative
        let p = ball();
        let free = [Param::KP, Param::C, Param::KR, Param::V0];
        let run = run(&p);
        let columns = force_sensitivities(&p, &free, &run);
        let x = *states(&p, &run).last().unwrap();
        let y_rate = (p.k_p * (x[0] - x[2]) - p.k_r * x[2]) / p.damping;
        let slope = p.k_p * (x[1] - y_rate);
        let t_f = |q: &ImpactParams| {
            let r = simulate(q, ContactLaw::Linear, &SolveOptions::default()).unwrap();
            r.contact_time.unwrap()
        };
        for (j, &q) in free.iter().enumerate() {
            let exact = -columns[j].last().unwrap() / slope;
            let moved = |d: f64| t_f(&super::super::apply(&p, &[q], &[q.get(&p) * d.exp()]));
            let cd = (moved(1e-4) - moved(-1e-4)) / 2e-4;
            let tol = 1e-6 * cd.abs() + 1e-9 * t_f(&p);
            assert!((exact - cd).abs() < tol, "{q:?}: {exact:e} against {cd:e}");
        }
    }

    /// A noise-free trace of `p` (1 000 rows over 10 ms, contact from 2.1 ms, baseline 0.3 N).
    fn trace(p: &ImpactParams) -> crate::measured::Trace {
        let opts = SolveOptions::default().with_samples(20_001);
        let h = simulate(p, ContactLaw::Linear, &opts).unwrap().history;
        let tf = *h.t.last().unwrap();
        let rows = 1000;
        let time: Vec<f64> = (0..rows).map(|i| i as f64 * 1e-2 / rows as f64).collect();
        let force = time
            .iter()
            .map(|&t| {
                let s = t - 2.1e-3;
                let k = ((s / h.t[1]).max(0.0) as usize).min(h.t.len() - 2);
                let w = (s - h.t[k]) / h.t[1];
                let f = h.force[k] * (1.0 - w) + h.force[k + 1] * w;
                0.3 + if s <= 0.0 || s >= tf { 0.0 } else { f }
            })
            .collect();
        crate::measured::Trace::from_columns(time, force)
    }

    /// The largest difference between the exact Jacobian's parameter columns and central
    /// differences (step 1e-4 in ln p) of the residuals, relative to each column's largest
    /// entry, at the given ball of a trace fit off the truth, the model run with `history`
    /// samples.
    fn worst_column_error(free: &[Param], history: usize) -> f64 {
        use super::super::bins::Samples;
        use super::super::lm::Residuals;
        use super::super::trace::TraceProblem;
        use crate::analysis::work::Unwatched;
        let truth = ball();
        let tr = trace(&truth);
        let summary = tr.summary().unwrap();
        let samples = Samples::rows(&tr);
        let p = TraceProblem::new(
            ImpactParams {
                k_p: 7e4,
                damping: 50.0,
                k_r: 1.4e5,
                ..truth
            },
            ContactLaw::Linear,
            free.to_vec(),
            &tr,
            summary,
            samples,
            &Unwatched,
        )
        .with_history(history);
        let x = p.starts()[3].clone();
        let r = p.residuals(&x).unwrap();
        let jac = p.jacobian(&x, &r).unwrap();
        let step = 1e-4;
        let mut worst = 0.0f64;
        for j in 0..free.len() {
            let at = |d: f64| {
                let mut y = x.clone();
                y[j] += d;
                p.residuals(&y).unwrap()
            };
            let (up, down) = (at(step), at(-step));
            let cd: Vec<f64> = up
                .iter()
                .zip(&down)
                .map(|(a, b)| (a - b) / (2.0 * step))
                .collect();
            let scale = cd.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            assert!(scale > 0.0 || free[j] == Param::ZP, "column {j} is zero");
            let err = (0..r.len())
                .map(|i| (jac[(i, j)] - cd[i]).abs())
                .fold(0.0, f64::max);
            worst = worst.max(err / scale.max(f64::MIN_POSITIVE));
        }
        worst
    }

    #[test]
    fn exact_jacobian_matches_central_differences() {
        // every parameter the linear phase has, v0 among them, at a ball off the truth (measured
        // 4.5e-9 at 20 000 samples, 3.5e-4 at 400); the
        // differences taken of a model run with 20 000 samples, where its interpolant (O(h³))
        // barely slides under the data as the parameters move the contact's end
        let free = [Param::KP, Param::C, Param::KR, Param::V0];
        let fine = worst_column_error(&free, 20_000);
        assert!(fine < 1e-7, "{fine:e}");
        // at the fit's least history (400 samples) the differences see that sliding, the
        // exact Jacobian does not: the disagreement is the differences'
        let coarse = worst_column_error(&free, 400);
        assert!(coarse > 10.0 * fine, "{coarse:e} against {fine:e}");
        // K_h and z_p through Eq. 16 (K_p = 1.5 K_h √z_p): the chain rule of `chain`
        let free = [Param::KH, Param::ZP, Param::C];
        let e = worst_column_error(&free, 20_000);
        assert!(e < 1e-7, "{e:e}");
    }
}
