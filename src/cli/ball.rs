//! Choosing the ball a command runs on: a preset (embedded or user), a `--config` file, or the
//! normalized ball, with the command-line overrides applied and validated.

use crate::catalog::{self, Catalog, Entry, Origin};
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, ParamError, validate_lambda_zeta};
use crate::preset::{Measured, ParamSource};
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
    /// Preset by name, embedded or user [default: superball]; `figure` takes several
    #[arg(long, value_name = "NAME", conflicts_with = "config", action = clap::ArgAction::Append)]
    pub preset: Vec<String>,
    /// Preset from a TOML file (same schema as the embedded presets)
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Parameter set of the preset [default: the preset's `parameters` field]
    #[arg(long, value_enum, value_name = "SET")]
    pub params: Option<SourceArg>,
    /// Contact law [default: the preset's `law` field]
    #[arg(long, value_enum)]
    pub law: Option<LawArg>,
    #[command(flatten)]
    pub set: Overrides,
}

/// Parameters set on the command line over the preset's, so that a fitted ball can be tried
/// without editing TOML. K_h follows K_p and z_p (Eq. 16) when either is set.
#[derive(Debug, Clone, Default, Args)]
pub struct Overrides {
    /// Contact stiffness K_p, N/m [default: the preset's]
    #[arg(long = "k-p", value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub k_p: Option<f64>,
    /// Dashpot c, kg/s [default: the preset's]
    #[arg(long, value_name = "kg/s", value_parser = super::number::number, allow_hyphen_values = true)]
    pub damping: Option<f64>,
    /// Recoil spring K_r, N/m [default: the preset's]
    #[arg(long = "k-r", value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub k_r: Option<f64>,
    /// Flattening threshold z_p, m [default: the preset's]
    #[arg(long = "z-p", value_name = "m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub z_p: Option<f64>,
}

impl Overrides {
    pub fn any(&self) -> bool {
        self.k_p.is_some() || self.damping.is_some() || self.k_r.is_some() || self.z_p.is_some()
    }

    /// The given values set on `params`; each checked, named by its field.
    pub fn apply(&self, params: &mut ImpactParams) -> anyhow::Result<()> {
        use crate::analysis::fit::{Param, apply};
        let given = [
            (Param::KP, "k_p", self.k_p),
            (Param::C, "damping", self.damping),
            (Param::KR, "k_r", self.k_r),
            (Param::ZP, "z_p", self.z_p),
        ];
        let mut free = Vec::new();
        let mut values = Vec::new();
        for (p, field, v) in given {
            if let Some(v) = v {
                crate::model::params::check_positive(field, v)
                    .map_err(|e| anyhow::anyhow!(param_message(&e)))?;
                free.push(p);
                values.push(v);
            }
        }
        *params = apply(params, &free, &values);
        Ok(())
    }
}

/// A ball ready to simulate.
#[derive(Debug, Clone)]
pub struct Ball {
    /// Preset name; `None` for the normalized ball.
    pub name: Option<String>,
    /// "embedded", a file path, or "normalized".
    pub origin: String,
    /// "adopted", "materials" or "normalized".
    pub source: &'static str,
    pub params: ImpactParams,
    pub law: ContactLaw,
    /// What was measured, for comparison (presets only).
    pub measured: Option<Measured>,
    pub description: String,
}

