//! Targets on a map: constraints `cor>=0.8`, `max_force<=2000`, `contact_time>=0.002`, in the
//! map's units (F̄_m and τ_f on a normalized map, N and s on a dimensional one).

use super::{Cell, MapError, Quantity};
use serde::Serialize;

/// Which side of its value a constraint keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Bound {
    /// `>=`
    AtLeast,
    /// `<=`
    AtMost,
}

/// One constraint: a quantity at least or at most a value.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Constraint {
    /// What is bounded.
    pub quantity: Quantity,
    /// At least or at most.
    pub bound: Bound,
    /// The bound, in the map's units (normalized or SI).
    pub value: f64,
}

impl Constraint {
    /// Whether a cell meets it. A contact time that does not exist (no rebound) and a NaN
    /// (no answer) meet no constraint.
    pub fn holds(&self, c: &Cell) -> bool {
        let v = c.get(self.quantity);
        match self.bound {
            Bound::AtLeast => v >= self.value,
            Bound::AtMost => v <= self.value,
        }
    }
}

impl std::fmt::Display for Constraint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let op = match self.bound {
            Bound::AtLeast => ">=",
            Bound::AtMost => "<=",
        };
        let v = crate::text::number(self.value);
        write!(f, "{}{op}{v}", self.quantity.name())
    }
}

/// Every constraint a cell must meet (none: every evaluated cell is feasible).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Targets(pub Vec<Constraint>);

impl Targets {
    /// Comma-separated constraints, `QUANTITY>=VALUE` or `QUANTITY<=VALUE`, QUANTITY one of
    /// `cor`, `max_force`, `contact_time`; spaces around the parts are allowed. An error names
    /// the part that does not read.
    ///
    /// ```
    /// use bouncelab::map::Targets;
    /// let t = Targets::parse("cor>=0.8, max_force<=2000")?;
    /// assert_eq!(t.0.len(), 2);
    /// let e = Targets::parse("cor>=0.8,force<=2").unwrap_err().to_string();
    /// assert_eq!(e, "invalid where: 'force<=2' (unknown quantity 'force'; \
    ///                expected cor, max_force or contact_time)");
    /// # Ok::<(), bouncelab::map::MapError>(())
    /// ```
    pub fn parse(text: &str) -> Result<Targets, MapError> {
        let mut out = Vec::new();
        for part in text.split(',') {
            out.push(parse_one(part.trim())?);
        }
        Ok(Targets(out))
    }

    /// Whether a cell meets every constraint.
    pub fn holds(&self, c: &Cell) -> bool {
        self.0.iter().all(|k| k.holds(c))
    }
}

impl std::fmt::Display for Targets {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = self.0.iter().map(ToString::to_string).collect();
        f.write_str(&parts.join(","))
    }
}

/// `s` up to `max` characters, with "… (N characters)" when it was longer.
fn cut(s: &str, max: usize) -> String {
    let n = s.chars().count();
    if n <= max {
        return s.to_string();
    }
    let head: String = s.chars().take(max).collect();
    format!("{head}… ({n} characters)")
}

fn parse_one(part: &str) -> Result<Constraint, MapError> {
    // a part is echoed in the error cut to its first 60 characters, with its length, so the
    // error stays one readable line whatever was given
    let bad = |reason: String| MapError::Target {
        part: cut(part, 60),
        reason,
    };
    if part.is_empty() {
        return Err(bad("empty constraint; expected e.g. cor>=0.8".into()));
    }
    let (name, bound, value) = if let Some((n, v)) = part.split_once(">=") {
        (n, Bound::AtLeast, v)
    } else if let Some((n, v)) = part.split_once("<=") {
        (n, Bound::AtMost, v)
    } else {
        return Err(bad("expected QUANTITY>=VALUE or QUANTITY<=VALUE".into()));
    };
    let name = name.trim();
    let quantity = match name {
        "cor" => Quantity::Cor,
        "max_force" => Quantity::MaxForce,
        "contact_time" => Quantity::ContactTime,
        _ => {
            return Err(bad(format!(
                "unknown quantity '{name}'; expected cor, max_force or contact_time"
            )));
        }
    };
    let value: f64 = value
        .trim()
        .parse()
        .map_err(|_| bad(format!("'{}' is not a number", value.trim())))?;
    if !value.is_finite() {
        return Err(bad("the value must be a finite number".into()));
    }
    let k = Constraint {
        quantity,
        bound,
        value,
    };
    match k.beyond_every_impact() {
        Some(range) => Err(bad(format!("no impact meets it: {range}"))),
        None => Ok(k),
    }
}

