//! `e` in the oblique view (docs/explorer.md): its three charts as figures — F_n and F_t,
//! v_c and ω against time, the paths over the surface — each written as SVG and CSV by
//! [`crate::tui::export::write`] (the other views' pattern: all files or none, never
//! overwriting, through `src/atomic.rs`), the CSV files headed by the `bouncelab oblique` line
//! that computes the impact (`y`'s) and its numbers. Built from the impact the view holds,
//! nothing re-solved.

use crate::figure::{Axis, Figure, Kind, Series, Style};
use crate::oblique::{ObliqueHistory, ObliqueResponse};
use crate::text::{human, number};

/// A series of `(x, y)` from two history columns.
fn series(label: &str, id: &str, style: Style, color: usize, pts: Vec<(f64, f64)>) -> Series {
    Series::new(label, id, Kind::Model, style, color).with_points(pts)
}

fn against_t(h: &ObliqueHistory, y: &[f64]) -> Vec<(f64, f64)> {
    h.t.iter().copied().zip(y.iter().copied()).collect()
}

/// F_n and F_t against time (s; the picture in ms), F_t dotted as on screen.
fn forces(h: &ObliqueHistory, subtitle: &str) -> Figure {
    Figure::new(
        "Normal and friction force against time".into(),
        subtitle.into(),
        Axis::linear("t (ms)", "t", 1e3),
        Axis::linear("force (N)", "force", 1.0),
        vec![
            series(
                "F_n",
                "normal_force",
                Style::Solid,
                0,
                against_t(h, &h.normal_force),
            ),
            series(
                "F_t",
                "friction_force",
                Style::Dotted,
                1,
                against_t(h, &h.friction_force),
            ),
        ],
    )
}

/// v_c (m/s) and ω (rad/s) against time: two figures, their units differ.
fn slip(h: &ObliqueHistory, subtitle: &str) -> [Figure; 2] {
    let t = || Axis::linear("t (ms)", "t", 1e3);
    [
        Figure::new(
            "Slip velocity of the contact point against time".into(),
            subtitle.into(),
            t(),
            Axis::linear("v_c (m/s)", "slip_velocity", 1.0),
            vec![series(
                "v_c = v_x − Rω",
                "slip_velocity",
                Style::Solid,
                2,
                against_t(h, &h.slip_velocity),
            )],
        ),
        Figure::new(
            "Spin against time".into(),
            subtitle.into(),
            t(),
            Axis::linear("ω (rad/s)", "spin", 1.0),
            vec![series("ω", "spin", Style::Solid, 3, against_t(h, &h.spin))],
        ),
    ]
}

/// The incoming and outgoing paths over the surface (x along it, y up, m/s as velocity
/// components): the ball comes in along (v_x, −v_y) and leaves along (v_x,out, v_y,out), both
/// drawn through the contact at the origin over one unit of time. The legend gives the angles
/// as `bouncelab oblique`'s text does (five digits, `text::human`), not to the last bit.
fn paths(r: &ObliqueResponse, subtitle: &str) -> Figure {
    let mut fig = Figure::new(
        "Incoming and outgoing paths".into(),
        subtitle.into(),
        Axis::linear("v_x (m/s)", "vx", 1.0),
        Axis::linear("v_y (m/s)", "vy", 1.0),
        vec![
            series(
                &format!("in, {}°", human(r.angle_in_deg, 5)),
                "in",
                Style::Dashed,
                0,
                vec![(-r.vx_in, r.vy_in), (0.0, 0.0)],
            ),
            series(
                &format!("out, {}°", human(r.angle_out_deg, 5)),
                "out",
                Style::Solid,
                1,
                vec![(0.0, 0.0), (r.vx_out, r.vy_out)],
            ),
        ],
    );
    // a metre per second the same length across and up: the angles drawn are the angles
    crate::figure::svg::equal_scales(&mut fig);
    fig
}

/// The oblique view's figures, in screen order, named as in the files
/// (`bouncelab-<ball>-oblique-forces-<n>.svg`, …); `None` without a history.
pub fn figures(r: &ObliqueResponse, subtitle: &str) -> Option<Vec<(&'static str, Figure)>> {
    let h = r.history.as_ref()?;
    let [v_c, spin] = slip(h, subtitle);
    Some(vec![
        ("oblique-forces", forces(h, subtitle)),
        ("oblique-slip-velocity", v_c),
        ("oblique-spin", spin),
        ("oblique-paths", paths(r, subtitle)),
    ])
}

/// The `#` lines of the CSV files: `line` (the `bouncelab oblique` line) and the impact's
/// numbers under the command line's JSON keys.
pub fn header(line: &str, r: &ObliqueResponse) -> Vec<String> {
    let e = r.cor_tangential.map_or_else(|| "null".to_string(), number);
    vec![
        format!("# {line}"),
        format!(
            "# v_out {} m/s, angle_out_deg {}, spin_out {} rad/s, vx_out {} m/s, vy_out {} m/s",
            number(r.v_out),
            number(r.angle_out_deg),
            number(r.spin_out),
            number(r.vx_out),
            number(r.vy_out)
        ),
        format!(
            "# cor_normal {}, cor_tangential {e}, apparent_friction {}, slid_throughout {}, \
             grip_time {} s, contact_time {} s",
            number(r.cor_normal),
            number(r.apparent_friction),
            r.slid_throughout,
            number(r.grip_time),
            number(r.contact_time)
        ),
        format!(
            "# max_normal_force {} N, max_friction_force {} N",
            number(r.max_normal_force),
            number(r.max_friction_force)
        ),
    ]
}
