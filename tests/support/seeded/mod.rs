//! The tests' one seeded generator: ChaCha8 (`chacha20`), the Monte Carlo's
//! (src/analysis/mc.rs), seeded as `SeedableRng::seed_from_u64` seeds it, so a test draws the
//! same points every run, on every platform. A crate's generator in place of the hand-written
//! xorshift and splitmix copies the tests each carried.
#![allow(dead_code)] // shared by several test crates, each of which uses a part

use chacha20::ChaCha8Rng;
use chacha20::rand_core::{Rng, SeedableRng};
use rand_distr::{Distribution, StandardNormal};

/// A seeded stream of numbers.
pub struct Seeded(ChaCha8Rng);

impl Seeded {
    pub fn new(seed: u64) -> Seeded {
        Seeded(ChaCha8Rng::seed_from_u64(seed))
    }

    /// Uniform in [0, 1): a word's top 53 bits, each multiple of 2⁻⁵³ equally likely.
    pub fn uniform(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Log-uniform over [`lo`, `hi`) (both > 0): uniform in log10.
    pub fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let (a, b) = (lo.log10(), hi.log10());
        10f64.powf(a + (b - a) * self.uniform())
    }

    /// `10^x`, `x` uniform over [`from`, `from + span`): log-uniform over `span` decades from
    /// `10^from`, written as the tests wrote it by hand, so that the same seed draws the same
    /// bits.
    pub fn decades(&mut self, from: f64, span: f64) -> f64 {
        10f64.powf(from + span * self.uniform())
    }

    /// Standard normal (`rand_distr`'s ziggurat).
    pub fn normal(&mut self) -> f64 {
        StandardNormal.sample(&mut self.0)
    }
}
