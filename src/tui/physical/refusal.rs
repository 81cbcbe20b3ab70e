//! The form's refusals in its own words: the field's symbol and its value in the form's unit,
//! never the library's `target_mass` nor a mass in kg beside a form in g (issue 51 item 4).

use super::Field;
use crate::api::BallError;
use crate::model::params::{self, ParamError};

impl Field {
    /// The form's field a library check names, if the form has it.
    pub(super) fn named(f: params::Field) -> Option<Field> {
        use params::Field as P;
        Some(match f {
            P::Mass => Field::Mass,
            P::Radius => Field::Radius,
            P::KP => Field::KP,
            P::KR => Field::KR,
            P::Damping => Field::C,
            P::ZP => Field::ZP,
            P::Lambda => Field::Lambda,
            P::Zeta => Field::Zeta,
            P::V0 => Field::V0,
            P::TargetMass => Field::TargetMass,
            P::TargetSpeed => Field::TargetSpeed,
            P::TargetStiffness => Field::TargetStiffness,
            P::TargetDamping => Field::TargetDamping,
            _ => return None,
        })
    }

    /// A typed value (SI) as a refusal shows it, in the field's screen unit.
    pub(super) fn shown(self, v: f64) -> String {
        if v.is_finite() {
            self.show(v)
        } else {
            "that".into()
        }
    }
}

/// A refusal of the library's checks in the form's words: the field's symbol and its value
/// in the form's unit — "invalid M: 0 g (must be positive)", never the library's
/// `target_mass` nor a mass in kg beside a form in g (issue 51 item 4).
pub fn refusal(e: &ParamError) -> String {
    match Field::named(e.field) {
        Some(f) => format!(
            "invalid {}: {} ({})",
            f.symbol(),
            f.shown(e.value),
            e.reason
        ),
        None => e.to_string(),
    }
}

/// [`refusal`] for the checks that say why as a [`BallError`].
pub(super) fn ball_refusal(e: &BallError) -> String {
    match e {
        BallError::Param(p) => refusal(p),
        other => other.to_string(),
    }
}
