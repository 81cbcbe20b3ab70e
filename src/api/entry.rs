//! A preset ball with the caller's choices applied: parameter set, contact law, speed and
//! parameter overrides — what the command line's `--params`, `--law`, `--v0`, `--mass`,
//! `--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p` choose, checked here once for the command
//! line, the explorer's exports and the Python package.
//!
//! `--mass` and `--radius` replace the preset's measured m and R, the ball its parameter set is
//! derived from (docs/presets.md, "Mass and radius"): with the adopted set m is the model's mass
//! (K_p, c, K_r, z_p, K_h stay: λ stays, ζ = √(m K_p)/(2c) moves) and R enters no parameter
//! (K_h is Eq. 16's) but what reads the ball's size — air drag and buoyancy (`drop`), the
//! peers' radius (`peers`, the exports' k_n = K_h/√R), the check z_m < R; with the materials
//! set everything derived from m and R follows as well: the density when not given, K_h
//! (Eq. 8), z_p and K_p (Eqs. 15–20), c (Eq. 5).

use super::{Ball, BallError};
use crate::analysis::fit::{Param, apply};
use crate::catalog::{Entry, Origin};
use crate::model::contact::ContactLaw;
use crate::model::params::{Field, ImpactParams, check_positive, check_range};
use crate::preset::{ParamSource, Preset};

