//! The explorer's drop view (`d`): the current ball released so that it meets the plate at the
//! explorer's v0, its bounce sequence (src/drop), the verdict of its own standard, and the
//! animation clock. State and logic only; `views::drop::widget` draws it.
//!
//! The height: the fall from rest that ends at v0 in standard air
//! ([`Flight::fall_height_for`]), so the λ, ζ and v0 keys all re-run the drop, and a new ball's
//! preset v0 (its standard's impact speed) gives back its standard's drop height. The clock
//! runs in simulated seconds, advanced by [`DropView::tick`] with the wall time the event loop
//! measured: real time. Without motion (reduced-motion setting, tests) the view shows the
//! whole sequence at once.

use crate::drop::standards::{self, Standard, Verdict};
use crate::drop::{Air, DropBall, DropRun, DropSetup, Flight, drop};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;

/// Bounces the view follows.
pub const BOUNCES: usize = 10;

/// What the drop view shows, and its clock.
#[derive(Debug, Clone, PartialEq)]
pub struct DropView {
    /// The sequence for `key`, or why there is none.
    pub run: Result<Option<DropRun>, String>,
    /// The preset's own standard and its verdict on the current parameters.
    pub verdict: Option<(&'static Standard, Verdict)>,
    /// Ball radius (m), for drawing.
    pub radius: f64,
    /// Animation time since release (s).
    pub t: f64,
    pub playing: bool,
    /// Whether to animate at all (off under the reduced-motion setting).
    pub motion: bool,
    key: Option<(ImpactParams, ContactLaw, String)>,
}

impl DropView {
    /// A view that animates (`motion`) or shows the whole sequence at once.
    pub fn new(motion: bool) -> DropView {
        DropView {
            run: Ok(None),
            verdict: None,
            radius: 0.0,
            t: 0.0,
            playing: false,
            motion,
            key: None,
        }
    }

    /// Re-run the drop when the parameters, law or ball changed; the animation restarts.
    pub fn refresh(&mut self, params: &ImpactParams, law: ContactLaw, preset: &Preset) {
        let key = (*params, law, preset.name.clone());
        if self.key.as_ref() == Some(&key) {
            return;
        }
        self.key = Some(key);
        let ball = DropBall {
            params: *params,
            law,
            radius: preset.measured.radius,
        };
        self.radius = ball.radius;
        let air = Some(Air::default());
        let flight = Flight::new(params.mass, ball.radius, air);
        self.run = match flight.fall_height_for(params.v0) {
            // said in words, and nothing drawn or judged as if it had bounced (issue 51 item 5)
            None => Err(format!(
                "no drop reaches v0 {} m/s: falling in air the ball tops out at its terminal \
                 speed {} m/s (drag); V lowers v0",
                crate::tui::format::value(params.v0),
                crate::tui::format::value(flight.terminal_speed())
            )),
            Some(h) => drop(
                &ball,
                &DropSetup {
                    bounces: BOUNCES,
                    ..DropSetup::new(h)
                },
            )
            .map(Some)
            .map_err(|e| e.to_string()),
        };
        self.verdict = standards::for_ball(&preset.name)
            .and_then(|s| s.judge(&ball, air).ok().map(|v| (s, v)));
        self.replay();
    }

    /// The sequence, when there is one.
    pub fn sequence(&self) -> Option<&DropRun> {
        self.run.as_ref().ok().and_then(Option::as_ref)
    }

    /// End of the sequence (s).
    pub fn duration(&self) -> f64 {
        self.sequence().map_or(0.0, DropRun::duration)
    }

    /// Start again from the release (animated), or show it all (no motion).
    pub fn replay(&mut self) {
        if self.motion {
            self.t = 0.0;
            self.playing = true;
        } else {
            self.t = self.duration();
            self.playing = false;
        }
    }

    /// Space: pause or resume (at the end, start again).
    pub fn toggle_pause(&mut self) {
        if !self.motion {
            return;
        }
        if !self.playing && self.t >= self.duration() {
            self.replay();
        } else {
            self.playing = !self.playing;
        }
    }

    /// Advance the clock by `dt` seconds of wall time; stops at the end.
    pub fn tick(&mut self, dt: f64) {
        if !self.playing || !dt.is_finite() || dt <= 0.0 {
            return;
        }
        self.t = (self.t + dt).min(self.duration());
        if self.t >= self.duration() {
            self.playing = false;
        }
    }

    /// Stopped by space before the end (the animation holds still until space again).
    pub fn paused(&self) -> bool {
        self.motion && !self.playing && self.sequence().is_some() && self.t < self.duration()
    }

    /// The ball's height now (m, bottom of the ball).
    pub fn height_now(&self) -> f64 {
        self.sequence().map_or(0.0, |r| r.height_at(self.t))
    }

    /// The standard's window on the first rebound in bottom-of-ball heights (m), for the band
    /// (drop standards only).
    pub fn band(&self) -> Option<(f64, f64)> {
        let (s, _) = self.verdict?;
        let standards::Test::Drop { rebound_ref, .. } = s.test else {
            return None;
        };
        let off = rebound_ref.offset(self.radius);
        match s.window {
            [Some(lo), Some(hi)] => Some((lo - off, hi - off)),
            _ => None,
        }
    }
}
