//! Ball presets: measured data, material data and the parameters the paper adopted
//! (MODEL.md §7), in a TOML schema documented in the README. Parsing only: no file I/O here.

use crate::model::contact::ContactLaw;
use crate::model::materials::{self, Layer};
use crate::model::params::{ImpactParams, display_number};
use serde::{Deserialize, Serialize};
use std::fmt;

mod text;
mod usable;

/// The three balls of the paper, embedded in the binary, first; then the balls of the drop
/// tests (docs/drop.md, "The new balls").
pub const EMBEDDED: [(&str, &str); 8] = [
    ("superball", include_str!("../presets/superball.toml")),
    ("golf", include_str!("../presets/golf.toml")),
    ("baseball", include_str!("../presets/baseball.toml")),
    ("tennis", include_str!("../presets/tennis.toml")),
    ("football", include_str!("../presets/football.toml")),
    ("basketball", include_str!("../presets/basketball.toml")),
    ("table-tennis", include_str!("../presets/table-tennis.toml")),
    ("softball", include_str!("../presets/softball.toml")),
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
    pub fn name(self) -> &'static str {
        match self {
            ParamSource::Adopted => "adopted",
            ParamSource::Materials => "materials",
        }
    }
}

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MaterialKind {
    /// Flattens: p0 = E z_p / R (Eq. 20).
    #[default]
    Elastomer,
    /// Yields: p0 = 2.2 S_y.
    Metal,
}

/// What was measured (Cross 1999 for the embedded balls). SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Measured {
    pub mass: f64,
    pub radius: f64,
    pub v0: f64,
    pub cor: Option<f64>,
    pub max_force: Option<f64>,
    pub contact_time: Option<f64>,
}

/// Material data. SI units.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    #[serde(default)]
    pub kind: MaterialKind,
    /// Young's modulus for contact; from the layers by Eq. 30 when absent.
    pub modulus: Option<f64>,
    pub poisson: f64,
    /// Modulus along the surface (Rayleigh waves); from the surface layers (Eq. 31) or the
    /// contact modulus when absent.
    pub surface_modulus: Option<f64>,
    pub surface_poisson: Option<f64>,
    /// Density; from m and R when absent (or from the surface layers, Eq. 31).
    pub density: Option<f64>,
    /// Yield strength S_y (metals).
    pub yield_strength: Option<f64>,
    #[serde(default)]
    pub layers: Vec<Layer>,
}

/// The parameters the paper adopted. K_r is required: no formula gives it (MODEL.md §4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Adopted {
    pub damping: Option<f64>,
    pub z_p: Option<f64>,
    pub k_p: Option<f64>,
    pub k_r: f64,
}

/// A ball.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    pub name: String,
    #[serde(default)]
    pub description: String,
    #[serde(default = "default_law")]
    pub law: ContactLaw,
    #[serde(default)]
    pub parameters: ParamSource,
    pub measured: Measured,
    pub material: Material,
    pub adopted: Adopted,
}

fn default_law() -> ContactLaw {
    ContactLaw::Linear
}

/// Parameters derived from the material data (MODEL.md §4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Derived {
    pub density: f64,
    pub contact_modulus: f64,
    pub e_star: f64,
    pub k_h: f64,
    pub z_p: f64,
    pub k_p: f64,
    pub damping: f64,
    pub surface_modulus: f64,
    pub surface_density: f64,
}

/// A preset that cannot be used: where, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct PresetError {
    /// A file path, or `embedded:NAME`.
    pub origin: String,
    /// 1-based line and column, when known.
    pub position: Option<(usize, usize)>,
    pub message: String,
}

impl fmt::Display for PresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.position {
            Some((l, c)) => write!(f, "{}:{l}:{c}: {}", self.origin, self.message),
            None => write!(f, "{}: {}", self.origin, self.message),
        }
    }
}

impl std::error::Error for PresetError {}

/// 1-based (line, column) of a byte offset.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// A message for one line of a terminal: the line breaks of a TOML message become spaces, and
/// other control characters (which a quoted key such as `"a\rb"` or `"\u001b[2J"` carries
/// into "unknown field" messages) are escaped, so that they neither break the line nor reach
/// the terminal as commands.
fn one_line(message: &str) -> String {
    message
        .trim()
        .chars()
        .map(|c| match c {
            '\n' => " ".to_string(),
            c if c.is_control() => c.escape_default().to_string(),
            c => c.to_string(),
        })
        .collect()
}

/// A field that fails the semantic checks: its table ("" at the top level), the layer's index
/// for `material.layers`, its key, and why.
struct Bad {
    table: &'static str,
    layer: Option<usize>,
    key: &'static str,
    message: String,
}

