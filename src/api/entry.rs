//! A preset ball with the caller's choices applied: parameter set, contact law, speed and
//! parameter overrides — what the command line's `--params`, `--law`, `--v0`, `--k-p`,
//! `--damping`, `--k-r`, `--z-p` choose, checked here once for the command line, the explorer's
//! exports and the Python package.

use super::{Ball, BallError};
use crate::analysis::fit::{Param, apply};
use crate::catalog::{Entry, Origin};
use crate::model::contact::ContactLaw;
use crate::model::params::{Field, ImpactParams, check_positive};
use crate::preset::ParamSource;

/// Parameters set over a preset's, SI units (`None` keeps the preset's), so that a fitted ball
/// can be tried without editing its TOML. K_h follows K_p and z_p (Eq. 16) when either is set.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// Contact stiffness K_p, N/m.
    pub k_p: Option<f64>,
    /// Dashpot c, kg/s.
    pub damping: Option<f64>,
    /// Recoil spring K_r, N/m.
    pub k_r: Option<f64>,
    /// Flattening threshold z_p, m.
    pub z_p: Option<f64>,
}

impl Overrides {
    /// Whether any value is set.
    pub fn any(&self) -> bool {
        self.k_p.is_some() || self.damping.is_some() || self.k_r.is_some() || self.z_p.is_some()
    }

    /// The values set on `params`; each checked (finite, positive, in 1e-15 … 1e15) and named
    /// by its field, `params` unchanged on an error.
    pub fn apply(&self, params: &mut ImpactParams) -> Result<(), BallError> {
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

impl Ball {
    /// A catalog entry with a parameter set, a contact law, a speed (each `None` keeps the
    /// preset's) and parameter overrides applied, every parameter checked: as the command line
    /// builds its ball. A bad `v0`, or any bad parameter once overrides are given, is named as
    /// the caller's; any other parameter out of its domain is the preset's, and the error names
    /// the preset.
    pub fn from_entry_with(
        entry: &Entry,
        source: Option<ParamSource>,
        law: Option<ContactLaw>,
        v0: Option<f64>,
        overrides: &Overrides,
    ) -> Result<Ball, BallError> {
        let p = &entry.preset;
        let source = source.unwrap_or(p.parameters);
        let mut params = p.params_from(source);
        if let Some(v0) = v0 {
            params.v0 = v0;
        }
        overrides.apply(&mut params)?;
        params.validate().map_err(|error| {
            // a bad v0 or an overridden value comes from the caller; anything else from the
            // preset's set
            if (error.field == Field::V0 && v0.is_some()) || overrides.any() {
                BallError::Param(error)
            } else {
                BallError::Preset {
                    name: p.name.clone(),
                    source: source.name(),
                    error,
                }
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
            law: law.unwrap_or(p.law),
            measured: Some(p.measured.clone()),
            description: p.description.clone(),
        })
    }

    /// The ball as a drop test takes it ([`crate::drop::DropBall`]): its parameters, law and
    /// the preset's measured radius (NaN for a ball that is no preset: give such a ball no
    /// air, or use [`crate::drop::drop`] with a radius).
    pub fn drop_ball(&self) -> crate::drop::DropBall {
        crate::drop::DropBall {
            params: self.params,
            law: self.law,
            radius: self.measured.as_ref().map_or(f64::NAN, |m| m.radius),
        }
    }

    /// The plain ball record the figures and the explorer draw ([`crate::ball::Ball`]): the
    /// same parameters, law and measurements; a ball that is no preset is named `"ball"`.
    pub fn record(&self) -> crate::ball::Ball {
        crate::ball::Ball {
            name: self.name.clone().unwrap_or_else(|| "ball".into()),
            source: self.source.into(),
            params: self.params,
            law: self.law,
            measured: self.measured.clone(),
        }
    }
}
