//! The live terminal explorer (ratatui). Entry point: [`run`].

use crate::preset::Preset;

/// Open the explorer on `preset`; returns when the user quits. The terminal is restored on
/// every exit path.
pub fn run(preset: Preset) -> anyhow::Result<()> {
    let _ = preset;
    anyhow::bail!("the explorer is not built yet; use `bouncelab run`")
}
