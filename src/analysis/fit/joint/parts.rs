//! The data sets of a joint fit (docs/fitting.md, "Joint calibration"), each a least-squares
//! problem of its own over the shared variables: x = (ln p₁ … ln p_k) and, with a trace, its
//! contact start and baseline after them. Each set's residuals are divided by its own
//! standard deviation: the one its rows state (`cor_sd`, `deflection_sd_m`, or a drop's
//! `--rebound-height-sd`), else its scale estimated from its own misses ([`Part::rescale`]).

use super::super::cor::CorProblem;
use super::super::lm::{Residuals, forward_jacobian};
use super::super::trace::TraceProblem;
use super::super::{Param, apply};
use crate::measured::StaticRow;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::model::static_chain::plates_deflection;
use nalgebra::DMatrix;
use std::cell::Cell;

/// Smallest scale a set's misses may be given, relative to its data's size: a noise-free set
/// would otherwise weigh without bound.
const SCALE_FLOOR: f64 = 1e-9;

/// Static deflections between two plates: (δ_model − δ)/σ, δ_model = 2 δ(M g) of the model's
/// chain at rest (docs/model.md §1–§3, `model::static_chain`).
pub(crate) struct StaticProblem<'a> {
    pub base: ImpactParams,
    pub law: ContactLaw,
    pub free: Vec<Param>,
    pub rows: &'a [StaticRow],
    /// The divisor of rows without a stated sd (m).
    pub scale: Cell<f64>,
}

impl StaticProblem<'_> {
    /// δ_model − δ at each row, m; `None` where the ball is invalid.
    pub fn misses(&self, x: &[f64]) -> Option<Vec<f64>> {
        let values: Vec<f64> = x[..self.free.len()].iter().map(|v| v.exp()).collect();
        let b = apply(&self.base, &self.free, &values);
        b.validate().ok()?;
        let m: Vec<f64> = self
            .rows
            .iter()
            .map(|r| plates_deflection(&b, self.law, r.load_kg) - r.deflection)
            .collect();
        m.iter().all(|v| v.is_finite()).then_some(m)
    }
}

impl Residuals for StaticProblem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let s = self.scale.get();
        let m = self.misses(x)?;
        Some(
            m.iter()
                .zip(self.rows)
                .map(|(d, r)| d / r.sd.unwrap_or(s))
                .collect(),
        )
    }
    fn step(&self, _: usize) -> f64 {
        1e-6
    }
}

/// A trace with a scale of its own: its residuals (N, weighed by its bins) divided by it.
pub(crate) struct TracePart<'a> {
    pub p: TraceProblem<'a>,
    pub scale: Cell<f64>,
}

