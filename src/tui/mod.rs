//! The live terminal explorer (ratatui). Entry point: [`run`].
//!
//! Layout of the module, after ratatui's event-driven template:
//! [`app`] holds the state and `update(action)`, the only place it changes (curves are computed
//! there, in [`compute`], with the library); [`action`] maps keys to actions; [`event`] is the
//! loop; [`ui`] lays the screen out and [`widgets`] draw it, reading the state only; [`export`]
//! turns the current view into SVG and CSV files (`e`) and [`save`] the current setting into a
//! user preset file (`s`): in both `update` only asks, the loop writes.

pub mod action;
pub mod app;
pub mod compute;
pub mod drop_view;
pub mod event;
pub mod export;
pub mod format;
pub mod param;
pub mod save;
pub mod state;
pub mod theme;
pub mod ui;
pub mod widgets;
pub mod worker;

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
    if !std::io::stdout().is_terminal() {
        anyhow::bail!("the explorer needs a terminal (stdout is not one); see `bouncelab --help`");
    }
    let mut app = app::App::new(preset, color_wanted())
        .with_background_sweeps()
        .with_motion(motion_wanted());
    let mut terminal = ratatui::try_init()
        .inspect_err(|_| {
            if terminal::is_raw_mode_enabled().unwrap_or(false) {
                ratatui::restore();
            }
        })
        .context("cannot set the terminal up for the explorer")?;
    let result = event::run(&mut terminal, &mut app);
    ratatui::restore();
    result
}
