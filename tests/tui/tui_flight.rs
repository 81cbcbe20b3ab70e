//! The explorer's flight view (`h`, issue 57 item 3): snapshots at every size (60×20 …
//! 200×60), its numbers against `bouncelab shot` run on the line `y` gives, its keys through
//! `update` (fine and coarse steps, a refused value kept out), and `e`'s export.

use crate::common;
use crate::tui_common;

use bouncelab::tui::action::{Action, Mode};
use bouncelab::tui::app::{App, View};
use bouncelab::tui::export;
use bouncelab::tui::views::flight::param::FlightParam;
use ratatui::crossterm::event::KeyCode;
use serde_json::Value;
use tui_common::*;

/// The tennis ball in the flight view: docs/flight.md §6's serve that clears the net, 5° down
/// (the view's default), and the net 11.89 m out.
fn serve() -> App {
    let app = opened_on("tennis", 'h', View::Flight);
    assert_eq!(app.mode(), Mode::Flight);
    app
}

const SIZES: [(u16, u16); 6] = [
    (60, 20),
    (80, 24),
    (100, 30),
    (120, 40),
    (160, 50),
    (200, 60),
];

#[test]
fn the_view_at_every_size() {
    let app = serve();
    for (w, h) in SIZES {
        let t = draw(&app, w, h);
        let text = screen_text(&t).join("\n");
        // the net, the landing and the bounce's numbers are in the readout
        for needle in [
            "flight",
            "clears by 0.183 m",
            "lands",
            "leaves",
            "16.7",
            "27.04",
        ] {
            // 60×20 keeps the way out and the end; the first landing (x 16.7 m) is cut, marked
            let shown =
                text.contains(needle) || (w == 60 && needle == "16.7" && text.contains('…'));
            assert!(shown, "{w}×{h}: {needle}\n{text}");
        }
        insta::assert_snapshot!(format!("flight_{w}x{h}"), t.backend());
    }
}

/// The words of `line` after `bouncelab`.
fn words(line: &str) -> Vec<String> {
    line.split_whitespace().skip(1).map(String::from).collect()
}

#[test]
fn y_gives_the_shot_line_and_it_computes_what_the_view_shows() {
    let mut app = serve();
    press(&mut app, &[KeyCode::Char('w'), KeyCode::Char('a')]);
    let line = app.command_line();
    assert!(line.starts_with("bouncelab shot --preset tennis"), "{line}");
    assert!(
        line.contains("--spin 210")
            && line.contains("--elevation -4")
            && line.ends_with("--net 11.89,0.914"),
        "{line}"
    );
    let mut args = words(&line);
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::bl(&args);
    assert_eq!(out.code, 0, "{line}: {}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let r = app.flight_view().report().expect("a shot");
    // to 1e-12, as the oblique view's (tests/tui/tui_oblique.rs): the view's ball is built from
    // the explorer's setting, the line's from the preset and its flags
    let f = |v: &Value| v.as_f64().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0);
    for (k, a, b) in [
        ("x", f(&j["bounces"][0]["x"]), r.bounces[0].x),
        ("v_out", f(&j["bounces"][0]["v_out"]), r.bounces[0].v_out),
        (
            "spin_out",
            f(&j["bounces"][0]["spin_out"]),
            r.bounces[0].spin_out,
        ),
        ("end x", f(&j["end"]["x"]), r.end.state.x),
        (
            "net clearance",
            f(&j["net"]["clearance"]),
            r.net.as_ref().unwrap().clearance.unwrap(),
        ),
    ] {
        assert!(close(a, b), "{k}: command line {a} view {b}");
    }
}

