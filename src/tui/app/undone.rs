//! What `u` says it undid: each value the undo changes, from what it was to what it is again,
//! in the explorer's one number format and the readout's units ("undone: m 50 → 37.4 g";
//! issue 51; tests/tui/tui_app.rs: `u_says_what_it_undid`).

use super::{App, Setting, Undoable};
use crate::tui::format::{screen_unit, value};
use crate::tui::physical::Field;
use crate::tui::views::flight::param::FlightParam;
use crate::tui::views::oblique::param::ObliqueParam;

/// A value in `unit` (SI) as the screen writes it, with its screen unit: "37.4 g", "∞".
fn shown(v: Option<f64>, unit: &str) -> (String, String) {
    let (u, k) = screen_unit(unit);
    let text = match v {
        Some(v) if v.is_infinite() => "∞".to_string(),
        Some(v) => value(v * k),
        // K_t and κ not set in the oblique view: the ball's
        None => "the ball's".to_string(),
    };
    (text, u.to_string())
}

/// "m 50 → 37.4 g": `name` from `now` to `then`.
fn change(name: &str, unit: &str, now: Option<f64>, then: Option<f64>) -> String {
    let ((a, u), (b, _)) = (shown(now, unit), shown(then, unit));
    let sep = if u.is_empty() || u.starts_with('°') {
        ""
    } else {
        " "
    };
    format!("{name} {a} → {b}{sep}{u}")
}

/// The fields in the order `u` names them: what a user types or steps first, λ and ζ (which
/// follow m, K_p, …) after, K_r and c (which follow λ and ζ) last.
const CHANGED_FIRST: [Field; 17] = [
    Field::V0,
    Field::Pressure,
    Field::Temperature,
    Field::Mass,
    Field::Radius,
    Field::KP,
    Field::ZP,
    Field::E,
    Field::TargetMass,
    Field::TargetSpeed,
    Field::TargetStiffness,
    Field::TargetDamping,
    Field::TangentialDamping,
    Field::Lambda,
    Field::Zeta,
    Field::KR,
    Field::C,
];

/// "p 60 → 80 kPa": a form field's change in the form's own unit ([`Field::show`]).
fn field_change(f: Field, now: f64, then: f64) -> String {
    let (a, b) = (f.show(now), f.show(then));
    let (a, _) = a.split_once(' ').unwrap_or((&a, ""));
    let (b, unit) = b.split_once(' ').unwrap_or((&b, ""));
    let sep = if unit.is_empty() { "" } else { " " };
    format!("{} {a} → {b}{sep}{unit}", f.symbol())
}

impl App {
    /// The changes from the current state back to `then`, one phrase each.
    pub(super) fn undone_text(&self, then: &Undoable) -> String {
        let (now, was): (&Setting, &Setting) = (&self.setting, &then.setting);
        let mut parts = Vec::new();
        if now.preset != was.preset {
            let name = |i: usize| self.presets.get(i).map_or("?", |p| p.name.as_str());
            parts.push(format!("ball {} → {}", name(now.preset), name(was.preset)));
        }
        // the surface picked (`G`): by name, the rigid plate's when none was picked
        let surface = |s: &Setting| {
            s.surface.as_ref().map_or_else(
                || crate::target::surface::Surface::rigid_plate().name,
                |x| x.name.clone(),
            )
        };
        if surface(now) != surface(was) {
            parts.push(format!("surface {} → {}", surface(now), surface(was)));
        }
        if now.law != was.law {
            parts.push(format!("law {} → {}", now.law, was.law));
        }
        if now.preset == was.preset {
            for f in CHANGED_FIRST {
                let (a, b) = (f.get(now), f.get(was));
                // NaN on both sides (a metal ball's E) is no change
                if a != b && !(a.is_nan() && b.is_nan()) {
                    parts.push(field_change(f, a, b));
                }
            }
        }
        for p in ObliqueParam::ALL {
            let (a, b) = (self.oblique.values.get(p), then.oblique.get(p));
            if a != b {
                parts.push(change(p.symbol(), p.unit().trim(), a, b));
            }
        }
        // the flight view's launch and μ (issue 57 item 3), in the view's own units (its
        // height in m, as the view writes it: "flight H 2.9 → 2.8 m")
        for p in FlightParam::ALL {
            let (a, b) = (self.flight.values.get(p), then.flight.get(p));
            if a != b {
                let (name, (a, b)) = (p.symbol(), (value(a), value(b)));
                parts.push(format!("flight {name} {a} → {b}{}", p.unit()));
            }
        }
        if let Some(m) = &then.measured {
            parts.insert(0, super::ask::put_away_what(m) + " put back");
        }
        match parts.len() {
            0 => "undone".into(),
            1..=3 => format!("undone: {}", parts.join(", ")),
            n => format!("undone: {}, and {} more", parts[..2].join(", "), n - 2),
        }
    }
}
