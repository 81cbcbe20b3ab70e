//! The force–time problem: x = (ln p₁ … ln p_k, t0, b); the model force at a sample time t is
//! b + F(t − t0), F from the solver's history (linear interpolation between samples spaced
//! no wider than the data's, at least 400 over the pulse, by [`interpolate`]),
//! zero outside the contact. A dense trace is compared in bins of its rows, each residual
//! weighted by √(rows) ([`super::bins`]); every model run is reported to the fit's
//! [`Watch`], which may stop the fit.

use super::bins::Samples;
use super::lm::{Residuals, forward_jacobian};
use super::sensitivity::{exact_applies, force_sensitivities};
use super::{Param, apply};
use crate::analysis::work::Watch;
use crate::measured::{Trace, TraceSummary};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{ImpactResponse, SolveOptions, simulate};
use nalgebra::DMatrix;
use std::cell::{Cell, RefCell};
use std::rc::Rc;

pub(super) struct TraceProblem<'a> {
    pub base: ImpactParams,
    pub law: ContactLaw,
    pub free: Vec<Param>,
    pub trace: &'a Trace,
    pub summary: TraceSummary,
    /// The rows, or their bins, the residuals are taken at.
    pub data: Samples,
    /// Samples of the model's history over the contact.
    history: usize,
    log_step: f64,
    watch: &'a dyn Watch,
    /// Model runs so far.
    runs: Cell<u64>,
    /// The watch said stop: every later run gives no answer, and the fit ends.
    stopped: Cell<bool>,
    /// The last model run and the parameters (x's first k, bit for bit) it ran at: the
    /// Levenberg–Marquardt loop asks the residuals at x and then, the step taken, the
    /// Jacobian at the same x, and the report asks the rows at the answer; one solver run
    /// serves them all (the solver is deterministic, and t0 and b do not enter it).
    /// `trace::tests::one_run_serves_residuals_jacobian_and_rows`.
    last: RefCell<Option<(Vec<u64>, Rc<ImpactResponse>)>>,
}

/// Model force on a uniform history grid `t` (`t[0] = 0`), at time `s`, and its slope:
/// Catmull–Rom (cubic Hermite with central-difference slopes), error O(h³) against linear
/// interpolation's O(h²). The difference matters to the Jacobian: as the parameters move, the
/// grid slides under the data, and linear interpolation's error, 1e-6 of the peak at 1 000
/// samples, changed fast enough to make forward differences noisy at the 1e-3 level.
fn interpolate(t: &[f64], f: &[f64], s: f64) -> (f64, f64) {
    let n = t.len();
    if n < 2 || s <= 0.0 || s >= t[n - 1] {
        return (0.0, 0.0);
    }
    let h = t[1];
    let k = ((s / h) as usize).min(n - 2);
    let u = (s - t[k]) / h;
    // slopes (per step) at the two ends; one-sided at the ends of the contact
    let m = |i: usize| match i {
        0 => f[1] - f[0],
        i if i == n - 1 => f[n - 1] - f[n - 2],
        i => 0.5 * (f[i + 1] - f[i - 1]),
    };
    let (p0, p1, m0, m1) = (f[k], f[k + 1], m(k), m(k + 1));
    let (u2, u3) = (u * u, u * u * u);
    let value = (2.0 * u3 - 3.0 * u2 + 1.0) * p0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * p1
        + (u3 - u2) * m1;
    let slope = (6.0 * u2 - 6.0 * u) * p0
        + (3.0 * u2 - 4.0 * u + 1.0) * m0
        + (-6.0 * u2 + 6.0 * u) * p1
        + (3.0 * u2 - 2.0 * u) * m1;
    (value, slope / h)
}

impl<'a> TraceProblem<'a> {
    pub fn new(
        base: ImpactParams,
        law: ContactLaw,
        free: Vec<Param>,
        trace: &'a Trace,
        summary: TraceSummary,
        data: Samples,
        watch: &'a dyn Watch,
    ) -> Self {
        // at least 400 samples over the contact, and no fewer than the data (or their bins)
        // have
        let n = data.len();
        let dt = (data.time[n - 1] - data.time[0]) / (n - 1).max(1) as f64;
        let width = summary.t_end - summary.t_start;
        let history = ((width / dt) as usize).clamp(400, 20_000);
        let log_step = if law == ContactLaw::Linear {
            1e-5
        } else {
            1e-4
        };
        TraceProblem {
            base,
            law,
            free,
            trace,
            summary,
            data,
            history,
            log_step,
            watch,
            runs: Cell::new(0),
            stopped: Cell::new(false),
            last: RefCell::new(None),
        }
    }

