//! Monte Carlo: the spread of the COR, peak force and contact time when a ball's parameters
//! are known only to a tolerance (docs/scale.md). No I/O; the command line (`bouncelab mc`),
//! the Python package and its Dask path all call [`Sampler`].
//!
//! What holds:
//!
//! - **A sample is a function of (seed, index) alone.** Sample `i` draws its variates from
//!   ChaCha8 keyed by the seed on stream `i` (a counter-based generator: no state passes from
//!   one sample to the next), so the same seed gives the same samples on any number of
//!   threads, in any chunking, on any machine of a cluster (`same_answer_on_one_thread_and_many`).
//! - **Spreads are relative.** A spread `s` on a parameter of nominal value `v`: `normal`
//!   draws v(1 + s N), sd s·v; `uniform` draws v(1 + s U), U uniform on [−1, 1), sd s·v/√3;
//!   `lognormal` draws v·exp(μ + σN) with σ² = ln(1 + s²), μ = −σ²/2, so its mean is v and
//!   its sd s·v as the normal's, and it never crosses 0.
//! - **K_h follows K_p and z_p** (Eq. 16) when either is varied, as the fit and the command
//!   line's overrides tie them (as [`super::fit::apply`]).
//! - **Each impact is `run`'s**: on the linear law the closed forms of [`crate::map::fast`]
//!   (flattening or not, to 1e-12 of the exact solver); under Hertz the Hertz table, then the
//!   Taylor steps ([`crate::solver::table::summary`], within 1e-9 of their reference and of
//!   `run` at its solver's stated precision, docs/numerics.md); else [`crate::simulate`]. The
//!   closed form runs four samples at once in lanes ([`crate::map::fast::lanes`]); each lane
//!   is a function of its own ball alone, so a sample's answer does not depend on its group.

use super::fit::Param;
use super::mc_rng::{Words, first_blocks, key_words};
use crate::map::fast::lanes::LANES;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use chacha20::rand_core::{Rng, SeedableRng};
use rand_distr::{Distribution, StandardNormal, StandardUniform};
use rayon::prelude::*;
use statrs::distribution::{ContinuousCDF, Normal};

pub use super::mc_conditions::McConditions;
pub use super::mc_corr::parse_correlate;
pub use super::mc_impact::{Outcome, impact, impacts, impacts_of_groups};
pub use super::mc_samples::{Columns, McStats, McSummary, Samples, summarize, summary};
pub use super::mc_spec::{Correlation, Dist, McError, McSpec, Spread, Varied, parse_vary};
pub use super::mc_stats::{
    PROBS, Quantiles, Stats, interval_warnings, order_ranks, stats as stats_of, stats_from_order,
};

/// Samples handed to the threads at once: the blocks run one after the other, so that an
/// error stops the run within a block (some 5 ms of closed forms on all cores).
const BLOCK: usize = 1 << 14;

/// Samples of one parallel task, solved in index order: its first error by index, and the
/// first of the tasks' by index ([`Sampler::samples_into`]), whatever the threads did.
const TASK: usize = 64 * LANES;

/// Draws and solves the samples of one spec on one ball.
#[derive(Debug, Clone)]
pub struct Sampler {
    base: ImpactParams,
    law: ContactLaw,
    spec: McSpec,
    /// ChaCha8's key: the seed expanded as `ChaCha8Rng::seed_from_u64` expands it.
    key: [u8; 32],
    /// The same as ChaCha's key words ([`key_words`]).
    words: [u32; 8],
    /// The run's conditions, for a spread in pressure or temperature (`super::mc_conditions`).
    conditions: Option<McConditions>,
}

/// The key `SeedableRng::seed_from_u64` makes of a seed (rand_core's own expansion), kept so
/// that each sample's generator is built from it without a clone (ChaCha8Rng has none):
/// `ChaCha8Rng::from_seed(key(s))` is `ChaCha8Rng::seed_from_u64(s)`.
fn key(seed: u64) -> [u8; 32] {
    struct Key([u8; 32]);
    impl SeedableRng for Key {
        type Seed = [u8; 32];
        fn from_seed(seed: [u8; 32]) -> Key {
            Key(seed)
        }
    }
    Key::seed_from_u64(seed).0
}

impl Sampler {
    /// The sampler of `spec` around the nominal ball `base` under `law`.
    pub fn new(base: ImpactParams, law: ContactLaw, spec: McSpec) -> Sampler {
        let key = key(spec.seed);
        Sampler {
            base,
            law,
            key,
            words: key_words(&key),
            spec,
            conditions: None,
        }
    }

    /// This sampler with the run's conditions, which a `pressure` or `temperature` spread
    /// moves each sample away from ([`McConditions`]).
    pub fn with_conditions(self, conditions: McConditions) -> Sampler {
        Sampler {
            conditions: Some(conditions),
            ..self
        }
    }

