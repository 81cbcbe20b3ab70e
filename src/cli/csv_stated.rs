//! The columns a CSV answer ends with: what its JSON states beside the answer, the ball
//! (`preset`, `origin`, `parameters`, `law`, where the command's columns lack them), the
//! surface (`surface`, its K_s, c_s, M) and the conditions (`temperature_c`,
//! `pressure_gauge_pa`, `atmosphere_pa`, the JSON `conditions` object's keys), so that a CSV
//! names the ball, what it ran on and at as every answer does (docs/cli.md, "Conditions").
//! Added at the end of a command's columns: columns are added, never renamed or moved.

use super::output::{num, opt_num};
use crate::api::{Ball, SurfaceUsed};
use crate::conditions::Conditions;

/// The ball's columns, the JSON header's keys (`run`'s CSV has them first).
pub const BALL: [&str; 4] = ["preset", "origin", "parameters", "law"];

/// The cells of [`BALL`] for `b` (`preset` empty for a ball that is no preset).
pub fn ball_cells(b: &Ball) -> [String; 4] {
    [
        b.name.clone().unwrap_or_default(),
        b.origin.clone(),
        b.source.into(),
        b.law.name().into(),
    ]
}

/// The surface's columns: its name and the normal numbers the answer ran on (`inf`: rigid,
/// fixed), as the JSON `surface` object's `name`, `stiffness`, `damping`, `mass`.
pub const SURFACE: [&str; 4] = [
    "surface",
    "surface_stiffness",
    "surface_damping",
    "surface_mass",
];

/// The conditions' columns, the JSON `conditions` object's keys (empty where it has `null`).
pub const CONDITIONS: [&str; 3] = ["temperature_c", "pressure_gauge_pa", "atmosphere_pa"];

/// The cells of [`SURFACE`] for `s`.
pub fn surface_cells(s: &SurfaceUsed) -> [String; 4] {
    let m = &s.mechanics;
    [
        s.name.clone(),
        num(m.stiffness),
        num(m.damping),
        num(m.mass),
    ]
}

/// The cells of [`CONDITIONS`] for `c`.
pub fn conditions_cells(c: &Conditions) -> [String; 3] {
    [
        opt_num(c.temperature_c),
        opt_num(c.pressure_gauge_pa),
        num(c.atmosphere_pa),
    ]
}

/// [`SURFACE`] then [`CONDITIONS`]: the last columns of an answer that names its ball in
/// its own columns (`run`).
pub fn columns() -> Vec<&'static str> {
    SURFACE.into_iter().chain(CONDITIONS).collect()
}

/// The cells of [`columns`].
pub fn cells(s: &SurfaceUsed, c: &Conditions) -> Vec<String> {
    surface_cells(s)
        .into_iter()
        .chain(conditions_cells(c))
        .collect()
}

/// [`BALL`], then [`columns`]: the last columns of an answer whose own columns do not name
/// the ball (`sweep velocity`, `oblique`, `drop`).
pub fn with_ball() -> Vec<&'static str> {
    BALL.into_iter().chain(columns()).collect()
}

/// The cells of [`with_ball`], for `b` on `s` (at `b`'s conditions).
pub fn with_ball_cells(b: &Ball, s: &SurfaceUsed) -> Vec<String> {
    ball_cells(b)
        .into_iter()
        .chain(cells(s, &b.conditions))
        .collect()
}
