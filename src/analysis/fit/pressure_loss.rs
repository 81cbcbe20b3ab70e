//! The leak rate of an inflated ball fitted from pressure readings (docs/model.md §10.3,
//! docs/fitting.md): p(t) = p₀ e^(−k t) (`conditions::leak`, docs/model.md §10.3) by bounded
//! Levenberg–Marquardt ([`super::lm`]), its intervals from the Jacobian ([`super::stats`]),
//! and whether the law follows the data ([`super::verdict`]).
//!
//! The variables are scaled to order one: p₀ over the largest reading, k times the readings'
//! time span. k is fitted free of sign, so that a ball that holds its pressure is a minimum
//! inside the box, not one pressed against a bound (where the minimizer's tests are not met);
//! it is reported clipped at 0 with its interval (a sealed ball gains no gas): a fitted k below
//! 0 reads as no measurable loss.

use super::Estimate;
use super::lm::{self, Residuals};
use super::stats::{self, Spread};
use super::verdict::{self, LackOfFit};
use crate::conditions::leak::Leak;
use crate::measured::PressureRow;
use nalgebra::DMatrix;

/// The fitted leak.
#[derive(Debug, Clone)]
pub struct LeakFit {
    /// p₀, the gauge pressure at time 0, Pa.
    pub p0: Estimate,
    /// k, 1/s; its interval clipped at 0.
    pub rate: Estimate,
    /// t½ = ln 2/k and its 95 % interval from k's (∞ where k's reaches 0), s.
    pub half_life: [f64; 3],
    /// Each reading's residual, Pa (reading − law).
    pub residuals: Vec<f64>,
    /// Degrees of freedom, n − 2.
    pub dof: usize,
    /// χ² against the stated deviations, or the runs test from 20 readings; `None` when
    /// neither applies.
    pub lack_of_fit: Option<LackOfFit>,
    /// Why the fit gave no answer (empty when it answered).
    pub no_answer: Vec<String>,
}

impl LeakFit {
    /// The fitted leak as the law's rate.
    pub fn leak(&self) -> Leak {
        Leak {
            rate: self.rate.value,
        }
    }
}

/// Readings the fit cannot start from.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LeakFitError {
    /// Fewer than two readings, or fewer than two distinct times.
    #[error("a pressure-loss fit needs readings at two times at least (got {0})")]
    TooFew(usize),
    /// A reading out of its domain: row `row` (1-based).
    #[error("reading {row}: {why}")]
    Reading {
        /// 1-based row among the readings.
        row: usize,
        /// What is wrong.
        why: &'static str,
    },
    /// The minimizer found no answer.
    #[error("the pressure-loss fit did not converge")]
    NoMinimum,
}

struct Problem<'a> {
    readings: &'a [PressureRow],
    p_scale: f64,
    t_span: f64,
}

impl Problem<'_> {
    fn sigma(&self, r: &PressureRow) -> f64 {
        r.sd.unwrap_or(self.p_scale)
    }
}

impl Residuals for Problem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let (p0, k) = (x[0] * self.p_scale, x[1] / self.t_span);
        Some(
            self.readings
                .iter()
                .map(|r| (r.gauge - p0 * (-k * r.time).exp()) / self.sigma(r))
                .collect(),
        )
    }
    fn step(&self, _j: usize) -> f64 {
        1e-7
    }
    fn jacobian(&self, x: &[f64], _r: &[f64]) -> Option<DMatrix<f64>> {
        let k = x[1] / self.t_span;
        let mut jac = DMatrix::zeros(self.readings.len(), 2);
        for (i, r) in self.readings.iter().enumerate() {
            let decay = (-k * r.time).exp();
            let s = self.sigma(r);
            jac[(i, 0)] = -self.p_scale * decay / s;
            jac[(i, 1)] = x[0] * self.p_scale * decay * r.time / self.t_span / s;
        }
        Some(jac)
    }
}

