//! Ball presets: measured data, material data and the parameters the paper adopted
//! (docs/model.md §7), in a TOML schema documented in the README. Parsing only: no file I/O here.

use crate::flight::published::Published;
use crate::model::contact::ContactLaw;
use crate::model::materials::{self, Layer};
use crate::model::params::ImpactParams;
use serde::{Deserialize, Serialize};

mod calibration;
mod fit_table;
mod outputs;
mod text;
mod usable;

pub use calibration::{Calibration, CalibrationData, SPEED_SLACK, TemperatureShift};
pub use fit_table::FitTable;
pub use outputs::{Output, words as output_words};

/// The three balls of the paper, embedded in the binary, first; then the balls of the drop
/// tests (docs/drop.md, "The new balls").
pub const EMBEDDED: [(&str, &str); 13] = [
    ("superball", include_str!("../presets/superball.toml")),
    ("golf", include_str!("../presets/golf.toml")),
    ("baseball", include_str!("../presets/baseball.toml")),
    ("tennis", include_str!("../presets/tennis.toml")),
    ("football", include_str!("../presets/football.toml")),
    ("basketball", include_str!("../presets/basketball.toml")),
    ("table-tennis", include_str!("../presets/table-tennis.toml")),
    ("softball", include_str!("../presets/softball.toml")),
    // balls that pass the standards the paper's cannot (issue 52: Cross's baseball is no MLB
    // ball), docs/presets.md
    ("baseball-mlb", include_str!("../presets/baseball-mlb.toml")),
    ("softball-44", include_str!("../presets/softball-44.toml")),
    // issue 56: the WSF squash ball (with its temperature shift) and the FIVB volleyball
    ("squash", include_str!("../presets/squash.toml")),
    ("volleyball", include_str!("../presets/volleyball.toml")),
    // issue 52: a golf ball fitted to a published fall of COR with speed (docs/presets.md)
    ("golf-driver", include_str!("../presets/golf-driver.toml")),
];

/// How many of [`EMBEDDED`] are the paper's balls.
pub const PAPER_BALLS: usize = 3;

fn parse_embedded(list: &[(&str, &str)]) -> Vec<Preset> {
    list.iter()
        .map(|(name, text)| {
            Preset::parse(text, &format!("embedded:{name}")).expect("embedded presets are tested")
        })
        .collect()
}

/// Which parameter set the model runs on.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ParamSource {
    /// The set the paper adopted (the default: it is what the paper ran).
    #[default]
    Adopted,
    /// c, z_p, K_p, K_h derived from the material data (Eqs. 5, 8, 15–20, 30–31); K_r, which
    /// no formula gives, from the adopted (fitted) set.
    Materials,
}

impl ParamSource {
    /// The set's name as the TOML, the command line (`--params`) and the JSON write it:
    /// `"adopted"` or `"materials"`.
    pub fn name(self) -> &'static str {
        match self {
            ParamSource::Adopted => "adopted",
            ParamSource::Materials => "materials",
        }
    }
}

/// How the ball's contact stops being Hertzian, which sets the mean contact pressure p0 of
/// Eqs. 15–17 (docs/model.md §3).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MaterialKind {
    /// Flattens: p0 = E z_p / R (Eq. 20).
    #[default]
    Elastomer,
    /// Yields: p0 = 2.2 S_y.
    Metal,
}

/// What was measured (Cross 1999 for the paper's three balls; for the drop-test balls the
/// reference values their standards put mid-window). SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Measured {
    /// Mass m, kg (the model's mass).
    pub mass: f64,
    /// Radius R, m (Hertz stiffness, flattening, dashpot area, drag area).
    pub radius: f64,
    /// Impact speed v0 the values below were measured at, m/s (the preset's default speed).
    pub v0: f64,
    /// Measured coefficient of restitution, when reported.
    pub cor: Option<f64>,
    /// Measured peak force, N, when reported.
    pub max_force: Option<f64>,
    /// Measured contact time, s, when reported.
    pub contact_time: Option<f64>,
    /// κ = I/(m R²), the moment of inertia about a diameter (oblique impacts,
    /// docs/oblique.md §1); a solid ball's 0.4 when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia_factor: Option<f64>,
    /// The air of the drop tests these values were fitted from (`fit --drop-test … --save`);
    /// absent for other data, and in presets saved before it was kept.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub drops: Option<FitAir>,
}

/// The air the drop tests a ball was fitted to were taken in (`[measured.drops]`): what
/// `bouncelab drop` must fall through for the fitted ball to give back the readings
/// (docs/fitting.md, "The air is stated").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitAir {
    /// The drag coefficient C_d of quadratic drag; 0 in vacuum (no drag correction).
    pub drag_coefficient: f64,
    /// The air density, kg/m³ (no part in vacuum).
    pub air_density: f64,
}