impl Ball {
    /// "superball (embedded, adopted parameters)" or "normalized ball (m = K_p = v0 = 1)".
    pub fn label(&self) -> String {
        match &self.name {
            Some(n) => format!("{n} ({}, {} parameters)", self.origin, self.source),
            None => "normalized ball (m = K_p = v0 = 1)".into(),
        }
    }
}

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
    /// The one preset asked for (`None`: the default); only `figure` takes several.
    pub fn preset(&self) -> anyhow::Result<Option<&str>> {
        match self.preset.as_slice() {
            [] => Ok(None),
            [one] => Ok(Some(one)),
            [first, ..] => anyhow::bail!(
                "--preset given {} times: this command runs one ball ({first})",
                self.preset.len()
            ),
        }
    }

    /// The preset ball with `--params`, `--law`, `--v0` applied and every parameter checked.
    pub fn resolve(&self, v0: Option<f64>) -> anyhow::Result<Ball> {
        let entry = select(self.preset()?, self.config.as_deref())?;
        let p = &entry.preset;
        let source = self.params.map_or(p.parameters, ParamSource::from);
        let mut params = p.params_from(source);
        if let Some(v0) = v0 {
            params.v0 = v0;
        }
        self.set.apply(&mut params)?;
        params.validate().map_err(|e| {
            // a bad v0 or an overridden value comes from the command line; anything else from
            // the preset's set
            if (e.field == "v0" && v0.is_some()) || self.set.any() {
                anyhow::anyhow!(param_message(&e))
            } else {
                anyhow::anyhow!(
                    "preset '{}' ({} parameters): {}",
                    p.name,
                    source.name(),
                    param_message(&e)
                )
            }
        })?;
        Ok(Ball {
            name: Some(p.name.clone()),
            origin: match &entry.origin {
                Origin::Embedded => "embedded".into(),
                Origin::File(f) => f.display().to_string(),
            },
            source: source.name(),
            params,
            law: self.law.map_or(p.law, ContactLaw::from),
            measured: Some(p.measured.clone()),
            description: p.description.clone(),
        })
    }
}

/// Change λ and/or ζ of a ball: K_r and c move, m and K_p stay (Eq. 24).
pub fn set_lambda_zeta(
    params: &mut ImpactParams,
    lambda: Option<f64>,
    zeta: Option<f64>,
) -> anyhow::Result<()> {
    validate_lambda_zeta(lambda.unwrap_or(0.0), zeta.unwrap_or(0.0))
        .map_err(|e| anyhow::anyhow!(param_message(&e)))?;
    let moved = params.with_lambda_zeta(lambda.unwrap_or(0.0), zeta.unwrap_or(1.0));
    if lambda.is_some() {
        params.k_r = moved.k_r;
    }
    if zeta.is_some() {
        params.damping = moved.damping;
    }
    // name what the user typed when the K_r or c it gives is out of range
    params.validate().map_err(|e| {
        let given = match e.field {
            "k_r" => lambda.map(|l| ("lambda", l, "K_r", "N/m")),
            "damping" => zeta.map(|z| ("zeta", z, "c", "kg/s")),
            _ => None,
        };
        match given {
            Some((field, v, name, unit)) => anyhow::anyhow!(
                "invalid {field}: {} (gives {name} = {} {unit}: {})",
                super::output::num(v),
                super::output::num(e.value),
                e.reason
            ),
            None => anyhow::anyhow!(param_message(&e)),
        }
    })
}

/// `--k-r` with `--lambda`, or `--damping` with `--zeta`, set one parameter twice.
pub fn check_overrides(
    set: &Overrides,
    lambda: Option<f64>,
    zeta: Option<f64>,
) -> anyhow::Result<()> {
    if set.k_r.is_some() && lambda.is_some() {
        anyhow::bail!("--k-r and --lambda both set K_r: give one of them");
    }
    if set.damping.is_some() && zeta.is_some() {
        anyhow::bail!("--damping and --zeta both set c: give one of them");
    }
    Ok(())
}

/// The normalized ball: m = K_p = v0 = 1; `zp_bar` = ∞ for no flattening.
pub fn normalized(
    lambda: f64,
    zeta: f64,
    zp_bar: Option<f64>,
    law: ContactLaw,
) -> anyhow::Result<Ball> {
    validate_lambda_zeta(lambda, zeta).map_err(|e| anyhow::anyhow!(param_message(&e)))?;
    if let Some(z) = zp_bar {
        check_positive("zp_bar", z)?;
    }
    let params = ImpactParams::from_normalized(lambda, zeta, zp_bar.unwrap_or(f64::INFINITY));
    params
        .validate()
        .map_err(|e| anyhow::anyhow!(param_message(&e)))?;
    Ok(Ball {
        name: None,
        origin: "normalized".into(),
        source: "normalized",
        params,
        law,
        measured: None,
        description: String::new(),
    })
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

/// A finite, positive, not absurd number, or an error naming `field`.
pub fn check_positive(field: &'static str, value: f64) -> anyhow::Result<()> {
    crate::model::params::check_positive(field, value).map_err(|e| anyhow::anyhow!(e.to_string()))
}
