//! `peers --pair PRESET`: the ball as the pair presents it to a DEM code, a reduced ball
//! calibrated to the pair's own COR (docs/targets.md §2, §8).

use super::PeersArgs;
use crate::api::{Ball, Partner};
use serde::Serialize;

/// The pair `--pair` calibrates for: the other ball as every answer names a ball, with the
/// effective mass and radius (the JSON `pair`, `collide --target-preset`'s: `api::Partner`).
#[derive(Debug, Clone, Serialize)]
pub(super) struct Pair {
    #[serde(flatten)]
    pub(super) partner: Partner,
    /// The pair's e at v0 onto the partner at rest, both balls deforming (`collide
    /// --target-preset`, docs/targets.md §8): the model's COR for the pair.
    #[serde(skip)]
    pub(super) cor: f64,
    /// `collide --target-preset`'s warnings of that impact: the reach against the ball's own
    /// radius (not R_eff), each ball's record at the speed it meets the other.
    #[serde(skip)]
    pub(super) warnings: Vec<String>,
}

impl std::ops::Deref for Pair {
    type Target = Partner;

    fn deref(&self) -> &Partner {
        &self.partner
    }
}

/// The ball as the pair with preset `name` presents it to a DEM code: mass m_eff and radius
/// R_eff (the presets' measured radii), the rest of the ball kept, v0 the closing speed (the
/// partner at rest): the reduced ball of docs/targets.md §2, which the peers' single contact
/// calibrates; the target COR is the pair's own, both balls deforming (docs/targets.md §8).
pub(super) fn pair_ball(
    a: &PeersArgs,
    mut b: Ball,
    name: &str,
) -> anyhow::Result<(Ball, Option<Pair>)> {
    let entry = crate::cli::ball::select(Some(name), a.ball.choice.config.as_deref())?;
    let other = Ball::from_entry(&entry, None, None, None)?;
    let rigid = (f64::INFINITY, 0.0);
    let met = b.collide_ball(&other, 0.0, rigid)?;
    let pair = Pair {
        partner: met.pair.unwrap_or_else(|| Partner::of(&b, &other)),
        cor: met.collision.cor,
        warnings: met.warnings,
    };
    b.params.mass = pair.effective_mass;
    b.params.validate()?;
    let radius = pair.effective_radius.unwrap_or(f64::NAN);
    if let Some(m) = b.measured.as_mut() {
        (m.mass, m.radius, m.cor) = (pair.effective_mass, radius, None);
    }
    Ok((b, Some(pair)))
}
