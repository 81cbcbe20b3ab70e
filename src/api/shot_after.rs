//! A shot ended D m past its last bounce (docs/flight.md §6: where a serve is a metre after
//! it bounces), the command line's `shot --after-bounce D` and Python's
//! `shot(after_bounce=D)`: the distance end it stands for. The faces word the refusals with
//! their own names (`--after-bounce`, `after_bounce=`).

use super::{Ball, BallError, ShotReport, ShotSpec};
use crate::flight::Ends;

/// Why D m past the last bounce is no end of this shot.
#[derive(Debug, Clone, PartialEq)]
pub enum AfterBounceError {
    /// D is not a positive number (the value given).
    NotPositive(f64),
    /// The shot makes no bounce (`bounces` 0).
    NoBounce,
    /// The shot ends (at this time, s) before its bounce `bounce`.
    EndsBefore {
        /// The bounce asked for (1-based).
        bounce: usize,
        /// When the shot ends, s.
        t: f64,
    },
    /// The ball passes that x (m) before its bounce `bounce`.
    PassesBefore {
        /// The bounce asked for (1-based).
        bounce: usize,
        /// The x asked for, m.
        x: f64,
    },
    /// The shot itself is refused.
    Shot(BallError),
}

impl Ball {
    /// The distance end of the shot `spec` ended `d` m (along x) past the last of its
    /// `spec.ends.bounces` bounces: that bounce's x plus `d`. A first run finds the bounce;
    /// the shot to that distance, whose event lies past the bounce, flies the first run's
    /// flight to it bit for bit (`after_bounce_is_the_distance_past_the_bounce`,
    /// tests/cli/cli_golden_shot.rs).
    pub fn after_bounce_distance(&self, spec: &ShotSpec, d: f64) -> Result<f64, AfterBounceError> {
        self.shot_after_bounce(spec, d).map(|(x, _)| x)
    }

    /// [`Ball::after_bounce_distance`] and the shot to it, unwarned
    /// ([`Ball::shot_unwarned`]'s numbers, no trajectory samples): `mc --shot
    /// --after-bounce D`'s samples, each ended D m past its own bounce.
    pub fn shot_after_bounce(
        &self,
        spec: &ShotSpec,
        d: f64,
    ) -> Result<(f64, ShotReport), AfterBounceError> {
        let n = spec.ends.bounces;
        if !(d.is_finite() && d > 0.0) {
            return Err(AfterBounceError::NotPositive(d));
        }
        if n == 0 {
            return Err(AfterBounceError::NoBounce);
        }
        let first = self
            .shot_unwarned(&ShotSpec {
                samples: 0,
                ..*spec
            })
            .map_err(AfterBounceError::Shot)?;
        let Some(last) = first.bounces.get(n - 1) else {
            return Err(AfterBounceError::EndsBefore {
                bounce: n,
                t: first.end.state.t,
            });
        };
        let x = last.x + d;
        let to = self
            .shot_unwarned(&ShotSpec {
                ends: Ends {
                    distance: Some(x),
                    ..spec.ends
                },
                samples: 0,
                ..*spec
            })
            .map_err(AfterBounceError::Shot)?;
        if to.bounces.len() < n {
            return Err(AfterBounceError::PassesBefore { bounce: n, x });
        }
        Ok((x, to))
    }
}
