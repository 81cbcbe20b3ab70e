//! The headless command line (clap). Entry point: [`main`].
//!
//! Every failure is one line on stderr, `bouncelab: error: …`, naming the field at fault (and
//! `file:line:column` for a preset file). Exit codes: 0 success (also when stdout is closed
//! early, e.g. `| head`), 2 bad input of any kind (arguments, presets, out-of-reach fits),
//! 1 a failure that is not the input's fault (writing the output, the explorer's terminal, an
//! impact without an answer). The library's errors are typed; `exit_code` alone maps their
//! kinds to these codes (`exit`).

pub mod ball;
pub mod bat;
pub mod batch;
mod batch_text;
pub mod budget;
pub mod collide;
pub mod conditions;
pub mod court;
mod csv_stated;
pub mod drop;
mod drop_json;
mod drop_leak;
mod drop_text;
mod exit;
pub mod explore;
pub mod figure;
pub mod fit;
mod intervals_text;
pub mod map;
pub use crate::measured::file as measured_file;
pub use crate::text::parse as number;
pub mod mc;
pub mod mc_shot;
mod mc_text;
pub mod oblique;
pub mod output;
pub mod outputs;
pub mod peers;
pub mod presets;
pub mod reproduce;
pub mod run;
mod run_text;
pub mod shot;
mod shot_after;
pub mod shot_net;
pub mod standards;
pub mod statics;
pub mod surface;
pub mod sweep;

use clap::{Parser, Subcommand};
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const ABOUT: &str = "The Christoforou–Yigit model of a deformable ball hitting a rigid wall: \
coefficient of restitution, peak force and contact time.";

const AFTER_HELP: &str = "With no subcommand, opens the terminal explorer on a preset \
(default: superball).\nUser presets: $XDG_CONFIG_HOME/bouncelab/presets/*.toml \
(default ~/.config/bouncelab/presets).";

