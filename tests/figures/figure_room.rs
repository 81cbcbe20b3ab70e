//! Every text of a figure has room: no text over another text or over a marker, in the
//! figures users make — `bouncelab figure` for every preset, law and speed from gentle to
//! 3× the preset's, several balls on one figure, `reproduce`, `map --format svg`,
//! `fit --plot` and the explorer's exports (`e`). A text drawn over another reads as another
//! number; the checker is tests/support/common/room.rs, the placement src/figure/room.rs.

use crate::common;
use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::solver::{SolveOptions, simulate};
use bouncelab::tui::app::{App, Effect};
use common::room::{Rect, boxes, collisions};
use common::*;
use ratatui::crossterm::event::KeyCode;
use std::path::Path;

const LAWS: [&str; 3] = ["linear", "elastic-plastic", "hertz"];

/// The figure `args` write as `out` in `dir`, read back. Its stderr is empty but for the
/// warning of a map's cells whose ball's centre passes the radius (the superball at λ 0.01
/// and a weak dashpot, tests/cli/answer_reach.rs) and `outside calibration:` (a map's another
/// law than the record's, tests/cli/calibration.rs; a figure's speeds past its ball's record,
/// tests/cli/cli_formats_name.rs).
fn figure(dir: &Path, args: &[&str], out: &str) -> String {
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--out", out, "--force"]);
    let o = bl_at(dir, &all);
    assert_eq!(o.code, 0, "{all:?}: {}", o.stderr);
    for line in o.stderr.lines() {
        let centre = "bouncelab: warning: peak displacement of the ball's centre exceeds";
        let calibration = "bouncelab: warning: outside calibration:";
        assert!(
            (args[0] == "map" && line.starts_with(centre)) || line.starts_with(calibration),
            "{all:?}: {line}"
        );
    }
    std::fs::read_to_string(dir.join(out)).unwrap()
}

/// Collect `name: what overlaps` for each figure that has an overlap.
fn check(found: &mut Vec<String>, name: &str, svg: &str) {
    found.extend(collisions(svg).into_iter().map(|c| format!("{name}: {c}")));
}

fn assert_room(found: &[String]) {
    assert!(
        found.is_empty(),
        "{} overlaps:\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn the_checker_sees_a_text_over_a_marker_and_over_a_text() {
    let svg = |body: &str| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"560\">{body}</svg>"
        )
    };
    let text = |x: i32, y: i32, t: &str| {
        format!("<text x=\"{x}\" y=\"{y}\" dy=\"0.76em\" font-size=\"52\">{t}</text>")
    };
    let dot = "<circle cx=\"1000\" cy=\"1000\" r=\"20\" fill=\"#000000\"/>";
    // "e = 0.75" is 8 characters: 8 × 0.52 × 52 = 216 wide, 52 high
    let apart = svg(&format!("{dot}{}", text(1036, 932, "e = 0.75")));
    assert!(collisions(&apart).is_empty(), "{:?}", collisions(&apart));
    let (texts, marks) = boxes(&apart);
    assert_eq!(texts[0].1.y1 - texts[0].1.y0, 52.0);
    assert!((texts[0].1.x1 - texts[0].1.x0 - 216.32).abs() < 1e-9);
    assert_eq!(marks.len(), 1);
    let over_dot = svg(&format!("{dot}{}", text(900, 990, "e = 0.75")));
    assert_eq!(collisions(&over_dot).len(), 1);
    let over_text = svg(&format!(
        "{}{}",
        text(1036, 932, "e = 0.75"),
        text(1200, 960, "e = 0.8")
    ));
    assert_eq!(collisions(&over_text).len(), 1);
    // a map's cells (wide rectangles) and the frame (unfilled) are not markers
    let cells = svg(&format!(
        "<rect x=\"990\" y=\"940\" width=\"61\" height=\"41\" fill=\"#440154\"/>\
         <rect x=\"0\" y=\"0\" width=\"3000\" height=\"2000\" fill=\"none\"/>{}",
        text(1000, 950, "0.8")
    ));
    assert!(collisions(&cells).is_empty());
    // a rotated axis label runs up the page from its anchor
    let up = svg(
        "<text x=\"64\" y=\"1000\" dy=\"0.76em\" text-anchor=\"middle\" font-size=\"68\" \
         transform=\"rotate(270, 64, 1000)\">abcd</text>",
    );
    let (texts, _) = boxes(&up);
    let r: Rect = texts[0].1;
    assert!(
        (r.x0 - 64.0).abs() < 1e-9 && (r.x1 - 132.0).abs() < 1e-9,
        "{r:?}"
    );
    assert!(r.y0 < 1000.0 && r.y1 > 1000.0 && (r.y1 - r.y0 - 141.44).abs() < 1e-9);
    // the second of two stacked figures (`fit --plot`) is drawn in its own viewBox, below
    let stacked = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"1120\">\
         <svg width=\"800\" height=\"560\" viewBox=\"0 0 3200 2240\">{}</svg>\
         <svg y=\"560\" width=\"800\" height=\"560\" viewBox=\"0 0 3200 2240\">{}</svg></svg>",
        text(1036, 932, "e = 0.75"),
        text(1036, 932, "e = 0.75")
    );
    assert!(
        collisions(&stacked).is_empty(),
        "{:?}",
        collisions(&stacked)
    );
    let (texts, _) = boxes(&stacked);
    assert_eq!((texts[0].1.y0, texts[1].1.y0), (233.0, 793.0));
}

