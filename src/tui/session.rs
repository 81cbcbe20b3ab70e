//! Sessions (issue 29 item 3): `S` writes the explorer's state to a TOML file, `bouncelab
//! --session FILE` opens the explorer in it again — the ball (its preset and every parameter,
//! SI), the law, v0, the target, the pins, the measured file (by path), the view, the
//! selected parameter, the map's quantity, targets and window (`map`), the fit pane's fit
//! (`fit`), the oblique view's θ, ω, μ, K_t, κ (`oblique`, version 2) and the flight view's
//! launch and μ (`flight`, version 3) (docs/explorer.md,
//! "Sessions"). Written atomically (src/atomic.rs); a
//! file that does not read is one line `FILE:LINE:COLUMN: why`, exit 2.

pub mod fit;
pub mod flight;
pub mod map;
pub mod oblique;

use super::app::{App, Held};
use super::param::Param;
use super::setting::Setting;
use super::state::View;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The session file's version: what this explorer writes. Version 2 added the `[oblique]`
/// table, version 3 the `[flight]` table; older files (without them) still read ([`READS`]).
pub const VERSION: u32 = 3;
/// The versions this explorer reads.
pub const READS: [u32; 3] = [1, 2, VERSION];

/// The explorer's state as the file holds it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Session {
    pub version: u32,
    /// The view shown: impact, sweeps, models, map or drop.
    pub view: String,
    /// The parameter the arrows move (the cursor): lambda, zeta or v0.
    pub selected: String,
    /// The measured file drawn and fitted to, by path (read again on restore).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub measured: Option<PathBuf>,
    /// The current setting.
    pub ball: Ball,
    /// The map view's quantity, targets and window (absent: the defaults).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map: Option<map::MapState>,
    /// The fit pane's finished fit (absent: none, or one still running).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit: Option<fit::Fit>,
    /// The oblique view's values, page and map quantity (absent: its defaults).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub oblique: Option<oblique::ObliqueState>,
    /// The flight view's launch, μ and selected value (absent: its defaults; version 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flight: Option<flight::FlightState>,
    /// The pinned settings, oldest first.
    #[serde(default)]
    pub pins: Vec<Ball>,
}

/// One setting: the ball by its preset's name, the law, its parameters and the target (SI;
/// `inf` for an infinite mass or stiffness).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ball {
    pub preset: String,
    pub law: String,
    pub radius: f64,
    pub elastomer: bool,
    pub target_mass: f64,
    pub target_speed: f64,
    pub target_stiffness: f64,
    pub target_damping: f64,
    /// The inflation pressure (Pa) and temperature (°C) typed in the form, as `--pressure`
    /// and `--temperature` (absent: the record's; version 3). `params` are the ball's at them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<f64>,
    /// The surface chosen (`G`), by name as `--surface` takes it (absent: none; version 3):
    /// read again from the embedded and user surfaces; the target above may differ from it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surface: Option<String>,
    /// c_t, kg/s (absent: none; version 3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_damping: Option<f64>,
    pub params: ImpactParams,
}

fn param_name(p: Param) -> &'static str {
    match p {
        Param::Lambda => "lambda",
        Param::Zeta => "zeta",
        Param::V0 => "v0",
    }
}

impl App {
    /// The session of the current state (`S`).
    pub fn session(&self) -> Session {
        Session {
            version: VERSION,
            view: self.view.name().into(),
            selected: param_name(self.selected).into(),
            measured: self.fit.loaded.as_ref().map(|l| l.path.clone()),
            ball: self.session_ball(&self.setting),
            map: Some(map::MapState::of(&self.map)),
            fit: self.fit.pane.as_ref().and_then(fit::Fit::of),
            oblique: Some(oblique::ObliqueState::of(&self.oblique)),
            flight: Some(flight::FlightState::of(&self.flight)),
            pins: self
                .pins
                .iter()
                .map(|g| self.session_ball(&g.setting))
                .collect(),
        }
    }

    /// What the session of this state holds of what `q` asks for (src/tui/app/quit.rs).
    pub(in crate::tui) fn held(&self) -> Held {
        Held {
            pins: self.pins.iter().map(|g| g.setting.clone()).collect(),
            measured: self.fit.loaded.as_ref().map(|l| l.path.clone()),
            fit: (self.fit.pane.as_ref())
                .and_then(fit::Fit::of)
                .map(|f| format!("{f:?}")),
        }
    }

    /// A setting as the session file holds it.
    fn session_ball(&self, s: &Setting) -> Ball {
        Ball {
            preset: self.presets[s.preset].name.clone(),
            law: s.law.name().into(),
            radius: s.radius,
            elastomer: s.elastomer,
            target_mass: s.target.mass,
            target_speed: s.target.speed,
            target_stiffness: s.target.stiffness,
            target_damping: s.target.damping,
            pressure: s.conditions.pressure,
            temperature: s.conditions.temperature,
            surface: s.surface.as_ref().map(|x| x.name.clone()),
            tangential_damping: s.tangential_damping,
            params: s.params,
        }
    }

