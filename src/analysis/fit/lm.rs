//! Bounded Levenberg–Marquardt (Moré's scaling, Nielsen's damping update).
//!
//! Written here rather than taken from a crate: `levenberg-marquardt` 0.15 (the maintained
//! Rust one) is built on nalgebra 0.34 while bouncelab uses 0.35 (two copies of nalgebra whose
//! matrices do not mix), and it takes no bounds. Bounds are kept by projecting each trial
//! point into the box; a model that cannot be evaluated at a trial point (a solver that gives
//! no answer, a parameter out of its domain) rejects the step like a rise in cost.
//! Tested on a problem with a known minimum in `tests::recovers_exponential_decay`.

use nalgebra::{DMatrix, DVector};

/// A least-squares problem: residuals r(x), and their Jacobian (forward differences unless
/// the model knows better).
pub trait Residuals {
    /// r(x); `None` where the model has no answer.
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>>;
    /// Finite-difference step of each variable.
    fn step(&self, j: usize) -> f64;
    /// A typical size of each variable's changes (1 for a logarithm), for the step test.
    fn typical(&self, _j: usize) -> f64 {
        1.0
    }
    /// Largest change of each variable in one step (a step that would move one further is
    /// shortened as a whole): a trust region in the logarithms, where an undamped step far
    /// from the minimum can ask for factors of 1e4 and land on a bound.
    fn max_step(&self, _j: usize) -> f64 {
        1.0
    }
    /// Whether the work was stopped from outside ([`crate::analysis::work::Watch`]): the
    /// minimizer then ends at once.
    fn stopped(&self) -> bool {
        false
    }
    /// ∂r/∂x at `x`, where `r` = r(x).
    fn jacobian(&self, x: &[f64], r: &[f64]) -> Option<DMatrix<f64>> {
        forward_jacobian(self, x, r)
    }
}

/// Forward differences, one extra evaluation per variable (a backward one at an upper bound
/// is not needed: the box is open to the step the caller chose).
pub fn forward_jacobian<P: Residuals + ?Sized>(
    p: &P,
    x: &[f64],
    r: &[f64],
) -> Option<DMatrix<f64>> {
    let mut jac = DMatrix::zeros(r.len(), x.len());
    let mut xh = x.to_vec();
    for j in 0..x.len() {
        let h = p.step(j);
        xh[j] = x[j] + h;
        let rh = p.residuals(&xh)?;
        xh[j] = x[j];
        for (i, (a, b)) in rh.iter().zip(r).enumerate() {
            jac[(i, j)] = (a - b) / h;
        }
    }
    Some(jac)
}

/// When the minimizer stops.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// Most Levenberg–Marquardt iterations (each one Jacobian); 200 by default.
    pub max_iterations: usize,
    /// Stop when a Gauss–Newton step would lower the cost by less than this fraction (a test
    /// on the gradient that does not depend on the damping: a heavily damped step lowers the
    /// cost by little far from a minimum too).
    pub ftol: f64,
    /// Stop when a step moves every variable by less than this times its typical size.
    pub xtol: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            max_iterations: crate::analysis::work::FIT_ITERATIONS,
            ftol: 1e-9,
            xtol: 1e-8,
        }
    }
}

/// Where the minimizer stopped.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The variables at the stop.
    pub x: Vec<f64>,
    /// The residuals r(x) there.
    pub residuals: Vec<f64>,
    /// ∂r/∂x there ([`Residuals::jacobian`]), one row a residual: the input of
    /// [`super::stats::uncertainty`].
    pub jacobian: DMatrix<f64>,
    /// ½ Σ r².
    pub cost: f64,
    /// Iterations taken.
    pub iterations: usize,
    /// A convergence test was met (not just the iteration budget).
    pub converged: bool,
}

/// A minimum and the box it was searched in.
pub(crate) struct Best {
    /// The minimum.
    pub sol: Solution,
    /// The box's lower corner.
    pub lo: Vec<f64>,
    /// Its upper corner.
    pub hi: Vec<f64>,
}

