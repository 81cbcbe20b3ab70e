//! The COR-table problem: x = (ln p₁ … ln p_k); one impact per measured speed, residuals
//! (e_model − e)/σ_e for each COR (σ_e from `cor_sd`, else `scale[0]` times the row's
//! `cor_sd_relative`: a drop test's rows weigh by their rebound heights' reading), and,
//! where a row has them, the relative misses of peak force and contact time,
//! `(F_model/F − 1)/scale[1]` and `(t_model/t − 1)/scale[2]`. The scales start at 1; when kinds
//! are mixed the fit sets them to each kind's RMS and fits again, so that each kind weighs by
//! its own scatter. Every model run (the table's impacts) is reported to the fit's [`Watch`],
//! also every [`WATCH_EVERY`] impacts within a run, and the watch may stop the fit.

use super::lm::Residuals;
use super::{Param, apply, fit_k_r, log_step};
use crate::analysis::work::Watch;
use crate::measured::CorPoint;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};
use std::cell::Cell;

pub(super) struct CorProblem<'a> {
    pub base: ImpactParams,
    pub law: ContactLaw,
    pub free: Vec<Param>,
    pub points: &'a [CorPoint],
    /// Divisors of the COR (rows without `cor_sd`), force and contact-time residuals.
    pub scale: [Cell<f64>; 3],
    log_step: f64,
    watch: &'a dyn Watch,
    /// Model runs so far.
    runs: Cell<u64>,
    /// The watch said stop: every later run gives no answer, and the fit ends.
    stopped: Cell<bool>,
}

/// Impacts of a model run between two looks of the watch: a table of 10 000 rows under the
/// Hertz law is some 0.3 s a run (BENCHMARKS.md), 64 impacts some 2 ms.
const WATCH_EVERY: usize = 64;

/// What one impact gives for one row: (COR, peak force, contact time).
type Predicted = (f64, f64, Option<f64>);

impl<'a> CorProblem<'a> {
    pub fn new(
        base: ImpactParams,
        law: ContactLaw,
        free: Vec<Param>,
        points: &'a [CorPoint],
        watch: &'a dyn Watch,
    ) -> Self {
        CorProblem {
            base,
            law,
            free,
            points,
            scale: [Cell::new(1.0), Cell::new(1.0), Cell::new(1.0)],
            log_step: log_step(law),
            watch,
            runs: Cell::new(0),
            stopped: Cell::new(false),
        }
    }

    pub fn ball(&self, x: &[f64]) -> ImpactParams {
        let values: Vec<f64> = x.iter().map(|v| v.exp()).collect();
        apply(&self.base, &self.free, &values)
    }

    /// Whether the watch stopped the fit.
    pub fn stopped(&self) -> bool {
        self.stopped.get()
    }

    /// Whether to go on: the watch asked (a stop is kept).
    fn go_on(&self) -> bool {
        if !self.stopped.get() && !self.watch.step(self.runs.get()) {
            self.stopped.set(true);
        }
        !self.stopped.get()
    }

    /// The model at every row at `x`, or `None` when the solver has no answer or the watch
    /// stops the fit (asked before the run and every [`WATCH_EVERY`] impacts).
    pub fn predict(&self, x: &[f64]) -> Option<Vec<Predicted>> {
        self.runs.set(self.runs.get() + 1);
        let b = self.ball(x);
        self.points
            .iter()
            .enumerate()
            .map(|(i, pt)| {
                if i % WATCH_EVERY == 0 && !self.go_on() {
                    return None;
                }
                let p = ImpactParams { v0: pt.v0, ..b };
                p.validate().ok()?;
                let r = simulate(&p, self.law, &SolveOptions::default()).ok()?;
                Some((r.cor, r.max_force, r.contact_time))
            })
            .collect()
    }

    /// Residual count: each COR, and each peak force and contact time given.
    pub fn count(&self) -> usize {
        self.points
            .iter()
            .map(|p| 1 + p.max_force.is_some() as usize + p.contact_time.is_some() as usize)
            .sum()
    }

    /// How many residuals of each kind: (COR, force, time).
    pub fn count_by_kind(&self) -> [usize; 3] {
        let mut n = [self.points.len(), 0, 0];
        for p in self.points {
            n[1] += p.max_force.is_some() as usize;
            n[2] += p.contact_time.is_some() as usize;
        }
        n
    }

