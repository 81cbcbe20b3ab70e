//! A preset as TOML text in the schema [`Preset::parse`] reads (README, "Preset schema"), laid
//! out like the embedded files: one table per section, the unit of each number in a comment.
//! Pure: the caller decides where the text goes.

use super::{MaterialKind, Preset};
use std::fmt::Write;

/// A float that reads back to the same double. `{:?}` is Rust's shortest round-trip form and
/// always TOML: `0.0374`, `54500.0`, `1e-7`.
fn number(x: f64) -> String {
    format!("{x:?}")
}

/// A TOML basic string, escaped by the toml crate (quotes, backslashes, control characters).
fn string(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// `key = value` with the unit (or a note) as a comment aligned after it.
fn line(out: &mut String, key: &str, value: String, note: &str) {
    let kv = format!("{key} = {value}");
    if note.is_empty() {
        let _ = writeln!(out, "{kv}");
    } else {
        let _ = writeln!(out, "{kv:<30} # {note}");
    }
}

fn opt(out: &mut String, key: &str, value: Option<f64>, note: &str) {
    if let Some(v) = value {
        line(out, key, number(v), note);
    }
}

impl Preset {
    /// The preset as TOML; `header` lines come first, each as a `#` comment (its hostile
    /// characters shown escaped); every string value is the toml crate's. Every value is
    /// written, none is defaulted away, so `Preset::parse(&p.to_toml(..))` gives `p` back
    /// exactly. Numbers must be finite (the schema has no infinity): callers check
    /// [`Preset::parse`] on the result.
    pub fn to_toml(&self, header: &[String]) -> String {
        let mut out = String::new();
        // a comment ends at a line break: whatever a header holds (a data file's name with CR,
        // LF, ESC…) stays in its comment, shown as `\u{a}` (crate::sanitize)
        for h in header {
            let _ = writeln!(out, "# {}", crate::sanitize::line(h));
        }
        line(&mut out, "name", string(&self.name), "");
        line(&mut out, "description", string(&self.description), "");
        line(&mut out, "law", string(self.law.name()), "");
        line(&mut out, "parameters", string(self.parameters.name()), "");
        if let Some(a) = self.aerodynamics {
            line(
                &mut out,
                "aerodynamics",
                string(a.name()),
                "the published flight model",
            );
        }

        let m = &self.measured;
        out.push_str("\n[measured]\n");
        line(&mut out, "mass", number(m.mass), "kg");
        line(&mut out, "radius", number(m.radius), "m");
        line(&mut out, "v0", number(m.v0), "m/s, the impact speed");
        opt(
            &mut out,
            "cor",
            m.cor,
            "measured coefficient of restitution",
        );
        opt(&mut out, "max_force", m.max_force, "N");
        opt(&mut out, "contact_time", m.contact_time, "s");
        opt(&mut out, "inertia_factor", m.inertia_factor, "κ = I/(m R²)");
        if let Some(a) = &m.drops {
            out.push_str("\n[measured.drops]\n");
            line(
                &mut out,
                "drag_coefficient",
                number(a.drag_coefficient),
                "0: vacuum",
            );
            line(&mut out, "air_density", number(a.air_density), "kg/m³");
        }

        let mat = &self.material;
        out.push_str("\n[material]\n");
        let kind = match mat.kind {
            MaterialKind::Elastomer => "elastomer",
            MaterialKind::Metal => "metal",
        };
        line(&mut out, "kind", string(kind), "");
        opt(&mut out, "modulus", mat.modulus, "Pa, for contact");
        line(&mut out, "poisson", number(mat.poisson), "");
        opt(
            &mut out,
            "surface_modulus",
            mat.surface_modulus,
            "Pa, along the surface (Eq. 5)",
        );
        opt(&mut out, "surface_poisson", mat.surface_poisson, "");
        opt(&mut out, "density", mat.density, "kg/m³");
        opt(&mut out, "yield_strength", mat.yield_strength, "Pa");
        for layer in &mat.layers {
            out.push_str("\n[[material.layers]]\n");
            if let Some(n) = &layer.name {
                line(&mut out, "name", string(n), "");
            }
            line(&mut out, "thickness", number(layer.thickness), "m");
            line(&mut out, "modulus", number(layer.modulus), "Pa");
            opt(&mut out, "density", layer.density, "kg/m³");
            opt(&mut out, "poisson", layer.poisson, "");
            line(&mut out, "surface", layer.surface.to_string(), "");
        }

        let a = &self.adopted;
        out.push_str("\n[adopted]\n");
        opt(&mut out, "damping", a.damping, "c, kg/s");
        opt(&mut out, "z_p", a.z_p, "m");
        opt(&mut out, "k_p", a.k_p, "N/m");
        line(&mut out, "k_r", number(a.k_r), "N/m");
        if let Some(f) = &self.fit {
            f.write(&mut out);
        }
        if let Some(c) = &self.calibration {
            c.write(&mut out);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_embedded_preset_reads_back_exactly() {
        for p in Preset::embedded_all() {
            let text = p.to_toml(&["a header".into()]);
            assert!(text.starts_with("# a header\nname = "), "{text}");
            let back = Preset::parse(&text, "x.toml").unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(back, p);
        }
    }

    #[test]
    fn awkward_strings_and_numbers_survive() {
        let mut p = Preset::embedded().remove(1);
        p.description = "a \"quoted\" \\ back\\slash\tand ünïcode # not a comment".into();
        p.material.layers[0].name = Some("line\nbreak".into());
        p.measured.mass = 0.1 + 0.2; // 0.30000000000000004
        p.adopted.k_r = 1e-7;
        p.adopted.damping = Some(123456789012345.0);
        let back = Preset::parse(&p.to_toml(&[]), "x.toml").unwrap();
        assert_eq!(back, p);
    }
}