#[derive(Debug, Parser)]
#[command(name = "bouncelab", version, about = ABOUT, after_help = AFTER_HELP)]
#[command(mut_arg("preset", |a| a.help("Preset the explorer opens on [default: superball]")))]
#[command(mut_arg("config", |a| {
    a.help("Preset file the explorer opens on (TOML, same schema as the embedded presets)")
}))]
#[command(mut_arg("params", |a| {
    a.help("Parameter set of the preset the explorer opens on [default: the preset's]")
}))]
#[command(mut_arg("law", |a| a.help("Contact law the explorer opens on [default: the preset's]")))]
pub struct Cli {
    /// The preset the explorer opens on, or the one a subcommand runs
    /// (`bouncelab --preset golf run` is `bouncelab run --preset golf`)
    #[command(flatten)]
    pub choice: ball::PresetChoice,
    /// Measured data the explorer draws on its charts (force–time trace, COR table or drop
    /// test; CSV, labelled by its file name)
    #[arg(long, value_name = "FILE")]
    pub measured: Option<PathBuf>,
    /// The state the explorer opens in: `run`'s options (src/cli/explore.rs)
    #[command(flatten)]
    pub explore: explore::ExplorerArgs,
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Simulate one impact: COR, peak force, contact time, indentation, energy budget
    #[command(allow_negative_numbers = true)]
    Run(run::RunArgs),
    /// Sweep ζ (normalized, Figs. 2–3) or the impact speed of a ball (Fig. 4)
    #[command(subcommand)]
    Sweep(sweep::Sweep),
    /// Fit the model to measurements: one COR (K_r), a COR table, a force–time trace or drop
    /// tests (several parameters, with intervals)
    #[command(allow_negative_numbers = true)]
    Fit(fit::FitArgs),
    /// List the embedded and user presets
    Presets(presets::PresetsArgs),
    /// Draw one of the paper's figures as SVG (and its data as CSV)
    #[command(allow_negative_numbers = true)]
    Figure(figure::FigureArgs),
    /// Write every figure, its data and a report of model against experiment into a folder
    Reproduce(reproduce::ReproduceArgs),
    /// Drop a ball onto a rigid plate: its bounces, and a verdict against a standard
    #[command(allow_negative_numbers = true)]
    Drop(drop::DropArgs),
    /// List the ball standards (drop and COR tests) and their windows
    Standards(standards::StandardsArgs),
    /// List the embedded and user surfaces: their give, friction and sources
    Surfaces(surface::SurfacesArgs),
    /// The ball squeezed between two plates under a load: forward and return deflection
    /// (the ITF deformation tests; docs/cli.md)
    #[command(allow_negative_numbers = true)]
    Static(statics::StaticArgs),
    /// The field's contact models (Kelvin–Voigt, Tsuji, Hunt–Crossley) calibrated to a COR,
    /// beside this model; --export writes them for LAMMPS, LIGGGHTS, Chrono, YADE or MuJoCo
    #[command(allow_negative_numbers = true)]
    Peers(peers::PeersArgs),
    /// COR, peak force and contact time over a (λ, ζ) grid, with targets: CSV, JSON or an SVG
    /// heat map (docs/map.md)
    Map(map::MapArgs),
    /// The ball against a target of mass M moving at v_t, rigid or with a surface that gives:
    /// the pair's COR, the apparent COR, both outgoing speeds (docs/targets.md)
    #[command(allow_negative_numbers = true)]
    Collide(collide::CollideArgs),
    /// A bat of effective mass M_eff: batted-ball speed, and the NCAA BBCOR test with a verdict
    #[command(allow_negative_numbers = true)]
    Bat(bat::BatArgs),
    /// Monte Carlo over a ball's parameter tolerances: quantiles, mean and sd of the COR, peak
    /// force and contact time (docs/scale.md)
    #[command(allow_negative_numbers = true)]
    Mc(mc::McArgs),
    /// A batch of balls in one CSV (an id column): one fit and one verdict per ball against a
    /// standard, the summary with Cpk (docs/batch.md)
    #[command(allow_negative_numbers = true)]
    Batch(batch::BatchArgs),
    /// An oblique impact with friction and spin: outgoing speed, angle and spin, the
    /// tangential COR and the grip (docs/oblique.md)
    #[command(allow_negative_numbers = true)]
    Oblique(oblique::ObliqueArgs),
    /// The ITF Court Pace Rating of a surface of friction μ (ITF CS 01/02, docs/oblique.md)
    Court(court::CourtArgs),
    /// A shot: flight with drag and Magnus lift, bounces by `oblique`, where it lands and
    /// where it is at the end (docs/flight.md)
    #[command(allow_negative_numbers = true)]
    Shot(shot::ShotArgs),
}

pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return exit::clap_error(e),
    };
    if cli.command.is_none() {
        // the explorer must not hold the stdout lock: on a signal, crate::signals takes it to
        // restore the terminal
        return explorer(cli.choice, &cli.explore, cli.measured)
            .map_or_else(exit::fail, |()| ExitCode::SUCCESS);
    }
    // every command watches SIGINT, SIGTERM, SIGHUP and SIGQUIT from its start, so that a
    // signal in its first moments, before any long work asked, still stops it with 130 and
    // nothing written (tests/cli/signals_early.rs)
    budget::interrupt_flag();
    budget::stop_on_tstp();
    if crate::fault::Fault::SlowStart.active() {
        std::thread::sleep(crate::fault::START_PAUSE);
    }
    let stdout = io::stdout();
    // no control character reaches the terminal, whatever a preset or path holds
    let mut out = crate::sanitize::Writer::new(io::BufWriter::new(stdout.lock()));
    let result = dispatch(cli, &mut out).and_then(|()| out.flush().map_err(Into::into));
    match result {
        // a command with nothing to publish that a signal came to still says so
        Ok(()) if budget::interrupted() => exit::fail(budget::Interrupted.into()),
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => exit::fail(e),
    }
}

