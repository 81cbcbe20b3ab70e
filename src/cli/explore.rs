//! The explorer's own options (issue 29 item 2): every option `run` takes for a preset ball —
//! `--params`, `--law`, `--mass`, `--radius`, `--k-p`, `--damping`, `--k-r`, `--z-p`, `--v0`,
//! `--lambda`, `--zeta` — and the oblique view's `--angle`, `--spin`, `--friction` — so that `bouncelab --preset golf --law hertz --v0 3 --lambda 0.5`
//! opens the explorer in the state `bouncelab run` with the same options runs, and the line
//! `y` shows (the `run` line) gives that state back without `run`. The ball is built by
//! `run`'s own steps ([`BallArgs::resolve_tuned`]).

use super::ball::{self, BallArgs, PresetChanges, PresetChoice};
use crate::catalog::surfaces;
use crate::tui::app::App;
use crate::tui::session::Session;
use clap::Args;

/// The state options of the explorer, as `run` takes them.
#[derive(Debug, Clone, Default, Args)]
pub struct ExplorerArgs {
    /// `--params`, `--law` and the overrides, as `run` takes them; their help says "the
    /// explorer opens on" (`Cli`'s `mut_arg`, src/cli/mod.rs).
    #[command(flatten)]
    pub changes: PresetChanges,
    /// Impact speed v0 (m/s) the explorer opens on [default: the preset's]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// λ = K_r/K_p the explorer opens on (K_r moves; Eq. 24)
    #[arg(long, value_name = "L", value_parser = super::number::number, allow_hyphen_values = true)]
    pub lambda: Option<f64>,
    /// ζ = √(m K_p)/(2c) the explorer opens on (c moves; Eq. 24)
    #[arg(long, value_name = "Z", value_parser = super::number::number, allow_hyphen_values = true)]
    pub zeta: Option<f64>,
    /// θ (degrees to the surface, (0, 90]): the explorer opens on its oblique view (`i`)
    #[arg(long, value_name = "DEG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub angle: Option<f64>,
    /// ω (rad/s, > 0 topspin): the explorer opens on its oblique view
    #[arg(long, value_name = "RAD_PER_S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub spin: Option<f64>,
    /// μ: the explorer opens on its oblique view
    #[arg(long, value_name = "MU", value_parser = super::number::number, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// The target's mass M (kg; `inf`: the wall) the explorer opens on, as `collide`
    /// --target-mass takes it [default: the wall]
    #[arg(long, value_name = "KG", value_parser = super::number::number, allow_hyphen_values = true)]
    pub target_mass: Option<f64>,
    /// The target's speed v_t toward the ball (m/s), as `collide` --target-speed
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub target_speed: Option<f64>,
    /// The stiffness K_s of the target's surface (N/m; `inf`: rigid), as `collide`
    #[arg(long, value_name = "N/m", value_parser = super::number::number, allow_hyphen_values = true)]
    pub target_stiffness: Option<f64>,
    /// The damping c_s beside K_s (kg/s), as `collide` --target-damping
    #[arg(long, value_name = "kg/s", value_parser = super::number::number, allow_hyphen_values = true)]
    pub target_damping: Option<f64>,
    /// The surface (`bouncelab surfaces` lists them) the explorer opens on, as the surface
    /// picker (`G`) sets it; the --target-* options override its numbers
    #[arg(long, value_name = "NAME")]
    pub surface: Option<String>,
    /// The tangential dashpot c_t (kg/s) beside K_t the explorer opens on, as `oblique`
    /// --tangential-damping [default: the surface's, else none]
    #[arg(long, value_name = "KG_PER_S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_damping: Option<f64>,
    /// Inflation (gauge) pressure the explorer opens on, as `run` --pressure takes it: Pa, or
    /// with a unit (0.8bar, 8psi, 55kPa); inflated balls only [default: the preset's nominal]
    #[arg(long, value_name = "P", value_parser = super::conditions::pressure, allow_hyphen_values = true)]
    pub pressure: Option<f64>,
    /// The ball's temperature (°C) the explorer opens on, as `run` --temperature
    #[arg(long, value_name = "°C", value_parser = super::number::number, allow_hyphen_values = true)]
    pub temperature: Option<f64>,
    /// A session the explorer's `S` saved: the explorer opens in it again (docs/explorer.md)
    #[arg(long, value_name = "FILE", conflicts_with_all = ["preset", "config"])]
    pub session: Option<std::path::PathBuf>,
}

