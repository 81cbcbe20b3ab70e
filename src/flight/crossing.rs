//! Where a shot's ball first crosses a watched x moving forward (a net's plane, docs/flight.md
//! §6): located inside the accepted step as a `--distance` end is, without changing the step
//! (`shot_watching`).

use super::step::{self, Y};
use super::{Flier, State, at};

/// The ball's first crossing of a watched x (a net's plane) moving forward: the state there,
/// located from its step's start as a distance end is, and the bounces made before it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// The state at x = the watched x (to rounding).
    pub state: State,
    /// Bounces made before it.
    pub bounces: usize,
}

impl Flier<'_> {
    /// The watched x crossed forward inside the accepted step from (t, `y`) to `y1` (of size
    /// `h`), before its event at `until` (the step is cut there): located from the step's
    /// start as a distance end is (`step::locate`), and the watch ended.
    pub(super) fn watch_crossing(
        &mut self,
        (t, y, k1): (f64, &Y, &Y),
        (y1, h): (&Y, f64),
        until: Option<f64>,
    ) {
        let Some(d) = self.watch.filter(|&d| y[0] < d && y1[0] >= d) else {
            return;
        };
        let (hs, ys) = step::locate(self.body, (y, k1), (h, y1), 0, d);
        if until.is_none_or(|u| hs <= u) {
            self.crossed = Some((t + hs, at(ys, 0, d)));
            self.watch = None;
        }
    }
}
