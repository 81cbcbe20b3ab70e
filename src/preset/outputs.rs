//! What a data set of a ball's record measured, by the answers' own JSON keys (docs/presets.md,
//! "The calibration record"): `outputs = ["cor", "max_force", "contact_time"]` on a
//! `[[calibration.data]]` entry. An answer that reports an output no data set measured says so
//! (`crate::api::Ball::uncalibrated_outputs`).

use serde::{Deserialize, Serialize};

/// An output a data set measured: the key `run` (and `sweep velocity`, `drop`) writes it under,
/// and `static`'s `deflection_m` for a static test between two plates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Output {
    /// The coefficient of restitution (a rebound test's rebound height is one).
    Cor,
    /// The peak force of the impact.
    MaxForce,
    /// The contact time of the impact.
    ContactTime,
    /// The peak indentation of the impact.
    MaxIndentation,
    /// The indentation left after the impact.
    PermanentIndentation,
    /// The deflection between two plates under a static load (`static`'s `deflection_m`).
    #[serde(rename = "deflection_m")]
    Deflection,
}

impl Output {
    /// Every output, in the order answers list them.
    pub const ALL: [Output; 6] = [
        Output::Cor,
        Output::MaxForce,
        Output::ContactTime,
        Output::MaxIndentation,
        Output::PermanentIndentation,
        Output::Deflection,
    ];

    /// The outputs of one impact, as `run` reports them.
    pub const IMPACT: [Output; 5] = [
        Output::Cor,
        Output::MaxForce,
        Output::ContactTime,
        Output::MaxIndentation,
        Output::PermanentIndentation,
    ];

    /// The outputs of a drop's bounces, as `drop` reports them (a rebound height is a COR).
    pub const DROP: [Output; 3] = [Output::Cor, Output::MaxForce, Output::ContactTime];

    /// The JSON key ("max_force").
    pub fn key(self) -> &'static str {
        match self {
            Output::Cor => "cor",
            Output::MaxForce => "max_force",
            Output::ContactTime => "contact_time",
            Output::MaxIndentation => "max_indentation",
            Output::PermanentIndentation => "permanent_indentation",
            Output::Deflection => "deflection_m",
        }
    }

    /// The name the text tables give it ("peak force").
    pub fn words(self) -> &'static str {
        match self {
            Output::Cor => "COR",
            Output::MaxForce => "peak force",
            Output::ContactTime => "contact time",
            Output::MaxIndentation => "peak indentation",
            Output::PermanentIndentation => "permanent indentation",
            Output::Deflection => "static deflection",
        }
    }
}

/// "COR, peak force and contact time": `outputs` in words, joined for a sentence.
pub fn words(outputs: &[Output]) -> String {
    let w: Vec<&str> = outputs.iter().map(|o| o.words()).collect();
    match w.split_last() {
        None => String::new(),
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_the_serialized_names() {
        for o in Output::ALL {
            assert_eq!(serde_json::to_value(o).unwrap(), o.key());
        }
        assert_eq!(words(&[Output::Cor]), "COR");
        assert_eq!(
            words(&[Output::MaxForce, Output::ContactTime, Output::Deflection]),
            "peak force, contact time and static deflection"
        );
    }
}
