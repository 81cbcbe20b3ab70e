//! Every name `--standard` takes, in `bouncelab standards`' order: the impact tests
//! (`super::standards`), then the static ones (`super::deformation`), then the pressure-loss
//! tests (`super::conditions`). One list for every "unknown standard" message, the command
//! line's and Python's alike (tests/golden/bad-standard.txt). A module of its own because the
//! static standards import the impact ones' verdict: the list cannot live beside either.

use super::conditions::PRESSURE_LOSS;
use super::deformation::DEFORMATION_STANDARDS;
use super::standards::STANDARDS;

/// Every standard's name.
pub fn all() -> Vec<&'static str> {
    let statics = DEFORMATION_STANDARDS.iter().map(|s| s.name);
    let leaks = PRESSURE_LOSS.iter().map(|p| p.name);
    STANDARDS
        .iter()
        .map(|s| s.name)
        .chain(statics)
        .chain(leaks)
        .collect()
}

/// The refusal of a name no standard has, listing every one.
pub fn unknown(name: &str) -> String {
    format!(
        "unknown standard '{name}' (available: {})",
        all().join(", ")
    )
}
