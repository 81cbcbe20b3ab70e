//! The samples of a Monte Carlo run, one column a quantity ([`Samples`], and [`Columns`] where
//! [`super::mc::Sampler::samples_into`] writes them), and their statistics ([`McStats`],
//! [`McSummary`]): what a run holds once drawn and solved, apart from how (`super::mc`).

use super::mc_spec::McSpec;
use super::mc_stats::{Stats, stats};
use serde::Serialize;

/// The samples `start … start + len` of a run, one column a quantity, in index order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Samples {
    /// Index of the first sample.
    pub start: u64,
    /// COR of each sample.
    pub cor: Vec<f64>,
    /// Peak force of each sample, N.
    pub max_force: Vec<f64>,
    /// Contact time of each sample, s (NaN: no rebound).
    pub contact_time: Vec<f64>,
}

impl Samples {
    /// Number of samples held.
    pub fn len(&self) -> usize {
        self.cor.len()
    }

    /// Whether none is held.
    pub fn is_empty(&self) -> bool {
        self.cor.is_empty()
    }

    /// `count` samples from `start`, every value 0 until solved
    /// ([`super::mc::Sampler::samples_into`]).
    pub fn zeroed(start: u64, count: usize) -> Samples {
        Samples {
            start,
            cor: vec![0.0; count],
            max_force: vec![0.0; count],
            contact_time: vec![0.0; count],
        }
    }

    /// The columns of the samples `range` (positions, not indices) to be written.
    pub fn columns_mut(&mut self, range: std::ops::Range<usize>) -> Columns<'_> {
        Columns {
            cor: &mut self.cor[range.clone()],
            max_force: &mut self.max_force[range.clone()],
            contact_time: &mut self.contact_time[range],
        }
    }

    /// `other`, the samples that follow these, appended.
    pub fn extend(&mut self, other: Samples) {
        debug_assert_eq!(other.start, self.start + self.len() as u64);
        self.cor.extend(other.cor);
        self.max_force.extend(other.max_force);
        self.contact_time.extend(other.contact_time);
    }
}

/// Where [`super::mc::Sampler::samples_into`] writes: one entry a sample, the three of equal
/// length.
#[derive(Debug)]
pub struct Columns<'a> {
    /// COR of each sample.
    pub cor: &'a mut [f64],
    /// Peak force of each sample, N.
    pub max_force: &'a mut [f64],
    /// Contact time of each sample, s (NaN: no rebound).
    pub contact_time: &'a mut [f64],
}

/// The statistics of the three quantities.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct McStats {
    /// Of the COR.
    pub cor: Stats,
    /// Of the peak force, N.
    pub max_force: Stats,
    /// Of the contact time, s, over the samples that rebound.
    pub contact_time: Stats,
}

/// The statistics of `s` (a whole run, or any samples): a function of the values in index
/// order only.
pub fn summarize(s: &Samples) -> McStats {
    McStats {
        cor: stats(&s.cor),
        max_force: stats(&s.max_force),
        contact_time: stats(&s.contact_time),
    }
}

/// A whole run's statistics, with what it ran.
#[derive(Debug, Clone, PartialEq)]
pub struct McSummary {
    /// The spec.
    pub spec: McSpec,
    /// Samples in which the ball stayed at the wall (no contact time).
    pub no_rebound: usize,
    /// The statistics.
    pub stats: McStats,
}

/// The summary of a complete run's samples.
pub fn summary(spec: &McSpec, s: &Samples) -> McSummary {
    McSummary {
        spec: spec.clone(),
        no_rebound: s.contact_time.iter().filter(|t| t.is_nan()).count(),
        stats: summarize(s),
    }
}
