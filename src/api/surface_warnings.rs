//! What an answer on a surface says about the surface (docs/surfaces.md §2, docs/drop.md
//! "Standards"), made here once for every face: the command line's `run`, `drop`, `oblique`,
//! `shot`, `mc --shot`, `collide` and `court`, and Python's answers on a surface, each adding
//! them to its own warnings (tests/cli/cli_surface_warnings.rs).

use super::SurfaceUsed;
use crate::drop::standards::Standard;

/// The mark of an embedded surface whose normal give is assumed, not published: its `model`
/// source says `ASSUMED rigid` (presets/surfaces/*.toml, docs/surfaces.md §5).
const ASSUMED_RIGID: &str = "ASSUMED rigid";

/// What an answer on the assumed-rigid surface `name` is, for every answer but `court`'s.
fn answer_is_the_plates(name: &str) -> String {
    format!(
        "the answer is the rigid plate's, not {name}'s own (a surface that gives changes the \
         bounce); give its K_s and c_s with --surface-stiffness and --surface-damping (Python: \
         surface={{'name': '{name}', 'stiffness': …, 'damping': …}})"
    )
}

/// What a court rating on an assumed-rigid court is (`court`'s consequence).
fn rating_by_friction(_: &str) -> String {
    "e_y is the rigid plate's and the rating ranks the court by μ alone; give the court's own e \
     with --surface-cor E or --fit FILE (Python: surface_cor=, fit=)"
        .into()
}

impl SurfaceUsed {
    /// The warnings of an answer on this surface (`run`, `drop`, `oblique`, `shot`,
    /// `collide`, and Python's): its normal give ASSUMED rigid, where it is
    /// (`SurfaceUsed::assumed_rigid_warning`); `[]` elsewhere.
    pub fn warnings(&self) -> Vec<String> {
        self.assumed_rigid_warning(answer_is_the_plates)
            .into_iter()
            .collect()
    }

    /// `court`'s warning on this surface: the same as every answer's, its consequence the
    /// rating's (tests/cli/court_assumed.rs).
    pub fn court_warnings(&self) -> Vec<String> {
        self.assumed_rigid_warning(rating_by_friction)
            .into_iter()
            .collect()
    }

    /// "surface NAME: its normal give is ASSUMED rigid (…), so " and `so(NAME)` on an embedded surface
    /// whose rigidity is assumed because no published value exists (every embedded court but
    /// hard-court, rigid as published: docs/surfaces.md §2, §5), its K_s neither given nor
    /// calibrated: the answer is then the rigid plate's. `None` on the plate itself, on a
    /// surface rigid by definition (`steel-plate`, `concrete`), on a K_s given, and on a
    /// user's surface (its file says what it assumed). Other numbers given over it (its mass)
    /// leave K_s assumed: the surface it started from is read.
    fn assumed_rigid_warning(&self, so: fn(&str) -> String) -> Option<String> {
        let given =
            |o: &String| ["stiffness", "target_stiffness", "calibrated"].contains(&o.as_str());
        let (name, origin) = self.started_from();
        let rigid = self.mechanics.stiffness.is_infinite();
        if origin != "embedded" || !rigid || self.overrides.iter().any(given) {
            return None;
        }
        let named = crate::target::surface::Surface::embedded()
            .into_iter()
            .find(|s| s.name == name)?;
        let assumed = (named.sources.iter())
            .any(|s| s.quantity == "model" && s.source.contains(ASSUMED_RIGID));
        assumed.then(|| {
            format!(
                "surface {name}: its normal give is ASSUMED rigid (no published K_s or c_s, \
                 docs/surfaces.md §5), so {}",
                so(&name)
            )
        })
    }

    /// "standard NAME: the standard's test is on …; this drop is on …" when this is not the
    /// surface of `standard`'s test: a verdict judged on it is the ball's there, not the
    /// standard's. The standard's surface is its own words (`Standard::surface`), which the
    /// model runs on its rigid plate: so this surface is the standard's when it is rigid and
    /// immovable and either that plate (`steel-plate`, the default) or a surface those words
    /// name (`concrete` for itf's "block (concrete or granite)"); any other — one that gives
    /// or moves, or another rigid one (grass, assumed so; hard-court) — is warned, for every
    /// impact standard (tests/cli/cli_surface_warnings.rs).
    pub fn off_standard_warning(&self, standard: &Standard) -> Option<String> {
        let words = standard.surface;
        let mut named_there = words.split(|c: char| !c.is_alphanumeric() && c != '-');
        let named =
            self.name == crate::target::surface::DEFAULT || named_there.any(|w| w == self.name);
        let its_own = self.mechanics.is_rigid() && named;
        (!its_own).then(|| {
            format!(
                "standard {}: the standard's test is on a {words}; this drop is on {}: the \
                 verdict is the ball's on that surface, not the standard's",
                standard.name,
                self.label()
            )
        })
    }
}