    /// The same problem with `samples` in each model run's history (a test's finer model).
    #[cfg(test)]
    pub fn with_history(mut self, samples: usize) -> Self {
        self.history = samples;
        self
    }

    /// Samples of each model run's history.
    pub fn history(&self) -> usize {
        self.history
    }

    /// Whether the watch stopped the fit.
    pub fn stopped(&self) -> bool {
        self.stopped.get()
    }

    /// The solver's run (with its history) at `x`, or `None` when it has no answer or the
    /// watch stops the fit (asked before every run). The last run answers again for the
    /// same parameters without running (nor counting) again.
    fn run(&self, x: &[f64]) -> Option<Rc<ImpactResponse>> {
        if self.stopped.get() {
            return None;
        }
        let key: Vec<u64> = x[..self.k()].iter().map(|v| v.to_bits()).collect();
        if let Some((at, r)) = &*self.last.borrow()
            && *at == key
        {
            return Some(Rc::clone(r));
        }
        let runs = self.runs.get() + 1;
        self.runs.set(runs);
        if !self.watch.step(runs) {
            self.stopped.set(true);
            return None;
        }
        let p = self.ball(x);
        p.validate().ok()?;
        let opts = SolveOptions::default().with_samples(self.history);
        let r = Rc::new(simulate(&p, self.law, &opts).ok()?);
        *self.last.borrow_mut() = Some((key, Rc::clone(&r)));
        Some(r)
    }

    /// Model runs so far (each a solver run; the last run's answer given again is none).
    #[cfg(test)]
    pub fn runs(&self) -> u64 {
        self.runs.get()
    }

    /// The model force at every row of the trace (not its bins), for the report and plots.
    pub fn model_at_rows(&self, x: &[f64]) -> Option<Vec<f64>> {
        let run = self.run(x)?;
        let h = &run.history;
        let (t0, b) = (x[self.k()], x[self.k() + 1]);
        let f = |t: f64| interpolate(&h.t, &h.force, t - t0).0 + b;
        Some(self.trace.time.iter().map(|&t| f(t)).collect())
    }

    pub fn k(&self) -> usize {
        self.free.len()
    }

    pub fn ball(&self, x: &[f64]) -> ImpactParams {
        let values: Vec<f64> = x[..self.k()].iter().map(|v| v.exp()).collect();
        apply(&self.base, &self.free, &values)
    }

    /// (model force at each sample (row or bin), its slope in t) or `None` when the solver has
    /// no answer.
    pub fn model(&self, x: &[f64]) -> Option<(Vec<f64>, Vec<f64>)> {
        let run = self.run(x)?;
        let h = &run.history;
        let (t0, b) = (x[self.k()], x[self.k() + 1]);
        Some(
            self.data
                .time
                .iter()
                .map(|&t| {
                    let (f, s) = interpolate(&h.t, &h.force, t - t0);
                    (f + b, s)
                })
                .unzip(),
        )
    }

    /// Starting points: springs and dashpot from the pulse's width, height and impulse at a few
    /// λ (a single spring K gives t_c = π √(m/K) and F_m = v0 √(m K); the Maxwell limit, Eq.
    /// 28, turns the COR the impulse shows, I = m v0 (1 + e), into ζ), then the given ball.
    pub fn starts(&self) -> Vec<Vec<f64>> {
        let (m, s) = (self.base.mass, &self.summary);
        // a free v0 starts where the impulse puts it for e = 0.75 (I = m v0 (1 + e))
        let v0 = if self.free.contains(&Param::V0) {
            s.impulse / (1.75 * m)
        } else {
            self.base.v0
        };
        let width = s.t_end - s.t_start;
        let k_width = m * (std::f64::consts::PI / width).powi(2);
        let k_peak = (s.peak / v0).powi(2) / m;
        let k_eff = (k_width * k_peak).sqrt();
        let e = (s.impulse / (m * v0) - 1.0).clamp(0.05, 0.95);
        let zeta = -e.ln() / (std::f64::consts::PI.powi(2) + e.ln().powi(2)).sqrt();
        // Hertz alone: ½ m v0² = (2/5) K_h z_m^{5/2} and F_m = K_h z_m^{3/2}
        let z_m = 1.25 * m * v0 * v0 / s.peak;
        let k_h = s.peak / z_m.powf(1.5);
        let nuisance = [s.t_start, s.baseline];
        let mut out = Vec::new();
        for lambda in [1.0, 0.3, 3.0] {
            let k_p = k_eff * (1.0 + lambda) / lambda;
            let guess = |p: Param| match p {
                Param::KP => k_p,
                Param::KR => lambda * k_p,
                Param::C => (m * k_p).sqrt() / (2.0 * zeta),
                Param::KH => k_h * (1.0 + lambda) / lambda,
                Param::ZP => self.base.z_p,
                Param::V0 => v0,
            };
            out.push(
                self.free
                    .iter()
                    .map(|&p| guess(p).ln())
                    .chain(nuisance)
                    .collect(),
            );
        }
        out.push(
            self.free
                .iter()
                .map(|&p| p.get(&self.base).ln())
                .chain(nuisance)
                .collect(),
        );
        out
    }

