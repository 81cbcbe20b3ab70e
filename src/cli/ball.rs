//! Choosing the ball a command runs on: a preset (embedded or user), a `--config` file, or the
//! normalized ball, with the command-line overrides applied and validated.

use crate::ball::Ball;
use crate::catalog::{self, Catalog, Entry, Origin};
use crate::model::contact::ContactLaw;
use crate::model::params::{Field, ImpactParams, check_positive, validate_lambda_zeta};
use crate::preset::ParamSource;
use clap::{Args, ValueEnum};
use serde::Serialize;
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

/// Which preset: by name, or from a file. Declared once, for the top level (the explorer, and
/// `bouncelab --preset golf run`), every subcommand that runs a preset ball, and `presets`.
#[derive(Debug, Clone, Default, Args)]
pub struct PresetChoice {
    /// Preset by name, embedded or user [default: superball]
    #[arg(long, value_name = "NAME", conflicts_with = "config")]
    pub preset: Option<String>,
    /// Preset from a TOML file (same schema as the embedded presets)
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
}

impl PresetChoice {
    /// Whether `--preset` or `--config` was given.
    pub fn is_given(&self) -> bool {
        self.preset.is_some() || self.config.is_some()
    }
}

/// Which preset, and what to change about it.
#[derive(Debug, Clone, Default, Args)]
pub struct BallArgs {
    #[command(flatten)]
    pub choice: PresetChoice,
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
            (Param::KP, Field::KP, self.k_p),
            (Param::C, Field::Damping, self.damping),
            (Param::KR, Field::KR, self.k_r),
            (Param::ZP, Field::ZP, self.z_p),
        ];
        let mut free = Vec::new();
        let mut values = Vec::new();
        for (p, field, v) in given {
            if let Some(v) = v {
                check_positive(field, v)?;
                free.push(p);
                values.push(v);
            }
        }
        *params = apply(params, &free, &values);
        Ok(())
    }
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

/// The ball's keys of a JSON document, in this order (flattened into it).
#[derive(Debug, Serialize)]
pub struct BallHeader<'a> {
    pub preset: Option<&'a str>,
    pub origin: &'a str,
    pub parameters: &'a str,
    pub law: &'static str,
}

/// Where the normalized ball comes from (its `origin`).
const NORMALIZED: &str = "normalized";

/// The ball a command runs on, and where it was chosen from.
#[derive(Debug, Clone)]
pub struct ChosenBall {
    pub ball: Ball,
    /// "embedded", a file path, or "normalized".
    pub origin: String,
    /// The preset's description (empty for the normalized ball).
    pub description: String,
}

impl ChosenBall {
    /// The preset's name; `None` for the normalized ball.
    pub fn preset(&self) -> Option<&str> {
        (self.origin != NORMALIZED).then_some(self.ball.name.as_str())
    }

    /// The keys every JSON document names its ball by.
    pub fn header(&self) -> BallHeader<'_> {
        BallHeader {
            preset: self.preset(),
            origin: &self.origin,
            parameters: &self.ball.source,
            law: self.ball.law.name(),
        }
    }

    /// "superball (embedded, adopted parameters)" or "normalized ball (m = K_p = v0 = 1)".
    pub fn label(&self) -> String {
        match self.preset() {
            Some(n) => format!("{n} ({}, {} parameters)", self.origin, self.ball.source),
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
    /// The preset ball with `--params`, `--law`, `--v0` applied and every parameter checked.
    pub fn resolve(&self, v0: Option<f64>) -> anyhow::Result<ChosenBall> {
        let entry = select(self.choice.preset.as_deref(), self.choice.config.as_deref())?;
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
            if (e.field == Field::V0 && v0.is_some()) || self.set.any() {
                e.into()
            } else {
                anyhow::anyhow!("preset '{}' ({} parameters): {e}", p.name, source.name())
            }
        })?;
        let law = self.law.map_or(p.law, ContactLaw::from);
        Ok(ChosenBall {
            ball: Ball {
                params,
                ..Ball::from_preset(p, source, law)
            },
            origin: match &entry.origin {
                Origin::Embedded => "embedded".into(),
                Origin::File(f) => f.display().to_string(),
            },
            description: p.description.clone(),
        })
    }
}

/// Change λ and/or ζ of a ball: K_r and c move, m and K_p stay (Eq. 24). The library's own
/// check and messages ([`crate::api::set_lambda_zeta`]), so code and command line agree.
pub fn set_lambda_zeta(
    params: &mut ImpactParams,
    lambda: Option<f64>,
    zeta: Option<f64>,
) -> anyhow::Result<()> {
    Ok(crate::api::set_lambda_zeta(params, lambda, zeta)?)
}

/// The normalized ball: m = K_p = v0 = 1; `zp_bar` = ∞ for no flattening.
pub fn normalized(
    lambda: f64,
    zeta: f64,
    zp_bar: Option<f64>,
    law: ContactLaw,
) -> anyhow::Result<ChosenBall> {
    validate_lambda_zeta(lambda, zeta)?;
    if let Some(z) = zp_bar {
        check_positive(Field::ZpBar, z)?;
    }
    let params = ImpactParams::from_normalized(lambda, zeta, zp_bar.unwrap_or(f64::INFINITY));
    params.validate()?;
    Ok(ChosenBall {
        ball: Ball {
            name: "ball".into(),
            source: NORMALIZED.into(),
            params,
            law,
            measured: None,
        },
        origin: NORMALIZED.into(),
        description: String::new(),
    })
}
