//! The oblique view's keys (src/tui/views/oblique/): `a` `w` `k` step θ, ω, μ as `l` `z` `v`
//! step λ, ζ, v0 (upper case: down); on the charts the arrows select and step them as they do
//! λ, ζ, v0, on the map they move the cursor; `=` types the selected one, `t` the page, `n`
//! the map's quantity.

use super::super::{Action, MAP_LEAP, ObliqueKey};
use crate::tui::views::oblique::param::ObliqueParam;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// The keys of both pages.
fn shared(key: KeyEvent) -> Option<ObliqueKey> {
    let step = |param, up| {
        Some(ObliqueKey::Step {
            param,
            up,
            coarse: false,
        })
    };
    match key.code {
        KeyCode::Char('a') => step(ObliqueParam::Angle, true),
        KeyCode::Char('A') => step(ObliqueParam::Angle, false),
        KeyCode::Char('w') => step(ObliqueParam::Spin, true),
        KeyCode::Char('W') => step(ObliqueParam::Spin, false),
        KeyCode::Char('k') => step(ObliqueParam::Friction, true),
        KeyCode::Char('K') => step(ObliqueParam::Friction, false),
        KeyCode::Char('=') | KeyCode::Enter => Some(ObliqueKey::Type),
        KeyCode::Char('t') => Some(ObliqueKey::Page),
        KeyCode::Char('n') => Some(ObliqueKey::Quantity),
        _ => None,
    }
}

/// On the charts: ↑ ↓ step the selected one (Shift, PgUp/PgDn: coarse), ← → select.
pub fn charts(key: KeyEvent) -> Option<Action> {
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    let stepped = |up, coarse| Some(ObliqueKey::StepSelected { up, coarse });
    let k = match key.code {
        KeyCode::Up => stepped(true, shift),
        KeyCode::Down => stepped(false, shift),
        KeyCode::PageUp => stepped(true, true),
        KeyCode::PageDown => stepped(false, true),
        KeyCode::Right => Some(ObliqueKey::Select { next: true }),
        KeyCode::Left => Some(ObliqueKey::Select { next: false }),
        _ => shared(key),
    };
    k.map(Action::Oblique)
}

/// On the map: the arrows move the cursor a cell, θ along ← →, μ along ↑ ↓ (Shift: 8).
pub fn map(key: KeyEvent) -> Option<Action> {
    let k = match super::arrow(key, MAP_LEAP) {
        Some((angle, friction)) => Some(ObliqueKey::Cursor { angle, friction }),
        None => shared(key),
    };
    k.map(Action::Oblique)
}
