//! `e` in the oblique view (docs/explorer.md): the impact's four charts written as SVG and
//! CSV through the explorer's one export writer (never overwriting, all or nothing), the CSV
//! files headed by `y`'s `bouncelab oblique` line and the impact's numbers, the series the
//! very history the view holds.

use crate::tui_common;

use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::export;
use ratatui::crossterm::event::KeyCode;
use std::fs;
use tui_common::*;

fn tennis() -> App {
    opened_on("tennis", 'i', View::Oblique)
}

#[test]
fn e_writes_the_oblique_charts_and_numbers() {
    let mut app = tennis();
    let r = app.oblique_view().response().unwrap().clone();
    let request = export_of(app.update(Action::Export));
    let names: Vec<&str> = request.charts.iter().map(|(n, _)| *n).collect();
    assert_eq!(
        names,
        [
            "oblique-forces",
            "oblique-slip-velocity",
            "oblique-spin",
            "oblique-paths"
        ]
    );
    // the header: the line `y` gives in this view, then the numbers under their JSON keys
    assert_eq!(request.header[0], format!("# {}", app.command_line()));
    assert!(request.header[0].starts_with("# bouncelab oblique --preset tennis"));
    let numbers = request.header.join("\n");
    for key in [
        "v_out",
        "angle_out_deg",
        "spin_out",
        "cor_normal",
        "cor_tangential",
    ] {
        assert!(numbers.contains(key), "{key}: {numbers}");
    }
    let dir = tempfile::tempdir().unwrap();
    let files = export::write(&request, dir.path()).unwrap();
    assert_eq!(files.len(), 8);
    let name = |i: usize| files[i].file_name().unwrap().to_string_lossy().into_owned();
    assert_eq!(name(0), "bouncelab-tennis-oblique-forces-1.svg");
    assert_eq!(name(7), "bouncelab-tennis-oblique-paths-1.csv");
    assert!(fs::read_to_string(&files[0]).unwrap().contains("<svg"));
    // the forces' CSV holds the history's F_n: its largest is the impact's sampled peak
    let csv = fs::read_to_string(&files[1]).unwrap();
    assert!(csv.starts_with("# bouncelab oblique"), "{csv}");
    let h = r.history.as_ref().unwrap();
    let peak = h.normal_force.iter().cloned().fold(0.0, f64::max);
    assert!(peak > 0.9 * r.max_normal_force && peak <= r.max_normal_force * (1.0 + 1e-12));
    assert!(
        csv.lines().count() > 2 * h.t.len(),
        "F_n and F_t, a row a sample"
    );
    // a second export takes the next number and leaves the first alone
    let again = export::write(&request, dir.path()).unwrap();
    assert!(again[0].ends_with("bouncelab-tennis-oblique-forces-2.svg"));
    assert_eq!(fs::read_to_string(&files[1]).unwrap(), csv);
    // the header after the loop reports back
    app.update(Action::Exported { files: again });
    assert!(app.message().unwrap().text.contains("(4 charts)"));
}

/// The paths' figure: the ball comes in along (v_x, −v_y) to the contact at the origin and
/// leaves along (v_x,out, v_y,out), the impact's own components.
#[test]
fn the_paths_are_the_arrival_and_the_departure() {
    let mut app = tennis();
    let r = app.oblique_view().response().unwrap().clone();
    let request = export_of(app.update(Action::Export));
    let paths = &request.charts[3].1;
    assert_eq!(
        paths.series[0].points,
        vec![(-r.vx_in, r.vy_in), (0.0, 0.0)]
    );
    assert_eq!(
        paths.series[1].points,
        vec![(0.0, 0.0), (r.vx_out, r.vy_out)]
    );
    assert!(paths.series[1].label.starts_with("out, "));
    // the legend printed the angles to the last bit ("out, 17.634123456789012°"): now as
    // `bouncelab oblique`'s text gives them
    let deg = |x: f64| format!("{}°", bouncelab::text::human(x, 5));
    assert_eq!(
        paths.series[0].label,
        format!("in, {}", deg(r.angle_in_deg))
    );
    assert_eq!(
        paths.series[1].label,
        format!("out, {}", deg(r.angle_out_deg))
    );
    assert!(
        paths.series[1].label.chars().count() <= "out, 123.45°".chars().count(),
        "{}",
        paths.series[1].label
    );
}

/// The paths' SVG has one scale across and up: the outgoing path, a straight line from the
/// contact, is drawn at its angle to the surface (issue 51 item 7: the axes were fitted each
/// to its own data, so a 16° path was drawn at some other angle). Read off the picture: the
/// solid polyline of the "out" path, its ends in pixels (y down).
#[test]
fn the_paths_svg_draws_each_angle_at_its_angle() {
    let mut app = tennis();
    // 16° at 25 m/s, as the example
    press(&mut app, &[KeyCode::Char('v'), KeyCode::Char('=')]);
    app.update(Action::InputClear);
    type_keys(&mut app, "25");
    press(&mut app, &[KeyCode::Enter, KeyCode::Char('=')]);
    app.update(Action::InputClear);
    type_keys(&mut app, "16");
    press(&mut app, &[KeyCode::Enter]);
    let r = app.oblique_view().response().unwrap().clone();
    assert!((r.angle_in_deg - 16.0).abs() < 1e-9, "{}", r.angle_in_deg);
    let request = export_of(app.update(Action::Export));
    let svg = bouncelab::figure::svg::render(&request.charts[3].1).unwrap();
    // every two-point polyline: the out path is the one whose first end is the contact and
    // whose second is up and to the right of it
    let lines: Vec<[(f64, f64); 2]> = svg
        .split("<polyline")
        .skip(1)
        .filter_map(|p| {
            let pts = p.split("points=\"").nth(1)?.split('"').next()?;
            let xy: Vec<(f64, f64)> = pts
                .split_whitespace()
                .filter_map(|q| {
                    let (x, y) = q.split_once(',')?;
                    Some((x.parse().ok()?, y.parse().ok()?))
                })
                .collect();
            (xy.len() == 2).then(|| [xy[0], xy[1]])
        })
        .collect();
    let angle = |[a, b]: [(f64, f64); 2]| (a.1 - b.1).atan2(b.0 - a.0).to_degrees();
    let drawn: Vec<f64> = lines.iter().map(|&l| angle(l)).collect();
    assert!(
        drawn.iter().any(|a| (a - r.angle_out_deg).abs() < 0.5),
        "out {}° not among the drawn {drawn:?}",
        r.angle_out_deg
    );
    // the incoming path's dashes go down to the contact at 16°
    assert!(
        drawn.iter().any(|a| (a + r.angle_in_deg).abs() < 0.5),
        "in −{}° not among the drawn {drawn:?}",
        r.angle_in_deg
    );
}
