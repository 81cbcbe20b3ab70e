//! What a two-body answer says of what the ball met (docs/targets.md §3, §8): the JSON
//! `target` object with whether the target is rigid, and with another ball as the target
//! (`collide --target-preset`, `peers --pair`, Python's `collide(target_preset=…)`) the
//! partner named as every answer names its ball — its preset, its `ball` object and its
//! `conditions`, the serializations the answer's own ball has (tests/cli/cli_collide_pair.rs).

use super::{Ball, BallRecord};
use crate::conditions::Conditions;
use crate::target::Target;
use serde::Serialize;

/// What the ball hit, the JSON `target` object: the target's mass, speed toward the ball,
/// and the K_s, c_s of a surface on it (`stiffness` `null`: none, ∞), then whether it is
/// rigid. A ball partner has no surface of its own (`stiffness` `null`) and is still not
/// rigid: its own chain deforms in series with the ball's (`pair`); a target with a surface
/// of finite K_s is not rigid either; a wall or a rigid body is.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TargetRecord {
    /// The target's mass, speed and surface.
    #[serde(flatten)]
    pub target: Target,
    /// Whether the target gives nothing under the ball (neither a surface of finite K_s nor a
    /// chain of its own).
    pub rigid: bool,
}

impl TargetRecord {
    /// A body of `target`'s mass and surface: rigid exactly when its surface is.
    pub fn body(target: Target) -> TargetRecord {
        TargetRecord {
            target,
            rigid: target.is_rigid(),
        }
    }
}

impl std::ops::Deref for TargetRecord {
    type Target = Target;

    fn deref(&self) -> &Target {
        &self.target
    }
}

/// The other ball of a pair: the JSON `pair` object of `collide --target-preset` and `peers
/// --pair` (`preset`, `effective_mass`, `effective_radius` first, as `peers` wrote them).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Partner {
    /// The partner's preset name (empty for a ball that is no preset).
    pub preset: String,
    /// m_eff = m1 m2/(m1 + m2), kg (the reduced mass).
    pub effective_mass: f64,
    /// R_eff = R1 R2/(R1 + R2), m, of the presets' radii (`null` without both).
    pub effective_radius: Option<f64>,
    /// The partner as every JSON answer names its ball (docs/cli.md, "The ball object").
    pub ball: BallRecord,
    /// The conditions the partner ran at (its record's), as the answer's `conditions`.
    pub conditions: Conditions,
}

impl Partner {
    /// `other` as the partner of `ball`.
    pub fn of(ball: &Ball, other: &Ball) -> Partner {
        let (m1, m2) = (ball.params.mass, other.params.mass);
        let (r1, r2) = (ball.radius(), other.radius());
        Partner {
            preset: other.name.clone().unwrap_or_default(),
            effective_mass: m1 * m2 / (m1 + m2),
            effective_radius: Some(r1 * r2 / (r1 + r2)).filter(|r| r.is_finite()),
            ball: other.record_json(),
            conditions: other.conditions,
        }
    }

    /// The JSON `surface_note` of an answer whose ball met this partner and no surface
    /// (`surface: null`): `collide --target-preset` without `--target-stiffness`.
    pub fn no_surface_note(&self) -> String {
        format!(
            "a pair: the ball met another ball, {} (`pair`), which deforms too; no surface",
            self.named()
        )
    }

    /// What the text's surface line says the ball met instead of a surface (`surface none:
    /// the ball met golf, which deforms too`: `collide --target-preset`, `peers --pair`).
    pub fn met_words(&self) -> String {
        format!("the ball met {}, which deforms too", self.named())
    }

    /// The partner's name as the text says it (`a ball` for one that is no preset).
    pub fn named(&self) -> &str {
        match self.preset.as_str() {
            "" => "a ball",
            name => name,
        }
    }
}