/// Where a semantic error points: the key, from the spans of the parsed document, so that
/// every TOML spelling (headers with comments, dotted keys, inline tables, quoted keys) is
/// found; when the key is missing (a required field), the table that lacks it; when that is
/// missing too, the start of the file. (A line scan used to miss all of these and leave the
/// error without line:column.)
fn locate(text: &str, bad: &Bad) -> (usize, usize) {
    use toml::de::{DeTable, DeValue};
    let Ok(doc) = DeTable::parse(text) else {
        return (1, 1);
    };
    let mut offset = 0;
    let mut table: &DeTable = doc.get_ref();
    let path = bad.table.split('.').filter(|s| !s.is_empty());
    for segment in path.chain([bad.key]) {
        let Some((key, value)) = table.get_key_value(segment) else {
            break;
        };
        offset = key.span().start;
        let value = match (value.get_ref(), bad.layer) {
            (DeValue::Array(layers), Some(i)) => match layers.get(i) {
                Some(layer) => {
                    offset = layer.span().start;
                    layer.get_ref()
                }
                None => break,
            },
            (v, _) => v,
        };
        match value {
            DeValue::Table(t) => table = t,
            _ => break,
        }
    }
    line_col(text, offset)
}

impl Preset {
    /// Parse and validate a preset; errors carry file:line:column.
    pub fn parse(text: &str, origin: &str) -> Result<Preset, PresetError> {
        let preset: Preset = toml::from_str(text).map_err(|e| PresetError {
            origin: origin.to_string(),
            // an error without a span concerns the whole document: its start
            position: Some(line_col(text, e.span().map_or(0, |s| s.start))),
            message: one_line(e.message()),
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
    fn check(&self) -> Result<(), Bad> {
        fn bad(table: &'static str, key: &'static str, message: String) -> Bad {
            Bad {
                table,
                layer: None,
                key,
                message,
            }
        }
        fn positive(table: &'static str, key: &'static str, v: f64) -> Result<(), Bad> {
            if v.is_finite() && v > 0.0 && v < 1e15 {
                Ok(())
            } else {
                Err(bad(
                    table,
                    key,
                    format!(
                        "must be a positive finite number, got {}",
                        display_number(v)
                    ),
                ))
            }
        }
        let opt = |table, key, v: Option<f64>| v.map_or(Ok(()), |v| positive(table, key, v));
        // printed by every command and drawn in figures: no control character may ride along
        // (crate::sanitize; tests/escaping.rs)
        // (a description may keep the tabs and line breaks of its TOML: they command nothing)
        for (key, text, allowed) in [
            ("name", &self.name, &[][..]),
            ("description", &self.description, &['\t', '\n'][..]),
        ] {
            if let Some((i, c)) = crate::sanitize::first_control(text, allowed) {
                let msg = format!(
                    "holds a control character, U+{:04X} (character {})",
                    c as u32,
                    i + 1
                );
                return Err(bad("", key, msg));
            }
        }
        if self.name.trim().is_empty() || self.name.chars().any(|c| c.is_whitespace() || c == '/') {
            return Err(bad(
                "",
                "name",
                "must be a non-empty word without spaces or '/'".into(),
            ));
        }
        let m = &self.measured;
        positive("measured", "mass", m.mass)?;
        positive("measured", "radius", m.radius)?;
        positive("measured", "v0", m.v0)?;
        if let Some(e) = m.cor
            && !(e.is_finite() && (0.0..=1.0).contains(&e))
        {
            return Err(bad(
                "measured",
                "cor",
                format!("must lie in [0, 1], got {}", display_number(e)),
            ));
        }
        opt("measured", "max_force", m.max_force)?;
        opt("measured", "contact_time", m.contact_time)?;
        let mat = &self.material;
        for (key, nu) in [
            ("poisson", Some(mat.poisson)),
            ("surface_poisson", mat.surface_poisson),
        ] {
            if let Some(nu) = nu
                && !(nu.is_finite() && (0.0..=0.5).contains(&nu))
            {
                return Err(bad(
                    "material",
                    key,
                    format!("must lie in [0, 0.5], got {}", display_number(nu)),
                ));
            }
        }
        opt("material", "modulus", mat.modulus)?;
        opt("material", "surface_modulus", mat.surface_modulus)?;
        opt("material", "density", mat.density)?;
        opt("material", "yield_strength", mat.yield_strength)?;
        for (i, l) in mat.layers.iter().enumerate() {
            positive("material.layers", "thickness", l.thickness)
                .and_then(|()| positive("material.layers", "modulus", l.modulus))
                .and_then(|()| opt("material.layers", "density", l.density))
                .map_err(|b| Bad {
                    layer: Some(i),
                    ..b
                })?;
        }
        if mat.modulus.is_none() && mat.layers.is_empty() {
            return Err(bad(
                "material",
                "modulus",
                "is required when there are no layers".into(),
            ));
        }
        if mat.kind == MaterialKind::Metal && mat.yield_strength.is_none() {
            return Err(bad(
                "material",
                "yield_strength",
                "is required for kind = \"metal\"".into(),
            ));
        }
        let a = &self.adopted;
        opt("adopted", "damping", a.damping)?;
        opt("adopted", "z_p", a.z_p)?;
        opt("adopted", "k_p", a.k_p)?;
        if !(a.k_r.is_finite() && a.k_r >= 0.0 && a.k_r < 1e15) {
            return Err(bad(
                "adopted",
                "k_r",
                format!(
                    "must be a non-negative finite number, got {}",
                    display_number(a.k_r)
                ),
            ));
        }
        if self.parameters == ParamSource::Adopted {
            for (key, v) in [("damping", a.damping), ("z_p", a.z_p), ("k_p", a.k_p)] {
                if v.is_none() {
                    return Err(bad(
                        "adopted",
                        key,
                        "is required when parameters = \"adopted\"".into(),
                    ));
                }
            }
        }
        // the commands' own check, so that load and use agree
        usable::check(self)
    }

    /// Parameters from the material data (MODEL.md §4).
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

    /// The impact parameters the preset runs on (its `parameters` choice).
    pub fn params(&self) -> ImpactParams {
        self.params_from(self.parameters)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_presets_parse() {
        assert_eq!(
            Preset::embedded()
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>(),
            ["superball", "golf", "baseball"]
        );
        let all = Preset::embedded_all();
        assert_eq!(
            all.iter().map(|p| p.name.as_str()).collect::<Vec<_>>(),
            [
                "superball",
                "golf",
                "baseball",
                "tennis",
                "football",
                "basketball",
                "table-tennis",
                "softball"
            ]
        );
        for p in &all {
            assert!(p.params().validate().is_ok(), "{}", p.name);
            assert!(
                p.params_from(ParamSource::Materials).validate().is_ok(),
                "{}",
                p.name
            );
        }
    }

    #[test]
    fn errors_point_at_file_line_column() {
        let bad = EMBEDDED[0].1.replace("mass = 0.0374", "mass = \"heavy\"");
        let e = Preset::parse(&bad, "x.toml").unwrap_err();
        assert_eq!(e.position.map(|p| p.0), Some(9), "{e}");
        assert!(e.to_string().starts_with("x.toml:9:8: "), "{e}");
        let neg = EMBEDDED[0]
            .1
            .replace("radius = 0.02155", "radius = -0.02155");
        let e = Preset::parse(&neg, "x.toml").unwrap_err();
        assert_eq!(
            e.to_string(),
            "x.toml:10:1: measured.radius: must be a positive finite number, got -0.02155"
        );
        let huge = EMBEDDED[0].1.replace("mass = 0.0374", "mass = 1e300");
        let e = Preset::parse(&huge, "x.toml").unwrap_err();
        assert!(e.to_string().ends_with("got 1e300"), "{e}");
        let unknown = EMBEDDED[0].1.replace("[adopted]", "[adopted]\nspring = 3");
        let e = Preset::parse(&unknown, "x.toml").unwrap_err();
        assert!(e.to_string().contains("spring"), "{e}");
    }

    /// Found by the `preset_toml` fuzz target (fuzz/regressions/preset_toml/): errors lost
    /// their line:column when the key was missing or written in another TOML spelling, and
    /// control characters of a quoted key reached the one-line message.
    #[test]
    fn every_error_has_a_position_and_one_line() {
        let sb = EMBEDDED[0].1;
        let at = |text: &str| Preset::parse(text, "x.toml").unwrap_err().to_string();
        // a comment after the table header
        let t = sb
            .replace("[measured]", "[measured]   # Cross")
            .replace("v0 = 3.12 ", "v0 = 0 ");
        assert_eq!(
            at(&t),
            "x.toml:11:1: measured.v0: must be a positive finite number, got 0"
        );
        // a required key that is missing: the table that lacks it
        let t = sb.replace("kind = \"elastomer\"", "kind = \"metal\"");
        assert_eq!(
            at(&t),
            "x.toml:16:2: material.yield_strength: is required for kind = \"metal\""
        );
        // dotted keys and inline tables
        let t = "name = \"d\"\nmeasured = { mass = 1, radius = 1, v0 = -1 }\n\
                 material.modulus = 1\nmaterial.poisson = 0.3\nadopted.k_r = 1\n";
        assert_eq!(
            at(t),
            "x.toml:2:36: measured.v0: must be a positive finite number, got -1"
        );
        // the layer at fault, not the first one
        let golf = EMBEDDED[1].1.replace("thickness = 5.4e-3", "thickness = 0");
        assert!(
            at(&golf).starts_with("x.toml:32:1: material.layers.thickness: "),
            "{}",
            at(&golf)
        );
        // control characters of a quoted key are escaped
        let t = format!("\"a\\rb\\u001b\" = 1\n{sb}");
        assert_eq!(at(&t).lines().count(), 1, "{:?}", at(&t));
        assert!(
            at(&t).starts_with("x.toml:1:1: unknown field `a\\rb\\u{1b}`"),
            "{:?}",
            at(&t)
        );
    }
}
