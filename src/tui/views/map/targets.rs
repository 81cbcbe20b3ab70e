//! The map view's targets in the units the map shows: a contact time in ms (the map, its
//! readout and the impact view all show ms), a peak force in N, the COR as it is. The library
//! and `bouncelab map --where` read seconds ([`crate::map::Targets`]); the explorer holds
//! them in SI too and converts only at the entry and on screen.

use crate::map::{MapError, Quantity, Targets};
use crate::text::given;

/// The factor from the screen's unit to SI for `q` (ms → s).
fn to_si(q: Quantity) -> f64 {
    match q {
        Quantity::ContactTime => 1e-3,
        _ => 1.0,
    }
}

/// Targets typed in the explorer (`contact_time>=2` meaning 2 ms), in SI.
pub fn parse(text: &str) -> Result<Targets, MapError> {
    let mut t = Targets::parse(text)?;
    for c in &mut t.0 {
        c.value *= to_si(c.quantity);
    }
    Ok(t)
}

/// The quantities a target names, in the units the explorer takes them in.
const QUANTITIES: &str = "cor, max_force (N) or contact_time (ms)";

/// A refused target as the explorer says it: always with the quantities a target may name and
/// their units here (issue 51 item 8: "expected QUANTITY>=VALUE" named none).
pub fn refusal(e: &MapError) -> String {
    let said = e.to_string();
    let listed = "expected cor, max_force or contact_time";
    if said.contains(listed) {
        said.replace(listed, &format!("expected {QUANTITIES}"))
    } else {
        format!("{said}; a target is QUANTITY>=VALUE or QUANTITY<=VALUE, QUANTITY {QUANTITIES}")
    }
}

/// Targets as the explorer shows and offers them for editing: "cor>=0.8,contact_time>=2";
/// [`parse`] reads it back to the same targets.
pub fn text(t: &Targets) -> String {
    let parts: Vec<String> =
        t.0.iter()
            .map(|c| {
                let mut shown = *c;
                shown.value = given(c.value / to_si(c.quantity), 15)
                    .parse()
                    .unwrap_or(c.value);
                shown.to_string()
            })
            .collect();
    parts.join(",")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contact_times_are_typed_and_shown_in_ms() {
        let t = parse("cor>=0.8, contact_time>=2, max_force<=2000").unwrap();
        assert_eq!(
            t,
            Targets::parse("cor>=0.8,contact_time>=0.002,max_force<=2000").unwrap()
        );
        assert_eq!(text(&t), "cor>=0.8,contact_time>=2,max_force<=2000");
        for typed in ["contact_time<=0.7", "contact_time>=1.23456789"] {
            assert_eq!(text(&parse(typed).unwrap()), typed);
        }
        assert!(parse("contact_time>=x").is_err());
    }

    /// Every refusal lists the quantities a target names, with the explorer's units (issue 51
    /// item 8).
    #[test]
    fn every_refusal_lists_the_quantities() {
        for bad in ["speed>=3", "cor=0.8", "contact_time>=x", "cor>=2"] {
            let why = refusal(&parse(bad).unwrap_err());
            assert!(why.contains(QUANTITIES), "{bad}: {why}");
            assert_eq!(why.matches("max_force").count(), 1, "{bad}: {why}");
        }
    }
}