/// A folder to draw figures in, and the overlaps found in them ([`check`]); a test draws its
/// figures here and ends with [`Room::assert_none`].
struct Room {
    dir: tempfile::TempDir,
    found: Vec<String>,
}

impl Room {
    fn new() -> Room {
        Room {
            dir: tempfile::tempdir().unwrap(),
            found: Vec::new(),
        }
    }

    /// The figure `args` write as `out` ([`figure`]), its overlaps kept under `name`.
    fn figure(&mut self, name: &str, args: &[&str], out: &str) {
        let svg = figure(self.dir.path(), args, out);
        self.check(name, &svg);
    }

    fn check(&mut self, name: &str, svg: &str) {
        check(&mut self.found, name, svg);
    }

    fn assert_none(&self) {
        assert_room(&self.found);
    }
}

/// The figures that drew a text over another or over a marker before the texts were placed
/// (src/figure/room.rs): a ball's name over another ball's marker on `cor-zeta`, and the
/// measured e of five balls over each other on `cor-velocity`.
#[test]
fn figures_that_overlapped_no_longer_do() {
    let mut room = Room::new();
    // "softball" sat over the baseball's ▲
    let softball = ["figure", "cor-zeta", "--preset", "softball"];
    room.figure("cor-zeta softball", &softball, "a.svg");
    let five = argv(
        "--preset tennis --preset softball --preset basketball --preset football \
            --preset table-tennis",
    );
    // "tennis" over "basketball" and the golf ball's ■; "e = 0.771" over "e = 0.79" and it
    // over "e = 0.881"; one "z_f" over another
    for name in ["cor-zeta", "cor-velocity", "force-displacement"] {
        let mut args = vec!["figure", name];
        args.extend(&five);
        room.figure(&format!("{name}, five balls"), &args, "b.svg");
    }
    room.assert_none();
}

/// Every preset, each law, speeds from gentle (0.3 v0) to 3 v0: the one-ball figures. The ζ
/// figures' markers are the measured balls, the same under every law; they are drawn on the
/// linear law (their default), which computes in a fraction of the time.
#[test]
fn every_preset_law_and_speed_has_room() {
    let mut room = Room::new();
    for p in Preset::embedded_all() {
        let name = p.name.clone();
        for fig in ["cor-zeta", "force-zeta"] {
            let args = ["figure", fig, "--preset", &name];
            room.figure(&format!("{fig} {name}"), &args, "z.svg");
        }
        for law in LAWS {
            for fig in ["cor-velocity", "peers-cor-velocity", "peers-force-time"] {
                let args = ["figure", fig, "--preset", &name, "--law", law];
                room.figure(&format!("{fig} {name} {law}"), &args, "v.svg");
            }
            for k in [0.3, 1.0, 3.0] {
                let v0 = (k * p.measured.v0).to_string();
                for fig in ["force-time", "force-displacement"] {
                    let args = ["figure", fig, "--preset", &name, "--law", law, "--v0", &v0];
                    room.figure(&format!("{fig} {name} {law} v0 = {v0}"), &args, "h.svg");
                }
            }
        }
    }
    room.assert_none();
}