    /// The nominal value of `what`: the ball's, or the run's gauge pressure (Pa) and absolute
    /// temperature (K); NaN where the sampler has no conditions (refused before by the api).
    fn nominal(&self, what: Varied) -> f64 {
        let c = self.conditions.as_ref();
        match what {
            Varied::Pressure => c.and_then(|c| c.inflated).map_or(f64::NAN, |i| i.0),
            Varied::Temperature => c.map_or(f64::NAN, McConditions::kelvin),
            _ => what.get(&self.base),
        }
    }

    /// The spec it runs.
    pub fn spec(&self) -> &McSpec {
        &self.spec
    }

    /// The varied parameters' values of sample `index`, in the spec's order.
    pub fn inputs(&self, index: u64) -> Vec<f64> {
        let (values, n) = self.draw(index);
        let celsius = |(s, v): (&super::mc_spec::Spread, &f64)| match s.what {
            // drawn in kelvin (the spread is relative to it), written in °C
            Varied::Temperature => v - crate::conditions::ZERO_CELSIUS,
            _ => *v,
        };
        self.spec
            .vary
            .iter()
            .zip(&values[..n])
            .map(celsius)
            .collect()
    }

    /// The values of [`Sampler::inputs`] without an allocation: the first `n` of the array.
    fn draw(&self, index: u64) -> ([f64; Varied::ALL.len()], usize) {
        let [block, ..] = first_blocks(&self.words, [index; LANES]);
        self.draw_from(&mut Words::new(&self.key, index, &block))
    }

    /// The varied parameters' values drawn from `rng`, a sample's own stream: ChaCha8 keyed
    /// by the seed on stream `index` (`mc_rng::Words`, the words of `ChaCha8Rng`).
    fn draw_from<R: Rng>(&self, rng: &mut R) -> ([f64; Varied::ALL.len()], usize) {
        if let Some(c) = &self.spec.correlation {
            return self.draw_correlated(rng, c);
        }
        let mut out = [0.0; Varied::ALL.len()];
        for (slot, s) in out.iter_mut().zip(&self.spec.vary) {
            let v = self.nominal(s.what);
            *slot = match self.spec.dist {
                Dist::Normal => {
                    let n: f64 = StandardNormal.sample(rng);
                    v * (1.0 + s.spread * n)
                }
                Dist::Uniform => {
                    let u: f64 = StandardUniform.sample(rng);
                    v * (1.0 + s.spread * (2.0 * u - 1.0))
                }
                Dist::Lognormal => {
                    let n: f64 = StandardNormal.sample(rng);
                    lognormal(v, s.spread, n)
                }
            };
        }
        (out, self.spec.vary.len())
    }

    /// Correlated draws (`super::mc_corr`): one standard normal per parameter, y = L z, each
    /// y the normal variate of its parameter (a Gaussian copula for `uniform`).
    fn draw_correlated<R: Rng>(
        &self,
        rng: &mut R,
        c: &Correlation,
    ) -> ([f64; Varied::ALL.len()], usize) {
        let n = self.spec.vary.len();
        let mut y = [0.0; Varied::ALL.len()];
        for slot in &mut y[..n] {
            *slot = StandardNormal.sample(rng);
        }
        c.apply(&mut y[..n]);
        let mut out = [0.0; Varied::ALL.len()];
        for ((slot, s), &y) in out.iter_mut().zip(&self.spec.vary).zip(&y) {
            let v = self.nominal(s.what);
            *slot = match self.spec.dist {
                Dist::Normal => v * (1.0 + s.spread * y),
                Dist::Uniform => {
                    let u = Normal::standard().cdf(y);
                    v * (1.0 + s.spread * (2.0 * u - 1.0))
                }
                Dist::Lognormal => lognormal(v, s.spread, y),
            };
        }
        (out, n)
    }

    /// The ball of sample `index`, checked. The values are set in [`Varied::ALL`]'s order (z_p
    /// before K_h, which reads it) and K_h then follows K_p and z_p, as
    /// [`super::fit::apply`] does (`k_h_follows_k_p_…` holds the two to the same ball).
    pub fn params(&self, index: u64) -> Result<ImpactParams, McError> {
        let (values, n) = self.draw(index);
        let p = self.ball(&values[..n]);
        p.validate().map_err(|e| McError::Domain {
            index,
            reason: super::mc_spec::drawn(&e),
        })?;
        Ok(p)
    }

    /// The ball of the varied parameters' `values` (in the spec's order), unchecked.
    fn ball(&self, values: &[f64]) -> ImpactParams {
        let mut p = self.base;
        let mut tied = false;
        let (mut pressure, mut kelvin) = (None, None);
        for (s, &v) in self.spec.vary.iter().zip(values) {
            match s.what {
                Varied::Pressure => pressure = Some(v),
                Varied::Temperature => kelvin = Some(v),
                Varied::Param(Param::KP) => p.k_p = v,
                Varied::Param(Param::C) => p.damping = v,
                Varied::Param(Param::KR) => p.k_r = v,
                Varied::Param(Param::ZP) => p.z_p = v,
                Varied::Param(Param::KH) => p.k_p = 1.5 * v * p.z_p.sqrt(),
                Varied::Mass => p.mass = v,
                // (the fit's v0 and the Monte Carlo's are the same speed)
                Varied::V0 | Varied::Param(Param::V0) => p.v0 = v,
            }
            tied |= matches!(s.what, Varied::Param(Param::KP | Param::ZP | Param::KH));
        }
        if let Some(c) = &self.conditions {
            c.apply(&mut p, pressure, kelvin);
            tied = true;
        }
        if tied && p.z_p.is_finite() {
            p.k_h = ImpactParams::k_h_matching(p.k_p, p.z_p);
        }
        p
    }

