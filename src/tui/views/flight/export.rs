//! `e` in the flight view (docs/explorer.md): the path of the shot as a figure, written as SVG
//! and CSV by [`crate::tui::export::write`] (the other views' pattern), the CSV headed by the
//! `bouncelab shot` line (`y`'s) and the landing's and the bounce's numbers; the widget draws
//! the same figure on the screen.

use crate::api::ShotReport;
use crate::figure::{Axis, Figure, GREY, Kind, Marker, Series, Style};
use crate::flight::EndReason;
use crate::text::number;

/// The centre's height against x, the bounces as markers, the surface (y = 0) as a line,
/// the net (when the shot has one) a vertical line from the surface to its top.
/// `radius`: the ball's, the centre's height at a bounce.
pub fn path_figure(r: &ShotReport, radius: f64, subtitle: &str) -> Figure {
    let path: Vec<(f64, f64)> = r.trajectory.iter().map(|s| (s.x, s.y)).collect();
    let bounces: Vec<(f64, f64)> = r.bounces.iter().map(|b| (b.x, radius)).collect();
    let x_end = path.iter().map(|p| p.0).fold(0.0_f64, f64::max);
    let x_start = path.iter().map(|p| p.0).fold(0.0_f64, f64::min);
    let net = r.net.iter().map(|n| {
        Series::new("net", "net", Kind::Reference, Style::Solid, GREY)
            .with_points(vec![(n.x, 0.0), (n.x, n.height)])
    });
    Figure::new(
        "Flight: the ball's centre over the surface".into(),
        subtitle.into(),
        Axis::linear("x (m)", "x", 1.0),
        Axis::linear("height of the centre (m)", "y", 1.0),
        vec![
            Series::new("surface", "surface", Kind::Reference, Style::Solid, GREY)
                .with_points(vec![(x_start, 0.0), (x_end, 0.0)]),
            Series::new("path", "path", Kind::Model, Style::Solid, 0).with_points(path),
            Series::new(
                "bounce",
                "bounce",
                Kind::Measured,
                Style::Markers(Marker::Circle),
                1,
            )
            .with_points(bounces),
        ]
        .into_iter()
        .chain(net)
        .collect(),
    )
}

/// Whether the ball clears the net, in a few words (the readout's narrow column holds 30
/// characters): "clears by 0.183 m", "0.0296 m too low" (its lowest point under the top),
/// "touches its cord", "not reached".
pub fn net_words(n: &crate::api::NetReport) -> String {
    match n.clearance {
        Some(c) if n.cleared => format!("clears by {} m", crate::text::sig(c, 3)),
        Some(c) if c < 0.0 => format!("{} m too low", crate::text::sig(-c, 3)),
        Some(_) => "touches its cord".into(),
        None => "not reached".into(),
    }
}

/// The `#` lines of the CSV: `line` (the `bouncelab shot` line), each bounce's numbers and
/// the end's, under the command line's JSON keys.
pub fn header(line: &str, r: &ShotReport) -> Vec<String> {
    let mut lines = vec![format!("# {line}")];
    for (i, b) in r.bounces.iter().enumerate() {
        lines.push(format!(
            "# bounce {}: t {} s, x {} m, v_in {} m/s, angle_in {}°, spin_in {} rad/s, \
             v_out {} m/s, angle_out {}°, spin_out {} rad/s, slid_throughout {}",
            i + 1,
            number(b.t),
            number(b.x),
            number(b.v_in),
            number(b.angle_in),
            number(b.spin_in),
            number(b.v_out),
            number(b.angle_out),
            number(b.spin_out),
            b.slid_throughout
        ));
    }
    if let Some(n) = &r.net {
        lines.push(format!(
            "# net at x {} m, height {} m: {}",
            number(n.x),
            number(n.height),
            net_words(n)
        ));
    }
    let e = r.end.state;
    lines.push(format!(
        "# end ({}): t {} s, x {} m, y {} m, vx {} m/s, vy {} m/s, spin {} rad/s",
        match r.end.reason {
            EndReason::Landing => "lands",
            EndReason::Distance => "reaches the distance",
            EndReason::Time => "at the time",
        },
        number(e.t),
        number(e.x),
        number(e.y),
        number(e.vx),
        number(e.vy),
        number(e.spin)
    ));
    lines
}
