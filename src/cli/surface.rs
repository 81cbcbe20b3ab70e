//! The surface a command runs on (docs/surfaces.md): `--surface NAME` and the explicit
//! `--surface-stiffness`, `--surface-damping`, `--surface-mass` (overriding the named
//! surface's), resolved against the embedded and user surfaces; the JSON `surface` object
//! every answer on a surface carries; and `bouncelab surfaces`, which lists them.

use super::output::{self, TextJson, human, table};
use crate::api::SurfaceError;
pub use crate::api::SurfaceUsed;
use crate::catalog::surfaces as catalog;
use crate::target::surface::{DEFAULT, Surface};
use clap::Args;
use serde::Serialize;
use std::io::Write;

/// The surface's options, shared by run, drop, oblique, court and collide.
#[derive(Debug, Clone, Default, Args)]
pub struct SurfaceArgs {
    /// The surface (`bouncelab surfaces` lists them) [default: steel-plate, the rigid plate]
    #[arg(long, value_name = "NAME")]
    pub surface: Option<String>,
    /// The surface's normal stiffness K_s, N/m (`inf`: rigid) [default: the surface's]
    #[arg(long, value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub surface_stiffness: Option<f64>,
    /// The surface's damping c_s ≥ 0 in parallel with K_s, kg/s [default: the surface's]
    #[arg(long, value_name = "KG_PER_S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub surface_damping: Option<f64>,
    /// The mass that moves with the surface, kg (`inf`: fixed) [default: the surface's]
    #[arg(long, value_name = "KG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub surface_mass: Option<f64>,
}

impl SurfaceArgs {
    /// The surface asked for: the named one (the default's when none) read from the catalog
    /// (embedded, then the user's surfaces folder), the explicit numbers over it.
    pub fn resolve(&self) -> anyhow::Result<SurfaceUsed> {
        let named = match &self.surface {
            None => SurfaceUsed::rigid_plate(),
            Some(name) => {
                let all = catalog::load(catalog::user_surfaces_dir().as_deref())?;
                // the flag named before the catalog's words (`invalid --surface: unknown …`)
                let entry = catalog::find(&all, name)
                    .map_err(|e| anyhow::anyhow!("invalid --surface: {e}"))?;
                SurfaceUsed::from_entry(&entry)
            }
        };
        let given = [
            self.surface_stiffness,
            self.surface_damping,
            self.surface_mass,
        ];
        let used = named.with_normal(given).map_err(|e| match e {
            SurfaceError::Invalid(e) => anyhow::anyhow!(
                "{}",
                e.to_string()
                    .replace("target_stiffness", "surface_stiffness")
                    .replace("target_damping", "surface_damping")
                    .replace("target_mass", "surface_mass")
            ),
            SurfaceError::RigidDashpot(damping) => anyhow::anyhow!(
                "invalid surface_damping: {}: a rigid surface's dashpot does nothing; give \
                     --surface-stiffness too",
                crate::text::short(damping, 6)
            ),
        })?;
        Ok(used)
    }
}

/// `bouncelab surfaces`.
#[derive(Debug, Clone, Args)]
pub struct SurfacesArgs {
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

#[derive(Serialize)]
struct Row<'a> {
    #[serde(flatten)]
    surface: &'a Surface,
    origin: String,
    default: bool,
}

/// `bouncelab surfaces`: every surface known, its numbers and its sources.
pub fn list(a: &SurfacesArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let dir = catalog::user_surfaces_dir();
    let all = catalog::load(dir.as_deref())?;
    let rows: Vec<Row> = all
        .iter()
        .map(|e| Row {
            surface: &e.surface,
            origin: e.origin.to_string(),
            default: e.surface.name == DEFAULT,
        })
        .collect();
    if a.format == TextJson::Json {
        return Ok(output::json(out, &rows)?);
    }
    let opt = |v: Option<f64>| v.map_or("—".to_string(), |x| human(x, 4));
    let inf = |v: f64, word: &str| {
        if v.is_infinite() {
            word.to_string()
        } else {
            human(v, 4)
        }
    };
    let mut t = vec![
        [
            "name",
            "K_s (N/m)",
            "c_s (kg/s)",
            "M (kg)",
            "μ",
            "K_t (N/m)",
            "c_t (kg/s)",
            "origin",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for e in &all {
        let s = &e.surface.mechanics;
        t.push(vec![
            e.surface.name.clone(),
            inf(s.stiffness, "rigid"),
            human(s.damping, 4),
            inf(s.mass, "fixed"),
            opt(s.friction),
            opt(s.tangential_stiffness),
            opt(s.tangential_damping),
            e.origin.to_string(),
        ]);
    }
    table(out, "", &t)?;
    writeln!(out)?;
    writeln!(
        out,
        "sources (— : not given; the command's option or default applies):"
    )?;
    for e in &all {
        writeln!(out, "  {}: {}", e.surface.name, e.surface.description)?;
        for s in &e.surface.sources {
            writeln!(out, "    {}: {}", s.quantity, s.source)?;
        }
    }
    writeln!(out)?;
    match dir {
        Some(d) => writeln!(out, "user surfaces are read from {}/*.toml", d.display())?,
        None => writeln!(
            out,
            "user surfaces: neither XDG_CONFIG_HOME nor HOME is set, so none are read"
        )?,
    }
    Ok(())
}
