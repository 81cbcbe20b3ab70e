//! The map view in a session file (issue 29 item 3): the quantity shown, the targets, and the
//! window of the (λ, ζ) plane on screen — with the ball's λ and ζ (the map's cursor: moving it
//! moves the ball) it puts the cursor back on the same cell of the same map.

use crate::map::{Quantity, Targets};
use crate::tui::views::map::state::{ENDS, MapView, Window};
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapState {
    /// cor, max_force or contact_time.
    pub quantity: String,
    /// The targets as `t` takes them (`cor>=0.8,max_force<=2000`; absent: none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub targets: Option<String>,
    /// The ends of the λ axis on screen (absent: the map not shown yet).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lambda: Option<[f64; 2]>,
    /// The ends of the ζ axis on screen.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zeta: Option<[f64; 2]>,
}

impl MapState {
    pub fn of(map: &MapView) -> MapState {
        MapState {
            quantity: map.quantity.name().into(),
            targets: map.targets.as_ref().map(Targets::to_string),
            lambda: map.window.map(|w| [w.lambda.0, w.lambda.1]),
            zeta: map.window.map(|w| [w.zeta.0, w.zeta.1]),
        }
    }

    /// Set `map`'s quantity, targets and window from the file; or why not.
    pub fn restore(&self, map: &mut MapView) -> Result<(), String> {
        map.quantity = Quantity::ALL
            .into_iter()
            .find(|q| q.name() == self.quantity)
            .ok_or_else(|| format!("map: quantity: unknown quantity '{}'", self.quantity))?;
        map.targets = match &self.targets {
            Some(t) => Some(Targets::parse(t).map_err(|e| format!("map: targets: {e}"))?),
            None => None,
        };
        map.window = match (self.lambda, self.zeta) {
            (Some(l), Some(z)) => Some(Window {
                lambda: ends("lambda", l)?,
                zeta: ends("zeta", z)?,
            }),
            (None, None) => None,
            _ => return Err("map: lambda and zeta go together".into()),
        };
        Ok(())
    }
}

/// A window's axis: increasing, inside the explorer's ends ([`ENDS`], with their rounding).
fn ends(name: &str, [a, b]: [f64; 2]) -> Result<(f64, f64), String> {
    let inside = |v: f64| v >= ENDS.0 * (1.0 - 1e-9) && v <= ENDS.1 * (1.0 + 1e-9);
    if a < b && inside(a) && inside(b) {
        Ok((a, b))
    } else {
        Err(format!(
            "map: {name}: [{a}, {b}] is not an increasing range inside {} … {}",
            ENDS.0, ENDS.1
        ))
    }
}
