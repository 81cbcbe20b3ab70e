//! What a Monte Carlo runs ([`super::mc`]): the parameters that can vary, their relative
//! spreads and distribution, the number of samples and the seed, each checked, with the one-line
//! errors of bad input (docs/scale.md).

use super::fit::Param;
use crate::model::params::ImpactParams;
use crate::solver::SolveError;
use nalgebra::DMatrix;
use serde::Serialize;

/// The distribution of every varied parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Dist {
    /// v(1 + s N), N standard normal.
    Normal,
    /// v(1 + s U), U uniform on [−1, 1).
    Uniform,
    /// v·exp(μ + σN): mean v, sd s·v.
    Lognormal,
}

impl Dist {
    /// `normal`, `uniform` or `lognormal`.
    pub fn name(self) -> &'static str {
        match self {
            Dist::Normal => "normal",
            Dist::Uniform => "uniform",
            Dist::Lognormal => "lognormal",
        }
    }

    /// The distribution of that [`name`](Dist::name).
    pub fn parse(s: &str) -> Option<Dist> {
        [Dist::Normal, Dist::Uniform, Dist::Lognormal]
            .into_iter()
            .find(|d| d.name() == s.trim())
    }

    /// The probability that a value drawn about `v` with relative `spread` falls below
    /// `ratio`·v: each variate's marginal, which correlation leaves as it is (a Gaussian
    /// copula, `mc_corr`). Normal Φ((r − 1)/s); uniform on v(1 ± s); lognormal of mean v and
    /// sd s·v, Φ((ln r + σ²/2)/σ) with σ² = ln(1 + s²) (`mc::lognormal`).
    pub fn below(self, spread: f64, ratio: f64) -> f64 {
        use statrs::distribution::{ContinuousCDF, Normal};
        if spread == 0.0 {
            return if ratio > 1.0 { 1.0 } else { 0.0 };
        }
        let phi = |x: f64| Normal::standard().cdf(x);
        match self {
            Dist::Normal => phi((ratio - 1.0) / spread),
            Dist::Uniform => (((ratio - 1.0) / spread + 1.0) / 2.0).clamp(0.0, 1.0),
            Dist::Lognormal => {
                if ratio <= 0.0 {
                    return 0.0;
                }
                let var = spread.mul_add(spread, 1.0).ln();
                phi((ratio.ln() + 0.5 * var) / var.sqrt())
            }
        }
    }
}

/// Why a drawn ball is out of its domain, its value to 4 significant figures (a draw is no
/// number the user typed: "invalid k_r: -6369 (must not be negative)").
pub fn drawn(e: &crate::model::params::ParamError) -> String {
    format!(
        "invalid {}: {} ({})",
        e.field,
        crate::text::short(e.value, 4),
        e.reason
    )
}

/// A parameter a Monte Carlo can vary: one a fit can free, the mass or the impact speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Varied {
    /// K_p, c, K_r, z_p or K_h (K_h moves K_p with it, Eq. 16).
    Param(Param),
    /// The mass m (kg).
    Mass,
    /// The impact speed v0 (m/s).
    V0,
    /// The gauge pressure of an inflated ball, Pa (`super::mc::McConditions`).
    Pressure,
    /// The ball's absolute temperature, K (`super::mc::McConditions`; written in °C).
    Temperature,
}

impl Varied {
    /// Every parameter, in the order the outputs list them.
    pub const ALL: [Varied; 9] = [
        Varied::Param(Param::KP),
        Varied::Param(Param::C),
        Varied::Param(Param::KR),
        Varied::Param(Param::ZP),
        Varied::Param(Param::KH),
        Varied::Mass,
        Varied::V0,
        Varied::Pressure,
        Varied::Temperature,
    ];

    /// `k_p`, `c`, `k_r`, `z_p`, `k_h`, `m`, `v0`, `pressure` or `temperature`.
    pub fn name(self) -> &'static str {
        match self {
            Varied::Param(p) => p.name(),
            Varied::Mass => "m",
            Varied::V0 => "v0",
            Varied::Pressure => "pressure",
            Varied::Temperature => "temperature",
        }
    }

    /// The parameter of that [`name`](Varied::name).
    pub fn parse(s: &str) -> Option<Varied> {
        Varied::ALL.into_iter().find(|v| v.name() == s.trim())
    }

    /// Its nominal value in `p`; NaN for the conditions, which `p` does not hold (the
    /// sampler's [`super::mc::McConditions`] do).
    pub fn get(self, p: &ImpactParams) -> f64 {
        match self {
            Varied::Param(q) => q.get(p),
            Varied::Mass => p.mass,
            Varied::V0 => p.v0,
            Varied::Pressure | Varied::Temperature => f64::NAN,
        }
    }
}

