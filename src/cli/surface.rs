//! The surface a command runs on (docs/surfaces.md): `--surface NAME` and the explicit
//! `--surface-stiffness`, `--surface-damping`, `--surface-mass` (overriding the named
//! surface's), resolved against the embedded and user surfaces; the JSON `surface` object
//! every answer on a surface carries; and `bouncelab surfaces`, which lists them.

use super::output::{self, human, table};
use crate::catalog::Origin;
use crate::catalog::surfaces::{self as catalog, SurfaceEntry};
use crate::target::Target;
use crate::target::surface::{DEFAULT, Surface};
use clap::{Args, ValueEnum};
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

/// The surface a command ran on: the named one with the command line's overrides.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceUsed {
    /// The surface's name.
    pub name: String,
    /// `embedded` or the file it was read from.
    pub origin: String,
    /// K_s, N/m (`null`: rigid).
    pub stiffness: f64,
    /// c_s, kg/s.
    pub damping: f64,
    /// The moving mass, kg (`null`: fixed).
    pub mass: f64,
    /// μ the answer used (`null` where the command uses none).
    pub friction: Option<f64>,
    /// K_t the answer used, N/m.
    pub tangential_stiffness: Option<f64>,
    /// c_t the answer used, kg/s.
    pub tangential_damping: Option<f64>,
    /// The quantities given on the command line over the surface's own, in the order above.
    pub overrides: Vec<&'static str>,
}

impl SurfaceUsed {
    /// The normal part: a target at rest.
    pub fn target(&self) -> Target {
        Target {
            mass: self.mass,
            speed: 0.0,
            stiffness: self.stiffness,
            damping: self.damping,
        }
    }

    /// Whether the answer is the rigid plate's (rigid and immovable).
    pub fn is_rigid(&self) -> bool {
        self.stiffness == f64::INFINITY && self.mass == f64::INFINITY
    }

    /// The tangential quantities the answer used, with the flags that set them over the
    /// surface's own recorded as overrides: μ, K_t, c_t (each: the flag, else the surface's).
    pub fn with_tangential(
        mut self,
        friction: Option<f64>,
        stiffness: Option<f64>,
        damping: Option<f64>,
    ) -> SurfaceUsed {
        let mut take = |flag: Option<f64>, own: Option<f64>, name, out: &mut Option<f64>| {
            if flag.is_some() && own.is_some() {
                self.overrides.push(name);
            }
            *out = flag.or(own);
        };
        let (mut f, mut k, mut c) = (None, None, None);
        take(friction, self.friction, "friction", &mut f);
        take(
            stiffness,
            self.tangential_stiffness,
            "tangential_stiffness",
            &mut k,
        );
        take(
            damping,
            self.tangential_damping,
            "tangential_damping",
            &mut c,
        );
        (
            self.friction,
            self.tangential_stiffness,
            self.tangential_damping,
        ) = (f, k, c);
        self
    }

    /// One line for a text header: "surface steel-plate (rigid, immovable)" or with its
    /// numbers and μ.
    pub fn label(&self) -> String {
        let normal = (self.stiffness, self.damping, self.mass);
        crate::api::surface_label(&self.name, normal, self.friction, &self.overrides)
    }
}

impl SurfaceArgs {
    /// The surface asked for: the named one (the default's when none) read from the catalog
    /// (embedded, then the user's surfaces folder), the explicit numbers over it.
    pub fn resolve(&self) -> anyhow::Result<SurfaceUsed> {
        let entry = match &self.surface {
            None => SurfaceEntry {
                surface: Surface::rigid_plate(),
                origin: Origin::Embedded,
            },
            Some(name) => {
                let all = catalog::load(catalog::user_surfaces_dir().as_deref())?;
                catalog::find(&all, name).map_err(anyhow::Error::msg)?
            }
        };
        let s = &entry.surface;
        let mut used = SurfaceUsed {
            name: s.name.clone(),
            origin: entry.origin.to_string(),
            stiffness: s.stiffness,
            damping: s.damping,
            mass: s.mass,
            friction: s.friction,
            tangential_stiffness: s.tangential_stiffness,
            tangential_damping: s.tangential_damping,
            overrides: Vec::new(),
        };
        let flags = [
            ("stiffness", self.surface_stiffness),
            ("damping", self.surface_damping),
            ("mass", self.surface_mass),
        ];
        for (name, value) in flags {
            let Some(v) = value else { continue };
            used.overrides.push(name);
            match name {
                "stiffness" => used.stiffness = v,
                "damping" => used.damping = v,
                _ => used.mass = v,
            }
        }
        used.target().validate().map_err(|e| {
            anyhow::anyhow!(
                "{}",
                e.to_string()
                    .replace("target_stiffness", "surface_stiffness")
                    .replace("target_damping", "surface_damping")
                    .replace("target_mass", "surface_mass")
            )
        })?;
        if used.stiffness.is_infinite() && used.damping > 0.0 && self.surface_damping.is_some() {
            anyhow::bail!(
                "invalid surface_damping: {}: a rigid surface's dashpot does nothing; give \
                 --surface-stiffness too",
                crate::text::short(used.damping, 6)
            );
        }
        Ok(used)
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SurfacesFormat {
    Text,
    Json,
}

/// `bouncelab surfaces`.
#[derive(Debug, Clone, Args)]
pub struct SurfacesArgs {
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: SurfacesFormat,
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
    if a.format == SurfacesFormat::Json {
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
        let s = &e.surface;
        t.push(vec![
            s.name.clone(),
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
