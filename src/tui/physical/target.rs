//! The target's fields of the form (M, v_t, K_s, c_s) checked as `collide` checks them, and
//! the check every setting passes: the ball and the target meet, and the pair's reduced ball
//! is one the model takes (docs/targets.md §2).

use super::{Field, refusal};
use crate::tui::format::value;
use crate::tui::setting::Setting;

/// `s` with the target's field `field` set to `value`, checked as `collide` checks it
/// (`Target::validate`); c_s needs K_s, as `--target-damping` needs `--target-stiffness`: a
/// dashpot beside a rigid spring has no effect (docs/targets.md §7).
pub(super) fn target_set(field: Field, value: f64, s: &Setting) -> Result<Setting, String> {
    let mut next = s.clone();
    match field {
        Field::TargetMass => next.target.mass = value,
        Field::TargetSpeed => next.target.speed = value,
        Field::TargetStiffness => next.target.stiffness = value,
        _ => next.target.damping = value,
    }
    next.target.validate().map_err(|e| refusal(&e))?;
    if next.target.damping != 0.0 && next.target.stiffness == f64::INFINITY {
        return Err(if field == Field::TargetStiffness {
            "a rigid surface takes no damping: set c_s to 0 first".into()
        } else {
            "c_s has no effect on a rigid surface: type K_s first".into()
        });
    }
    Ok(next)
}

/// `closing` for what sets the target outside the form (the surface picker): the ball and
/// the target meet, and the pair's reduced ball is one the model takes.
pub fn closing_check(s: &Setting) -> Result<(), String> {
    closing(s)
}

/// The ball and the target must meet (v0 + v_t > 0), and the pair's reduced ball be one the
/// model takes (docs/targets.md §2).
pub(super) fn closing(s: &Setting) -> Result<(), String> {
    if s.params.v0 + s.target.speed <= 0.0 {
        return Err(format!(
            "the ball and the target never meet: v0 + v_t = {} m/s must be positive",
            value(s.params.v0 + s.target.speed)
        ));
    }
    s.run_params().validate().map_err(|e| refusal(&e))
}
