//! A ball's Monte Carlo over parameter tolerances ([`crate::analysis::mc`]), within the one
//! work limit, and the report `bouncelab mc --format json` writes (docs/scale.md).

use super::{Ball, BallError};
use crate::analysis::mc::{
    Dist, McError, McSpec, McStats, McSummary, Sampler, Samples, Varied, summary,
};
use crate::analysis::work;
use crate::model::contact::ContactLaw;
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
        let sampler = Sampler::new(self.params, self.law, spec.clone());
        match self.mc_conditions(spec) {
            Ok(Some(c)) => sampler.with_conditions(c),
            _ => sampler,
        }
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

    /// [`Ball::monte_carlo`] in chunks, the samples done reported to `watch` before each,
    /// which may stop the run ([`BallError::Interrupted`]): Python's Ctrl-C. The same samples
    /// as one call: each is made from its index alone (analysis::mc_tests,
    /// `same_answer_on_one_thread_and_many_and_in_any_chunks`; tests/analysis/mc_watched.rs).
    pub fn monte_carlo_watched(
        &self,
        spec: &McSpec,
        watch: &dyn work::Watch,
    ) -> Result<MonteCarlo, BallError> {
        self.check_samples(spec.samples)?;
        self.mc_conditions(spec)?;
        let sampler = self.sampler(spec);
        // some 5 ms of work on all cores: 16 384 closed-form samples, 409 of another law
        let chunk = ((1u64 << 14) / work::cost(self.law)).max(1) as usize;
        let mut samples = Samples::zeroed(0, spec.samples);
        let mut done = 0;
        while done < spec.samples {
            if !watch.step(done as u64) {
                return Err(BallError::Interrupted);
            }
            let n = chunk.min(spec.samples - done);
            sampler.samples_into(done as u64, samples.columns_mut(done..done + n))?;
            done += n;
        }
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
        self.check_samples(count)?;
        self.mc_conditions(spec)?;
        Ok(self.sampler(spec).samples(start, count)?)
    }
}

impl Ball {
    /// Refuse `samples` Monte Carlo samples of this ball beyond the work limit: under Hertz,
    /// samples of a ball the Hertz table answers count as cheap ones
    /// ([`work::check_samples_by`]; the spreads move a sample off the nominal ball's patch
    /// rarely, and then onto the Taylor steps, some 15 µs); under the elastic–plastic law the
    /// nominal ball's path decides (`solver::table::summary`: the table below yield, `steps`
    /// 0; the Taylor steps past it), a sample near yield that the spreads carry past it
    /// costing the Taylor steps' 15 µs.
    pub fn check_samples(&self, samples: usize) -> Result<(), work::TooMuchWork> {
        let n = self.params.normalized();
        let nominal = match self.law {
            ContactLaw::Hertz if crate::solver::table::hertz(&n).is_some() => work::Nominal::Table,
            ContactLaw::ElasticPlastic => match crate::solver::table::summary(&n, self.law) {
                Some(s) if s.steps == 0 => work::Nominal::Table,
                Some(_) => work::Nominal::TaylorSteps,
                None => work::Nominal::Solver,
            },
            _ => work::Nominal::Solver,
        };
        work::check_samples_by(samples, self.law, nominal)
    }

