//! The surface an answer ran on (docs/surfaces.md): the named surface with the explicit
//! numbers given over its own, checked; the JSON `surface` object every answer on a surface
//! carries, the command line's (src/cli/surface.rs) and the Python package's
//! (python/src/surface.rs) alike. Reading the named surface is the faces' (the catalog);
//! the wording of the errors too (`--surface-damping` against `surface={"damping": …}`).

use crate::ParamError;
use crate::catalog::Origin;
use crate::catalog::surfaces::SurfaceEntry;
use crate::target::surface::DEFAULT;
use crate::target::surface::{Surface, SurfaceMechanics};
use serde::Serialize;

/// The name of the default plate once numbers given over it changed it.
const GIVEN_DEFAULT: &str = "given-surface";
/// What a named surface's name is marked with once numbers given over it changed it.
const MODIFIED: &str = "-modified";
/// How the origin of a surface renamed so begins, the surface it started from after it.
const GIVEN_OVER: &str = "given over ";

/// The surface a command ran on: the named one with the explicit numbers over it; the JSON
/// `surface` object, its fields in this order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceUsed {
    /// The surface's name.
    pub name: String,
    /// `embedded` or the file it was read from.
    pub origin: String,
    /// The numbers the answer ran on: K_s, c_s, M (`null` for ∞: rigid, fixed), and μ, K_t,
    /// c_t (`null` where the command uses none).
    #[serde(flatten)]
    pub mechanics: SurfaceMechanics,
    /// The quantities given over the surface's own, in the order above.
    pub overrides: Vec<String>,
}

/// Why explicit normal numbers cannot be the surface's.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceError {
    /// A number out of range, named as the target's (`target_stiffness`, …): the face
    /// renames it as its own option.
    Invalid(ParamError),
    /// A damping given for a rigid surface, whose dashpot does nothing (the value given).
    RigidDashpot(f64),
}