    /// Sample `index`: its ball, and the impact `bouncelab run` would solve for it (as in
    /// [`Sampler::samples`]: [`impact`]'s lanes give a sample the same answer alone as in any
    /// group).
    pub fn outcome(&self, index: u64) -> Result<Outcome, McError> {
        let p = self.params(index)?;
        impact(&p, self.law).map_err(McError::Solve)
    }

    /// The samples `start … start + count`, on all cores, four at a time; the first error by
    /// index, if any.
    pub fn samples(&self, start: u64, count: usize) -> Result<Samples, McError> {
        let mut out = Samples::zeroed(start, count);
        self.samples_into(start, out.columns_mut(0..count))?;
        Ok(out)
    }

    /// The samples `start …` into `out` (as many as it holds), on all cores in tasks of
    /// `TASK` samples, four at a time: the same values as [`Sampler::samples`], written
    /// where they belong (no copy, no per-sample `Result`); the first error by index, if any.
    pub fn samples_into(&self, start: u64, out: Columns<'_>) -> Result<(), McError> {
        let n = out.cor.len();
        assert!(out.max_force.len() == n && out.contact_time.len() == n);
        let blocks = out
            .cor
            .chunks_mut(BLOCK)
            .zip(out.max_force.chunks_mut(BLOCK))
            .zip(out.contact_time.chunks_mut(BLOCK));
        for (b, ((cor, max_force), contact_time)) in blocks.enumerate() {
            let first = start + (b * BLOCK) as u64;
            let first_error = cor
                .par_chunks_mut(TASK)
                .zip(max_force.par_chunks_mut(TASK))
                .zip(contact_time.par_chunks_mut(TASK))
                .enumerate()
                .find_map_first(|(k, ((cor, max_force), contact_time))| {
                    let out = Columns {
                        cor,
                        max_force,
                        contact_time,
                    };
                    self.fill(first + (k * TASK) as u64, out).err()
                });
            if let Some(e) = first_error {
                return Err(e);
            }
        }
        Ok(())
    }

    /// The balls of samples `index`, each checked (`None`: refused).
    fn balls(&self, index: [u64; LANES]) -> [Option<ImpactParams>; LANES] {
        let blocks = first_blocks(&self.words, index);
        std::array::from_fn(|k| {
            let words = &mut Words::new(&self.key, index[k], &blocks[k]);
            let (values, m) = self.draw_from(words);
            let p = self.ball(&values[..m]);
            p.validate().is_ok().then_some(p)
        })
    }

    /// The samples `start …` into `out`, in index order, four at a time (the last group
    /// padded with its own last sample, whose copies are dropped); stops at the first error.
    /// Each sample's draws and ball are [`Sampler::params`]' and its impact [`impacts`]' lane:
    /// a function of its index alone, whatever its group.
    fn fill(&self, start: u64, out: Columns<'_>) -> Result<(), McError> {
        let n = out.cor.len();
        let index: Vec<[u64; LANES]> = (0..n)
            .step_by(LANES)
            .map(|g| std::array::from_fn(|k| start + (g + k).min(n - 1) as u64))
            .collect();
        let balls: Vec<[Option<ImpactParams>; LANES]> =
            index.iter().map(|&index| self.balls(index)).collect();
        let solved = impacts_of_groups(&balls, self.law);
        for ((g, index), solved) in (0..n).step_by(LANES).zip(index).zip(solved) {
            for (k, s) in solved.into_iter().enumerate().take(n - g) {
                let o = match s {
                    Some(Ok(o)) => o,
                    Some(Err(e)) => return Err(McError::Solve(e)),
                    // the ball refused: its error, as `params` words it
                    None => return Err(self.params(index[k]).expect_err("a refused ball")),
                };
                out.cor[g + k] = o.cor;
                out.max_force[g + k] = o.max_force;
                out.contact_time[g + k] = o.contact_time;
            }
        }
        Ok(())
    }
}

/// v·exp(σn − σ²/2), σ² = ln(1 + s²): mean v and sd s·v for a standard normal n.
fn lognormal(v: f64, spread: f64, n: f64) -> f64 {
    let var = spread.mul_add(spread, 1.0).ln();
    v * (var.sqrt() * n - 0.5 * var).exp()
}

#[cfg(test)]
#[path = "mc_tests.rs"]
mod tests;