    pub fn bounds(&self, x0: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let s = &self.summary;
        let width = s.t_end - s.t_start;
        let span = s.peak + s.baseline.abs();
        let mut lo: Vec<f64> = x0[..self.k()]
            .iter()
            .map(|v| v - 4.0 * std::f64::consts::LN_10)
            .collect();
        let mut hi: Vec<f64> = x0[..self.k()]
            .iter()
            .map(|v| v + 4.0 * std::f64::consts::LN_10)
            .collect();
        lo.extend([self.trace.time[0] - 2.0 * width, s.baseline - span]);
        hi.extend([s.t_peak, s.baseline + span]);
        (lo, hi)
    }
}

impl Residuals for TraceProblem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let (f, _) = self.model(x)?;
        let d = &self.data;
        Some(
            f.iter()
                .zip(&d.force)
                .zip(&d.weight)
                .map(|((m, d), w)| w * (m - d))
                .collect(),
        )
    }

    fn stopped(&self) -> bool {
        self.stopped.get()
    }

    fn step(&self, j: usize) -> f64 {
        match j.checked_sub(self.k()) {
            None => self.log_step,
            Some(0) => 1e-6 * (self.summary.t_end - self.summary.t_start),
            Some(_) => 1e-6 * self.summary.peak,
        }
    }

    fn typical(&self, j: usize) -> f64 {
        match j.checked_sub(self.k()) {
            None => 1.0,
            Some(0) => self.summary.t_end - self.summary.t_start,
            Some(_) => self.summary.peak,
        }
    }

    /// A factor e in a parameter, a fifth of the pulse in t0, a tenth of the peak in b.
    fn max_step(&self, j: usize) -> f64 {
        match j.checked_sub(self.k()) {
            None => 1.0,
            Some(0) => 0.2 * (self.summary.t_end - self.summary.t_start),
            Some(_) => 0.1 * self.summary.peak,
        }
    }

    /// One model run for the whole Jacobian where the law is linear and the ball does not
    /// flatten: ∂r/∂(ln p) from the solution's exact sensitivities ([`super::sensitivity`]);
    /// else forward differences in the log-parameters, one run more each. t0 and b in closed
    /// form either way: ∂r/∂t0 = −F'(t − t0) (the slope of the interpolant) and ∂r/∂b = 1.
    fn jacobian(&self, x: &[f64], r: &[f64]) -> Option<DMatrix<f64>> {
        let k = self.k();
        let run = self.run(x)?;
        let ball = self.ball(x);
        let (h, t0, d) = (&run.history, x[k], &self.data);
        let mut jac = DMatrix::zeros(r.len(), k + 2);
        if exact_applies(self.law, &ball, &run) {
            let columns = force_sensitivities(&ball, &self.free, &run);
            for (j, col) in columns.iter().enumerate() {
                for (i, (t, w)) in d.time.iter().zip(&d.weight).enumerate() {
                    jac[(i, j)] = w * interpolate(&h.t, col, t - t0).0;
                }
            }
        } else {
            let sub = Sub { p: self, x };
            let part = forward_jacobian(&sub, &x[..k], r)?;
            jac.columns_mut(0, k).copy_from(&part);
        }
        for (i, (t, w)) in d.time.iter().zip(&d.weight).enumerate() {
            jac[(i, k)] = -w * interpolate(&h.t, &h.force, t - t0).1;
            jac[(i, k + 1)] = *w;
        }
        Some(jac)
    }
}

/// The problem in the log-parameters alone, t0 and b held at `x`'s.
struct Sub<'a, 'b> {
    p: &'a TraceProblem<'b>,
    x: &'a [f64],
}

impl Residuals for Sub<'_, '_> {
    fn residuals(&self, y: &[f64]) -> Option<Vec<f64>> {
        let mut x = self.x.to_vec();
        x[..y.len()].copy_from_slice(y);
        self.p.residuals(&x)
    }
    fn step(&self, j: usize) -> f64 {
        self.p.step(j)
    }
    fn stopped(&self) -> bool {
        self.p.stopped()
    }
}

#[cfg(test)]
mod tests;