/// One data set of a joint fit.
pub(crate) enum Part<'a> {
    Cor(CorProblem<'a>),
    Trace(TracePart<'a>),
    Static(StaticProblem<'a>),
}

impl Part<'_> {
    /// Residuals of this set at the joint `x`, each in units of its standard deviation.
    pub fn residuals(&self, x: &[f64], k: usize) -> Option<Vec<f64>> {
        match self {
            Part::Cor(p) => p.residuals(&x[..k]),
            Part::Trace(t) => {
                let s = t.scale.get();
                Some(t.p.residuals(x)?.iter().map(|r| r / s).collect())
            }
            Part::Static(p) => p.residuals(&x[..k]),
        }
    }

    /// This set's rows of the joint Jacobian (`vars` columns), at `x` with residuals `r`.
    pub fn jacobian(&self, x: &[f64], r: &[f64], vars: usize, k: usize) -> Option<DMatrix<f64>> {
        let block = match self {
            Part::Cor(p) => forward_jacobian(p, &x[..k], r)?,
            Part::Static(p) => forward_jacobian(p, &x[..k], r)?,
            Part::Trace(t) => {
                let s = t.scale.get();
                let raw: Vec<f64> = r.iter().map(|v| v * s).collect();
                t.p.jacobian(x, &raw)? / s
            }
        };
        let mut jac = DMatrix::zeros(r.len(), vars);
        jac.columns_mut(0, block.ncols()).copy_from(&block);
        Some(jac)
    }

    /// Residuals of this set (number of).
    pub fn count(&self) -> usize {
        match self {
            Part::Cor(p) => p.count(),
            Part::Trace(t) => t.p.data.len(),
            Part::Static(p) => p.rows.len(),
        }
    }

    /// Whether every residual of the set is divided by a stated standard deviation.
    pub fn stated(&self) -> bool {
        match self {
            Part::Cor(p) => {
                p.points.iter().all(|q| q.cor_sd.is_some()) && p.count() == p.points.len()
            }
            Part::Trace(_) => false,
            Part::Static(p) => p.rows.iter().all(|r| r.sd.is_some()),
        }
    }

    /// The set's scale of misses (its COR's for a table; `None` when stated).
    pub fn scale(&self) -> Option<f64> {
        if self.stated() {
            return None;
        }
        Some(match self {
            Part::Cor(p) => p.scale[0].get(),
            Part::Trace(t) => t.scale.get(),
            Part::Static(p) => p.scale.get(),
        })
    }

    /// Set the set's scales to the RMS of its own misses at `x` (a COR table's by kind: COR,
    /// peak force, contact time), rows with a stated sd aside; returns the largest relative
    /// change, `None` where the model has no answer. A stated set is left as it is.
    pub fn rescale(&self, x: &[f64], k: usize) -> Option<f64> {
        let set = |c: &Cell<f64>, v: f64, floor: f64| -> f64 {
            let v = v.max(floor);
            let change = (v / c.get() - 1.0).abs();
            c.set(v);
            change
        };
        match self {
            Part::Cor(p) => {
                let kinds = p.rms_by_kind(&x[..k])?;
                let mut change: f64 = 0.0;
                for (j, v) in kinds.iter().enumerate() {
                    if v.is_finite() && (j > 0 || p.points.iter().all(|q| q.cor_sd.is_none())) {
                        change = change.max(set(&p.scale[j], *v, SCALE_FLOOR));
                    }
                }
                Some(change)
            }
            Part::Trace(t) => {
                let raw = t.p.residuals(x)?;
                let floor = SCALE_FLOOR * t.p.summary.peak.abs().max(f64::MIN_POSITIVE);
                Some(set(&t.scale, rms(&raw), floor))
            }
            Part::Static(p) => {
                let m = p.misses(&x[..k])?;
                let free: Vec<f64> = m
                    .iter()
                    .zip(p.rows)
                    .filter(|(_, r)| r.sd.is_none())
                    .map(|(d, _)| *d)
                    .collect();
                if free.is_empty() {
                    return Some(0.0);
                }
                let top = p.rows.iter().map(|r| r.deflection).fold(0.0, f64::max);
                Some(set(&p.scale, rms(&free), SCALE_FLOOR * top))
            }
        }
    }

    /// The smallest miss the set resolves, in units of its residuals (its scale's
    /// [`SCALE_FLOOR`] over the scale it was weighed by: 1 for a set fitted to within its
    /// floor; 0 for a stated set, read as its rows say). A joint answer's nudge below it is
    /// float noise, not a contradiction (`lack::f_test`).
    pub fn resolution(&self) -> f64 {
        let (floor, scale) = match self {
            _ if self.stated() => return 0.0,
            Part::Cor(p) => (SCALE_FLOOR, p.scale[0].get()),
            Part::Trace(t) => (
                SCALE_FLOOR * t.p.summary.peak.abs().max(f64::MIN_POSITIVE),
                t.scale.get(),
            ),
            Part::Static(p) => (
                SCALE_FLOOR * p.rows.iter().map(|r| r.deflection).fold(0.0, f64::max),
                p.scale.get(),
            ),
        };
        if scale > 0.0 { floor / scale } else { 0.0 }
    }

    /// RMS of the set's misses in its own unit (COR, N, m) at `x`.
    pub fn rms_raw(&self, x: &[f64], k: usize) -> Option<f64> {
        match self {
            Part::Cor(p) => {
                let pred = p.predict(&x[..k])?;
                let m: Vec<f64> = pred
                    .iter()
                    .zip(p.points)
                    .map(|(e, q)| e.0 - q.cor)
                    .collect();
                Some(rms(&m))
            }
            Part::Trace(t) => {
                let f = t.p.model_at_rows(x)?;
                let m: Vec<f64> = f.iter().zip(&t.p.trace.force).map(|(a, b)| a - b).collect();
                Some(rms(&m))
            }
            Part::Static(p) => Some(rms(&p.misses(&x[..k])?)),
        }
    }

    /// Rows of the set's data (a trace's rows, not its bins).
    pub fn rows(&self) -> usize {
        match self {
            Part::Cor(p) => p.points.len(),
            Part::Trace(t) => t.p.trace.time.len(),
            Part::Static(p) => p.rows.len(),
        }
    }

    /// Whether the set's model runs were stopped by the watch.
    pub fn stopped(&self) -> bool {
        match self {
            Part::Cor(p) => p.stopped(),
            Part::Trace(t) => t.p.stopped(),
            Part::Static(_) => false,
        }
    }
}

pub(crate) fn rms(r: &[f64]) -> f64 {
    (r.iter().map(|v| v * v).sum::<f64>() / r.len().max(1) as f64).sqrt()
}
