//! The semantic checks of a parsed preset, table by table, each naming the key at fault
//! (`Bad`, located in the file by `error::locate`).

use super::error::Bad;
use super::{Adopted, Material, MaterialKind, Measured, ParamSource, Preset, usable};
use crate::text::number;

/// Every check, in the order of the file: the name and description, `[measured]`,
/// `[material]`, `[adopted]`, then the commands' own check, so that load and use agree.
pub(super) fn preset(p: &Preset) -> Result<(), Bad> {
    text(p)?;
    measured(&p.measured)?;
    material(&p.material)?;
    adopted(&p.adopted, p.parameters)?;
    super::fit_table::check(p)?;
    super::calibration::check(&p.calibration)?;
    usable::check(p)
}

fn bad(table: &'static str, key: &'static str, message: String) -> Bad {
    Bad {
        table,
        layer: None,
        key,
        message,
    }
}

/// Every preset number lies below this (the parameters' range, `model::checks`).
const BELOW: f64 = 1e15;

/// Why `v` is refused: past [`BELOW`] where it is a finite number there, else not `what`
/// ("positive", "non-negative").
fn refused(v: f64, what: &str) -> String {
    if v.is_finite() && v >= BELOW {
        format!(
            "must be below 1e15 (every parameter's range), got {}",
            number(v)
        )
    } else {
        format!("must be a {what} finite number, got {}", number(v))
    }
}

fn positive(table: &'static str, key: &'static str, v: f64) -> Result<(), Bad> {
    if v.is_finite() && v > 0.0 && v < BELOW {
        Ok(())
    } else {
        Err(bad(table, key, refused(v, "positive")))
    }
}

fn opt(table: &'static str, key: &'static str, v: Option<f64>) -> Result<(), Bad> {
    v.map_or(Ok(()), |v| positive(table, key, v))
}

/// The name is one word, and neither it nor the description holds a control character.
fn text(p: &Preset) -> Result<(), Bad> {
    // printed by every command and drawn in figures: no control character may ride along
    // (crate::sanitize; tests/cli/escaping.rs)
    // (a description may keep the tabs and line breaks of its TOML: they command nothing)
    for (key, text, allowed) in [
        ("name", &p.name, &[][..]),
        ("description", &p.description, &['\t', '\n'][..]),
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
    // a name is what presets are told apart by: nothing in it may print as nothing, or
    // `golf\u{200B}` lists as a second "golf" (crate::sanitize::invisible; tests/cli/escaping.rs,
    // `invisible_characters_cannot_hide`); a description shows them escaped instead
    if let Some((i, c)) = crate::sanitize::first_invisible(&p.name) {
        let msg = format!(
            "holds an invisible character, U+{:04X} (character {}): a name must print as it \
             compares",
            c as u32,
            i + 1
        );
        return Err(bad("", "name", msg));
    }
    if p.name.trim().is_empty() || p.name.chars().any(|c| c.is_whitespace() || c == '/') {
        return Err(bad(
            "",
            "name",
            "must be a non-empty word without spaces or '/'".into(),
        ));
    }
    Ok(())
}

fn measured(m: &Measured) -> Result<(), Bad> {
    positive("measured", "mass", m.mass)?;
    positive("measured", "radius", m.radius)?;
    positive("measured", "v0", m.v0)?;
    if let Some(e) = m.cor
        && !(e.is_finite() && (0.0..=1.0).contains(&e))
    {
        return Err(bad(
            "measured",
            "cor",
            format!("must lie in [0, 1], got {}", number(e)),
        ));
    }
    opt("measured", "max_force", m.max_force)?;
    opt("measured", "contact_time", m.contact_time)?;
    if let Some(k) = m.inertia_factor
        && !(k > 0.0 && k <= 1.0)
    {
        return Err(bad(
            "measured",
            "inertia_factor",
            format!("must lie in (0, 1], got {}", number(k)),
        ));
    }
    if let Some(a) = &m.drops {
        let fine = |x: f64| x.is_finite() && x >= 0.0;
        if !fine(a.drag_coefficient) {
            let msg = format!("must be finite and ≥ 0, got {}", number(a.drag_coefficient));
            return Err(bad("measured.drops", "drag_coefficient", msg));
        }
        if !(fine(a.air_density) && a.air_density > 0.0) {
            let msg = format!("must be finite and positive, got {}", number(a.air_density));
            return Err(bad("measured.drops", "air_density", msg));
        }
    }
    Ok(())
}

fn material(mat: &Material) -> Result<(), Bad> {
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
                format!("must lie in [0, 0.5], got {}", number(nu)),
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
    Ok(())
}

/// `[adopted]`: K_r always (no formula gives it), c, z_p and K_p when the preset runs on it.
fn adopted(a: &Adopted, parameters: ParamSource) -> Result<(), Bad> {
    opt("adopted", "damping", a.damping)?;
    opt("adopted", "z_p", a.z_p)?;
    opt("adopted", "k_p", a.k_p)?;
    if !(a.k_r.is_finite() && a.k_r >= 0.0 && a.k_r < BELOW) {
        return Err(bad("adopted", "k_r", refused(a.k_r, "non-negative")));
    }
    if parameters == ParamSource::Adopted {
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
    Ok(())
}
