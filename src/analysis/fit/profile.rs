//! Profile-t intervals of a least-squares fit (Bates & Watts, *Nonlinear Regression Analysis
//! and Its Applications*, 1988, §6.1): the variable j held at θ and the others fitted again,
//! the profile t statistic
//!
//! ```text
//! τ(θ) = sign(θ − θ̂) √(S(θ) − S(θ̂)) / s,   s² = S(θ̂)/(n − p),   S = Σ r²,
//! ```
//!
//! and the 95 % interval {θ : |τ(θ)| ≤ t₀.₉₇₅(n − p)}. Where the model is linear in the
//! variables, τ is the straight line (θ − θ̂)/s_θ and the interval is the Jacobian's
//! θ̂ ± t s_θ ([`super::stats`]); where it bends, the profile follows the cost and the
//! Jacobian's interval does not — the oblique fit's K_t with spins, whose intervals from the
//! Jacobian covered the truth 91 % of the time (docs/oblique.md §9).

use super::lm::{self, Options, Residuals, Solution};

/// The problem with variable `held` fixed at `value`: the others are its variables.
struct Held<'a, P> {
    problem: &'a P,
    held: usize,
    value: f64,
}

impl<P: Residuals> Held<'_, P> {
    /// The full variables from the others'.
    fn full(&self, others: &[f64]) -> Vec<f64> {
        let mut x = others.to_vec();
        x.insert(self.held, self.value);
        x
    }
    /// The full problem's index of the others' variable `k`.
    fn index(&self, k: usize) -> usize {
        if k < self.held { k } else { k + 1 }
    }
}

impl<P: Residuals> Residuals for Held<'_, P> {
    fn residuals(&self, others: &[f64]) -> Option<Vec<f64>> {
        self.problem.residuals(&self.full(others))
    }
    fn step(&self, k: usize) -> f64 {
        self.problem.step(self.index(k))
    }
    fn typical(&self, k: usize) -> f64 {
        self.problem.typical(self.index(k))
    }
    fn max_step(&self, k: usize) -> f64 {
        self.problem.max_step(self.index(k))
    }
    fn stopped(&self) -> bool {
        self.problem.stopped()
    }
}

/// Most profile fits on each side of an interval: the first guess, a widening or two, and
/// the regula falsi's steps to |τ| within `TAU_TOL` of t.
pub const FITS_PER_SIDE: usize = 8;

/// How close |τ| must come to t at an end: 1 % of t, a hundredth of a standard error.
const TAU_TOL: f64 = 0.01;

/// The smallest half-width, relative to |θ̂| (or 1), a profile resolves: below it the
/// interval is the Jacobian's (`exactly_fitted_data_keep_the_jacobians_interval`).
const RESOLVED: f64 = 1e-9;

/// Where the profile of variable `j` crosses ±t, from the minimum `best` in the box
/// `[lo, hi]`: `[low end, high end]` in the variable's own units (±∞ where the profile stays
/// below t up to the box's side: the data do not bound it there; the Jacobian's θ̂ ± t s_θ
/// where that half-width is below the rounding a profile can see, `RESOLVED`). `cov` is the
/// Jacobian's
/// covariance at `best` (its column j gives the first guesses: the Wald ends, the others
/// moved along their regression on θ_j). `None` where a profile fit has no answer, no end is
/// found within 4⁷ half-widths, or the work was stopped.
pub fn interval<P: Residuals>(
    problem: &P,
    best: &Solution,
    j: usize,
    cov: &nalgebra::DMatrix<f64>,
    t: f64,
    [lo, hi]: [&[f64]; 2],
    opts: Options,
) -> Option<[f64; 2]> {
    let n = best.residuals.len();
    let p = best.x.len();
    let s0 = 2.0 * best.cost;
    let s2 = s0 / n.checked_sub(p).filter(|&d| d > 0)? as f64;
    let sd = cov[(j, j)].sqrt();
    if !(s2 > 0.0 && sd.is_finite() && sd > 0.0 && t.is_finite()) {
        return None;
    }
    let theta = best.x[j];
    if t * sd <= RESOLVED * theta.abs().max(1.0) {
        // a half-width at the rounding of θ (data the model fits exactly): no profile can be
        // told from the cost's rounding there, and the model is straight at that scale
        return Some([theta - t * sd, theta + t * sd]);
    }
    let slope: Vec<f64> = (0..p).map(|k| cov[(k, j)] / cov[(j, j)]).collect();
    let mut ends = [0.0; 2];
    for (side, sign) in [(0, -1.0), (1, 1.0)] {
        let bound = if sign < 0.0 { lo[j] } else { hi[j] };
        let profile = |theta: f64| -> Option<f64> {
            let held = Held {
                problem,
                held: j,
                value: theta,
            };
            let start: Vec<f64> = (0..p)
                .filter(|&k| k != j)
                .map(|k| (best.x[k] + slope[k] * (theta - best.x[j])).clamp(lo[k], hi[k]))
                .collect();
            let s = if start.is_empty() {
                held.residuals(&[])?.iter().map(|r| r * r).sum::<f64>()
            } else {
                let (l, h) = (drop_at(lo, j), drop_at(hi, j));
                2.0 * lm::minimize(&held, &start, &l, &h, opts)?.cost
            };
            // a lower cost than the minimum's (a better valley on the way) reads as τ = 0
            Some(((s - s0).max(0.0) / s2).sqrt())
        };
        ends[side] = crossing(profile, best.x[j], sign * t * sd, bound, t)?;
    }
    Some(ends)
}