#[test]
fn the_keys_step_fine_and_coarse_and_a_refused_value_is_kept_out() {
    let mut app = serve();
    let v = |app: &App, p| app.flight_view().values.get(p);
    // ↑ steps the selected value (speed): 1 m/s; Shift+↑ 5 m/s
    press(&mut app, &[KeyCode::Up]);
    assert_eq!(v(&app, FlightParam::Speed), 51.0);
    app.update(Action::Flight(
        bouncelab::tui::action::FlightKey::StepSelected {
            up: true,
            coarse: true,
        },
    ));
    assert_eq!(v(&app, FlightParam::Speed), 55.0);
    // → selects the elevation; the shot follows every step
    let x0 = app.flight_view().report().unwrap().bounces[0].x;
    press(&mut app, &[KeyCode::Right, KeyCode::Up]);
    assert_eq!(v(&app, FlightParam::Elevation), -4.0);
    assert!(app.flight_view().report().unwrap().bounces[0].x > x0);
    // the height down to below R: the library refuses it, the view keeps 0.0335 + …
    for _ in 0..2 {
        press(&mut app, &[KeyCode::Right]);
    }
    assert_eq!(app.flight_view().selected.0, FlightParam::Height);
    for _ in 0..40 {
        press(&mut app, &[KeyCode::Down]);
    }
    let h = v(&app, FlightParam::Height);
    assert!((h - 0.1).abs() < 1e-12, "{h}");
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("--height"), "{text}");
    // h leaves for the impact view
    press(&mut app, &[KeyCode::Char('h')]);
    assert_eq!(app.view(), View::Impact);
}

#[test]
fn e_exports_the_path_headed_by_the_shot_line() {
    let mut app = serve();
    let effects = app.update(Action::Export);
    let request = export_of(effects);
    assert_eq!(request.header[0], format!("# {}", app.command_line()));
    assert!(
        request.header[1].contains("bounce 1: t 0.396"),
        "{:?}",
        request.header
    );
    assert!(
        request.header[2].starts_with("# net at x 11.89 m, height 0.914 m: clears by 0.183"),
        "{:?}",
        request.header
    );
    let (_, path) = &request.charts[0];
    assert!(
        path.series.iter().any(|s| s.id == "net"),
        "the figure draws the net"
    );
    let dir = tempfile::tempdir().unwrap();
    let files = export::write(&request, dir.path()).unwrap();
    let names = file_names(&files);
    assert_eq!(
        names,
        [
            "bouncelab-tennis-flight-path-1.svg",
            "bouncelab-tennis-flight-path-1.csv"
        ]
    );
}

/// The defect (issue 57): the view's default serve (6° down) went into the net, and neither
/// the side view nor the readout said so. Its default now clears it (5° down, as
/// docs/flight.md §6), the net is drawn and the readout gives the clearance; stepped 1° down,
/// it says the ball hits the net. Fails on the old code (no net, the serve 6° down).
#[test]
fn the_default_serve_clears_the_net_and_the_readout_says_by_how_much() {
    let mut app = serve();
    let net = app
        .flight_view()
        .report()
        .unwrap()
        .net
        .clone()
        .expect("a net");
    assert!(net.cleared, "{net:?}");
    assert_eq!((net.x, net.height), (11.89, 0.914));
    press(&mut app, &[KeyCode::Char('A')]);
    assert_eq!(app.flight_view().values.elevation, -6.0);
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(text.contains("net 11.89 m: 0.0296 m too low"), "{text}");
}

/// The defect: the serve's bounce meets the court at 9.25 m/s across it, outside the tennis
/// ball's record (fitted at 6.906 m/s), and `bouncelab shot` warns of it; the flight view said
/// nothing. Its readout now gives the shot's warnings, the command line's own (its `y` line's
/// JSON), at every size, cut at a word where the rows are few. Fails on the old code.
#[test]
fn the_readout_gives_the_shots_warnings_as_the_command_line() {
    let app = serve();
    let mut args = words(&app.command_line());
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::bl(&args);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let said: Vec<&str> = j["bounces"][0]["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert!(
        said.iter()
            .any(|w| w.starts_with("outside calibration: impact speed 9.248 m/s")),
        "{said:?}"
    );
    let r = app.flight_view().report().unwrap();
    assert_eq!(r.warnings(), said);
    for (w, h) in SIZES {
        let text = screen_text(&draw(&app, w, h)).join("\n");
        assert!(text.contains("outside calibration:"), "{w}×{h}\n{text}");
    }
    // the wide readout has the rows to say where the speed lies, the narrow one its border
    for (w, h) in [(80, 24), (120, 40)] {
        let text = screen_text(&draw(&app, w, h)).join("\n");
        assert!(text.contains("9.248 m/s"), "{w}×{h}\n{text}");
    }
}
