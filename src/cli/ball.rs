//! Choosing the ball a command runs on: a preset (embedded or user), a `--config` file, or the
//! normalized ball, with the command-line overrides applied and validated.

use crate::api::{self, Ball};
use crate::catalog::{self, Catalog, Entry};
use crate::model::contact::ContactLaw;
use crate::preset::ParamSource;
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
    #[command(flatten)]
    pub changes: PresetChanges,
    /// `--pressure`, `--temperature`, `--inflated-at`, `--after`, `--half-life`.
    #[command(flatten)]
    pub conditions: super::conditions::ConditionsArgs,
}

/// What to change about a preset: its parameter set, its contact law and its parameters.
/// Declared once, for every command that runs a preset ball and for `figure`'s balls.
#[derive(Debug, Clone, Default, Args)]
pub struct PresetChanges {
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
/// without editing TOML. K_h follows K_p and z_p (Eq. 16) when either is set; `--mass` and
/// `--radius` replace the measured m and R the parameter set is derived from
/// ([`api::Overrides`]).
#[derive(Debug, Clone, Default, Args)]
pub struct Overrides {
    #[command(flatten)]
    pub size: Size,
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

/// The ball's mass and radius over the preset's measured ones (every command that takes a
/// ball, `map` included).
#[derive(Debug, Clone, Default, Args)]
pub struct Size {
    /// Mass m, kg [default: the preset's measured mass]
    #[arg(long, value_name = "kg", value_parser = super::number::number, allow_hyphen_values = true)]
    pub mass: Option<f64>,
    /// Radius R, m: air drag, the peers' radius, z_m < R; K_h etc. with --params materials [default: the preset's]
    #[arg(long, value_name = "m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub radius: Option<f64>,
}

impl PresetChanges {
    /// The first of these options given (`--params`, `--law`, then the overrides), as a
    /// command that takes none names it.
    pub fn first_given(&self) -> Option<&'static str> {
        let s = &self.set;
        [
            ("--params", self.params.is_some()),
            ("--law", self.law.is_some()),
            ("--mass", s.size.mass.is_some()),
            ("--radius", s.size.radius.is_some()),
            ("--k-p", s.k_p.is_some()),
            ("--damping", s.damping.is_some()),
            ("--k-r", s.k_r.is_some()),
            ("--z-p", s.z_p.is_some()),
        ]
        .into_iter()
        .find_map(|(flag, given)| given.then_some(flag))
    }
}

impl Overrides {
    /// The values given, for the library to apply and check ([`api::Overrides`]).
    pub fn values(&self) -> api::Overrides {
        api::Overrides {
            mass: self.size.mass,
            radius: self.size.radius,
            k_p: self.k_p,
            damping: self.damping,
            k_r: self.k_r,
            z_p: self.z_p,
        }
    }

