//! `peers --pair PRESET`: the ball as the pair presents it to a DEM code, a reduced ball
//! calibrated to the pair's own COR (docs/targets.md §2, §8).

use super::PeersArgs;
use crate::api::Ball;
use serde::Serialize;

/// The pair `--pair` calibrates for: the other preset and the effective mass and radius.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Pair {
    pub(super) preset: String,
    pub(super) effective_mass: f64,
    pub(super) effective_radius: f64,
    /// The pair's e at v0 onto the partner at rest, both balls deforming (`collide
    /// --target-preset`, docs/targets.md §8): the model's COR for the pair.
    #[serde(skip)]
    pub(super) cor: f64,
    /// `collide --target-preset`'s warnings of that impact: the reach against the ball's own
    /// radius (not R_eff), each ball's record at the speed it meets the other.
    #[serde(skip)]
    pub(super) warnings: Vec<String>,
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
    let (m1, m2) = (b.params.mass, other.params.mass);
    let radius = |x: &Ball| x.measured.as_ref().map_or(f64::NAN, |m| m.radius);
    let (r1, r2) = (radius(&b), radius(&other));
    let rigid = (f64::INFINITY, 0.0);
    let met = b.collide_ball(&other, 0.0, rigid)?;
    let pair = Pair {
        preset: other.name.clone().unwrap_or_default(),
        effective_mass: m1 * m2 / (m1 + m2),
        effective_radius: r1 * r2 / (r1 + r2),
        cor: met.collision.cor,
        warnings: met.warnings,
    };
    b.params.mass = pair.effective_mass;
    b.params.validate()?;
    if let Some(m) = b.measured.as_mut() {
        (m.mass, m.radius, m.cor) = (pair.effective_mass, pair.effective_radius, None);
    }
    Ok((b, Some(pair)))
}
