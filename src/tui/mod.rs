//! The live terminal explorer (ratatui). Entry point: [`run`].
//!
//! Layout of the module, after ratatui's event-driven template (the Elm architecture):
//! [`app`] holds the state and `update(action) -> effects`, the only place it changes (curves
//! are computed there, in [`compute`], with the library); [`action`] maps keys to actions;
//! [`event`] is the loop, which carries out the [`effect`]s; [`ui`] lays the screen out and
//! [`widgets`] draw it, each from the few things it shows — a chart from its figure
//! (`crate::figure::explorer`), the same one the export writes; [`export`] writes the current
//! view's figures as SVG and CSV files (`e`) and [`save`] the current setting as a user preset
//! file (`s`): in both `update` only asks, the loop writes. The COR-vs-speed sweeps and the
//! models view's calibrations ([`views::models`]) run on background [`worker`]s.
//!
//! A view with state of its own has a folder in [`views`] — `map`, `models`, `drop`, and `fit`
//! (the measured data and the fit pane) — holding its state, its worker, its widget and its
//! export, and its part of `update` (`update.rs`). The map's first pass is computed in
//! `update`, the finer ones on its worker's thread. [`layout`] is the screen's geometry, which
//! `update` needs for the map's grid.
//!
//! The modules import each other without a cycle (tests/project/architecture.rs): state below
//! `update`, widgets and the loop above it.

pub mod action;
pub mod app;
pub mod background;
pub mod chartview;
pub mod clipboard;
pub mod command;
pub mod compute;
pub mod crosshair;
pub mod effect;
pub mod event;
pub mod exact;
pub mod export;
pub mod format;
pub mod keys;
pub mod layout;
pub mod palette;
pub mod param;
pub mod physical;
pub mod picker;
pub mod save;
pub mod session;
pub mod setting;
pub mod state;
pub mod surface;
pub mod theme;
pub mod ui;
pub mod views;
pub mod widgets;
pub mod worker;
pub mod workers;

use crate::preset::Preset;
use anyhow::Context;
use ratatui::crossterm::terminal;
use std::io::IsTerminal;

/// Whether to draw in colour: not when NO_COLOR is set to a non-empty value (no-color.org).
pub fn color_wanted() -> bool {
    std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
}

/// Whether to animate (the drop view): not when BOUNCELAB_REDUCED_MOTION is set to a
/// non-empty value, a reduced-motion setting in the manner of NO_COLOR.
pub fn motion_wanted() -> bool {
    std::env::var_os("BOUNCELAB_REDUCED_MOTION").is_none_or(|v| v.is_empty())
}

/// Open the explorer on `preset`; returns when the user quits. The terminal is restored on
/// every exit path: normal return, error, and panic (ratatui's hook restores it, then chains
/// the previous hook).
pub fn run(preset: Preset) -> anyhow::Result<()> {
    run_with_measured(preset, Vec::new())
}

/// [`run`], with measured data drawn on the charts (`bouncelab --measured FILE`).
pub fn run_with_measured(
    preset: Preset,
    measured: Vec<crate::figure::explorer::MeasuredOverlay>,
) -> anyhow::Result<()> {
    run_from(preset, measured, None, None)
}

/// [`run_with_measured`], with the measured file's data too, for the fit (`f`), and the
/// preset's file when it was read from `config` (`bouncelab --config FILE`), which "copy as
/// command" (`y`) then names.
pub fn run_from(
    preset: Preset,
    measured: Vec<crate::figure::explorer::MeasuredOverlay>,
    loaded: Option<views::fit::state::Loaded>,
    config: Option<std::path::PathBuf>,
) -> anyhow::Result<()> {
    run_app(
        app::App::new(preset, color_wanted()),
        measured,
        loaded,
        config,
    )
}

/// [`run_from`] on an explorer already set up: opened in the state the command line gave
/// (`bouncelab --preset golf --law hertz --v0 3 …`, src/cli/explore.rs).
pub fn run_app(
    app: app::App,
    measured: Vec<crate::figure::explorer::MeasuredOverlay>,
    loaded: Option<views::fit::state::Loaded>,
    config: Option<std::path::PathBuf>,
) -> anyhow::Result<()> {
    if !std::io::stdout().is_terminal() {
        anyhow::bail!("the explorer needs a terminal (stdout is not one); see `bouncelab --help`");
    }
    remove_stale_temporaries();
    let mut app = app
        .with_background_sweeps()
        .with_osc52(clipboard::osc52_here())
        .with_motion(motion_wanted())
        .with_color_depth(palette::detect(
            std::env::var("COLORTERM").ok().as_deref(),
            std::env::var("TERM").ok().as_deref(),
        ))
        .with_measured(measured);
    if let Some(l) = loaded {
        app = app.with_loaded(l);
    }
    if let Some(path) = config {
        app = app.with_config(std::path::absolute(&path).unwrap_or(path));
    }
    let terminal = ratatui::try_init();
    // over ratatui's hook (which restores the terminal on a panic): a worker's panic is the
    // view's to report, the explorer goes on (src/tui/background.rs)
    background::quiet_worker_panics();
    let mut terminal = terminal
        .inspect_err(|_| {
            if terminal::is_raw_mode_enabled().unwrap_or(false) {
                ratatui::restore();
            }
        })
        .context("cannot set the terminal up for the explorer")?;
    // a terminating signal restores the terminal too, then exits 128 + n (crate::signals)
    let guard = crate::signals::TerminalGuard::new(restore_all, resume_all);
    let result = guard
        .map_err(anyhow::Error::from)
        .and_then(|_guard| event::run(&mut terminal, &mut app));
    ratatui::restore();
    print_last_command(&app);
    result
}

/// The last line `y` showed, on the main screen once the explorer has left it: one line the
/// scrollback keeps whole, however narrow the explorer's box was (docs/explorer.md, `y`).
fn print_last_command(app: &app::App) {
    if let Some(line) = app.last_command() {
        use std::io::Write;
        // a failure to print loses only this reminder: the line was on screen
        let _ = writeln!(std::io::stdout(), "{line}");
    }
}

/// Raw mode off, the main screen back, the cursor shown.
fn restore_all() {
    // errors ignored: after SIGHUP the terminal is gone (ratatui::restore would print them)
    let _ = ratatui::try_restore();
    let _ = ratatui::crossterm::execute!(std::io::stdout(), ratatui::crossterm::cursor::Show);
}

/// After a suspension (Ctrl-Z, SIGTSTP; crate::signals): raw mode, the alternate screen, the
/// cursor hidden, as `ratatui::try_init` left them.
fn resume_all() {
    let _ = terminal::enable_raw_mode();
    let _ = ratatui::crossterm::execute!(
        std::io::stdout(),
        terminal::EnterAlternateScreen,
        terminal::Clear(terminal::ClearType::All),
        ratatui::crossterm::cursor::Hide
    );
}

/// Saves and exports killed mid-write (kill -9) leave their temporary files: remove those of
/// processes that are gone, in the presets folder and among the export's files
/// (tests/tui/tui_exit_pty.rs, `the_debris_of_a_killed_save_is_removed_at_start`).
fn remove_stale_temporaries() {
    if let Some(dir) = crate::catalog::user_presets_dir() {
        crate::atomic::remove_stale(&dir, |name| name.ends_with(".toml"));
    }
    crate::atomic::remove_stale(&export::dir_from_env(), |name| {
        name.starts_with("bouncelab-")
    });
}