/// Parameters set over a preset's, SI units (`None` keeps the preset's), so that a fitted ball
/// can be tried without editing its TOML. K_h follows K_p and z_p (Eq. 16) when either is set.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// Mass m, kg (the preset's measured mass replaced; see the module docs).
    pub mass: Option<f64>,
    /// Radius R, m (the preset's measured radius replaced; see the module docs).
    pub radius: Option<f64>,
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
    /// A derived quantity out of range (ζ, λ, z̄_p, K_h) named by the override the user gave
    /// that moves it, its own parameter first (ζ = √(m K_p)/(2c): c, else m, else K_p), so
    /// that `--mass 1e15` is refused as "invalid mass" and `--k-p 1e15` as "invalid k_p"
    /// (tests/cli/field_names.rs). `None` when no override moves it.
    fn blamed(&self, e: &crate::model::params::ParamError) -> Option<BallError> {
        let suspects: &[(&'static str, Option<f64>)] = match e.field {
            Field::Zeta => &[
                ("damping", self.damping),
                ("mass", self.mass),
                ("k_p", self.k_p),
            ],
            Field::Lambda => &[("k_r", self.k_r), ("k_p", self.k_p)],
            Field::ZpBar => &[("z_p", self.z_p), ("mass", self.mass), ("k_p", self.k_p)],
            Field::KH => &[
                ("k_p", self.k_p),
                ("z_p", self.z_p),
                ("radius", self.radius),
            ],
            _ => return None,
        };
        let (field, value) = suspects.iter().find_map(|&(f, v)| Some((f, v?)))?;
        let group = e.field.as_str();
        // four significant figures: "gives zeta = 2.670e6", not 2670176.9136145264
        let derived = crate::text::human(e.value, 4);
        Some(BallError::Invalid {
            field,
            value,
            reason: format!("gives {group} = {derived}: {}", e.reason),
        })
    }

    /// Whether any value is set.
    pub fn any(&self) -> bool {
        self.mass.is_some() || self.radius.is_some() || self.parameters()
    }

    /// Whether any of K_p, c, K_r, z_p is set.
    pub fn parameters(&self) -> bool {
        self.k_p.is_some() || self.damping.is_some() || self.k_r.is_some() || self.z_p.is_some()
    }

    /// The names of the values set, in the order of the JSON `ball.overrides` (docs/cli.md).
    pub fn names(&self) -> Vec<String> {
        [
            ("mass", self.mass.is_some()),
            ("radius", self.radius.is_some()),
            ("k_p", self.k_p.is_some()),
            ("c", self.damping.is_some()),
            ("k_r", self.k_r.is_some()),
            ("z_p", self.z_p.is_some()),
        ]
        .into_iter()
        .filter(|(_, set)| *set)
        .map(|(n, _)| n.to_string())
        .collect()
    }

    /// `preset` with the mass and radius given as its measured ones, each checked and named.
    pub fn sized(&self, preset: &Preset) -> Result<Preset, BallError> {
        let mut p = preset.clone();
        if let Some(m) = self.mass {
            check_positive(Field::Mass, m)?;
            p.measured.mass = m;
        }
        if let Some(r) = self.radius {
            check_positive(Field::Radius, r)?;
            p.measured.radius = r;
        }
        Ok(p)
    }

    /// The values set on `params` (m included; R is no parameter, [`Overrides::sized`] sets
    /// it); each checked (finite, positive, in 1e-15 … 1e15; K_r also 0, the ball with no
    /// recoil spring that λ = 0 and a preset's `k_r = 0` give, which [`ImpactParams::validate`]
    /// takes) and named by its field, `params` unchanged on an error.
    pub fn apply(&self, params: &mut ImpactParams) -> Result<(), BallError> {
        if let Some(m) = self.mass {
            check_positive(Field::Mass, m)?;
        }
        let given = [
            (Param::KP, Field::KP, self.k_p, false),
            (Param::C, Field::Damping, self.damping, false),
            (Param::KR, Field::KR, self.k_r, true),
            (Param::ZP, Field::ZP, self.z_p, false),
        ];
        let mut free = Vec::new();
        let mut values = Vec::new();
        for (p, field, v, zero) in given {
            if let Some(v) = v {
                check_range(field, v, zero, false)?;
                free.push(p);
                values.push(v);
            }
        }
        *params = apply(params, &free, &values);
        if let Some(m) = self.mass {
            params.mass = m;
        }
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
        // the preset itself unless a mass or radius replaces its measured one: a clone of its
        // strings and tables costs Python's `run` more than its closed form (BENCHMARKS.md)
        let resized;
        let p = if overrides.mass.is_some() || overrides.radius.is_some() {
            resized = overrides.sized(&entry.preset)?;
            &resized
        } else {
            &entry.preset
        };
        let source = source.unwrap_or(p.parameters);
        let mut params = p.params_from(source);
        if let Some(v0) = v0 {
            params.v0 = v0;
        }
        overrides.apply(&mut params)?;
        params.validate().map_err(|error| {
            // a bad v0 or an overridden value comes from the caller; anything else from the
            // preset's set
            if let Some(named) = overrides.blamed(&error) {
                named
            } else if (error.field == Field::V0 && v0.is_some()) || overrides.any() {
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
            // the table describes the fit's ball: its adopted set under its law
            fit: p
                .fit
                .clone()
                .filter(|_| source == ParamSource::Adopted && law.is_none_or(|l| l == p.law)),
            poisson_ratio: Some(p.material.poisson),
            calibration: p.calibration.clone().map(|mut c| {
                let law = law.filter(|&l| l != p.law);
                c.other_model = match (source != p.parameters, law) {
                    (true, Some(l)) => Some(format!("the {} set on the {l} law", source.name())),
                    (true, None) => Some(format!("the {} set", source.name())),
                    (false, Some(l)) => Some(format!("the {l} law")),
                    (false, None) => None,
                };
                c
            }),
            overrides: overrides.names(),
            conditions: super::recorded_conditions(p.calibration.as_ref()),
            flight_model: p.flight_model(),
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

/// One preset as `bouncelab presets --format json` lists it (the Python package's
/// `presets()` too): its name, where it comes from, its law and set, the λ and ζ it runs at,
/// its measured speed and radius, ν, κ and its `[calibration]` record.
#[derive(Debug, Clone, serde::Serialize)]
pub struct PresetRow {
    /// The preset's name.
    pub name: String,
    /// `"embedded"` or the file it was read from.
    pub origin: String,
    /// What the preset is.
    pub description: String,
    /// The contact law's name.
    pub law: &'static str,
    /// The parameter set's name.
    pub parameters: &'static str,
    /// λ = K_r/K_p.
    pub lambda: f64,
    /// ζ = √(m K_p)/(2c).
    pub zeta: f64,
    /// The speed it was measured at, m/s.
    pub v0: f64,
    /// R, m.
    pub radius: f64,
    /// ν of its material.
    pub poisson_ratio: f64,
    /// κ = I/(m R²): the preset's, or a solid ball's 0.4.
    pub inertia_factor: f64,
    /// The `[calibration]` record (`null` for a preset without one).
    pub calibration: Option<crate::preset::Calibration>,
    /// The published flight model the ball flies on (docs/flight.md §2): its `aerodynamics`,
    /// or the model named like it; `null` for neither (the assumed smooth sphere).
    pub aerodynamics: Option<&'static str>,
}

impl PresetRow {
    /// The row of a catalog entry.
    pub fn of(e: &Entry) -> PresetRow {
        let p = &e.preset;
        let n = p.params().normalized();
        PresetRow {
            name: p.name.clone(),
            origin: match &e.origin {
                Origin::Embedded => "embedded".into(),
                Origin::File(f) => f.display().to_string(),
            },
            description: p.description.clone(),
            law: p.law.name(),
            parameters: p.parameters.name(),
            lambda: n.lambda,
            zeta: n.zeta,
            v0: p.measured.v0,
            radius: p.measured.radius,
            poisson_ratio: p.material.poisson,
            inertia_factor: p
                .measured
                .inertia_factor
                .unwrap_or(super::SOLID_INERTIA_FACTOR),
            calibration: p.calibration.clone(),
            aerodynamics: p.flight_model().map(|m| m.name()),
        }
    }
}
