//! The height of the bottom of the ball against time over a bounce sequence, from the flight's
//! closed forms (docs/drop.md, "Trajectory"). During a contact the height is drawn as 0 and the
//! velocity jumps from −v_in to +v_out: the few millimetres of compression are not drawn.

use super::{DropRun, End};
use serde::Serialize;

/// One point of the trajectory, SI: time since release (s), height of the bottom of the ball
/// (m), vertical velocity (m/s, positive upward).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// Time since release, s.
    pub t: f64,
    /// Height of the bottom of the ball above the plate, m (0 in contact).
    pub height: f64,
    /// Vertical velocity, m/s, positive upward.
    pub velocity: f64,
}

/// Points per flight phase at most (the CSV's size is bounded by bounces × this).
const MAX_PER_PHASE: usize = 2000;

impl DropRun {
    /// Time from release to the end of the sequence: the last apex, or the end of the last
    /// contact when the ball stays on the plate.
    pub fn duration(&self) -> f64 {
        let Some(last) = self.bounces.last() else {
            return 0.0;
        };
        let after = if self.end == End::NoRebound {
            0.0
        } else {
            self.flight.rise_time(last.v_out)
        };
        last.t_start + last.contact_time + after
    }

    /// The trajectory sampled every `dt` seconds within each flight phase, plus the exact
    /// release, contact and apex points. `dt` must be positive; a phase gets at most 2000
    /// points.
    pub fn trajectory(&self, dt: f64) -> Vec<Sample> {
        let mut out = Vec::new();
        let mut drop_from = self.setup.height;
        let mut t0 = 0.0;
        for (i, b) in self.bounces.iter().enumerate() {
            // the fall from rest at `drop_from`, from the release or the previous apex
            let fall = b.t_start - t0;
            for t in steps(fall, dt) {
                let (s, v) = self.flight.fall_at(t);
                out.push(Sample {
                    t: t0 + t,
                    height: (drop_from - s).max(0.0),
                    velocity: -v,
                });
            }
            out.push(Sample {
                t: b.t_start,
                height: 0.0,
                velocity: -b.v_in,
            });
            let t_leave = b.t_start + b.contact_time;
            out.push(Sample {
                t: t_leave,
                height: 0.0,
                velocity: b.v_out,
            });
            let last = i + 1 == self.bounces.len();
            if last && self.end == End::NoRebound {
                break;
            }
            let rise = self.flight.rise_time(b.v_out);
            for t in steps(rise, dt).skip(1) {
                let (h, v) = self.flight.rise_at(b.v_out, t);
                out.push(Sample {
                    t: t_leave + t,
                    height: h.max(0.0),
                    velocity: v,
                });
            }
            out.push(Sample {
                t: t_leave + rise,
                height: b.rebound_height,
                velocity: 0.0,
            });
            drop_from = b.rebound_height;
            t0 = t_leave + rise;
        }
        out
    }

    /// The height at time `t` since release (for animation): the flight's closed forms in the
    /// phase that holds `t`; after the end, the final height.
    pub fn height_at(&self, t: f64) -> f64 {
        let mut drop_from = self.setup.height;
        let mut t0 = 0.0;
        for b in &self.bounces {
            if t < b.t_start {
                return (drop_from - self.flight.fall_at((t - t0).max(0.0)).0).max(0.0);
            }
            let t_leave = b.t_start + b.contact_time;
            if t < t_leave || b.v_out == 0.0 {
                return 0.0;
            }
            let rise = self.flight.rise_time(b.v_out);
            if t < t_leave + rise {
                return self.flight.rise_at(b.v_out, t - t_leave).0.max(0.0);
            }
            drop_from = b.rebound_height;
            t0 = t_leave + rise;
        }
        drop_from
    }
}

/// 0, dt, 2dt, … strictly below `span` (at most [`MAX_PER_PHASE`] points, evenly spread).
fn steps(span: f64, dt: f64) -> impl Iterator<Item = f64> {
    let n = ((span / dt).ceil() as usize).clamp(1, MAX_PER_PHASE);
    let h = span / n as f64;
    (0..n).map(move |i| i as f64 * h)
}