/// `reproduce`, several balls on one figure, the design map and `fit --plot`.
#[test]
fn reproduce_several_balls_maps_and_fit_plots_have_room() {
    let mut room = Room::new();
    let d = room.dir.path().to_path_buf();
    ok_at(&d, &["reproduce", "--out", "rep"]);
    for f in std::fs::read_dir(d.join("rep")).unwrap() {
        let f = f.unwrap().path();
        if f.extension().is_some_and(|e| e == "svg") {
            let svg = std::fs::read_to_string(&f).unwrap();
            room.check(&f.display().to_string(), &svg);
        }
    }
    let sets: [&[&str]; 2] = [
        &["golf", "baseball", "superball"],
        &argv("tennis softball basketball football table-tennis"),
    ];
    for set in sets {
        for fig in [
            "cor-zeta",
            "force-zeta",
            "cor-velocity",
            "force-time",
            "force-displacement",
        ] {
            let mut args = vec!["figure", fig];
            for p in set {
                args.extend(["--preset", p]);
            }
            room.figure(&format!("{fig} {set:?}"), &args, "m.svg");
        }
    }
    for p in ["superball", "golf", "baseball", "tennis", "softball"] {
        for extra in [
            &[][..],
            &["--where", "cor>=0.7"],
            &["--law", "elastic-plastic"],
        ] {
            let mut args = vec!["map", "--preset", p, "--lambda", "0.01:10:40"];
            args.extend(["--zeta", "0.01:100:40", "--format", "svg"]);
            args.extend(extra);
            room.figure(&format!("map {p} {extra:?}"), &args, "map.svg");
        }
    }
    for (data, flag) in fit_data(&d) {
        let args = ["fit", flag, data.as_str(), "--plot", "fit.svg", "--force"];
        ok_at(&d, &args);
        let svg = std::fs::read_to_string(d.join("fit.svg")).unwrap();
        room.check(&format!("fit {flag} {data}"), &svg);
    }
    room.assert_none();
}

/// A superball trace (the solver's, sampled) and a COR table of a softer superball at five
/// speeds, written in `dir`: (file, the fit's flag).
fn fit_data(dir: &Path) -> Vec<(String, &'static str)> {
    let p = embedded("superball");
    let mut params = p.params();
    params.k_r *= 1.3;
    let r = simulate(&params, p.law, &SolveOptions::default().with_samples(300)).unwrap();
    let mut trace = String::from("time_s,force_N\n");
    for (t, f) in r.history.t.iter().zip(&r.history.force) {
        trace.push_str(&format!("{t},{f}\n"));
    }
    std::fs::write(dir.join("trace.csv"), trace).unwrap();
    let mut table = String::from("v0,cor\n");
    for v0 in [1.0, 2.0, 3.0, 5.0, 8.0] {
        let q = bouncelab::ImpactParams { v0, ..params };
        let e = simulate(&q, p.law, &SolveOptions::default()).unwrap().cor;
        table.push_str(&format!("{v0},{e}\n"));
    }
    std::fs::write(dir.join("cor.csv"), table).unwrap();
    vec![
        ("trace.csv".into(), "--force-time"),
        ("cor.csv".into(), "--cor-table"),
    ]
}

/// What `e` exports in each view of the explorer (Tab to the next, round to the first),
/// rendered; the charts' names.
fn exports(app: &mut App, found: &mut Vec<String>, what: &str) -> Vec<&'static str> {
    let (mut charts, first) = (Vec::new(), app.view());
    loop {
        charts.extend(exports_here(app, found, what));
        tui_common::press(app, &[KeyCode::Tab]);
        if app.view() == first {
            return charts;
        }
    }
}

