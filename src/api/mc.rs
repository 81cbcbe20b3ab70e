//! A ball's Monte Carlo over parameter tolerances ([`crate::analysis::mc`]), within the one
//! work limit, and the report `bouncelab mc --format json` writes (docs/scale.md).

use super::{Ball, BallError};
use crate::analysis::mc::{McSpec, McStats, McSummary, Sampler, Samples, summary};
use crate::analysis::work;
use serde::Serialize;
use serde::ser::SerializeMap;

/// A complete run: its statistics and its samples.
#[derive(Debug, Clone, PartialEq)]
pub struct MonteCarlo {
    /// The statistics, with the spec that made them.
    pub summary: McSummary,
    /// Every sample, in index order.
    pub samples: Samples,
}

impl Ball {
    /// The sampler of `spec` around this ball (its parameters the nominal values, its law).
    pub fn sampler(&self, spec: &McSpec) -> Sampler {
        Sampler::new(self.params, self.law, spec.clone())
    }

    /// COR, peak force and contact time over `spec.samples` samples of this ball's parameters
    /// spread as `spec` says, on all cores, as `bouncelab mc`; the same seed gives the same
    /// numbers on any number of threads. Within the work limit ([`work::check_samples`]).
    ///
    /// ```
    /// use bouncelab::analysis::mc::{Dist, McSpec, parse_vary};
    /// let golf = bouncelab::Ball::from_preset("golf")?;
    /// let spec = McSpec::new(parse_vary("k_p=5%,c=5%,k_r=5%")?, Dist::Normal, 2000, 1)?;
    /// let mc = golf.monte_carlo(&spec)?;
    /// let cor = mc.summary.stats.cor;
    /// assert!(cor.q.q2_5 < golf.impact()?.cor && golf.impact()?.cor < cor.q.q97_5);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn monte_carlo(&self, spec: &McSpec) -> Result<MonteCarlo, BallError> {
        let samples = self.monte_carlo_samples(spec, 0, spec.samples)?;
        Ok(MonteCarlo {
            summary: summary(spec, &samples),
            samples,
        })
    }

    /// The samples `start … start + count` of `spec` (a chunk of a larger run: a Dask task's),
    /// within the work limit for `count` samples.
    pub fn monte_carlo_samples(
        &self,
        spec: &McSpec,
        start: u64,
        count: usize,
    ) -> Result<Samples, BallError> {
        work::check_samples(count, self.law)?;
        Ok(self.sampler(spec).samples(start, count)?)
    }
}

/// The parameters varied and their spreads, as a JSON object in the spec's order.
struct VaryMap<'a>(&'a McSpec);

impl Serialize for VaryMap<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.vary.len()))?;
        for v in &self.0.vary {
            m.serialize_entry(v.what.name(), &v.spread)?;
        }
        m.end()
    }
}

/// `bouncelab mc --format json`, SI: `samples`, `seed`, `stats` (each quantity's `n`, `mean`,
/// `sd`, `min`, `max` and quantiles `q`), with the ball and the spec that made them.
#[derive(Serialize)]
pub struct McReport<'a> {
    /// Number of samples.
    pub samples: usize,
    /// The seed.
    pub seed: u64,
    /// Preset name (`None` for a ball given by its parameters).
    pub preset: Option<&'a str>,
    /// Contact law.
    pub law: &'static str,
    /// Nominal impact speed, m/s.
    pub v0: f64,
    /// `normal`, `uniform` or `lognormal`.
    pub dist: &'static str,
    vary: VaryMap<'a>,
    /// Samples in which the ball stayed at the wall (left out of `contact_time`).
    pub no_rebound: usize,
    /// The statistics.
    pub stats: &'a McStats,
}

impl<'a> McReport<'a> {
    /// The report of `summary`, run on `ball`.
    pub fn new(ball: &'a Ball, summary: &'a McSummary) -> McReport<'a> {
        let spec = &summary.spec;
        McReport {
            samples: spec.samples,
            seed: spec.seed,
            preset: ball.name.as_deref(),
            law: ball.law.name(),
            v0: ball.params.v0,
            dist: spec.dist.name(),
            vary: VaryMap(spec),
            no_rebound: summary.no_rebound,
            stats: &summary.stats,
        }
    }
}
