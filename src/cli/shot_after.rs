//! `shot --after-bounce D`: the shot ended D m past its last bounce (docs/cli.md `shot`,
//! docs/flight.md §6: where a serve is a metre after it bounces), and the library's
//! refusals of a shot named by their flags.

use super::output::given;
use crate::api::{Ball, ShotSpec};
use crate::flight::Ends;

/// `--after-bounce D` as the distance it stands for: the x of the last of the shot's
/// bounces, plus D. A first run finds that bounce; the shot is then run to that distance,
/// whose event lies past the bounce, so the flight to it is the first run's, bit for bit
/// (`after_bounce_is_the_distance_past_the_bounce`, tests/cli/cli_golden_shot.rs).
pub(super) fn past_bounce(ball: &Ball, spec: &ShotSpec, d: f64) -> anyhow::Result<f64> {
    let n = spec.ends.bounces;
    if !(d.is_finite() && d > 0.0) {
        anyhow::bail!("invalid --after-bounce: {} (must be positive)", given(d, 6));
    }
    if n == 0 {
        anyhow::bail!("invalid --after-bounce: the shot makes no bounce (--bounces 0)");
    }
    let first = ball
        .shot_unwarned(&ShotSpec {
            samples: 0,
            ..*spec
        })
        .map_err(flag_named)?;
    let Some(last) = first.bounces.get(n - 1) else {
        anyhow::bail!(
            "invalid --after-bounce: the shot ends (at t = {} s) before its bounce {n}",
            given(first.end.state.t, 4)
        );
    };
    let x = last.x + d;
    let to = ball.shot_unwarned(&ShotSpec {
        ends: Ends {
            distance: Some(x),
            ..spec.ends
        },
        samples: 0,
        ..*spec
    });
    if to.map_err(flag_named)?.bounces.len() < n {
        anyhow::bail!(
            "invalid --after-bounce: the ball passes x = {} m before its bounce {n}",
            given(x, 6)
        );
    }
    Ok(x)
}

/// A value refused by the library, named by its flag: `invalid --drag-coefficient: …`.
pub(super) fn flag_named(e: crate::api::BallError) -> anyhow::Error {
    match &e {
        crate::api::BallError::Invalid { field, value, .. } if *field == "shot" => {
            anyhow::anyhow!(
                "the ball flies for more than {} s without landing (a lift that holds it up?): \
                 give --time or --distance",
                given(*value, 6)
            )
        }
        crate::api::BallError::Invalid { field, .. } => {
            let flag = format!("--{}", field.replace('_', "-"));
            anyhow::anyhow!("{}", e.to_string().replacen(field, &flag, 1))
        }
        _ => e.into(),
    }
}