/// One varied parameter and its relative spread (0.05 for 5 %).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// The parameter.
    pub what: Varied,
    /// Its relative spread, ≥ 0.
    pub spread: f64,
}

/// Why a Monte Carlo cannot run, one line naming the field.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum McError {
    /// A `--vary` entry names no parameter that can vary.
    #[error(
        "invalid vary: unknown parameter '{0}' (choose from k_p, c, k_r, z_p, k_h, m, v0, pressure, temperature)"
    )]
    Unknown(String),
    /// A `--vary` entry without `=` or with a spread that is not a number.
    #[error("invalid vary: '{0}' is not NAME=SPREAD (e.g. k_p=5% or k_p=0.05)")]
    Syntax(String),
    /// A spread that rounds to 0 or to a subnormal (`k_p=1e-400`): refused, not run as 0.
    #[error("invalid vary {0}: {1}")]
    Underflow(&'static str, String),
    /// A spread below 0 or not finite.
    #[error("invalid vary {0}: {1} (the spread must be a finite number ≥ 0)")]
    Spread(&'static str, f64),
    /// A uniform spread of 1 (100 %) or more would reach 0.
    #[error(
        "invalid vary {0}: {1} (a uniform spread must be below 1, 100 %: the parameter would reach 0)"
    )]
    UniformWide(&'static str, f64),
    /// The same parameter twice.
    #[error("invalid vary: {0} given twice")]
    Twice(&'static str),
    /// Nothing to vary.
    #[error("invalid vary: no parameter given")]
    Empty,
    /// No sample asked for.
    #[error("invalid samples: 0 (must be at least 1)")]
    NoSamples,
    /// A normal draw crossed into a parameter's forbidden domain.
    #[error(
        "invalid vary: sample {index} draws an out-of-domain ball ({reason}); a normal spread this wide crosses 0: use --dist lognormal or a smaller spread"
    )]
    Domain {
        /// The sample's index.
        index: u64,
        /// The parameter's own message.
        reason: String,
    },
    /// A `--correlate` that names no pair of varied parameters, or no correlation matrix.
    #[error("invalid correlate: {0}")]
    Correlate(String),
    /// `--vary fit` on a ball without a saved fit, or with options that do not go with it.
    #[error("invalid vary fit: {0}")]
    Fit(String),
    /// An impact without an answer (not the input's fault).
    #[error(transparent)]
    Solve(SolveError),
}

/// `k_p=5%,c=0.05,…`: the parameters and their relative spreads, in [`Varied::ALL`]'s order.
pub fn parse_vary(text: &str) -> Result<Vec<Spread>, McError> {
    use crate::text::parse::refusal;
    let mut out: Vec<Spread> = Vec::new();
    for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let (name, value) = item
            .split_once('=')
            .ok_or_else(|| McError::Syntax(item.into()))?;
        let what = Varied::parse(name).ok_or_else(|| McError::Unknown(name.trim().into()))?;
        let value = value.trim();
        let (number, scale) = match value.strip_suffix('%') {
            Some(v) => (v.trim(), 0.01),
            None => (value, 1.0),
        };
        // the command line's reader (`text::parse`): `1e-400` is refused, never a spread of 0
        let typed = match crate::text::parse::read(number) {
            Ok(x) => x,
            Err(crate::text::parse::Refused::NotANumber) => {
                return Err(McError::Syntax(item.into()));
            }
            Err(why) => return Err(McError::Underflow(what.name(), refusal(number, why))),
        };
        let spread = typed * scale;
        if spread.is_subnormal() || (spread == 0.0 && typed != 0.0) {
            // 1e-307% is 1e-309: held to fewer digits than typed
            let why = crate::text::parse::Refused::Subnormal;
            return Err(McError::Underflow(what.name(), refusal(value, why)));
        }
        if out.iter().any(|s| s.what == what) {
            return Err(McError::Twice(what.name()));
        }
        out.push(Spread { what, spread });
    }
    out.sort_by_key(|s| s.what);
    Ok(out)
}

/// What a Monte Carlo runs: the spreads, their distribution, how many samples, the seed.
#[derive(Debug, Clone, PartialEq)]
pub struct McSpec {
    /// The varied parameters, in [`Varied::ALL`]'s order.
    pub vary: Vec<Spread>,
    /// Their distribution.
    pub dist: Dist,
    /// Number of samples.
    pub samples: usize,
    /// The generator's seed.
    pub seed: u64,
    /// Correlations between the varied parameters (`None`: independent).
    pub correlation: Option<Correlation>,
}

