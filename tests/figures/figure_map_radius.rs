//! The map's picture and the peers' figures say when their impacts pass the ball's radius,
//! as the impact figures do (tests/figures/figure_radius.rs): `map --format svg` and the explorer's
//! map export carry `api::map_radius_note` in the subtitle (`svg_map::View::radius_note`),
//! `figure peers-cor-velocity` the speed the curve passes it from, `peers-force-time` its
//! impact's note. These once said it on stderr only, or not at all.

use crate::common;

use bouncelab::Ball;
use bouncelab::map::{Axis, MapSpec, Param, Quantity, Scale, compute};
use bouncelab::tui::views::map::export::MapExport;
use common::room::collisions;
use common::*;
use std::path::Path;

fn svg(dir: &Path, args: &[&str]) -> String {
    let mut all = args.to_vec();
    all.extend(["--out", "f.svg", "--force"]);
    // the map's warnings stay on stderr beside the picture's note
    let o = bl_at(dir, &all);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    let text = std::fs::read_to_string(dir.join("f.svg")).unwrap();
    let found = collisions(&text);
    assert!(found.is_empty(), "{args:?}: {found:?}");
    text
}

const MAP: [&str; 8] = [
    "map", "--lambda", "0.1:10:3", "--zeta", "0.01:1:3", "--format", "svg", "--preset",
];

/// The superball at 45 m/s: 8 of 9 cells pass R by z_m, the ninth by its centre (as the
/// command's two warnings on stderr count them).
#[test]
fn the_map_svg_says_which_cells_pass_the_radius() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let fast = svg(d, &[&MAP[..], &["superball", "--v0", "45"]].concat());
    let note = "outside the model&apos;s range: z_m or centre&apos;s α_max &gt; radius 21.55 mm \
                in 9 of 9 cells";
    assert!(fast.contains(note), "{fast}");
    // the stored copy in <desc> as well
    assert!(fast.contains("centre's α_max &gt; radius 21.55 mm in 9 of 9 cells."));
    // within the radius, or a normalized ball (no radius), no note
    let slow = svg(d, &[&MAP[..], &["superball"]].concat());
    assert!(!slow.contains("outside the model"), "{slow}");
    let norm = argv("map --normalized --lambda 0.1:10:3 --zeta 0.01:1:3");
    let norm = svg(d, &[&norm[..], &["--format", "svg"]].concat());
    assert!(!norm.contains("outside the model"), "{norm}");
}

/// The explorer's `e` on the map view: the same note, from the ball's radius.
#[test]
fn the_explorers_map_export_says_so_too() {
    let mut params = Ball::from_preset("superball").unwrap().params;
    params.v0 = 45.0;
    let spec = MapSpec::dimensional(
        params,
        bouncelab::model::contact::ContactLaw::Linear,
        Axis::new(Param::Lambda, 0.1, 10.0, 3, Scale::Log).unwrap(),
        Axis::new(Param::Zeta, 0.01, 1.0, 3, Scale::Log).unwrap(),
    )
    .unwrap();
    let export = |radius: f64| MapExport {
        map: compute(spec.clone()),
        quantity: Quantity::Cor,
        targets: None,
        own: (1.0, 0.1),
        title_ball: "superball at v0 = 45 m/s".into(),
        radius,
    };
    let (svg, _) = export(0.02155).render().unwrap();
    assert!(svg.contains("radius 21.55 mm in 9 of 9 cells"), "{svg}");
    let (svg, _) = export(f64::NAN).render().unwrap();
    assert!(!svg.contains("outside the model"), "{svg}");
}

/// `figure peers-cor-velocity` to 60 m/s: the Christoforou–Yigit curve passes the radius by
/// its centre from 25.08 m/s (as `figure cor-velocity` says of its own speeds); the peers'
/// force–time at 45 m/s by z_m 31.05 mm, as `figure force-time`.
#[test]
fn the_peers_figures_say_where_the_impacts_pass_the_radius() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let peers = ["figure", "peers-cor-velocity", "--preset", "superball"];
    let s = svg(d, &[&peers[..], &["--to", "60"]].concat());
    assert!(
        s.contains("from v0 = 25.08 m/s: centre&apos;s α_max 22.12 mm &gt; radius 21.55 mm"),
        "{s}"
    );
    let s = svg(d, &[&peers[..], &["--to", "10"]].concat());
    assert!(!s.contains("outside the model"), "{s}");
    let ft = argv("figure peers-force-time --preset superball --v0 45");
    let s = svg(d, &ft);
    assert!(
        s.contains("outside the model&apos;s range: z_m 31.05 mm &gt; radius 21.55 mm"),
        "{s}"
    );
}
