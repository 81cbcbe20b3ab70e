//! A shot's tolerances by Monte Carlo (`bouncelab mc --shot`, docs/flight.md §7): the launch's
//! speed, spin, elevation and height spread, each sample a shot, and the spread of where it
//! lands and how it leaves. Sample i draws from ChaCha8 keyed by the seed on stream i, as
//! `mc`'s samples do, so the answer is the same on any number of threads.

use super::{Ball, BallError, ShotReport, ShotSpec};
use chacha20::ChaCha8Rng;
use chacha20::rand_core::SeedableRng;
use rand_distr::{Distribution, StandardNormal, StandardUniform};
use rayon::prelude::*;
use serde::Serialize;

/// Samples allowed at most: their six numbers are kept for the quantiles (48 bytes a
/// sample, about 100 MB at most with the sorting).
pub const MAX_SHOT_SAMPLES: usize = 2_000_000;

/// The launch's spreads: the sd of a normal spread, the half-width of a uniform one.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct ShotSpread {
    /// Of the speed, relative (0.02: 2 %).
    pub speed: f64,
    /// Of the spin (rad/s).
    pub spin: f64,
    /// Of the elevation (degrees).
    pub elevation: f64,
    /// Of the height (m).
    pub height: f64,
}

/// A shot's Monte Carlo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShotMcSpec {
    /// The nominal shot.
    pub shot: ShotSpec,
    /// The spreads.
    pub spread: ShotSpread,
    /// Uniform (± spread) rather than normal (sd = spread).
    pub uniform: bool,
    /// Samples.
    pub samples: usize,
    /// The generator's seed.
    pub seed: u64,
}

/// One quantity's spread over the samples that answered.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spread {
    /// Mean.
    pub mean: f64,
    /// Standard deviation (n − 1).
    pub sd: f64,
    /// Smallest.
    pub min: f64,
    /// Largest.
    pub max: f64,
    /// 2.5 % quantile (the order statistic at ⌈0.025 n⌉).
    pub q025: f64,
    /// Median.
    pub q50: f64,
    /// 97.5 % quantile.
    pub q975: f64,
}

/// The quantities of a shot's Monte Carlo, in the report's order.
pub const SHOT_MC_QUANTITIES: [&str; 6] = [
    "landing_x",
    "landing_t",
    "v_out",
    "angle_out",
    "spin_out",
    "end_x",
];

/// A shot's Monte Carlo's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShotMcReport {
    /// Samples drawn.
    pub samples: usize,
    /// The seed.
    pub seed: u64,
    /// `normal` or `uniform`.
    pub dist: &'static str,
    /// The spreads.
    pub vary: ShotSpread,
    /// Samples with no answer (a launch drawn out of its domain), left out of the stats.
    pub failed: usize,
    /// [`SHOT_MC_QUANTITIES`]' spreads, in that order (the first bounce's for landing_x …
    /// spin_out; NaN with bounces = 0).
    pub stats: Vec<(&'static str, Spread)>,
    /// The nominal shot's warnings (its bounces', as `shot` gives them for the same flags),
    /// as `mc` gives its nominal impact's: "outside calibration: …" as it is, any other
    /// opened by "at the nominal launch: ". The samples' own are not made
    /// ([`Ball::shot_unwarned`]).
    pub warnings: Vec<String>,
}

fn row(r: &ShotReport) -> [f64; 6] {
    let b = r.bounces.first();
    let nan = f64::NAN;
    [
        b.map_or(nan, |b| b.x),
        b.map_or(nan, |b| b.t),
        b.map_or(nan, |b| b.v_out),
        b.map_or(nan, |b| b.angle_out),
        b.map_or(nan, |b| b.spin_out),
        r.end.state.x,
    ]
}

fn spread(mut v: Vec<f64>) -> Spread {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let mean = v.iter().sum::<f64>() / n as f64;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n.max(2) - 1) as f64;
    let q = |p: f64| v[((p * n as f64).ceil() as usize).clamp(1, n) - 1];
    Spread {
        mean,
        sd: var.sqrt(),
        min: v[0],
        max: v[n - 1],
        q025: q(0.025),
        q50: q(0.5),
        q975: q(0.975),
    }
}

