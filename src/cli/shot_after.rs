//! `shot --after-bounce D`: the shot ended D m past its last bounce (docs/cli.md `shot`,
//! docs/flight.md §6: where a serve is a metre after it bounces), and the library's
//! refusals of a shot named by their flags.

use super::output::given;
use crate::api::{AfterBounceError, Ball, ShotSpec};

/// `--after-bounce D` as the distance it stands for (`Ball::after_bounce_distance`), its
/// refusals named by the flags.
pub(super) fn past_bounce(ball: &Ball, spec: &ShotSpec, d: f64) -> anyhow::Result<f64> {
    ball.after_bounce_distance(spec, d).map_err(|e| match e {
        AfterBounceError::NotPositive(d) => {
            anyhow::anyhow!("invalid --after-bounce: {} (must be positive)", given(d, 6))
        }
        AfterBounceError::NoBounce => {
            anyhow::anyhow!("invalid --after-bounce: the shot makes no bounce (--bounces 0)")
        }
        AfterBounceError::EndsBefore { bounce, t } => anyhow::anyhow!(
            "invalid --after-bounce: the shot ends (at t = {} s) before its bounce {bounce}",
            given(t, 4)
        ),
        AfterBounceError::PassesBefore { bounce, x } => anyhow::anyhow!(
            "invalid --after-bounce: the ball passes x = {} m before its bounce {bounce}",
            given(x, 6)
        ),
        AfterBounceError::Shot(e) => flag_named(e),
    })
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
