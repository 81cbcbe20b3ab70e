//! The ball's calibration warning in the explorer (issue 52 item 2): the library's own
//! "outside calibration: …" text (`Ball::calibration_warning`) in the impact view's readout
//! and the oblique view's, whole on the message line when it appears, cut at a word in the
//! short readouts, and gone inside the record's range.

use crate::tui_common::*;
use bouncelab::Ball;
use bouncelab::tui::app::View;
use bouncelab::tui::state::Severity;
use ratatui::crossterm::event::KeyCode;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// The library's warning for the tennis ball at `v` m/s (`bouncelab run` prints it).
fn library(v: f64) -> Option<String> {
    Ball::from_preset("tennis").unwrap().calibration_warning(v)
}

fn screen(app: &bouncelab::tui::app::App, w: u16, h: u16) -> String {
    screen_text(&draw(app, w, h)).join("\n")
}

#[test]
fn tennis_at_20_m_s_says_it_is_outside_its_calibration_at_every_size() {
    let app = explorer_from("bouncelab --preset tennis --v0 20");
    let w = library(20.0).expect("20 m/s is outside the tennis ball's record");
    assert!(
        w.starts_with("outside calibration: impact speed 20 m/s"),
        "{w}"
    );
    assert_eq!(app.calibration().as_deref(), Some(w.as_str()));
    // the message line says it whole when the explorer opens outside the record
    let m = app.message().expect("a message");
    assert_eq!(
        (m.text.as_str(), m.severity),
        (w.as_str(), Severity::Warning)
    );
    for (width, height) in SIZES {
        let text = screen(&app, width, height);
        // the readout too, beside the charts or below them (the message line wraps, so the
        // readout's own line is looked for: it starts with a space inside its border)
        let readout_lines = text
            .lines()
            .filter(|l| l.contains("│ outside calibration:"))
            .count();
        assert!(readout_lines >= 1, "{width}×{height}:\n{text}");
        insta::assert_snapshot!(
            format!("tennis_20_m_s_{width}x{height}"),
            draw(&app, width, height).backend()
        );
    }
}

#[test]
fn the_warning_disappears_inside_the_record_and_comes_back_outside_it() {
    let mut app = explorer_from("bouncelab --preset tennis --v0 6.906");
    assert_eq!(library(6.906), None);
    assert_eq!(app.calibration(), None);
    assert!(
        app.message()
            .is_none_or(|m| !m.text.contains("calibration"))
    );
    for (width, height) in SIZES {
        let text = screen(&app, width, height);
        assert!(!text.contains("calibration"), "{width}×{height}:\n{text}");
    }
    // v steps v0 by 0.1 m/s: out of the record, which the readout says (the message line
    // only when the explorer opens outside it)
    press(&mut app, &[KeyCode::Char('v')]);
    let v0 = app.setting().params.v0;
    assert!((v0 - 7.006).abs() < 1e-9, "{v0}");
    let w = library(v0).expect("7.006 m/s is outside it");
    assert_eq!(app.calibration().as_deref(), Some(w.as_str()));
    assert!(screen(&app, 120, 40).contains("outside calibration: impact speed"));
    // back to the fitted speed: gone from the readout and the message line
    press(&mut app, &[KeyCode::Char('V')]);
    assert_eq!(app.calibration(), None);
    assert!(
        app.message()
            .is_none_or(|m| !m.text.contains("calibration"))
    );
    let text = screen(&app, 120, 40);
    assert!(
        !text.lines().any(|l| l.contains("│ outside calibration")),
        "{text}"
    );
}

#[test]
fn the_short_readout_cuts_the_warning_at_a_word() {
    let app = explorer_from("bouncelab --preset tennis --v0 20");
    let w = library(20.0).unwrap();
    let text = screen(&app, 80, 24);
    let line = text
        .lines()
        .find_map(|l| l.split("│ outside calibration:").nth(1))
        .unwrap_or_else(|| panic!("no readout line:\n{text}"));
    let shown = format!("outside calibration:{}", line.trim_end_matches(['│', ' ']));
    assert!(shown.ends_with('…'), "{shown}");
    let kept = shown.trim_end_matches('…');
    assert!(w.starts_with(kept), "{kept} | {w}");
    // cut before a space of the whole text: at a word
    assert_eq!(w[kept.len()..].chars().next(), Some(' '), "{kept} | {w}");
}

#[test]
fn the_oblique_view_warns_at_the_normal_speed_v_sin_theta() {
    // 30 m/s at 16°: the normal impact at 8.269 m/s, outside the record's 6.906 m/s
    // `--angle` opens the oblique view
    let app = explorer_from("bouncelab --preset tennis --v0 30 --angle 16");
    assert_eq!(app.view(), View::Oblique);
    let vy = app.oblique_view().response().expect("the impact").vy_in;
    assert!((vy - 30.0 * 16f64.to_radians().sin()).abs() < 1e-9, "{vy}");
    let w = library(vy).unwrap();
    assert!(w.contains("impact speed 8.269 m/s"), "{w}");
    assert_eq!(app.calibration().as_deref(), Some(w.as_str()));
    for (width, height) in SIZES {
        let text = screen(&app, width, height);
        assert!(
            text.contains("outside calibration"),
            "{width}×{height}:\n{text}"
        );
    }
    // at v sin θ = 6.906 m/s the oblique impact is inside the record, the normal one at v0 not
    let v0 = 6.906 / 16f64.to_radians().sin();
    let mut app = explorer_from(&format!("bouncelab --preset tennis --v0 {v0} --angle 16"));
    assert_eq!(app.calibration(), None);
    let text = screen(&app, 120, 40);
    assert!(!text.contains("outside calibration"), "{text}");
    press(&mut app, &[KeyCode::Char('i')]);
    assert_eq!(app.view(), View::Impact);
    assert!(app.calibration().is_some());
}
