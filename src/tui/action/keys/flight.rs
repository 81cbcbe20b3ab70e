//! The flight view's keys (src/tui/views/flight/): ← → select the launch's speed, elevation,
//! spin, height or μ, ↑ ↓ step it (Shift, PgUp/PgDn: coarse), and `a` `w` `k` step the
//! elevation, spin and μ directly as they step θ, ω, μ in the oblique view (upper case: down).

use super::super::{Action, FlightKey};
use crate::tui::views::flight::param::FlightParam;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

pub fn keys(key: KeyEvent) -> Option<Action> {
    let shift = key.modifiers.contains(KeyModifiers::SHIFT);
    let stepped = |up, coarse| Some(FlightKey::StepSelected { up, coarse });
    let step = |param, up| {
        Some(FlightKey::Step {
            param,
            up,
            coarse: false,
        })
    };
    let k = match key.code {
        KeyCode::Up => stepped(true, shift),
        KeyCode::Down => stepped(false, shift),
        KeyCode::PageUp => stepped(true, true),
        KeyCode::PageDown => stepped(false, true),
        KeyCode::Right => Some(FlightKey::Select { next: true }),
        KeyCode::Left => Some(FlightKey::Select { next: false }),
        KeyCode::Char('a') => step(FlightParam::Elevation, true),
        KeyCode::Char('A') => step(FlightParam::Elevation, false),
        KeyCode::Char('w') => step(FlightParam::Spin, true),
        KeyCode::Char('W') => step(FlightParam::Spin, false),
        KeyCode::Char('k') => step(FlightParam::Friction, true),
        KeyCode::Char('K') => step(FlightParam::Friction, false),
        _ => None,
    };
    k.map(Action::Flight)
}