fn cost(r: &[f64]) -> f64 {
    0.5 * r.iter().map(|v| v * v).sum::<f64>()
}

/// Minimize ½‖r(x)‖² over `lo ≤ x ≤ hi` from `x0`; `None` when r(x0) has no answer.
pub fn minimize<P: Residuals>(
    p: &P,
    x0: &[f64],
    lo: &[f64],
    hi: &[f64],
    opts: Options,
) -> Option<Solution> {
    let mut x = x0.to_vec();
    clamp(&mut x, lo, hi);
    let mut r = p.residuals(&x)?;
    let mut c = cost(&r);
    let mut jac = p.jacobian(&x, &r)?;
    let mut gain = gauss_newton_gain(&jac, &r);
    let (mut mu, mut nu) = (None::<f64>, 2.0);
    let mut converged = false;
    let mut it = 0;
    while it < opts.max_iterations && !converged {
        if p.stopped() {
            return None;
        }
        it += 1;
        let jtj = jac.transpose() * &jac;
        let g = jac.transpose() * DVector::from_column_slice(&r);
        // μ is relative to each variable's own curvature (Moré): dimensionless
        let m = *mu.get_or_insert(1e-3);
        let Some(xn) = trial_point(p, &x, (&jtj, &g), m, (lo, hi)) else {
            mu = Some(m * nu);
            nu *= 2.0;
            continue;
        };
        let step = DVector::from_iterator(x.len(), xn.iter().zip(&x).map(|(a, b)| a - b));
        let small = (0..x.len()).all(|j| step[j].abs() <= opts.xtol * p.typical(j));
        let Some(rn) = p.residuals(&xn) else {
            mu = Some(m * nu);
            nu *= 2.0;
            converged = small;
            continue;
        };
        let cn = cost(&rn);
        // the reduction the linear model predicts for the projected step
        let predicted = -(g.dot(&step) + 0.5 * step.dot(&(&jtj * &step)));
        if cn < c {
            let rho = if predicted > 0.0 {
                (c - cn) / predicted
            } else {
                0.0
            };
            mu = Some(m * (1.0f64 / 3.0).max(1.0 - (2.0 * rho - 1.0).powi(3)));
            nu = 2.0;
            x = xn;
            r = rn;
            c = cn;
            jac = p.jacobian(&x, &r)?;
            gain = gauss_newton_gain(&jac, &r);
            // a tiny step means little when the damping made it tiny
            converged = (small && m < 1.0) || gain <= enough(c, r.len(), x.len(), 1e-4, opts);
        } else {
            mu = Some(m * nu);
            nu *= 2.0;
            // steps keep failing although the undamped one promises little: the cost has a
            // kink here (a sample entering or leaving the contact as t0 moves), which the
            // linear model cannot see past; the minimum is found to ~0.14 standard errors
            converged =
                (small && m > 1e10) || (m > 1e2 && gain <= enough(c, r.len(), x.len(), 1e-2, opts));
        }
    }
    Some(Solution {
        x,
        residuals: r,
        jacobian: jac,
        cost: c,
        iterations: it,
        converged,
    })
}

/// `x` clamped into the box [`lo`, `hi`].
fn clamp(x: &mut [f64], lo: &[f64], hi: &[f64]) {
    x.iter_mut()
        .enumerate()
        .for_each(|(j, v)| *v = v.clamp(lo[j], hi[j]))
}

