//! Pinning runs (`p`) and clearing the pins (`P`).

use super::{App, Ghost, MAX_PINS};

impl App {
    /// Pin the current run: its curves stay, dimmed and tagged, while the setting moves on.
    /// A run already pinned is not pinned twice; past [`MAX_PINS`] nothing is pinned.
    pub(in crate::tui) fn pin(&mut self) {
        if let Some(i) = self.pins.iter().position(|g| g.setting == self.setting) {
            return self.info(format!("already pinned as p{}", i + 1));
        }
        if self.pins.len() >= MAX_PINS {
            return self.warn(format!("{MAX_PINS} runs pinned, the most: P clears them"));
        }
        // the curves of this setting, even when earlier keys of the batch changed it
        self.refresh_run();
        let (want, _) = self.speed_targets();
        let speed = self.sweeps.curve.clone().filter(|c| c.request == want);
        self.pins.push(Ghost {
            setting: self.setting.clone(),
            run: self.run.clone(),
            zeta: self.zeta.clone(),
            speed,
        });
        let n = self.pins.len();
        self.info(format!(
            "pinned as p{n}: its curves stay, dimmed (p pins more, P clears)"
        ));
    }

    pub(super) fn unpin(&mut self) {
        match std::mem::take(&mut self.pins).len() {
            0 => self.warn("nothing pinned: p pins the current run".into()),
            1 => self.info("pin cleared".into()),
            n => self.info(format!("{n} pins cleared")),
        }
    }
}