    /// The spec that samples this ball's own fit (`bouncelab mc --vary fit`): the multivariate
    /// normal of the preset's `[fit]` table (its values the means, its covariance C), as
    /// relative spreads s_i = √C_ii / value_i and correlations C_ij / √(C_ii C_jj) — the
    /// normal v_i (1 + s_i y_i) with corr(y) = R has covariance C exactly.
    pub fn fit_spec(&self, samples: usize, seed: u64) -> Result<McSpec, BallError> {
        let Some(fit) = &self.fit else {
            return Err(McError::Fit(format!(
                "{} carries no fit to sample (a preset saved by `bouncelab fit … --save NAME` \
                 does, under its own law and adopted parameters, when its data outnumber the \
                 parameters: an exact fit has no covariance)",
                self.label()
            ))
            .into());
        };
        let params = fit.params();
        let sd: Vec<f64> = (0..params.len())
            .map(|i| fit.covariance[i][i].sqrt())
            .collect();
        let vary = params
            .iter()
            .zip(&fit.values)
            .zip(&sd)
            .map(|((p, v), sd)| crate::analysis::mc::Spread {
                what: Varied::Param(*p),
                spread: sd / v,
            })
            .collect();
        let mut pairs = Vec::new();
        for i in 0..params.len() {
            for j in 0..i {
                if sd[i] > 0.0 && sd[j] > 0.0 {
                    let rho = (fit.covariance[i][j] / (sd[i] * sd[j])).clamp(-1.0, 1.0);
                    pairs.push((Varied::Param(params[j]), Varied::Param(params[i]), rho));
                }
            }
        }
        let spec = McSpec::new(vary, Dist::Normal, samples, seed)?;
        // the user gave no --correlate: a matrix that cannot be sampled is the fit's, named
        // so (issue 54 item 9; tests/cli/field_names.rs)
        Ok(if pairs.is_empty() {
            spec
        } else {
            spec.with_correlation(pairs).map_err(|e| match e {
                McError::Correlate(_) => McError::Fit(format!(
                    "the [fit] covariance of {} gives correlations no normal distribution has \
                     (not positive definite): refit the ball (`bouncelab fit … --save NAME`)",
                    self.label()
                )),
                e => e,
            })?
        })
    }
}

impl Ball {
    /// The warnings of a Monte Carlo run of this ball with statistics `st`: those of its
    /// impact at the nominal parameters ([`Ball::warnings`]: a peak indentation beyond the
    /// radius, said "at the nominal parameters"; the samples' own indentations are not
    /// kept), then what `spec`'s temperature spread takes the samples to that the conditions'
    /// model does not vouch for (beyond a shift's span, past the COR's turn: as `run` warns
    /// of and refuses one temperature), then the quantiles too far in the tail for the
    /// samples to give their interval an end (`analysis::mc::interval_warnings`). The JSON,
    /// the text and Python say these.
    pub fn mc_warnings(&self, spec: &McSpec, st: &McStats) -> Vec<String> {
        let nominal = self.impact().map(|r| self.warnings(&r)).unwrap_or_default();
        nominal
            .into_iter()
            // "outside calibration:" opens its warning wherever it is said (issue 52)
            .map(|w| {
                if w.starts_with("outside calibration:") {
                    w
                } else {
                    format!("at the nominal parameters: {w}")
                }
            })
            .chain(self.temperature_spread_warnings(spec))
            .chain(crate::analysis::mc::interval_warnings(&[
                &st.cor,
                &st.max_force,
                &st.contact_time,
            ]))
            .collect()
    }
}

/// The correlations given, as a JSON object `{"k_p:c": 0.5, …}`.
struct CorrMap<'a>(&'a [(Varied, Varied, f64)]);

impl Serialize for CorrMap<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (a, b, rho) in self.0 {
            m.serialize_entry(&format!("{}:{}", a.name(), b.name()), rho)?;
        }
        m.end()
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
/// `sd`, `min`, `max`, quantiles `q`, and the 95 % intervals `mean_se`, `mean_ci`, `q_ci`),
/// with the ball and the spec that made them, and `warnings`.
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
    /// Correlations between the varied parameters, when given.
    #[serde(skip_serializing_if = "Option::is_none")]
    correlate: Option<CorrMap<'a>>,
    /// Samples in which the ball stayed at the wall (left out of `contact_time`).
    pub no_rebound: usize,
    /// The statistics, each with its 95 % intervals (`mean_se`, `mean_ci`, `q_ci`).
    pub stats: &'a McStats,
    /// What the reader should know: quantiles too far in the tail for the samples to give
    /// their interval an end (`analysis::mc::interval_warnings`); `[]` when nothing.
    pub warnings: Vec<String>,
    /// The ball sampled around (docs/cli.md, "The ball object").
    pub ball: super::BallRecord,
    /// The surface every sample ran on (docs/surfaces.md): the rigid plate, as `run`'s
    /// default (plain `mc` takes no `--surface`; `mc --shot` does).
    pub surface: super::SurfaceUsed,
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
            correlate: spec.correlation.as_ref().map(|c| CorrMap(&c.pairs)),
            no_rebound: summary.no_rebound,
            stats: &summary.stats,
            warnings: ball.mc_warnings(spec, &summary.stats),
            ball: ball.record_json(),
            surface: super::SurfaceUsed::rigid_plate(),
        }
    }
}