/// θ where `tau(θ)` (|τ|, 0 at θ̂, growing away from it) reaches `t`, searched from θ̂ in the
/// direction and first distance `first`, not beyond `bound`; ±∞ (the sign of `first`) where
/// τ at the bound is still below t.
fn crossing(
    tau: impl Fn(f64) -> Option<f64>,
    theta_hat: f64,
    first: f64,
    bound: f64,
    t: f64,
) -> Option<f64> {
    let toward = first.signum();
    let past_bound = |x: f64| (x - bound) * toward >= 0.0;
    // bracket: (a, τ_a) below t, (b, τ_b) at or above it
    let (mut a, mut ta) = (theta_hat, 0.0);
    let mut b = theta_hat + first;
    let mut fits = 0;
    let tb = loop {
        if past_bound(b) {
            b = bound;
        }
        let tb = tau(b)?;
        fits += 1;
        if (tb - t).abs() <= TAU_TOL * t {
            return Some(b);
        }
        if tb >= t {
            break tb;
        }
        if b == bound {
            // the profile stays below t to the box's side: the data do not bound it there
            return Some(toward * f64::INFINITY);
        }
        if fits >= FITS_PER_SIDE {
            // no end within 4⁷ of the Jacobian's half-width, nor the box: no answer
            return None;
        }
        (a, ta) = (b, tb);
        b = theta_hat + 4.0 * (b - theta_hat);
    };
    // Illinois' regula falsi on τ − t
    let (mut fa, mut fb) = (ta - t, tb - t);
    let mut x = b;
    while fits < FITS_PER_SIDE {
        x = b - fb * (b - a) / (fb - fa);
        let fx = tau(x)? - t;
        fits += 1;
        if fx.abs() <= TAU_TOL * t {
            break;
        }
        if fx > 0.0 {
            (b, fb) = (x, fx);
            fa *= 0.5;
        } else {
            (a, fa) = (x, fx);
            fb *= 0.5;
        }
    }
    Some(x)
}