    /// Whether any of `--mass`, `--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p` was given.
    pub fn any(&self) -> bool {
        self.values().any()
    }
}

/// `--k-r` with `--lambda`, or `--damping` with `--zeta`, set one parameter twice.
fn check_overrides(set: &Overrides, lambda: Option<f64>, zeta: Option<f64>) -> anyhow::Result<()> {
    if set.k_r.is_some() && lambda.is_some() {
        anyhow::bail!("--k-r and --lambda both set K_r: give one of them");
    }
    if set.damping.is_some() && zeta.is_some() {
        anyhow::bail!("--damping and --zeta both set c: give one of them");
    }
    Ok(())
}

/// The catalog: embedded presets, the user's presets folder, and `config` if given.
/// A `--config` file that cannot be read is named as such.
pub fn load_catalog(config: Option<&Path>) -> anyhow::Result<Catalog> {
    let cat = load_catalog_quietly(config)?;
    warn_skipped(cat.skipped(), None);
    Ok(cat)
}

/// [`load_catalog`] without the warnings of what the presets folder skipped.
fn load_catalog_quietly(config: Option<&Path>) -> anyhow::Result<Catalog> {
    Catalog::load(catalog::user_presets_dir().as_deref(), config).map_err(|e| match e {
        catalog::CatalogError::Io { path, message } if Some(path.as_path()) == config => {
            anyhow::anyhow!("--config {}: {message}", path.display())
        }
        e => e.into(),
    })
}

/// The presets folder's links that lead nowhere and files that cannot be read, each named once
/// a run on stderr as a warning (a command may load the catalog more than once); not `asked`,
/// the file whose error the command ends with.
fn warn_skipped(skipped: &[catalog::Skipped], asked: Option<&catalog::Skipped>) {
    static WARNED: std::sync::Once = std::sync::Once::new();
    let lines: Vec<String> = skipped
        .iter()
        .filter(|s| asked != Some(*s))
        .map(catalog::Skipped::message)
        .collect();
    if lines.is_empty() {
        return;
    }
    WARNED.call_once(|| super::output::warnings_to_stderr(&lines));
}

/// The preset entry chosen by `--preset` / `--config` (default: superball). A bad file of the
/// presets folder holding the preset asked for is the error, not a warning.
pub fn select(preset: Option<&str>, config: Option<&Path>) -> anyhow::Result<Entry> {
    let cat = load_catalog_quietly(config)?;
    let name = preset.unwrap_or(DEFAULT_PRESET);
    let asked = config.is_none().then(|| cat.skipped_for(name)).flatten();
    warn_skipped(cat.skipped(), asked);
    let entry = match config {
        Some(path) => cat
            .from_file(path)
            .ok_or_else(|| anyhow::anyhow!("{}: not loaded", path.display()))?,
        None => cat.get(preset.unwrap_or(DEFAULT_PRESET))?,
    };
    Ok(entry.clone())
}

impl BallArgs {
    /// The first ball option given, as a command that takes no ball names it.
    pub fn first_given(&self) -> Option<&'static str> {
        let c = &self.conditions;
        let chosen = [
            ("--preset", self.choice.preset.is_some()),
            ("--config", self.choice.config.is_some()),
        ];
        let conditions = [
            ("--pressure", c.pressure.is_some()),
            ("--temperature", c.temperature.is_some()),
            ("--inflated-at", c.inflated_at.is_some()),
            ("--after", c.after.is_some()),
            ("--half-life", c.half_life.is_some()),
        ];
        let first = |flags: &[(&'static str, bool)]| {
            flags
                .iter()
                .find_map(|&(flag, given)| given.then_some(flag))
        };
        first(&chosen)
            .or_else(|| self.changes.first_given())
            .or_else(|| first(&conditions))
    }

    /// The preset ball with `--params`, `--law`, `--v0` and the overrides applied, every
    /// parameter checked by the library ([`Ball::from_entry_with`]).
    pub fn resolve(&self, v0: Option<f64>) -> anyhow::Result<Ball> {
        let entry = select(self.choice.preset.as_deref(), self.choice.config.as_deref())?;
        let source = self.changes.params.map(ParamSource::from);
        let law = self.changes.law.map(ContactLaw::from);
        let ball = Ball::from_entry_with(&entry, source, law, v0, &self.changes.set.values())?;
        Ok(ball.at_conditions(&self.conditions.spec())?)
    }

    /// [`BallArgs::resolve`] with `standard_ball` as the preset when neither `--preset` nor
    /// `--config` is given: a test-rig command (`bat`, `court`) fires the ball of the standard
    /// it judges by default (its `balls[0]`, as `bouncelab standards` names it).
    pub fn resolve_for_standard(&self, standard_ball: &str) -> anyhow::Result<Ball> {
        let mut args = self.clone();
        if !args.choice.is_given() {
            args.choice.preset = Some(standard_ball.into());
        }
        args.resolve(None)
    }

    /// [`BallArgs::resolve`], then λ and/or ζ changed: K_r and c move, m and K_p stay (Eq. 24),
    /// by the library's own check and messages ([`crate::api::set_lambda_zeta`]), so code and
    /// command line agree. Each given is an override of the preset's ball (`ball.overrides`:
    /// `lambda`, `zeta`). `--k-r` with `--lambda`, or `--damping` with `--zeta`, is refused
    /// before the preset is read.
    pub fn resolve_tuned(
        &self,
        v0: Option<f64>,
        lambda: Option<f64>,
        zeta: Option<f64>,
    ) -> anyhow::Result<Ball> {
        check_overrides(&self.changes.set, lambda, zeta)?;
        let ball = self.resolve(v0)?;
        // `--zeta` beside a temperature that shifts c is refused by the library, as Python's
        // `run(zeta=…)` is (tests/physics/conditions_bounds.rs, the_documented_pairs_are_refused)
        Ok(ball.with_lambda_zeta_at(self.conditions.temperature, lambda, zeta)?)
    }
}