fn check(readings: &[PressureRow]) -> Result<(), LeakFitError> {
    for (i, r) in readings.iter().enumerate() {
        let row = i + 1;
        if !r.time.is_finite() || r.time < 0.0 {
            return Err(LeakFitError::Reading {
                row,
                why: "time must be finite and ≥ 0",
            });
        }
        if !r.gauge.is_finite() {
            return Err(LeakFitError::Reading {
                row,
                why: "gauge pressure must be finite",
            });
        }
        if r.sd.is_some_and(|s| !s.is_finite() || s <= 0.0) {
            return Err(LeakFitError::Reading {
                row,
                why: "sd must be finite and positive",
            });
        }
    }
    let t0 = readings.first().map(|r| r.time);
    if readings.len() < 2 || readings.iter().all(|r| Some(r.time) == t0) {
        return Err(LeakFitError::TooFew(readings.len()));
    }
    Ok(())
}

/// The start: a straight line through (t, ln p) of the positive readings (k = 0 where the
/// readings rise or too few are positive).
fn start(readings: &[PressureRow], p_scale: f64, t_span: f64) -> [f64; 2] {
    let pts: Vec<(f64, f64)> = readings
        .iter()
        .filter(|r| r.gauge > 0.0)
        .map(|r| (r.time, r.gauge.ln()))
        .collect();
    let n = pts.len() as f64;
    let (st, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| (a + t, b + y));
    let (mt, my) = (st / n, sy / n);
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), (t, y)| {
        (a + (t - mt) * (y - my), b + (t - mt) * (t - mt))
    });
    let slope = if pts.len() >= 2 && sxx > 0.0 {
        sxy / sxx
    } else {
        0.0
    };
    let k = (-slope).max(0.0);
    let p0 = if pts.is_empty() {
        p_scale
    } else {
        (my + k * mt).exp()
    };
    [p0 / p_scale, (k * t_span).min(50.0)]
}

/// Fit p(t) = p₀ e^(−k t) to `readings` (in any order).
pub fn fit_pressure_loss(readings: &[PressureRow]) -> Result<LeakFit, LeakFitError> {
    check(readings)?;
    let p_scale = readings
        .iter()
        .map(|r| r.gauge.abs())
        .fold(0.0, f64::max)
        .max(1.0);
    let t_span = readings.iter().map(|r| r.time).fold(0.0, f64::max);
    let problem = Problem {
        readings,
        p_scale,
        t_span,
    };
    let x0 = start(readings, p_scale, t_span);
    let sol = lm::minimize(
        &problem,
        &x0,
        &[1e-12, -50.0],
        &[1e3, 50.0],
        lm::Options::default(),
    )
    .ok_or(LeakFitError::NoMinimum)?;
    let stated = readings.iter().all(|r| r.sd.is_some());
    let spread = if stated {
        Spread::Stated
    } else {
        Spread::Residuals
    };
    let unc = stats::uncertainty_by(&sol.jacobian, &sol.residuals, spread);
    let dof = readings.len() - 2;
    let se = |j: usize| unc.covariance[(j, j)].max(0.0).sqrt();
    let interval = |v: f64, s: f64, lo: f64| [(v - unc.t975 * s).max(lo), v + unc.t975 * s];
    let (p0, sp0) = (sol.x[0] * p_scale, se(0) * p_scale);
    let (k_free, sk) = (sol.x[1] / t_span, se(1) / t_span);
    let rate_ci = interval(k_free, sk, 0.0).map(|x| x.max(0.0));
    let k = k_free.max(0.0);
    let ln2 = std::f64::consts::LN_2;
    let half_life = [ln2 / k, ln2 / rate_ci[1], ln2 / rate_ci[0]];
    let scale: Vec<f64> = readings.iter().map(|r| problem.sigma(r)).collect();
    let residuals: Vec<f64> = sol
        .residuals
        .iter()
        .zip(&scale)
        .map(|(r, s)| r * s)
        .collect();
    let (lack_of_fit, no_answer) = verdict::judge_law(
        &sol.residuals,
        dof,
        stated,
        sol.converged,
        "the readings do not follow an exponential decay (lack of fit)",
    );
    Ok(LeakFit {
        p0: Estimate::new("p0", "Pa", p0, sp0, interval(p0, sp0, 0.0)),
        rate: Estimate::new("leak_rate", "1/s", k, sk, rate_ci),
        half_life,
        residuals,
        dof,
        lack_of_fit,
        no_answer,
    })
}

#[cfg(test)]
mod tests;