fn dispatch(cli: Cli, out: &mut dyn Write) -> anyhow::Result<()> {
    let top = cli.choice;
    let Some(command) = cli.command else {
        return explorer(top, &cli.explore, cli.measured);
    };
    explorer_options_refused(&cli.explore, cli.measured.as_deref())?;
    match command {
        Command::Run(mut a) => {
            if a.normalized {
                no_ball_choice(&top, NORMALIZED_WITH_CHOICE)?;
            }
            merge(top, &mut a.ball)?;
            run::run(&a, out)
        }
        Command::Sweep(sweep::Sweep::Velocity(mut a)) => {
            merge(top, &mut a.ball)?;
            sweep::run(&sweep::Sweep::Velocity(a), out)
        }
        Command::Sweep(s) => {
            no_ball_choice(
                &top,
                "sweep zeta runs the normalized ball: --preset and --config do not apply",
            )?;
            sweep::run(&s, out)
        }
        Command::Fit(a) => with_ball(top, a, |a| &mut a.ball, fit::run, out),
        Command::Presets(mut a) => {
            merge_config(top, &mut a.choice)?;
            presets::run(&a, out)
        }
        Command::Figure(mut a) => {
            a.settle()?;
            merge(top, &mut a.ball)?;
            figure::run(&a, out)
        }
        Command::Peers(a) => with_ball(top, a, |a| &mut a.ball, peers::run, out),
        Command::Reproduce(a) => {
            no_ball_choice(
                &top,
                "reproduce runs the paper's three embedded balls: --preset and --config do \
                 not apply",
            )?;
            reproduce::run(&a, out)
        }
        Command::Map(mut a) => {
            merge_map_choice(top, &mut a)?;
            map::run(&a, out)
        }
        Command::Drop(a) => with_ball(top, a, |a| &mut a.ball, drop::run, out),
        Command::Collide(a) => with_ball(top, a, |a| &mut a.ball, collide::run, out),
        Command::Bat(a) => with_ball(top, a, |a| &mut a.ball, bat::run, out),
        Command::Mc(a) => with_ball(top, a, |a| &mut a.ball, mc::run, out),
        Command::Batch(a) => with_ball(top, a, |a| &mut a.ball, batch::run, out),
        Command::Oblique(a) => with_ball(top, a, |a| &mut a.ball, oblique::run, out),
        Command::Court(a) => with_ball(top, a, |a| &mut a.ball, court::run, out),
        Command::Shot(a) => with_ball(top, a, |a| &mut a.ball, shot::run, out),
        Command::Static(a) => with_ball(top, a, |a| &mut a.ball, statics::run, out),
        Command::Standards(a) => {
            no_ball_choice(
                &top,
                "standards lists the standards: --preset and --config do not apply",
            )?;
            standards::run(&a, out)
        }
        Command::Surfaces(a) => {
            no_ball_choice(
                &top,
                "surfaces lists the surfaces: --preset and --config do not apply",
            )?;
            surface::list(&a, out)
        }
    }
}

/// The explorer's options given before a subcommand: refused, with where they belong.
fn explorer_options_refused(
    explore: &explore::ExplorerArgs,
    measured: Option<&Path>,
) -> anyhow::Result<()> {
    if let Some(option) = explore.given() {
        anyhow::bail!(
            "{option} before a subcommand is for the explorer; give it after the subcommand"
        );
    }
    if let Some(m) = measured {
        anyhow::bail!(
            "--measured before a subcommand is for the explorer; to draw {} on a figure use \
             `bouncelab figure NAME --measured FILE`, to fit it `bouncelab fit`",
            m.display()
        );
    }
    Ok(())
}

/// `--normalized` is a ball of its own (m = K_p = v0 = 1): no preset before the subcommand.
const NORMALIZED_WITH_CHOICE: &str = "--normalized cannot be used with --preset or --config";