/// Material data. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Elastomer (flattens, Eq. 20) or metal (yields); elastomer when absent.
    #[serde(default)]
    pub kind: MaterialKind,
    /// Young's modulus for contact; from the layers by Eq. 30 when absent.
    pub modulus: Option<f64>,
    /// Poisson's ratio ν for contact (E* = E/(1 − ν²)).
    pub poisson: f64,
    /// Modulus along the surface (Rayleigh waves); from the surface layers (Eq. 31) or the
    /// contact modulus when absent.
    pub surface_modulus: Option<f64>,
    /// Poisson's ratio along the surface (the dashpot, Eq. 5); `poisson` when absent.
    pub surface_poisson: Option<f64>,
    /// Density; from m and R when absent (or from the surface layers, Eq. 31).
    pub density: Option<f64>,
    /// Yield strength S_y (metals).
    pub yield_strength: Option<f64>,
    /// The ball's layers from the surface inwards (Eqs. 30, 31); empty for a uniform ball.
    #[serde(default)]
    pub layers: Vec<Layer>,
}

/// The parameters the paper adopted. K_r is required: no formula gives it (docs/model.md §4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Adopted {
    /// Dashpot c, kg/s (required to run the adopted set).
    pub damping: Option<f64>,
    /// Flattening (or yield) indentation z_p, m (required to run the adopted set).
    pub z_p: Option<f64>,
    /// Contact stiffness K_p, N/m (required to run the adopted set).
    pub k_p: Option<f64>,
    /// Recoil spring K_r, N/m, fitted to the measured COR (both sets use it).
    pub k_r: f64,
}

/// A ball, as one preset TOML file holds it (docs/presets.md): what was measured, the
/// material, and the adopted parameters. [`Preset::parse`] checks every field.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// The name `--preset` and [`crate::Ball::from_preset`] take.
    pub name: String,
    /// One line on the ball and where its numbers come from.
    #[serde(default)]
    pub description: String,
    /// The contact law it runs on by default (linear when absent).
    #[serde(default = "default_law")]
    pub law: ContactLaw,
    /// The parameter set it runs on by default (adopted when absent).
    #[serde(default)]
    pub parameters: ParamSource,
    /// The published flight model the ball has (docs/flight.md §2); when absent, the one named
    /// like the preset, if any ([`Preset::flight_model`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub aerodynamics: Option<Published>,
    /// What was measured on the ball.
    pub measured: Measured,
    /// Its material data.
    pub material: Material,
    /// The parameters the paper (or the preset's author) adopted.
    pub adopted: Adopted,
    /// A fitted preset's uncertainty (`fit … --save`): the source of its 95 % intervals.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit: Option<FitTable>,
    /// What the parameters were fitted to and the impact speeds they hold over
    /// (`[calibration]`, docs/presets.md): every answer outside says so.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub calibration: Option<Calibration>,
}

fn default_law() -> ContactLaw {
    ContactLaw::Linear
}

/// Parameters derived from the material data (docs/model.md §4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Derived {
    /// Density ρ, kg/m³: given, or m / ((4/3) π R³).
    pub density: f64,
    /// Young's modulus E for contact, Pa: given, or the layers in series (Eq. 30).
    pub contact_modulus: f64,
    /// Effective modulus against the rigid wall, E* = E/(1 − ν²), Pa.
    pub e_star: f64,
    /// Hertz stiffness K_h = (4/3) E* √R, N/m^{3/2} (Eq. 8).
    pub k_h: f64,
    /// Flattening (Eq. 20) or yield (Eq. 17) indentation z_p, m.
    pub z_p: f64,
    /// Contact stiffness K_p = 1.5 K_h √z_p, N/m (Eqs. 15, 16).
    pub k_p: f64,
    /// Dashpot from Rayleigh-wave radiation, c = 0.94 A √(ρ G), kg/s (Eq. 5).
    pub damping: f64,
    /// Young's modulus along the surface, Pa (Eq. 31, or the contact modulus).
    pub surface_modulus: f64,
    /// Density along the surface, kg/m³ (Eq. 31, or the density).
    pub surface_density: f64,
}

mod check;
pub(crate) mod error;
pub use error::PresetError;
use error::{Bad, line_col, locate, one_line};

