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

/// Samples allowed at most: their ten numbers (the six quantities, the end's height and
/// time, the net's verdict and clearance) are kept for the quantiles (80 bytes a sample,
/// 160 MB, and one column of 16 MB sorted at a time: about 180 MB at most).
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
    /// End each sample this many m past its own last bounce (`--after-bounce D`; the
    /// nominal's distance would end a short sample before its bounce).
    pub after_bounce: Option<f64>,
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

/// The quantities added after [`SHOT_MC_QUANTITIES`] when the shot ends off the surface (at
/// a distance, a time or D m past its bounce): the end's height and time.
pub const SHOT_MC_END_QUANTITIES: [&str; 2] = ["end_y", "end_t"];

/// How many samples clear the net (`mc --shot --net`): the count, the fraction, and the
/// clearance's spread over the samples that reach it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NetMc {
    /// Where the net stands (m).
    pub x: f64,
    /// Its height (m).
    pub height: f64,
    /// Samples that clear it.
    pub cleared: usize,
    /// `cleared` over the samples that answered.
    pub fraction: f64,
    /// The clearance (y − R − height at the net) over the samples that reach it; `None` when
    /// none does.
    pub clearance: Option<Spread>,
}

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
    /// The end's height and time ([`SHOT_MC_END_QUANTITIES`]) when the shot ends off the
    /// surface; empty when it ends on a landing (its height is R).
    pub end_stats: Vec<(&'static str, Spread)>,
    /// The net's answer over the samples, with a net.
    pub net: Option<NetMc>,
    /// D when each sample ended D m past its own bounce.
    pub after_bounce: Option<f64>,
    /// The nominal shot's warnings (its bounces', as `shot` gives them for the same flags),
    /// as `mc` gives its nominal impact's: "outside calibration: …" as it is, any other
    /// opened by "at the nominal launch: ". The samples' own are not made
    /// ([`Ball::shot_unwarned`]).
    pub warnings: Vec<String>,
}

/// One sample's numbers, named in [`ROW`].
type Row = [f64; 10];

/// The names of a sample's numbers ([`ShotReport::quantity`]): [`SHOT_MC_QUANTITIES`],
/// [`SHOT_MC_END_QUANTITIES`], whether it clears the net (1 or 0) and its clearance (NaN when
/// it does not reach it or has no net).
pub(super) const ROW: [&str; 10] = {
    let [x, t, v_out, angle_out, spin_out, end_x] = SHOT_MC_QUANTITIES;
    let [end_y, end_t] = SHOT_MC_END_QUANTITIES;
    let net = ["net_cleared", "net_clearance"];
    [
        x, t, v_out, angle_out, spin_out, end_x, end_y, end_t, net[0], net[1],
    ]
};

fn row(r: &ShotReport) -> Row {
    r.quantities(&ROW)
}

/// The net's answer over the rows, for the net `spec` has.
fn net_mc(spec: &ShotSpec, rows: &[Row]) -> Option<NetMc> {
    let net = spec.net?;
    let cleared = rows.iter().filter(|r| r[8] == 1.0).count();
    let reached: Vec<f64> = rows.iter().map(|r| r[9]).filter(|c| !c.is_nan()).collect();
    Some(NetMc {
        x: net.x,
        height: net.height,
        cleared,
        fraction: cleared as f64 / rows.len() as f64,
        clearance: (!reached.is_empty()).then(|| spread(reached)),
    })
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
        .chain(nominal.net.iter().flat_map(|n| &n.warnings))
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

/// Why the nominal shot has no end D m past its bounce, in words.
fn after_bounce_reason(e: super::AfterBounceError) -> String {
    use super::AfterBounceError as E;
    match e {
        E::NotPositive(_) => "must be positive".into(),
        E::NoBounce => "the shot makes no bounce".into(),
        E::EndsBefore { bounce, t } => {
            format!("the shot ends (at t = {t} s) before its bounce {bounce}")
        }
        E::PassesBefore { bounce, x } => {
            format!("the ball passes x = {x} m before its bounce {bounce}")
        }
        E::Shot(e) => e.to_string(),
    }
}

impl Ball {
    /// Sample `index`'s numbers (`None`: drawn out of the shot's domain, or no end D m past
    /// its own bounce with `after_bounce`).
    fn sample_row(&self, spec: &ShotMcSpec, index: u64) -> Option<Row> {
        let shot = spec.sample(index);
        let r = match spec.after_bounce {
            Some(d) => self.shot_after_bounce(&shot, d).ok()?.1,
            None => self.shot_unwarned(&shot).ok()?,
        };
        Some(row(&r))
    }

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
        if let Some(d) = spec.after_bounce {
            self.shot_after_bounce(&spec.shot, d)
                .map_err(|e| invalid("after_bounce", d, &after_bounce_reason(e)))?;
        }
        let mut ok: Vec<Row> = Vec::with_capacity(spec.samples);
        let mut done = 0usize;
        while done < spec.samples {
            if !watch(done) {
                return Ok(None);
            }
            let end = (done + SHOT_MC_BLOCK).min(spec.samples);
            let block: Vec<Option<Row>> = (done as u64..end as u64)
                .into_par_iter()
                .map(|i| self.sample_row(spec, i))
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
        let column = |k: usize| spread(ok.iter().map(|r| r[k]).collect());
        let stats = SHOT_MC_QUANTITIES
            .iter()
            .enumerate()
            .map(|(k, name)| (*name, column(k)))
            .collect();
        let ends = &spec.shot.ends;
        let off_surface =
            ends.distance.is_some() || ends.time.is_some() || spec.after_bounce.is_some();
        let end_stats = if off_surface {
            let n = SHOT_MC_QUANTITIES.len();
            (SHOT_MC_END_QUANTITIES.iter().enumerate())
                .map(|(k, name)| (*name, column(n + k)))
                .collect()
        } else {
            Vec::new()
        };
        Ok(Some(ShotMcReport {
            samples: spec.samples,
            seed: spec.seed,
            dist: if spec.uniform { "uniform" } else { "normal" },
            vary: spec.spread,
            failed: spec.samples - ok.len(),
            stats,
            end_stats,
            net: net_mc(&spec.shot, &ok),
            after_bounce: spec.after_bounce,
            warnings: nominal_warnings(&nominal),
        }))
    }
}