    /// This explorer in `session`'s state: the pins pinned again (their runs recomputed), the
    /// setting, view and cursor; or why not (a preset the explorer does not hold, a name it
    /// does not know). The measured file is the caller's to read.
    pub fn with_session(mut self, session: &Session) -> Result<App, String> {
        for pin in &session.pins {
            self.setting = self.setting_of(pin)?;
            self.refresh();
            self.pin();
        }
        self.setting = self.setting_of(&session.ball)?;
        self.view = View::ALL
            .into_iter()
            .find(|&v| v.name() == session.view)
            .ok_or_else(|| format!("view: unknown view '{}'", session.view))?;
        self.selected = [Param::Lambda, Param::Zeta, Param::V0]
            .into_iter()
            .find(|&p| param_name(p) == session.selected)
            .ok_or_else(|| format!("selected: unknown parameter '{}'", session.selected))?;
        if let Some(m) = &session.map {
            m.restore(&mut self.map)?;
        }
        if let Some(f) = &session.fit {
            self.fit.id += 1;
            self.fit.pane = Some(f.pane(self.fit.id)?);
        }
        if let Some(o) = &session.oblique {
            o.restore(&mut self.oblique)?;
        }
        if let Some(f) = &session.flight {
            let ball = self.oblique_ball();
            f.restore(&mut self.flight, &ball)?;
        }
        self.undo.clear();
        self.keep();
        // the measured file is read after this, by the caller: held by path already
        self.session_held = Some(Held {
            measured: session.measured.clone(),
            ..self.held()
        });
        self.message = None;
        // a session goes on where it was: its readout shows the calibration warning, the
        // message line stays clear (src/tui/app/calibration.rs says it only on a fresh start)
        self.calibration_said = Some(String::new());
        self.refresh();
        Ok(self)
    }

    fn setting_of(&self, b: &Ball) -> Result<Setting, String> {
        let preset = self
            .presets
            .iter()
            .position(|p| p.name == b.preset)
            .ok_or_else(|| format!("preset: '{}' is not among the explorer's balls", b.preset))?;
        let law: ContactLaw = b
            .law
            .parse()
            .map_err(|_| format!("law: unknown law '{}'", b.law))?;
        let s = Setting {
            preset,
            params: b.params,
            law,
            radius: b.radius,
            elastomer: b.elastomer,
            target: crate::target::Target {
                mass: b.target_mass,
                speed: b.target_speed,
                stiffness: b.target_stiffness,
                damping: b.target_damping,
            },
            conditions: crate::api::ConditionsSpec {
                pressure: b.pressure,
                temperature: b.temperature,
                ..Default::default()
            },
            record: crate::tui::setting::record(&self.presets[preset]),
            surface: b.surface.as_deref().map(surface_named).transpose()?,
            tangential_damping: b.tangential_damping,
        };
        if let Some(c) = s.tangential_damping
            && !(c.is_finite() && c >= 0.0)
        {
            return Err(format!(
                "tangential_damping: {c} (must be zero or positive, kg/s)"
            ));
        }
        // the radius as `run --radius` checks it (it sets the validity check, z_m < R)
        crate::model::params::check_positive(crate::model::params::Field::Radius, s.radius)
            .map_err(|e| e.to_string())?;
        s.params.validate().map_err(|e| e.to_string())?;
        s.target.validate().map_err(|e| e.to_string())?;
        // the conditions as `--pressure`, `--temperature` check them (the library's refusal)
        let preset = &self.presets[preset];
        crate::tui::physical::conditions::conditioned(
            preset,
            preset.params(),
            s.radius,
            &s.conditions,
        )?;
        Ok(s)
    }
}

impl Session {
    /// The file's text.
    pub fn to_toml(&self) -> String {
        let body = toml::to_string(self).expect("a session is plain numbers and names");
        format!("# bouncelab explorer session (docs/explorer.md, Sessions)\n{body}")
    }

    /// Read a session from `text` (the file `path`); an error is one line
    /// `PATH:LINE:COLUMN: why`.
    pub fn parse(path: &Path, text: &str) -> Result<Session, String> {
        let s: Session = toml::from_str(text).map_err(|e| {
            let at = e.span().map_or((1, 1), |r| line_column(text, r.start));
            let why = e
                .message()
                .lines()
                .next()
                .unwrap_or("not a session")
                .to_string();
            format!("{}:{}:{}: {why}", path.display(), at.0, at.1)
        })?;
        if !READS.contains(&s.version) {
            let line = text
                .lines()
                .position(|l| l.trim_start().starts_with("version"))
                .map_or(1, |i| i + 1);
            return Err(format!(
                "{}:{line}:1: version {} is not one this explorer reads (1, 2 or {VERSION})",
                path.display(),
                s.version
            ));
        }
        Ok(s)
    }
}

/// The surface `name` among the embedded and the user's surfaces, as `--surface` finds it; or
/// why not (`surface: …`, listing the names there are).
fn surface_named(name: &str) -> Result<crate::target::surface::Surface, String> {
    use crate::catalog::surfaces;
    let all = surfaces::load(surfaces::user_surfaces_dir().as_deref())
        .map_err(|e| format!("surface: {e}"))?;
    surfaces::find(&all, name)
        .map(|e| e.surface)
        .map_err(|e| format!("surface: {e}"))
}

/// The 1-based line and column (in characters) of byte `at` of `text`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
