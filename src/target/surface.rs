//! A playing surface as a preset (docs/surfaces.md): its normal give — a stiffness K_s in
//! parallel with a damping c_s, on a mass M where the surface moves (∞ for a fixed one) — and
//! its tangential contact with a ball: Coulomb friction μ, the tangential spring K_t and its
//! dashpot c_t. A surface's normal part is a [`Target`] at rest (docs/targets.md §1); its
//! tangential part is what `oblique` and `court` take (docs/oblique.md §1).
//!
//! Every number a surface file gives must cite where it comes from (a `[[sources]]` entry
//! naming the quantity): a number without a source is refused at its `file:line:column`. A
//! quantity a surface does not give is left to the command (rigid, immovable, and the
//! command's own friction and tangential options). Parsing only: no file I/O here
//! (`crate::catalog::surfaces` reads the user's files).

use super::Target;
use crate::preset::PresetError;
use crate::preset::error::{line_col, one_line};
use serde::{Deserialize, Serialize};
use std::sync::LazyLock;
use toml::Spanned;

/// The embedded surfaces, the default (the rigid test plate) first.
pub const EMBEDDED: [(&str, &str); 8] = [
    (
        "steel-plate",
        include_str!("../../presets/surfaces/steel-plate.toml"),
    ),
    (
        "concrete",
        include_str!("../../presets/surfaces/concrete.toml"),
    ),
    (
        "hard-court",
        include_str!("../../presets/surfaces/hard-court.toml"),
    ),
    ("clay", include_str!("../../presets/surfaces/clay.toml")),
    ("grass", include_str!("../../presets/surfaces/grass.toml")),
    ("carpet", include_str!("../../presets/surfaces/carpet.toml")),
    (
        "hardwood",
        include_str!("../../presets/surfaces/hardwood.toml"),
    ),
    ("turf", include_str!("../../presets/surfaces/turf.toml")),
];

/// The surface every command runs on unless told otherwise.
pub const DEFAULT: &str = "steel-plate";

/// One quantity's source.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Source {
    /// The quantity it is for: `stiffness`, `damping`, `mass`, `friction`,
    /// `tangential_stiffness`, `tangential_damping`, or `model` for what the file says of the
    /// surface as a whole (what it leaves out and why).
    pub quantity: String,
    /// Where the number comes from, and how it was derived from it.
    pub source: String,
}

/// What a surface does to a ball that meets it, SI units: its normal give and its tangential
/// contact. A surface file's numbers, and the numbers an answer ran on
/// (`crate::api::SurfaceUsed`); serialized as six fields of the object holding it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SurfaceMechanics {
    /// K_s (N/m); ∞ for a rigid surface (JSON `null`).
    pub stiffness: f64,
    /// c_s (kg/s) in parallel with K_s; 0 for none.
    pub damping: f64,
    /// The mass that moves with the surface (kg); ∞ for a fixed one (JSON `null`).
    pub mass: f64,
    /// μ (`None`: the surface gives none, or the answer used none).
    pub friction: Option<f64>,
    /// K_t, N/m (`None`: as μ's).
    pub tangential_stiffness: Option<f64>,
    /// c_t, kg/s (`None`: as μ's).
    pub tangential_damping: Option<f64>,
}

impl SurfaceMechanics {
    /// Whether the surface neither gives nor moves (K_s = ∞, M = ∞): the ball's normal impact
    /// on it is `run`'s.
    pub fn is_rigid(&self) -> bool {
        self.stiffness == f64::INFINITY && self.mass == f64::INFINITY
    }

    /// The surface's normal part as a target at rest (docs/targets.md §1).
    pub fn target(&self) -> Target {
        Target {
            mass: self.mass,
            speed: 0.0,
            stiffness: self.stiffness,
            damping: self.damping,
        }
    }
}

/// A surface, SI units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Surface {
    /// Short name (`--surface NAME`).
    pub name: String,
    /// One line.
    pub description: String,
    /// Its numbers: a quantity the file does not give is rigid, immovable, or `None`.
    #[serde(flatten)]
    pub mechanics: SurfaceMechanics,
    /// Where each number comes from.
    pub sources: Vec<Source>,
}