/// `--preset`/`--config` before a subcommand that runs no chosen ball: refused with `why`.
fn no_ball_choice(top: &ball::PresetChoice, why: &'static str) -> anyhow::Result<()> {
    match top.is_given() {
        true => Err(anyhow::Error::msg(why)),
        false => Ok(()),
    }
}

/// `bouncelab --preset P map` means `bouncelab map --preset P`: not with `--normalized`, nor
/// with a choice after the subcommand too.
fn merge_map_choice(top: ball::PresetChoice, a: &mut map::MapArgs) -> anyhow::Result<()> {
    if a.normalized {
        no_ball_choice(&top, NORMALIZED_WITH_CHOICE)?;
    }
    if top.is_given() {
        if a.choice.is_given() {
            anyhow::bail!("--preset/--config given both before and after the subcommand");
        }
        a.choice = top;
    }
    Ok(())
}

/// `bouncelab --config F presets` means `bouncelab presets --config F`; `presets` takes no
/// `--preset`, before the subcommand or after it.
fn merge_config(top: ball::PresetChoice, choice: &mut ball::PresetChoice) -> anyhow::Result<()> {
    if top.preset.is_some() || choice.preset.is_some() {
        anyhow::bail!("presets lists every preset: --preset does not apply");
    }
    if let Some(c) = top.config {
        if choice.config.is_some() {
            anyhow::bail!("--config given twice");
        }
        choice.config = Some(c);
    }
    Ok(())
}

/// A command that runs one ball: the preset chosen before the subcommand merged into its
/// own options (`merge`), then its `run`.
fn with_ball<A>(
    top: ball::PresetChoice,
    mut args: A,
    ball: fn(&mut A) -> &mut ball::BallArgs,
    run: fn(&A, &mut dyn Write) -> anyhow::Result<()>,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    merge(top, ball(&mut args))?;
    run(&args, out)
}

/// `bouncelab --preset golf run` means `bouncelab run --preset golf`.
fn merge(top: ball::PresetChoice, ball: &mut ball::BallArgs) -> anyhow::Result<()> {
    if !top.is_given() {
        return Ok(());
    }
    if ball.choice.is_given() {
        anyhow::bail!("--preset/--config given both before and after the subcommand");
    }
    ball.choice = top;
    Ok(())
}

/// No subcommand: the explorer, which needs a terminal.
fn explorer(
    choice: ball::PresetChoice,
    state: &explore::ExplorerArgs,
    measured: Option<PathBuf>,
) -> anyhow::Result<()> {
    // a session names its own measured file, or none (docs/explorer.md, Sessions)
    if let (Some(_), Some(m)) = (&state.session, &measured) {
        anyhow::bail!(
            "--measured {}: --session restores the whole state; give one of them",
            m.display()
        );
    }
    // the state's options (or session) are checked before the terminal, as `run` checks them
    let (app, from_session) = state.app(&choice, crate::tui::color_wanted())?;
    let measured = measured.or(from_session);
    // a measured file is read and checked before anything else is asked of the user
    let data = match &measured {
        Some(path) => Some((measured_file::any(path)?, path)),
        None => None,
    };
    if !io::stdout().is_terminal() {
        anyhow::bail!(
            "the explorer needs a terminal and stdout is not one; for headless output use \
             `bouncelab run` (e.g. `bouncelab run --preset superball --format json`)"
        );
    }
    let (overlays, loaded) = match data {
        Some((data, path)) => {
            let p = app.setting().params;
            let label = measured_file::label(path);
            let overlays =
                crate::figure::explorer::MeasuredOverlay::from_data(&data, &label, p.mass, p.v0)
                    .map_err(|e| measured_file::at(path, e))?;
            let path = path.clone();
            let loaded = crate::tui::views::fit::state::Loaded { path, label, data };
            (overlays, Some(loaded))
        }
        None => (Vec::new(), None),
    };
    let config = choice.config.clone();
    crate::tui::run_app(app, overlays, loaded, config).map_err(|e| exit::ExplorerFailed(e).into())
}