    /// The RMS of each kind of residual at `x`, unscaled (the COR's relative to each row's
    /// `cor_sd_relative`): (COR, force, time).
    pub fn rms_by_kind(&self, x: &[f64]) -> Option<[f64; 3]> {
        let pred = self.predict(x)?;
        let mut acc = [(0.0, 0usize); 3];
        for (pt, (e, f, t)) in self.points.iter().zip(pred) {
            acc[0].0 += ((e - pt.cor) / pt.cor_sd_relative).powi(2);
            acc[0].1 += 1;
            if let Some(m) = pt.max_force {
                acc[1].0 += (f / m - 1.0).powi(2);
                acc[1].1 += 1;
            }
            if let (Some(m), Some(t)) = (pt.contact_time, t) {
                acc[2].0 += (t / m - 1.0).powi(2);
                acc[2].1 += 1;
            }
        }
        Some(acc.map(|(s, n)| {
            if n > 0 {
                (s / n as f64).sqrt()
            } else {
                f64::NAN
            }
        }))
    }

    /// Starting points, each a vector of ln p: the given ball with K_r matched to the slowest
    /// point's COR (fit_k_r, when K_r is free); when z_p is free, that ball with z_p at the
    /// peak indentation it reaches without flattening at the quartiles of the measured speeds
    /// (so that flattening sets in inside the data, where z_p shows); every free parameter 3×
    /// and ⅓× as large; and the given ball itself.
    pub fn starts(&self) -> Vec<Vec<f64>> {
        let logs =
            |b: &ImpactParams| -> Vec<f64> { self.free.iter().map(|p| p.get(b).ln()).collect() };
        let mut centre = self.base;
        let mut speeds: Vec<f64> = self.points.iter().map(|p| p.v0).collect();
        speeds.sort_by(f64::total_cmp);
        if let (true, Some(pt)) = (
            self.free.contains(&Param::KR),
            self.points.iter().min_by(|a, b| a.v0.total_cmp(&b.v0)),
        ) && let Ok(f) = fit_k_r(
            &ImpactParams {
                v0: pt.v0,
                ..self.base
            },
            self.law,
            pt.cor,
        ) && f.k_r > 0.0
        {
            centre.k_r = f.k_r;
        }
        let mut out = vec![logs(&centre)];
        if self.free.contains(&Param::ZP) {
            for q in [0.25, 0.5, 0.75] {
                let v0 = speeds[((speeds.len() - 1) as f64 * q).round() as usize];
                let rigid = ImpactParams {
                    v0,
                    z_p: f64::INFINITY,
                    ..centre
                };
                if let Ok(r) = simulate(&rigid, self.law, &SolveOptions::default())
                    && r.max_indentation > 0.0
                {
                    let b = apply(&centre, &[Param::ZP], &[r.max_indentation]);
                    out.push(logs(&b));
                }
            }
        }
        let c = logs(&centre);
        for f in [3.0f64, 1.0 / 3.0] {
            out.push(c.iter().map(|v| v + f.ln()).collect());
        }
        out.push(logs(&self.base));
        out
    }

    pub fn bounds(&self, x0: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let w = 5.0 * std::f64::consts::LN_10;
        (
            x0.iter().map(|v| v - w).collect(),
            x0.iter().map(|v| v + w).collect(),
        )
    }
}

impl Residuals for CorProblem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let pred = self.predict(x)?;
        let [se, sf, st] = [0, 1, 2].map(|k| self.scale[k].get());
        let mut r = Vec::with_capacity(self.count());
        for (pt, (e, f, t)) in self.points.iter().zip(pred) {
            r.push((e - pt.cor) / pt.cor_sd.unwrap_or(se * pt.cor_sd_relative));
            if let Some(m) = pt.max_force {
                r.push((f / m - 1.0) / sf);
            }
            if let Some(m) = pt.contact_time {
                r.push((t? / m - 1.0) / st);
            }
        }
        Some(r)
    }

    fn step(&self, _: usize) -> f64 {
        self.log_step
    }

    fn stopped(&self) -> bool {
        self.stopped.get()
    }
}