impl Constraint {
    /// Where no impact can meet the constraint whatever the ball — 0 ≤ e ≤ 1 (the dashpot
    /// only dissipates, docs/model.md §9), F_m > 0 and t_f > 0 — the range it falls outside.
    fn beyond_every_impact(&self) -> Option<&'static str> {
        let v = self.value;
        match (self.quantity, self.bound) {
            (Quantity::Cor, Bound::AtLeast) if v > 1.0 => Some("the COR is at most 1"),
            (Quantity::Cor, Bound::AtMost) if v < 0.0 => Some("the COR is at least 0"),
            (Quantity::MaxForce, Bound::AtMost) if v <= 0.0 => Some("the peak force is above 0"),
            (Quantity::ContactTime, Bound::AtMost) if v <= 0.0 => {
                Some("the contact time is above 0")
            }
            _ => None,
        }
    }
}

/// A warning when no cell of `map` meets `targets` (every `feasible` false, no outline): each
/// constraint with the cells that meet it alone and its quantity's span over the map, so
/// that the one to relax shows. `None` when some cell meets them all, or with no targets.
pub fn unmet_warning(map: &super::Map, targets: &Targets) -> Option<String> {
    let cells: Vec<&Cell> = map.cells().iter().flatten().collect();
    if targets.0.is_empty() || cells.iter().any(|c| targets.holds(c)) {
        return None;
    }
    let each: Vec<String> = targets
        .0
        .iter()
        .map(|k| {
            let values = cells
                .iter()
                .map(|c| c.get(k.quantity))
                .filter(|v| v.is_finite());
            let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
            let met = cells.iter().filter(|c| k.holds(c)).count();
            let span = if lo <= hi {
                format!("{} spans {} … {}", k.quantity.name(), sig(lo), sig(hi))
            } else {
                format!("no cell has a {}", k.quantity.name())
            };
            format!("{k} in {met} of {} cells ({span})", cells.len())
        })
        .collect();
    Some(format!(
        "no cell meets the targets '{targets}': {}",
        each.join("; ")
    ))
}

/// Four significant digits, as the map's other warnings print their numbers.
fn sig(x: f64) -> String {
    crate::text::sig(x, 4)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_holds() {
        let t = Targets::parse("cor>=0.8,max_force<=2000,contact_time>=0.002").unwrap();
        assert_eq!(
            t.to_string(),
            "cor>=0.8,max_force<=2000,contact_time>=0.002"
        );
        let c = Cell {
            cor: 0.8,
            max_force: 2000.0,
            contact_time: Some(0.002),
        };
        assert!(t.holds(&c));
        assert!(!t.holds(&Cell { cor: 0.79, ..c }));
        assert!(!t.holds(&Cell {
            max_force: 2000.5,
            ..c
        }));
        assert!(!t.holds(&Cell {
            contact_time: None,
            ..c
        }));
        assert!(!t.holds(&Cell::UNRESOLVED));
    }

    #[test]
    fn bad_parts_are_named() {
        for (text, part, why) in [
            ("cor>=0.8,", "", "empty constraint"),
            ("cor=0.8", "cor=0.8", "expected QUANTITY>=VALUE"),
            ("cor>=x", "cor>=x", "'x' is not a number"),
            ("cor>=nan", "cor>=nan", "finite"),
            ("cor>=0.1,speed<=3", "speed<=3", "unknown quantity 'speed'"),
        ] {
            let e = Targets::parse(text).unwrap_err().to_string();
            assert!(e.starts_with(&format!("invalid where: '{part}'")), "{e}");
            assert!(e.contains(why), "{e}");
        }
        // a 120 kB part: cut, its length said
        let long = format!("cor>={}", "9".repeat(120_000));
        let e = Targets::parse(&long).unwrap_err().to_string();
        assert!(e.len() < 300, "{} bytes", e.len());
        assert!(e.contains("… (120005 characters)"), "{e}");
    }
}
