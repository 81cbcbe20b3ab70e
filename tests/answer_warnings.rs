//! Warnings travel with the answer (issue 27, item 6): an indentation beyond the ball's radius
//! is said in run, sweep velocity, drop and peers (JSON `warnings`, a `warning:` line in text),
//! and the explorer's readout no longer says "no flattening (z_m < z_p)" under the Hertz law,
//! which never flattens.

mod common;
mod tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::app::App;
use common::*;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

const BEYOND: &str = "exceeds the ball's radius";

/// `run --preset superball --v0 45` reported a peak indentation of 31 mm on a ball of
/// 21.6 mm radius without a word.
#[test]
fn run_says_when_the_indentation_passes_the_radius() {
    let v = json(&[
        "run",
        "--preset",
        "superball",
        "--v0",
        "45",
        "--format",
        "json",
    ]);
    let w = v["warnings"].as_array().expect("a warnings array");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].as_str()
            .unwrap()
            .contains("31.05 mm exceeds the ball's radius 21.55 mm")
    );
    let text = ok(&["run", "--preset", "superball", "--v0", "45"]);
    assert!(
        text.contains(&format!("warning: peak indentation 31.05 mm {BEYOND}")),
        "{text}"
    );
    // at the measured speed nothing to say, and the key is still there
    let v = json(&["run", "--preset", "superball", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
    assert!(!ok(&["run", "--preset", "superball"]).contains("warning:"));
}

#[test]
fn sweep_rows_drop_and_peers_carry_their_warnings() {
    let v = json(&[
        "sweep",
        "velocity",
        "--preset",
        "superball",
        "--from",
        "5",
        "--to",
        "45",
        "--points",
        "3",
        "--format",
        "json",
    ]);
    let rows = v["rows"].as_array().unwrap();
    // z_m grows with v0: 3.45 mm at 5 m/s, 31 mm at 45
    assert_eq!(rows[0]["warnings"], serde_json::json!([]));
    assert!(rows[0]["max_indentation"].as_f64().unwrap() > 0.0);
    assert!(rows[2]["warnings"][0].as_str().unwrap().contains(BEYOND));
    // a drop from 100 m without air meets the plate at 44 m/s: the superball's first impact
    // passes R
    let v = json(&[
        "drop",
        "--preset",
        "superball",
        "--height",
        "100",
        "--no-drag",
        "--format",
        "json",
    ]);
    assert!(
        v["warnings"][0].as_str().unwrap().contains(BEYOND),
        "{}",
        v["warnings"]
    );
    let v = json(&["drop", "--preset", "tennis", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
    let v = json(&[
        "peers",
        "--preset",
        "superball",
        "--v0",
        "45",
        "--format",
        "json",
    ]);
    assert!(v["warnings"][0].as_str().unwrap().contains(BEYOND));
    let v = json(&["peers", "--preset", "superball", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
}

/// The explorer under the Hertz law said "no flattening (z_m < z_p)" with z_m 11 mm > z_p
/// 6 mm (tennis, football, basketball, softball).
#[test]
fn the_readout_does_not_claim_z_m_below_z_p_under_hertz() {
    let tennis = Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == "tennis")
        .unwrap();
    let mut app = App::new(tennis, true);
    // c cycles the law: linear → elastic–plastic → Hertz
    while !screen_text(&draw(&app, 120, 40))
        .concat()
        .contains("law hertz")
    {
        press(&mut app, &[KeyCode::Char('c')]);
    }
    let screen = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(!screen.contains("no flattening (z_m < z_p)"), "{screen}");
    assert!(
        screen.contains("Hertz: elastic, never flattens"),
        "{screen}"
    );
}