/// The TOML file as written, with the positions of its numbers.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    name: Spanned<String>,
    description: String,
    #[serde(default)]
    normal: Normal,
    #[serde(default)]
    tangential: Tangential,
    #[serde(default)]
    sources: Vec<SourceFile>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Normal {
    stiffness: Option<Spanned<f64>>,
    damping: Option<Spanned<f64>>,
    mass: Option<Spanned<f64>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Tangential {
    friction: Option<Spanned<f64>>,
    stiffness: Option<Spanned<f64>>,
    damping: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SourceFile {
    quantity: Spanned<String>,
    source: String,
}

/// The quantities a source may name.
const QUANTITIES: [&str; 7] = [
    "stiffness",
    "damping",
    "mass",
    "friction",
    "tangential_stiffness",
    "tangential_damping",
    "model",
];

/// A number's check: its name (as a source names it), its value, where it is, and whether 0
/// and ∞ are allowed.
struct Number<'a> {
    quantity: &'static str,
    value: &'a Spanned<f64>,
    zero: bool,
    infinite: bool,
}

impl Surface {
    /// Parse and check a surface file; `origin` names it in errors (`embedded:NAME` or a
    /// path). Every error is one line at `origin:line:column`.
    pub fn parse(text: &str, origin: &str) -> Result<Surface, PresetError> {
        let at = |offset: usize, message: String| PresetError {
            origin: origin.to_string(),
            position: Some(line_col(text, offset)),
            message,
        };
        let file: File = toml::from_str(text)
            .map_err(|e| at(e.span().map_or(0, |s| s.start), one_line(e.message())))?;
        let name = file.name.get_ref();
        if name.is_empty() || name.chars().any(|c| c.is_control() || c.is_whitespace()) {
            return Err(at(
                file.name.span().start,
                "name: must be non-empty, without spaces or control characters".into(),
            ));
        }
        for s in &file.sources {
            if !QUANTITIES.contains(&s.quantity.get_ref().as_str()) {
                return Err(at(
                    s.quantity.span().start,
                    format!(
                        "sources.quantity: unknown quantity '{}' (one of {})",
                        one_line(s.quantity.get_ref()),
                        QUANTITIES.join(", ")
                    ),
                ));
            }
        }
        let cited = |q: &str| file.sources.iter().any(|s| s.quantity.get_ref() == q);
        let (n, t) = (&file.normal, &file.tangential);
        let numbers = [
            ("stiffness", "normal.stiffness", &n.stiffness, false, true),
            ("damping", "normal.damping", &n.damping, true, false),
            ("mass", "normal.mass", &n.mass, false, true),
            ("friction", "tangential.friction", &t.friction, true, false),
            (
                "tangential_stiffness",
                "tangential.stiffness",
                &t.stiffness,
                false,
                false,
            ),
            (
                "tangential_damping",
                "tangential.damping",
                &t.damping,
                true,
                false,
            ),
        ];
        for (quantity, key, value, zero, infinite) in numbers {
            let Some(value) = value else { continue };
            let n = Number {
                quantity,
                value,
                zero,
                infinite,
            };
            if let Some(why) = n.fault(cited(quantity)) {
                return Err(at(value.span().start, format!("{key}: {why}")));
            }
        }
        let get = |v: &Option<Spanned<f64>>| v.as_ref().map(|s| *s.get_ref());
        Ok(Surface {
            name: name.clone(),
            description: file.description,
            mechanics: SurfaceMechanics {
                stiffness: get(&n.stiffness).unwrap_or(f64::INFINITY),
                damping: get(&n.damping).unwrap_or(0.0),
                mass: get(&n.mass).unwrap_or(f64::INFINITY),
                friction: get(&t.friction),
                tangential_stiffness: get(&t.stiffness),
                tangential_damping: get(&t.damping),
            },
            sources: file
                .sources
                .into_iter()
                .map(|s| Source {
                    quantity: s.quantity.into_inner(),
                    source: s.source,
                })
                .collect(),
        })
    }

    /// The embedded surfaces, in [`EMBEDDED`]'s order.
    pub fn embedded() -> Vec<Surface> {
        EMBEDDED
            .iter()
            .map(|(name, text)| {
                Surface::parse(text, &format!("embedded:{name}"))
                    .expect("embedded surfaces are tested")
            })
            .collect()
    }

    /// The rigid, immovable test plate without friction data: today's wall. Parsed once: every
    /// answer on the plate names it, and `run` from Python answers in a few µs a call
    /// (BENCHMARKS.md), which parsing the file on each call would more than double.
    pub fn rigid_plate() -> Surface {
        static PLATE: LazyLock<Surface> = LazyLock::new(|| {
            Surface::parse(EMBEDDED[0].1, "embedded:steel-plate")
                .expect("embedded surfaces are tested")
        });
        PLATE.clone()
    }
}

impl Number<'_> {
    /// Why the number cannot stand, if it cannot.
    fn fault(&self, cited: bool) -> Option<String> {
        let v = *self.value.get_ref();
        if v.is_nan() || (v.is_infinite() && !(self.infinite && v > 0.0)) {
            return Some(if self.infinite {
                "must be a positive number or inf".into()
            } else {
                "must be finite".into()
            });
        }
        if v < 0.0 || (v == 0.0 && !self.zero) {
            return Some(if self.zero {
                "must be ≥ 0".into()
            } else {
                "must be > 0".into()
            });
        }
        if !cited {
            return Some(format!(
                "no source: every number needs a [[sources]] entry with quantity = \"{}\" \
                 (docs/surfaces.md)",
                self.quantity
            ));
        }
        None
    }
}
