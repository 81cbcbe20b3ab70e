//! The flight view's keys (src/tui/views/flight/): ← → select the launch's speed, elevation,
//! spin, height or μ, ↑ ↓ step it (Shift, PgUp/PgDn: coarse), and `a` `w` `k` step the
//! elevation, spin and μ directly as they step θ, ω, μ in the oblique view (upper case: down).

use super::super::{Action, FlightKey};
use super::{lettered, stepping};
use crate::tui::views::flight::param::FlightParam;
use ratatui::crossterm::event::KeyEvent;

pub fn keys(key: KeyEvent) -> Option<Action> {
    let letters = [
        ('a', FlightParam::Elevation),
        ('w', FlightParam::Spin),
        ('k', FlightParam::Friction),
    ];
    let step = |(param, up)| FlightKey::Step {
        param,
        up,
        coarse: false,
    };
    let k = stepping(
        key,
        |up, coarse| FlightKey::StepSelected { up, coarse },
        |next| FlightKey::Select { next },
    )
    .or_else(|| lettered(key.code, letters).map(step));
    k.map(Action::Flight)
}