/// Where one step from `x` at damping `m` goes: (JᵀJ + m D) δ = −g with Moré's scaling D
/// (each variable damped by its own curvature), δ shortened so no variable moves by more
/// than its `max_step`, the point clamped into the box; `None` when JᵀJ + m D has no
/// Cholesky factor.
fn trial_point<P: Residuals>(
    p: &P,
    x: &[f64],
    (jtj, g): (&DMatrix<f64>, &DVector<f64>),
    m: f64,
    (lo, hi): (&[f64], &[f64]),
) -> Option<Vec<f64>> {
    let d: Vec<f64> = (0..x.len()).map(|j| jtj[(j, j)].max(1e-300)).collect();
    let mut a = jtj.clone();
    for j in 0..x.len() {
        a[(j, j)] += m * d[j];
    }
    let delta = a.cholesky().map(|ch| ch.solve(&(-g)))?;
    let shrink = (0..x.len())
        .map(|j| delta[j].abs() / p.max_step(j))
        .fold(1.0, f64::max);
    let mut xn: Vec<f64> = x
        .iter()
        .zip(delta.iter())
        .map(|(a, b)| a + b / shrink)
        .collect();
    clamp(&mut xn, lo, hi);
    Some(xn)
}

/// A gain not worth another step: a fraction `ftol` of the cost, or `of_variance` of the
/// residual variance s² = 2 cost/(n − p) — a step that gains 1e-4 s² moves the parameters by
/// about √(2e-4) ≈ 0.014 of their standard errors, far below what the intervals resolve (and
/// below the noise that finite differences leave in the Jacobian).
fn enough(c: f64, n: usize, p: usize, of_variance: f64, opts: Options) -> f64 {
    let s2 = 2.0 * c / n.saturating_sub(p).max(1) as f64;
    (opts.ftol * c).max(of_variance * s2)
}

/// ½ gᵀ (JᵀJ)⁻¹ g, g = Jᵀr: what an undamped step would gain (a hair of damping keeps a
/// rank-deficient JᵀJ invertible; such a direction gains nothing anyway).
fn gauss_newton_gain(jac: &DMatrix<f64>, r: &[f64]) -> f64 {
    let mut jtj = jac.transpose() * jac;
    let g = jac.transpose() * DVector::from_column_slice(r);
    for j in 0..jtj.ncols() {
        jtj[(j, j)] *= 1.0 + 1e-12;
        jtj[(j, j)] += 1e-300;
    }
    jtj.cholesky()
        .map_or(f64::INFINITY, |ch| 0.5 * g.dot(&ch.solve(&g)))
}

/// The tests' problem: a curve y = `model`(v, x) through the points (`x`, `y`), its residuals
/// `model`(v, x) − y, every step 1e-7.
#[cfg(test)]
pub(super) struct Curve {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub model: fn(&[f64], f64) -> f64,
}

#[cfg(test)]
impl Residuals for Curve {
    fn residuals(&self, v: &[f64]) -> Option<Vec<f64>> {
        Some(
            self.x
                .iter()
                .zip(&self.y)
                .map(|(&x, y)| (self.model)(v, x) - y)
                .collect(),
        )
    }
    fn step(&self, _: usize) -> f64 {
        1e-7
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y = a e^{−b t} sampled without noise: the minimum is (a, b) exactly, from a start 3×
    /// off, and a bound below the answer holds the variable at the bound.
    #[test]
    fn recovers_exponential_decay() {
        let x: Vec<f64> = (0..30).map(|i| i as f64 * 0.1).collect();
        let y = (0..30)
            .map(|i| 2.5 * (-1.7 * i as f64 * 0.1).exp())
            .collect();
        let data = Curve {
            x,
            y,
            model: |v, t| v[0] * (-v[1] * t).exp(),
        };
        let s = minimize(
            &data,
            &[7.0, 0.5],
            &[0.0, 0.0],
            &[100.0, 100.0],
            Options::default(),
        )
        .unwrap();
        assert!(s.converged);
        assert!(
            (s.x[0] - 2.5).abs() < 1e-7 && (s.x[1] - 1.7).abs() < 1e-7,
            "{:?}",
            s.x
        );
        let s = minimize(
            &data,
            &[7.0, 0.5],
            &[0.0, 2.0],
            &[100.0, 100.0],
            Options::default(),
        )
        .unwrap();
        assert_eq!(s.x[1], 2.0);
    }
}