/// What `e` exports in the current view, rendered; the charts' names.
fn exports_here(app: &mut App, found: &mut Vec<String>, what: &str) -> Vec<&'static str> {
    let mut charts = Vec::new();
    {
        for e in tui_common::press(app, &[KeyCode::Char('e')]) {
            if let Effect::Export(r) = e {
                for (chart, fig) in &r.charts {
                    let svg = bouncelab::figure::svg::render(fig).unwrap();
                    check(found, &format!("explorer {what} {chart}"), &svg);
                    charts.push(*chart);
                }
                if let Some(m) = &r.map {
                    let (svg, _) = m.render().unwrap();
                    check(found, &format!("explorer {what} map"), &svg);
                    charts.push("map");
                }
            }
        }
    }
    charts
}

/// The oblique view's export (`i`, then `e`), its charts' names.
fn oblique_exports(app: &mut App, found: &mut Vec<String>, what: &str) -> Vec<&'static str> {
    tui_common::press(app, &[KeyCode::Char('i')]);
    let charts = exports_here(app, found, what);
    tui_common::press(app, &[KeyCode::Char('i')]);
    charts
}

/// The explorer's exports of every preset under each law, at its speed, 0.3× and 3× it (the
/// coarse speed step, 1 m/s), with a pinned run beside: every view's charts, the map and the
/// oblique view's.
#[test]
fn the_explorers_exports_have_room() {
    let (mut found, mut charts) = (Vec::new(), Vec::new());
    for p in Preset::embedded_all() {
        let (name, v0) = (p.name.clone(), p.measured.v0);
        let mut app = App::new(p, false);
        tui_common::press(&mut app, &[KeyCode::Char('p'), KeyCode::Char(']')]);
        for law in LAWS {
            let down = ((v0 - 0.3 * v0).round() as usize).max(1);
            let up = (2.0 * v0).round() as usize;
            let at = format!("{name} {law} v0");
            charts.extend(exports(&mut app, &mut found, &at));
            charts.extend(oblique_exports(&mut app, &mut found, &at));
            tui_common::press(&mut app, &vec![KeyCode::Char('V'); down]);
            charts.extend(exports(
                &mut app,
                &mut found,
                &format!("{name} {law} gentle"),
            ));
            tui_common::press(&mut app, &vec![KeyCode::Char('v'); down + up]);
            charts.extend(exports(&mut app, &mut found, &format!("{name} {law} 3 v0")));
            tui_common::press(&mut app, &vec![KeyCode::Char('V'); up]);
            tui_common::press(&mut app, &[KeyCode::Char('c')]);
        }
    }
    charts.sort_unstable();
    charts.dedup();
    let every = argv(
        "cor-velocity cor-zeta force-displacement force-time force-zeta map oblique-forces \
         oblique-paths oblique-slip-velocity oblique-spin peers-cor-velocity \
         peers-force-displacement peers-force-time",
    );
    assert_eq!(charts, every, "every view's export was checked");
    assert_room(&found);
}

/// This run's marker is drawn last in the SVG, over a measured marker at the same place, so it
/// is never hidden under it (issue 51 item 7); the legend keeps the series' order.
#[test]
fn this_runs_marker_is_drawn_over_a_measured_one() {
    use bouncelab::figure::{Axis, Figure, Kind, Marker, PALETTE, Series, Style, svg};
    let at = vec![(0.5, 0.75)];
    let run = Series::new(
        "this run",
        "this run",
        Kind::ThisRun,
        Style::Markers(Marker::Diamond),
        4,
    )
    .with_points(at.clone());
    let measured = Series::new(
        "measured",
        "measured",
        Kind::Measured,
        Style::Markers(Marker::Circle),
        0,
    )
    .with_points(at);
    let fig = Figure::new(
        "t".into(),
        String::new(),
        Axis::linear("x", "x", 1.0),
        Axis::linear("y", "y", 1.0),
        vec![run, measured],
    );
    let picture = svg::render(&fig).unwrap();
    // each colour is used twice: its marker in the plot, then its legend sample under it;
    // the first use is the marker
    let first = |(r, g, b): (u8, u8, u8)| {
        let hex = format!("#{r:02X}{g:02X}{b:02X}");
        picture
            .find(&hex)
            .unwrap_or_else(|| panic!("{hex} not drawn"))
    };
    let (run_at, measured_at) = (first(PALETTE[4]), first(PALETTE[0]));
    assert!(
        run_at > measured_at,
        "this run at {run_at}, the measured marker at {measured_at}: drawn under it"
    );
}
