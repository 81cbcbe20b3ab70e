//! The surface picker (`G`, issue 53 item 6): the surfaces `bouncelab surfaces` lists — the
//! embedded ones, then the user's surface files — one of which the ball meets. Listing reads
//! the user's surfaces folder, so it is an effect ([`super::effect::Effect::ListSurfaces`])
//! carried out by the loop with [`list`]; the state keeps the answer in a [`SurfacePicker`].
//!
//! Choosing a surface sets what the ball meets as `--surface NAME` sets it on the command
//! line (docs/surfaces.md): its normal give K_s ∥ c_s on its mass M (at rest) is the target
//! of the impact view (the form's K_s, c_s, M), its μ and K_t (where it gives them) the
//! oblique view's, its c_t the oblique view's tangential dashpot. One change `u` undoes.

use crate::api::SurfaceUsed;
use crate::catalog::Origin;
use crate::catalog::surfaces::{self, SurfaceEntry};
use crate::target::surface::{Surface, SurfaceMechanics};
use crate::tui::format::value;
use crate::tui::setting::Setting;

/// The open surface picker: every surface, the highlighted one, and why the user surfaces
/// could not be read (then only the embedded ones are listed).
pub type SurfacePicker = crate::tui::picker::Picker<SurfaceEntry>;

/// Every surface `--surface` knows now: the embedded ones, then the user's from `dir`. When
/// the folder cannot be read, the embedded ones and the reason.
pub fn list_in(dir: Option<&std::path::Path>) -> (Vec<SurfaceEntry>, Option<String>) {
    match surfaces::load(dir) {
        Ok(all) => (all, None),
        Err(e) => (
            surfaces::load(None).unwrap_or_default(),
            Some(format!("user surfaces not read: {e}")),
        ),
    }
}

/// [`list_in`] the user's surfaces folder.
pub fn list() -> (Vec<SurfaceEntry>, Option<String>) {
    list_in(surfaces::user_surfaces_dir().as_deref())
}

/// Where a surface comes from, as the picker writes it.
pub fn origin(o: &Origin) -> String {
    match o {
        Origin::Embedded => "embedded".into(),
        Origin::File(p) => p.display().to_string(),
    }
}

/// A number of a surface as the screen writes it: "∞" for a rigid K_s or a fixed M.
fn shown(x: f64) -> String {
    if x.is_infinite() {
        "∞".into()
    } else {
        value(x)
    }
}

/// The surface's numbers in one line, as the picker and the readouts write them: "K_s ∞ N/m,
/// c_s 0 kg/s, M ∞ kg, μ 0.6000" (μ, K_t, c_t where it gives them; "rigid" for K_s = ∞ and
/// M = ∞ with no more).
pub fn numbers(s: &SurfaceMechanics) -> String {
    let mut parts = Vec::new();
    if s.stiffness.is_infinite() {
        parts.push("rigid".to_string());
    } else {
        parts.push(format!("K_s {} N/m", shown(s.stiffness)));
        parts.push(format!("c_s {} kg/s", shown(s.damping)));
    }
    if s.mass.is_finite() {
        parts.push(format!("M {} kg", shown(s.mass)));
    }
    if let Some(mu) = s.friction {
        parts.push(format!("μ {}", value(mu)));
    }
    if let Some(k) = s.tangential_stiffness {
        parts.push(format!("K_t {} N/m", value(k)));
    }
    if let Some(c) = s.tangential_damping {
        parts.push(format!("c_t {} kg/s", value(c)));
    }
    parts.join(", ")
}

/// The surface the answer on screen runs on, as the library names it and warns of it
/// ([`SurfaceUsed`], docs/surfaces.md §1–2): the surface picked (`G`; the rigid plate when none
/// was) with the form's K_s, c_s, M given over its own where they differ — what `y`'s line
/// gives over `--surface NAME` — and, for the oblique view, its μ, K_t and c_t (`oblique`'s
/// line gives its μ always, K_t where set, c_t where not the surface's). Renamed by the
/// library's one rule once a number differs (`clay-modified`, `given-surface`); its
/// [`SurfaceUsed::warnings`] are the command line's.
pub fn used(setting: &Setting, tangential: Option<[Option<f64>; 3]>) -> SurfaceUsed {
    let picked = setting.surface.clone().unwrap_or_else(Surface::rigid_plate);
    // user surfaces may not take an embedded one's name (catalog::surfaces::load): an
    // embedded name is that surface; a user's file is not at hand here, and its path is no
    // part of what the screen says (its name, its warnings: none for a user's surface)
    let origin = if Surface::embedded().contains(&picked) {
        Origin::Embedded
    } else {
        Origin::File("a user's surface file".into())
    };
    let own = picked.mechanics;
    let start = SurfaceUsed::from_entry(&SurfaceEntry {
        surface: picked,
        origin,
    });
    let t = setting.target;
    let differs = |now: f64, own: f64| (now != own).then_some(now);
    let normal = [
        differs(t.stiffness, own.stiffness),
        differs(t.damping, own.damping),
        differs(t.mass, own.mass),
    ];
    // a c_s typed beside a rigid K_s, which `with_normal` refuses (its dashpot does nothing):
    // the numbers given as `collide`'s target, K_s among them only where it moved
    let used = start
        .clone()
        .with_normal(normal)
        .unwrap_or_else(|_| start.with_target(normal[2], normal[0], Some(t.damping)));
    match tangential {
        Some(given) => used.with_tangential(given),
        None => used,
    }
}