impl McSpec {
    /// A checked spec: at least one parameter and one sample, each spread finite and ≥ 0 (< 1
    /// for `uniform`), no parameter twice. The spreads are put in [`Varied::ALL`]'s order, so
    /// that the order they were given in does not change the samples.
    pub fn new(
        mut vary: Vec<Spread>,
        dist: Dist,
        samples: usize,
        seed: u64,
    ) -> Result<McSpec, McError> {
        if vary.is_empty() {
            return Err(McError::Empty);
        }
        vary.sort_by_key(|s| s.what);
        for (i, s) in vary.iter().enumerate() {
            if !(s.spread.is_finite() && s.spread >= 0.0) {
                return Err(McError::Spread(s.what.name(), s.spread));
            }
            if dist == Dist::Uniform && s.spread >= 1.0 {
                return Err(McError::UniformWide(s.what.name(), s.spread));
            }
            if i > 0 && vary[i - 1].what == s.what {
                return Err(McError::Twice(s.what.name()));
            }
        }
        if samples == 0 {
            return Err(McError::NoSamples);
        }
        Ok(McSpec {
            vary,
            dist,
            samples,
            seed,
            correlation: None,
        })
    }

    /// This spec with the varied parameters correlated by `pairs` (A, B, ρ), the matrix
    /// checked positive definite ([`Correlation::new`]).
    pub fn with_correlation(self, pairs: Vec<(Varied, Varied, f64)>) -> Result<McSpec, McError> {
        let correlation = Some(Correlation::new(&self.vary, pairs)?);
        Ok(McSpec {
            correlation,
            ..self
        })
    }
}

/// A correlation matrix over a spec's varied parameters (in the spec's order) and its
/// Cholesky factor.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlation {
    /// R, row-major, n × n: symmetric, unit diagonal, positive definite.
    pub matrix: Vec<Vec<f64>>,
    /// The pairs as given, (first, second, ρ), for the reports.
    pub pairs: Vec<(Varied, Varied, f64)>,
    /// L, lower triangular, row-major: R = L Lᵀ.
    lower: Vec<Vec<f64>>,
}

impl Correlation {
    /// R over `vary` with the off-diagonal `pairs` set (the rest 0), checked positive
    /// definite by its Cholesky factorization.
    pub fn new(vary: &[Spread], pairs: Vec<(Varied, Varied, f64)>) -> Result<Correlation, McError> {
        let n = vary.len();
        let index = |v: Varied| vary.iter().position(|s| s.what == v);
        let mut r = DMatrix::<f64>::identity(n, n);
        let mut set = vec![vec![false; n]; n];
        for &(a, b, rho) in &pairs {
            let name = || format!("{}:{}", a.name(), b.name());
            let (Some(i), Some(j)) = (index(a), index(b)) else {
                return Err(McError::Correlate(format!(
                    "{} names a parameter not in --vary",
                    name()
                )));
            };
            if i == j {
                return Err(McError::Correlate(format!(
                    "{} correlates a parameter with itself",
                    name()
                )));
            }
            if !(rho.is_finite() && (-1.0..=1.0).contains(&rho)) {
                return Err(McError::Correlate(format!(
                    "{} = {rho}: a correlation lies in [-1, 1]",
                    name()
                )));
            }
            if set[i][j] {
                return Err(McError::Correlate(format!("{} given twice", name())));
            }
            (set[i][j], set[j][i]) = (true, true);
            (r[(i, j)], r[(j, i)]) = (rho, rho);
        }
        let matrix: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| r[(i, j)]).collect())
            .collect();
        let chol = r.cholesky().ok_or_else(|| {
            McError::Correlate(
                "the correlation matrix is not positive definite (no set of parameters can be \
                 correlated so): weaken the correlations"
                    .into(),
            )
        })?;
        let l = chol.l();
        let lower = (0..n)
            .map(|i| (0..n).map(|j| l[(i, j)]).collect())
            .collect();
        Ok(Correlation {
            matrix,
            pairs,
            lower,
        })
    }

    /// y = L z over the first `n` entries of `z`, in place (L lower triangular: from the
    /// last row up, each row reads only entries not yet overwritten).
    pub fn apply(&self, z: &mut [f64]) {
        let n = self.lower.len();
        for i in (0..n).rev() {
            z[i] = (0..=i).map(|j| self.lower[i][j] * z[j]).sum();
        }
    }
}