impl ExplorerArgs {
    /// The first option given, as the error before a subcommand names it.
    pub fn given(&self) -> Option<&'static str> {
        if let Some(flag) = self.changes.first_given() {
            return Some(flag);
        }
        [
            ("--v0", self.v0.is_some()),
            ("--lambda", self.lambda.is_some()),
            ("--zeta", self.zeta.is_some()),
            ("--angle", self.angle.is_some()),
            ("--spin", self.spin.is_some()),
            ("--friction", self.friction.is_some()),
            ("--target-mass", self.target_mass.is_some()),
            ("--target-speed", self.target_speed.is_some()),
            ("--target-stiffness", self.target_stiffness.is_some()),
            ("--target-damping", self.target_damping.is_some()),
            ("--surface", self.surface.is_some()),
            ("--tangential-damping", self.tangential_damping.is_some()),
            ("--pressure", self.pressure.is_some()),
            ("--temperature", self.temperature.is_some()),
            ("--session", self.session.is_some()),
        ]
        .into_iter()
        .find_map(|(name, on)| on.then_some(name))
    }

    /// The explorer in the state these options give the ball of `choice`, as `run` builds it
    /// (bad input: `run`'s one-line errors, exit 2), or in the session `--session` names, with
    /// the session's measured file.
    pub fn app(
        &self,
        choice: &PresetChoice,
        color: bool,
    ) -> anyhow::Result<(App, Option<std::path::PathBuf>)> {
        let Some(path) = &self.session else {
            return Ok((self.state_app(choice, color)?, None));
        };
        if let Some(option) = self.given().filter(|&o| o != "--session") {
            anyhow::bail!("{option}: --session restores the whole state; give one of them");
        }
        let text = read_session(path)?;
        let session = Session::parse(path, &text).map_err(|e| anyhow::anyhow!(e))?;
        // the session's ball by name: a preset this bouncelab lacks is the file's fault, named
        // (issue 51 item 8; tests/tui/tui_session.rs)
        let entry = ball::select(Some(&session.ball.preset), None)
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        let app = App::new(entry.preset, color)
            .with_session(&session)
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        Ok((app, session.measured))
    }

    fn state_app(&self, choice: &PresetChoice, color: bool) -> anyhow::Result<App> {
        let entry = ball::select(choice.preset.as_deref(), choice.config.as_deref())?;
        let args = BallArgs {
            choice: choice.clone(),
            changes: self.changes.clone(),
            conditions: super::conditions::ConditionsArgs {
                pressure: self.pressure,
                temperature: self.temperature,
                ..Default::default()
            },
        };
        let b = args.resolve_tuned(self.v0, self.lambda, self.zeta)?;
        let radius = b.measured.as_ref().map(|m| m.radius);
        let conditions = crate::api::ConditionsSpec {
            pressure: self.pressure,
            temperature: self.temperature,
            ..Default::default()
        };
        let app = App::new(entry.preset, color)
            .with_conditions(conditions)
            .with_start(b.params, b.law, radius);
        // the surface as `--surface` finds it, before the target's own options (which
        // override it) and the oblique ones (--friction over its μ)
        let app = match &self.surface {
            Some(name) => {
                let all = surfaces::load(surfaces::user_surfaces_dir().as_deref())?;
                let s = surfaces::find(&all, name).map_err(anyhow::Error::msg)?;
                app.with_surface(s.surface)
                    .map_err(|e| anyhow::anyhow!("--surface: {e}"))?
            }
            None => app,
        };
        let target = [
            self.target_mass,
            self.target_speed,
            self.target_stiffness,
            self.target_damping,
        ];
        // `collide`'s target, checked as the form (`m`) checks it (src/tui/physical.rs)
        let app = if target.iter().any(Option::is_some) {
            app.with_target(target).map_err(|e| anyhow::anyhow!(e))?
        } else {
            app
        };
        let app = match self.tangential_damping {
            Some(c) => app
                .with_tangential_damping(c)
                .map_err(|e| anyhow::anyhow!("--tangential-damping: {e}"))?,
            None => app,
        };
        let oblique = [self.angle, self.spin, self.friction];
        if oblique.iter().all(Option::is_none) {
            return Ok(app);
        }
        // `oblique`'s own checks and messages (tests/cli/cli_explorer_oblique.rs)
        app.with_oblique(oblique).map_err(|e| anyhow::anyhow!(e))
    }
}

/// Largest session file read: a session is a page of TOML (a few KiB); 1 MiB leaves room.
pub const MAX_SESSION_BYTES: u64 = 1 << 20;

/// The text of a session file: a regular file (a FIFO blocks its reader, a device may never
/// end),
/// at most [`MAX_SESSION_BYTES`], UTF-8, read as the data readers read
/// (`measured::file::read_text`); missing, unreadable or not UTF-8 is bad input, exit 2,
/// naming the file (tests/cli/session_file.rs).
fn read_session(path: &std::path::Path) -> anyhow::Result<String> {
    let say = |msg: String| anyhow::anyhow!("--session {}: {msg}", path.display());
    if let Ok(meta) = std::fs::metadata(path) {
        if meta.is_dir() {
            return Err(say("is a directory, not a session file".into()));
        }
        if !meta.is_file() {
            return Err(say(
                "is not a regular file (a FIFO, socket or device is not read)".into(),
            ));
        }
        if meta.len() > MAX_SESSION_BYTES {
            return Err(say(format!(
                "is {} bytes; a session file is at most {MAX_SESSION_BYTES} bytes",
                meta.len()
            )));
        }
    }
    // missing, unreadable, not UTF-8: `read_text`'s one line naming the file (no I/O error
    // in the chain, so exit 2)
    crate::measured::file::read_text(path).map_err(|e| anyhow::anyhow!("--session {e:#}"))
}
