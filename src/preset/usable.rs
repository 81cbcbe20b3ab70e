//! The load-time check that a preset can be run: its own parameter set passes
//! [`crate::ImpactParams::validate`], the very check every command and the explorer apply
//! before solving. Field checks alone let `k_p = 1e-320` through (positive, finite), which every
//! command then refused and the explorer showed as "λ —"; now the file is refused at load,
//! naming the key to change (tests/cli/cli_guarantees.rs, `a_preset_the_commands_refuse_is_refused_at_load`).

use super::{Bad, ParamSource, Preset};
use crate::model::params::{Field, ParamError};
use crate::text::number;

/// The first parameter of the preset's own set that the solver would refuse.
pub(super) fn check(p: &Preset) -> Result<(), Bad> {
    p.params().validate().map_err(|e| bad(p.parameters, &e))
}

/// The key of the file behind a refused parameter, and why.
fn bad(source: ParamSource, e: &ParamError) -> Bad {
    let adopted = source == ParamSource::Adopted;
    let (table, key) = match e.field {
        Field::Mass => ("measured", "mass"),
        Field::V0 => ("measured", "v0"),
        Field::KR | Field::Lambda => ("adopted", "k_r"),
        // K_h follows K_p and z_p (Eq. 16); K_p, c and z_p come from the material otherwise
        Field::KP | Field::KH if adopted => ("adopted", "k_p"),
        Field::Damping | Field::Zeta if adopted => ("adopted", "damping"),
        Field::ZP | Field::ZpBar if adopted => ("adopted", "z_p"),
        _ => ("material", "modulus"),
    };
    let value = number(e.value);
    let message = if e.field.as_str() == key {
        format!("{value} cannot be run: {}", e.reason)
    } else {
        format!(
            "gives {} = {value} ({} parameters), which cannot be run: {}",
            e.field,
            source.name(),
            e.reason
        )
    };
    Bad {
        table,
        layer: None,
        key,
        message,
    }
}