/// The nominal shot's warnings as a Monte Carlo states them (`Ball::mc_warnings`' rule).
fn nominal_warnings(nominal: &ShotReport) -> Vec<String> {
    nominal
        .bounces
        .iter()
        .flat_map(|b| &b.warnings)
        .map(|w| {
            if w.starts_with("outside calibration:") {
                w.clone()
            } else {
                format!("at the nominal launch: {w}")
            }
        })
        .collect()
}

impl ShotMcSpec {
    /// The shot of sample `index`.
    pub fn sample(&self, index: u64) -> ShotSpec {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream(index);
        let mut draw = |s: f64| -> f64 {
            if self.uniform {
                let u: f64 = StandardUniform.sample(&mut rng);
                s * (2.0 * u - 1.0)
            } else {
                let n: f64 = StandardNormal.sample(&mut rng);
                s * n
            }
        };
        let (sp, l) = (self.spread, self.shot.launch);
        let mut shot = self.shot;
        shot.launch.speed = l.speed * (1.0 + draw(sp.speed));
        shot.launch.spin = l.spin + draw(sp.spin);
        shot.launch.elevation_deg = l.elevation_deg + draw(sp.elevation);
        shot.launch.height = l.height + draw(sp.height);
        shot.samples = 0;
        shot
    }
}

/// Shots a block of the Monte Carlo runs between two calls of its watcher (in parallel): some
/// 20 ms on one core, so that a Ctrl-C is seen within 0.5 s on a loaded machine too.
pub const SHOT_MC_BLOCK: usize = 1024;

impl Ball {
    /// A shot's Monte Carlo (docs/flight.md §7).
    pub fn shot_mc(&self, spec: &ShotMcSpec) -> Result<ShotMcReport, BallError> {
        self.shot_mc_watched(spec, &mut |_| true)?
            .ok_or_else(|| BallError::Invalid {
                field: "samples",
                value: spec.samples as f64,
                reason: "stopped".into(),
            })
    }

    /// [`Ball::shot_mc`] in blocks of `SHOT_MC_BLOCK` shots, `watch(done)` called before
    /// each block and once after the last with the count of shots done: `None` once it
    /// answers false (a Ctrl-C). The blocks change no sample (each is a function of its index).
    pub fn shot_mc_watched(
        &self,
        spec: &ShotMcSpec,
        watch: &mut dyn FnMut(usize) -> bool,
    ) -> Result<Option<ShotMcReport>, BallError> {
        let invalid = |field, value: f64, reason: &str| BallError::Invalid {
            field,
            value,
            reason: reason.into(),
        };
        if spec.samples == 0 || spec.samples > MAX_SHOT_SAMPLES {
            return Err(invalid(
                "samples",
                spec.samples as f64,
                "must lie in 1 … 2000000",
            ));
        }
        let s = spec.spread;
        for (field, x) in [
            ("speed", s.speed),
            ("spin", s.spin),
            ("elevation", s.elevation),
            ("height", s.height),
        ] {
            if !(x.is_finite() && x >= 0.0) {
                return Err(invalid(field, x, "its spread must be zero or positive"));
            }
        }
        // the nominal shot first: its errors are the input's, its warnings the report's
        let nominal = self.shot(&spec.shot)?;
        let mut ok: Vec<[f64; 6]> = Vec::with_capacity(spec.samples);
        let mut done = 0usize;
        while done < spec.samples {
            if !watch(done) {
                return Ok(None);
            }
            let end = (done + SHOT_MC_BLOCK).min(spec.samples);
            let block: Vec<Option<[f64; 6]>> = (done as u64..end as u64)
                .into_par_iter()
                .map(|i| self.shot_unwarned(&spec.sample(i)).ok().map(|r| row(&r)))
                .collect();
            ok.extend(block.into_iter().flatten());
            done = end;
        }
        if !watch(done) {
            return Ok(None);
        }
        if ok.is_empty() {
            return Err(invalid(
                "samples",
                spec.samples as f64,
                "no sample answered",
            ));
        }
        let stats = SHOT_MC_QUANTITIES
            .iter()
            .enumerate()
            .map(|(k, name)| (*name, spread(ok.iter().map(|r| r[k]).collect())))
            .collect();
        Ok(Some(ShotMcReport {
            samples: spec.samples,
            seed: spec.seed,
            dist: if spec.uniform { "uniform" } else { "normal" },
            vary: spec.spread,
            failed: spec.samples - ok.len(),
            stats,
            warnings: nominal_warnings(&nominal),
        }))
    }
}