fn drop_at(v: &[f64], j: usize) -> Vec<f64> {
    v.iter()
        .enumerate()
        .filter(|&(k, _)| k != j)
        .map(|(_, &x)| x)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::fit::lm::Curve;
    use crate::analysis::fit::stats::{t975, uncertainty};

    /// y = a + b x: linear in (a, b), so the profile interval is the Jacobian's, θ̂ ± t s_θ.
    fn line(x: Vec<f64>, y: Vec<f64>) -> Curve {
        Curve {
            x,
            y,
            model: |v, x| v[0] + v[1] * x,
        }
    }

    #[test]
    fn a_linear_models_profile_is_the_jacobians_interval() {
        let x: Vec<f64> = (0..12).map(f64::from).collect();
        let noise = [
            0.3, -0.2, 0.1, 0.4, -0.5, 0.2, -0.1, 0.0, 0.3, -0.4, 0.1, -0.2,
        ];
        let y = x
            .iter()
            .zip(noise)
            .map(|(x, e)| 1.0 + 0.5 * x + e)
            .collect();
        let line = line(x, y);
        let (lo, hi) = ([-1e3, -1e3], [1e3, 1e3]);
        let opts = Options::default();
        let best = lm::minimize(&line, &[0.0, 0.0], &lo, &hi, opts).unwrap();
        let u = uncertainty(&best.jacobian, &best.residuals);
        let t = t975(10);
        for j in 0..2 {
            let [l, h] = interval(&line, &best, j, &u.covariance, t, [&lo, &hi], opts).unwrap();
            let sd = u.covariance[(j, j)].sqrt();
            let (wl, wh) = (best.x[j] - t * sd, best.x[j] + t * sd);
            // |τ − t| ≤ TAU_TOL t at an end: within TAU_TOL of the half-width t s_θ
            let near = |a: f64, b: f64| (a - b).abs() <= TAU_TOL * t * sd;
            assert!(near(l, wl) && near(h, wh), "{j}: {l} {h} vs {wl} {wh}");
        }
    }

    /// y = exp(k x): curved in k, so the profile's ends are where S rises by s² t², which
    /// the Wald interval misses on the steep side.
    fn decay(x: Vec<f64>, y: Vec<f64>) -> Curve {
        Curve {
            x,
            y,
            model: |v, x| (v[0] * x).exp(),
        }
    }

    #[test]
    fn a_curved_profile_ends_where_the_cost_rises_by_t_squared() {
        let x: Vec<f64> = (0..8).map(|i| 0.5 * f64::from(i)).collect();
        let noise = [0.02, -0.03, 0.01, 0.03, -0.02, 0.0, 0.01, -0.01];
        let y = x
            .iter()
            .zip(noise)
            .map(|(x, e)| (-0.7 * x).exp() + e)
            .collect();
        let decay = decay(x, y);
        let (lo, hi) = ([-10.0], [10.0]);
        let opts = Options::default();
        let best = lm::minimize(&decay, &[-1.0], &lo, &hi, opts).unwrap();
        let u = uncertainty(&best.jacobian, &best.residuals);
        let t = t975(7);
        let ends = interval(&decay, &best, 0, &u.covariance, t, [&lo, &hi], opts).unwrap();
        let s0 = 2.0 * best.cost;
        let s2 = s0 / 7.0;
        for end in ends {
            let s = decay
                .residuals(&[end])
                .unwrap()
                .iter()
                .map(|r| r * r)
                .sum::<f64>();
            let tau = ((s - s0) / s2).sqrt();
            assert!((tau - t).abs() <= TAU_TOL * t, "{end}: τ {tau} vs t {t}");
        }
        assert!(ends[0] < best.x[0] && best.x[0] < ends[1]);
    }

    /// Data the model fits to rounding: the half-width is some ulps of θ̂, which no refit
    /// can resolve; the Jacobian's interval, not "unbounded" (the profile's steps would all
    /// round to θ̂ itself).
    #[test]
    fn exactly_fitted_data_keep_the_jacobians_interval() {
        let x: Vec<f64> = (0..8).map(|i| 0.5 * f64::from(i)).collect();
        let y = x.iter().map(|x| (-0.7 * x).exp()).collect();
        let decay = decay(x, y);
        let (lo, hi) = ([-10.0], [10.0]);
        let opts = Options::default();
        let best = lm::minimize(&decay, &[-1.0], &lo, &hi, opts).unwrap();
        let u = uncertainty(&best.jacobian, &best.residuals);
        let (t, sd) = (t975(7), u.covariance[(0, 0)].sqrt());
        assert!(t * sd < RESOLVED, "{sd}");
        let ends = interval(&decay, &best, 0, &u.covariance, t, [&lo, &hi], opts).unwrap();
        assert_eq!(ends, [best.x[0] - t * sd, best.x[0] + t * sd]);
    }

    #[test]
    fn a_profile_that_stays_low_to_the_box_is_unbounded() {
        // y = exp(k x) sampled where x = 0 only: no k changes the model
        let decay = decay(vec![0.0; 5], vec![1.0, 1.1, 0.9, 1.05, 0.95]);
        let (lo, hi) = ([-10.0], [10.0]);
        let opts = Options::default();
        let best = lm::minimize(&decay, &[-1.0], &lo, &hi, opts).unwrap();
        let cov = nalgebra::DMatrix::from_element(1, 1, 1.0);
        let ends = interval(&decay, &best, 0, &cov, t975(4), [&lo, &hi], opts).unwrap();
        assert_eq!(ends, [f64::NEG_INFINITY, f64::INFINITY]);
    }
}