impl SurfaceUsed {
    /// The normal quantities a surface's explicit numbers may override, in the order of
    /// [`SurfaceUsed::with_normal`]'s argument and of `overrides` (Python's `surface=` dict
    /// keys too).
    pub const NORMAL: [&'static str; 3] = ["stiffness", "damping", "mass"];
    /// The tangential ones, in the order of [`SurfaceUsed::with_tangential`]'s argument.
    pub const TANGENTIAL: [&'static str; 3] =
        ["friction", "tangential_stiffness", "tangential_damping"];

    /// This surface calibrated by `how` (`court --surface-cor`, `court --fit FILE`) to the
    /// court `c`: its K_s and c_s, `calibrated` among the overrides in place of `stiffness`,
    /// and a name saying it is no longer the surface it started from — `calibrated-court`
    /// from the default rigid plate, `NAME-calibrated` from a named one
    /// (tests/physics/surfaces.rs, `a_calibrated_court_is_named_for_what_it_is`).
    pub fn calibrated(&mut self, c: &super::CourtCalibration, how: &str) {
        (self.mechanics.stiffness, self.mechanics.damping) = (c.stiffness, c.damping);
        self.overrides.retain(|o| o != "stiffness");
        // first, where the normal quantities it stands for are listed (before μ, K_t, c_t)
        self.overrides.insert(0, "calibrated".into());
        // from the surface asked for: a K_s given is the calibration's, not a second change
        let (from, origin) = self.started_from();
        self.name = if from == DEFAULT {
            "calibrated-court".to_string()
        } else {
            format!("{from}-calibrated")
        };
        self.origin = format!("calibrated by {how} from {from} ({origin})");
    }

    /// The name and origin of the surface this one started from: its own, unless numbers
    /// given over it renamed it (`SurfaceUsed::name_for_what_it_is`), whose `origin` keeps
    /// them (`given over NAME (ORIGIN)`).
    pub fn started_from(&self) -> (String, String) {
        let from = match self.name.as_str() {
            GIVEN_DEFAULT => Some(DEFAULT),
            name => name.strip_suffix(MODIFIED),
        };
        let own = from.and_then(|from| {
            let rest = self.origin.strip_prefix(GIVEN_OVER)?.strip_prefix(from)?;
            let origin = rest.strip_prefix(" (")?.strip_suffix(')')?;
            Some((from.to_string(), origin.to_string()))
        });
        own.unwrap_or_else(|| (self.name.clone(), self.origin.clone()))
    }

    /// The rule of every answer's surface name (docs/surfaces.md §1, "The name"): once a
    /// number the answer runs on differs from the surface's own `own` — K_s, c_s, M, or a μ,
    /// K_t, c_t the surface gives (one filled in where it gives none replaces nothing) — it is
    /// no longer the surface it started from, and is named for what it is: `given-surface`
    /// from the default plate, `NAME-modified` from a named one, its origin `given over NAME
    /// (ORIGIN)`; `overrides` says what was given. Once renamed (or calibrated, or a bat: every
    /// number given) it keeps its name (tests/cli/cli_surface_names.rs).
    fn name_for_what_it_is(&mut self, own: &SurfaceMechanics) {
        let renamed = self.origin.starts_with(GIVEN_OVER)
            || self.origin.starts_with("calibrated by ")
            || self.name == "bat";
        let m = &self.mechanics;
        let normal = [
            (m.stiffness, own.stiffness),
            (m.damping, own.damping),
            (m.mass, own.mass),
        ];
        let tangential = [
            (m.friction, own.friction),
            (m.tangential_stiffness, own.tangential_stiffness),
            (m.tangential_damping, own.tangential_damping),
        ];
        let changed = normal.iter().any(|(used, own)| used != own)
            || (tangential.iter()).any(|(used, own)| own.is_some() && used != own);
        if renamed || !changed {
            return;
        }
        self.origin = format!("{GIVEN_OVER}{} ({})", self.name, self.origin);
        self.name = match self.name.as_str() {
            DEFAULT => GIVEN_DEFAULT.to_string(),
            name => format!("{name}{MODIFIED}"),
        };
    }

    /// The catalog entry's numbers, nothing overridden.
    pub fn from_entry(e: &SurfaceEntry) -> SurfaceUsed {
        SurfaceUsed {
            name: e.surface.name.clone(),
            origin: e.origin.to_string(),
            mechanics: e.surface.mechanics,
            overrides: Vec::new(),
        }
    }

    /// The rigid, immovable test plate (the default), its tangential quantities unset.
    pub fn rigid_plate() -> SurfaceUsed {
        SurfaceUsed::from_entry(&SurfaceEntry {
            surface: Surface::rigid_plate(),
            origin: Origin::Embedded,
        })
    }

    /// The bat `bat` runs against, as the surface the ball met (docs/cli.md, "The surface
    /// object"): named `bat`, its effective mass M_eff, its barrel's K_s (`None`: rigid) and
    /// c_s; every number came from the command line (or Python's arguments), so each given is
    /// an override of the rigid barrel of no set mass, `mass` always. No μ: the bat's impact
    /// is head-on. Its speed is the answer's `bat_speed`, not the surface's.
    pub fn bat(mass: f64, stiffness: Option<f64>, damping: Option<f64>) -> SurfaceUsed {
        let given = [stiffness, damping, Some(mass)];
        let overrides = given
            .iter()
            .zip(Self::NORMAL)
            .filter(|(v, _)| v.is_some())
            .map(|(_, name)| name.to_string())
            .collect();
        SurfaceUsed {
            name: "bat".into(),
            origin: "given (the bat's effective mass and barrel)".into(),
            mechanics: SurfaceMechanics {
                stiffness: stiffness.unwrap_or(f64::INFINITY),
                damping: damping.unwrap_or(0.0),
                mass,
                friction: None,
                tangential_stiffness: None,
                tangential_damping: None,
            },
            overrides,
        }
    }

    /// One line for a text header: "surface steel-plate (rigid, immovable)" or with its
    /// numbers and μ ([`super::surface_label`]).
    /// Its `given:` names the normal quantities given (and `calibrated`, `target_*`), not the
    /// tangential ones: μ is in the line as its number, K_t and c_t are the command's own lines
    /// (the text headers stay as they were when μ joined `overrides`).
    pub fn label(&self) -> String {
        let m = &self.mechanics;
        let normal = (m.stiffness, m.damping, m.mass);
        let given: Vec<&String> = (self.overrides.iter())
            .filter(|o| !Self::TANGENTIAL.contains(&o.as_str()))
            .collect();
        super::surface_label(&self.name, normal, m.friction, &given)
    }

    /// The explicit K_s, c_s, M (in that order) over the surface's own, each recorded as an
    /// override, the result checked: every number in range, and no damping given for a
    /// surface that stays rigid.
    pub fn with_normal(mut self, given: [Option<f64>; 3]) -> Result<SurfaceUsed, SurfaceError> {
        let own = self.mechanics;
        let m = &mut self.mechanics;
        let slots = [&mut m.stiffness, &mut m.damping, &mut m.mass];
        let mut overrides = Vec::new();
        for ((slot, value), name) in slots.into_iter().zip(given).zip(Self::NORMAL) {
            let Some(v) = value else { continue };
            overrides.push(name.to_string());
            *slot = v;
        }
        self.overrides.extend(overrides);
        self.name_for_what_it_is(&own);
        let m = &self.mechanics;
        m.target().validate().map_err(SurfaceError::Invalid)?;
        if m.stiffness.is_infinite() && m.damping > 0.0 && given[1].is_some() {
            return Err(SurfaceError::RigidDashpot(m.damping));
        }
        Ok(self)
    }

    /// `collide`'s target numbers over the surface's own, each recorded as an override: the
    /// mass M (`target_mass`), and K_s (`target_stiffness`) with c_s beside it (given:
    /// `target_damping`; else 0, a new spring comes without the old dashpot). Unchecked: the
    /// collision checks its target. The command line's and Python's `collide` alike.
    pub fn with_target(
        mut self,
        mass: Option<f64>,
        stiffness: Option<f64>,
        damping: Option<f64>,
    ) -> SurfaceUsed {
        let own = self.mechanics;
        if let Some(m) = mass {
            self.mechanics.mass = m;
            self.overrides.push("target_mass".into());
        }
        if let Some(k) = stiffness {
            self.mechanics.stiffness = k;
            self.mechanics.damping = damping.unwrap_or(0.0);
            self.overrides.push("target_stiffness".into());
            if damping.is_some() {
                self.overrides.push("target_damping".into());
            }
        }
        self.name_for_what_it_is(&own);
        self
    }

    /// The tangential quantities the answer used, μ, K_t, c_t (in that order): each the one
    /// given, else the surface's own; every one given is recorded as an override, over the
    /// surface's own or where it has none (`court --surface clay --friction 0.8`: μ came from
    /// the command line, tests/cli/court_assumed.rs).
    pub fn with_tangential(mut self, given: [Option<f64>; 3]) -> SurfaceUsed {
        let own = self.mechanics;
        let m = &mut self.mechanics;
        let slots = [
            &mut m.friction,
            &mut m.tangential_stiffness,
            &mut m.tangential_damping,
        ];
        let mut overrides = Vec::new();
        for ((slot, value), name) in slots.into_iter().zip(given).zip(Self::TANGENTIAL) {
            if value.is_some() {
                overrides.push(name.to_string());
            }
            *slot = value.or(*slot);
        }
        self.overrides.extend(overrides);
        self.name_for_what_it_is(&own);
        self
    }
}
