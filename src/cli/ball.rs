//! Choosing the ball a command runs on: a preset (embedded or user), a `--config` file, or the
//! normalized ball, with the command-line overrides applied and validated.

use crate::catalog::{self, Catalog, Entry};
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, ParamError};
use crate::preset::ParamSource;
use crate::solver::SolveError;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};

/// The name used when no preset is asked for.
pub const DEFAULT_PRESET: &str = "superball";

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LawArg {
    Linear,
    ElasticPlastic,
    Hertz,
}

impl From<LawArg> for ContactLaw {
    fn from(l: LawArg) -> ContactLaw {
        match l {
            LawArg::Linear => ContactLaw::Linear,
            LawArg::ElasticPlastic => ContactLaw::ElasticPlastic,
            LawArg::Hertz => ContactLaw::Hertz,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SourceArg {
    Adopted,
    Materials,
}

impl From<SourceArg> for ParamSource {
    fn from(s: SourceArg) -> ParamSource {
        match s {
            SourceArg::Adopted => ParamSource::Adopted,
            SourceArg::Materials => ParamSource::Materials,
        }
    }
}

/// Which preset, and what to change about it.
#[derive(Debug, Clone, Default, Args)]
pub struct BallArgs {
    /// Preset by name, embedded or user [default: superball]
    #[arg(long, value_name = "NAME", conflicts_with = "config")]
    pub preset: Option<String>,
    /// Preset from a TOML file (same schema as the embedded presets)
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Parameter set of the preset [default: the preset's `parameters` field]
    #[arg(long, value_enum, value_name = "SET")]
    pub params: Option<SourceArg>,
    /// Contact law [default: the preset's `law` field]
    #[arg(long, value_enum)]
    pub law: Option<LawArg>,
}

/// A ball ready to simulate: the library's (`crate::ball`), which holds the checks and
/// messages the command line shows.
pub use crate::ball::Ball;

/// The catalog: embedded presets, the user's presets folder, and `config` if given.
/// A `--config` file that cannot be read is named as such.
pub fn load_catalog(config: Option<&Path>) -> anyhow::Result<Catalog> {
    Catalog::load(catalog::user_presets_dir().as_deref(), config).map_err(|e| match e {
        catalog::CatalogError::Io { path, message } if Some(path.as_path()) == config => {
            anyhow::anyhow!("--config {}: {message}", path.display())
        }
        e => e.into(),
    })
}

/// The preset entry chosen by `--preset` / `--config` (default: superball).
pub fn select(preset: Option<&str>, config: Option<&Path>) -> anyhow::Result<Entry> {
    let cat = load_catalog(config)?;
    let entry = match config {
        Some(path) => cat
            .from_file(path)
            .ok_or_else(|| anyhow::anyhow!("{}: not loaded", path.display()))?,
        None => cat.get(preset.unwrap_or(DEFAULT_PRESET))?,
    };
    Ok(entry.clone())
}

impl BallArgs {
    /// The preset ball with `--params`, `--law`, `--v0` applied and every parameter checked.
    pub fn resolve(&self, v0: Option<f64>) -> anyhow::Result<Ball> {
        let entry = select(self.preset.as_deref(), self.config.as_deref())?;
        Ok(Ball::from_entry(
            &entry,
            self.params.map(ParamSource::from),
            self.law.map(ContactLaw::from),
            v0,
        )?)
    }
}

/// Change λ and/or ζ of a ball: K_r and c move, m and K_p stay (Eq. 24).
pub fn set_lambda_zeta(
    params: &mut ImpactParams,
    lambda: Option<f64>,
    zeta: Option<f64>,
) -> anyhow::Result<()> {
    Ok(crate::ball::set_lambda_zeta(params, lambda, zeta)?)
}

/// The normalized ball: m = K_p = v0 = 1; `zp_bar` = ∞ for no flattening.
pub fn normalized(
    lambda: f64,
    zeta: f64,
    zp_bar: Option<f64>,
    law: ContactLaw,
) -> anyhow::Result<Ball> {
    Ok(Ball::normalized(lambda, zeta, zp_bar, law)?)
}

/// "invalid zeta: NaN (not a number)", with large and small values in exponent form.
pub fn param_message(e: &ParamError) -> String {
    e.to_string()
}

/// A solver error for the user: bad parameters are bad input (exit 2); an impact the solver
/// could not bring to an end within its budgets is not the user's fault (exit 1).
pub fn solve_error(e: SolveError) -> anyhow::Error {
    match e {
        SolveError::Param(p) => anyhow::anyhow!(param_message(&p)),
        e @ SolveError::Unresolved { .. } => super::Runtime(anyhow::anyhow!(e.to_string())).into(),
    }
}

/// A library error for the user: an impact without an answer is not the user's fault (exit 1),
/// anything else is bad input (exit 2).
pub fn ball_error(e: crate::ball::BallError) -> anyhow::Error {
    match e {
        crate::ball::BallError::Solve(e) => solve_error(e),
        e => e.into(),
    }
}

/// A finite, positive, not absurd number, or an error naming `field`.
pub fn check_positive(field: &'static str, value: f64) -> anyhow::Result<()> {
    crate::model::params::check_positive(field, value).map_err(|e| anyhow::anyhow!(e.to_string()))
}
