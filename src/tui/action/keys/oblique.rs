//! The oblique view's keys (src/tui/views/oblique/): `a` `w` `k` step θ, ω, μ as `l` `z` `v`
//! step λ, ζ, v0 (upper case: down); on the charts the arrows select and step them as they do
//! λ, ζ, v0, on the map they move the cursor; `=` types the selected one, `t` the page, `n`
//! the map's quantity.

use super::super::{Action, MAP_LEAP, ObliqueKey};
use super::{lettered, stepping};
use crate::tui::views::oblique::param::ObliqueParam;
use ratatui::crossterm::event::{KeyCode, KeyEvent};

/// The keys of both pages.
fn shared(key: KeyEvent) -> Option<ObliqueKey> {
    let letters = [
        ('a', ObliqueParam::Angle),
        ('w', ObliqueParam::Spin),
        ('k', ObliqueParam::Friction),
    ];
    if let Some((param, up)) = lettered(key.code, letters) {
        return Some(ObliqueKey::Step {
            param,
            up,
            coarse: false,
        });
    }
    match key.code {
        KeyCode::Char('=') | KeyCode::Enter => Some(ObliqueKey::Type),
        KeyCode::Char('t') => Some(ObliqueKey::Page),
        KeyCode::Char('n') => Some(ObliqueKey::Quantity),
        _ => None,
    }
}

/// On the charts: ↑ ↓ step the selected one (Shift, PgUp/PgDn: coarse), ← → select.
pub fn charts(key: KeyEvent) -> Option<Action> {
    let k = stepping(
        key,
        |up, coarse| ObliqueKey::StepSelected { up, coarse },
        |next| ObliqueKey::Select { next },
    )
    .or_else(|| shared(key));
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