impl Preset {
    /// Parse and validate a preset; errors carry file:line:column.
    pub fn parse(text: &str, origin: &str) -> Result<Preset, PresetError> {
        let preset: Preset = toml::from_str(text).map_err(|e| {
            // an error without a span concerns the whole document: its start
            let offset = e.span().map_or(0, |s| s.start);
            let message = one_line(e.message());
            PresetError {
                origin: origin.to_string(),
                position: Some(line_col(text, offset)),
                // a value of the wrong type: the message names no field, the path does
                message: match e.span().and_then(|_| error::key_at(text, offset)) {
                    Some(key) => format!("{key}: {message}"),
                    None => message,
                },
            }
        })?;
        preset.check().map_err(|bad| PresetError {
            origin: origin.to_string(),
            position: Some(locate(text, &bad)),
            message: if bad.table.is_empty() {
                format!("{}: {}", bad.key, bad.message)
            } else {
                format!("{}.{}: {}", bad.table, bad.key, bad.message)
            },
        })?;
        Ok(preset)
    }

    /// The paper's three embedded balls, in the order superball, golf, baseball (the figures,
    /// `reproduce` and the explorer's keys 1 2 3 run these).
    pub fn embedded() -> Vec<Preset> {
        parse_embedded(&EMBEDDED[..PAPER_BALLS])
    }

    /// Every embedded preset: the paper's three, then the balls of the drop tests.
    pub fn embedded_all() -> Vec<Preset> {
        parse_embedded(&EMBEDDED)
    }

    /// Semantic checks: the first bad field.
    /// The semantic checks, table by table, then the solver's own (see `check`).
    fn check(&self) -> Result<(), Bad> {
        check::preset(self)
    }

    /// Parameters from the material data (docs/model.md §4).
    pub fn derived(&self) -> Derived {
        let (m, r, mat) = (self.measured.mass, self.measured.radius, &self.material);
        let density = mat.density.unwrap_or_else(|| materials::density(m, r));
        let contact_modulus = mat
            .modulus
            .unwrap_or_else(|| materials::layered_contact_modulus(r, &mat.layers));
        let e_star = materials::effective_modulus(contact_modulus, mat.poisson);
        let flat = match mat.kind {
            MaterialKind::Elastomer => materials::elastomer_flattening(e_star, contact_modulus, r),
            MaterialKind::Metal => {
                materials::metal_plastic(e_star, r, mat.yield_strength.unwrap_or(f64::NAN))
            }
        };
        let layered = materials::layered_surface(&mat.layers);
        let surface_modulus = mat
            .surface_modulus
            .or(layered.map(|l| l.0))
            .unwrap_or(contact_modulus);
        let surface_density = layered.map(|l| l.1).filter(|&d| d > 0.0).unwrap_or(density);
        let surface_poisson = mat.surface_poisson.unwrap_or(mat.poisson);
        Derived {
            density,
            contact_modulus,
            e_star,
            k_h: materials::hertz_stiffness(e_star, r),
            z_p: flat.z_p,
            k_p: flat.k_p,
            damping: materials::rayleigh_damping(
                r,
                surface_density,
                surface_modulus,
                surface_poisson,
            ),
            surface_modulus,
            surface_density,
        }
    }

    /// The impact parameters from the chosen set. With the adopted set K_h follows Eq. 16,
    /// K_h = K_p / (1.5 √z_p), so the Hertz phase meets the linear one with matching slope.
    pub fn params_from(&self, source: ParamSource) -> ImpactParams {
        let (mass, v0) = (self.measured.mass, self.measured.v0);
        match source {
            ParamSource::Adopted => {
                let a = &self.adopted;
                let (k_p, z_p) = (a.k_p.unwrap_or(f64::NAN), a.z_p.unwrap_or(f64::NAN));
                ImpactParams {
                    mass,
                    k_p,
                    damping: a.damping.unwrap_or(f64::NAN),
                    k_r: a.k_r,
                    z_p,
                    k_h: ImpactParams::k_h_matching(k_p, z_p),
                    v0,
                }
            }
            ParamSource::Materials => {
                let d = self.derived();
                ImpactParams {
                    mass,
                    k_p: d.k_p,
                    damping: d.damping,
                    k_r: self.adopted.k_r,
                    z_p: d.z_p,
                    k_h: d.k_h,
                    v0,
                }
            }
        }
    }

    /// The published flight model its ball flies on (docs/flight.md §2): its `aerodynamics`,
    /// or when absent the model named like the preset (a user's file named `golf` flies as
    /// golf), else none (the assumed smooth sphere).
    pub fn flight_model(&self) -> Option<Published> {
        self.aerodynamics.or_else(|| Published::named(&self.name))
    }

    /// The impact parameters the preset runs on (its `parameters` choice).
    pub fn params(&self) -> ImpactParams {
        self.params_from(self.parameters)
    }
}

#[cfg(test)]
mod tests;
