//! A net in a shot's path (issue 57, docs/flight.md §6): a vertical net at x = `x` from the
//! launch point, `height` high, and whether the ball clears it. The flight is the same with
//! and without a net: the net's own response (a ball caught in its mesh, or a net-cord ball
//! that trickles over) is not modelled, so a ball that meets it is flown on as if it were
//! absent, and the answer says so (`NetReport::warnings`).

use crate::flight::Crossing;
use crate::text::given;
use serde::Serialize;

/// The tennis net's height at the centre (m): 3 feet, held down there by a strap (ITF Rules
/// of Tennis, Rule 1; docs/flight.md §6 says where the figure was read).
pub const TENNIS_NET_HEIGHT: f64 = 0.914;

/// A vertical net across the path: its plane at x = `x` (m from the launch point), its top
/// edge `height` m above the surface.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Net {
    /// Where it stands, m from the launch along x.
    pub x: f64,
    /// Its top above the surface (m).
    pub height: f64,
}

/// Whether and by how much the ball clears the net (the JSON's `net` object).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NetReport {
    /// Where the net stands (m).
    pub x: f64,
    /// Its height (m).
    pub height: f64,
    /// The ball's lowest point above the net's top as its centre crosses the net's plane,
    /// y − R − height (m); negative: it meets the net; `None` when the shot does not reach it.
    pub clearance: Option<f64>,
    /// Whether the ball passes without touching the net: it reaches it with its centre more
    /// than R from the top edge along the path, (y − height) cos θ > R (θ the path's angle
    /// to the horizontal there, the path straight over the ball's size).
    pub cleared: bool,
    /// When the centre crosses the net's plane (s); `None` when it does not reach it.
    pub t: Option<f64>,
    /// The centre's height there (m).
    pub y: Option<f64>,
    /// The bounces made before it reaches the net.
    pub bounces_before: Option<usize>,
    /// What the answer rests on when the ball does not clear the net (made by
    /// [`crate::Ball::shot`], not by `shot_unwarned`).
    pub warnings: Vec<String>,
}

impl NetReport {
    /// The net's answer for the ball of radius `r` crossing as `crossing` (or not reaching it).
    pub fn of(net: &Net, crossing: Option<&Crossing>, r: f64) -> NetReport {
        let Some(c) = crossing else {
            return NetReport {
                x: net.x,
                height: net.height,
                clearance: None,
                cleared: false,
                t: None,
                y: None,
                bounces_before: None,
                warnings: Vec::new(),
            };
        };
        let s = c.state;
        let cos = s.vx / s.vx.hypot(s.vy);
        NetReport {
            x: net.x,
            height: net.height,
            clearance: Some(s.y - r - net.height),
            cleared: (s.y - net.height) * cos > r,
            t: Some(s.t),
            y: Some(s.y),
            bounces_before: Some(c.bounces),
            warnings: Vec::new(),
        }
    }

    /// The warning of a ball that does not clear the net (none when it does): where it meets
    /// it, and that the flight past it is computed as if there were no net.
    pub fn warning(&self) -> Option<String> {
        if self.cleared {
            return None;
        }
        let at = format!("the net at x = {} m", given(self.x, 6));
        Some(match (self.clearance, self.y) {
            (Some(c), Some(y)) => {
                let lowest = if c < 0.0 {
                    format!("{} m under the top", given(-c, 3))
                } else {
                    format!(
                        "{} m over the top, within its radius of the cord",
                        given(c, 3)
                    )
                };
                format!(
                    "the ball meets {at} ({} m high): its centre crosses it {} m up, its lowest \
                     point {lowest}; the flight past it is computed as if there were no net \
                     (the net's response is not modelled)",
                    given(self.height, 4),
                    given(y, 4),
                )
            }
            _ => format!("the ball does not reach {at} before the shot ends"),
        })
    }
}
