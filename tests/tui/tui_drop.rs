//! The explorer's drop view (`d`): a snapshot, the keys that re-run it, the animation clock,
//! and the reduced-motion setting.

use crate::common::embedded;
use crate::tui_common;

use bouncelab::drop::standards;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

#[test]
fn drop_view_tennis() {
    let mut app = App::new(embedded("tennis"), false);
    press(&mut app, &[KeyCode::Char('d')]);
    assert_eq!(app.view(), View::Drop);
    let t = draw(&app, 120, 36);
    // the key hints offer the drop view's own keys, not `e`, which exports nothing there
    let hints: String = (0..120)
        .map(|x| t.backend().buffer()[(x, 35)].symbol().to_string())
        .collect();
    assert!(
        hints.contains("space pause") && hints.contains("b replay"),
        "{hints}"
    );
    assert!(!hints.contains("e export"), "{hints}");
    insta::assert_snapshot!(t.backend());
}

#[test]
fn the_tennis_ball_drops_from_the_itf_height_and_passes() {
    let mut app = App::new(embedded("tennis"), false);
    press(&mut app, &[KeyCode::Char('d')]);
    let d = app.drop_view();
    let run = d.sequence().unwrap();
    // the preset's v0 is the impact speed of the ITF drop, so the height comes back to 2.54 m
    assert!(
        (run.setup.height - 2.54).abs() < 1e-3,
        "{}",
        run.setup.height
    );
    let (s, v) = d.verdict.unwrap();
    assert_eq!(s.name, "itf");
    assert!(v.pass);
    // the band is the window, in bottom-of-ball heights (ITF reads the bottom)
    assert_eq!(d.band(), Some((1.35, 1.47)));
    // FIBA reads the top: the band moves down by the diameter
    let mut bb = App::new(embedded("basketball"), false);
    press(&mut bb, &[KeyCode::Char('d')]);
    let (lo, hi) = bb.drop_view().band().unwrap();
    let r = embedded("basketball").measured.radius;
    assert!((lo - (1.20 - 2.0 * r)).abs() < 1e-12 && (hi - (1.40 - 2.0 * r)).abs() < 1e-12);
    assert_eq!(standards::for_ball("golf"), None);
}

#[test]
fn lambda_zeta_and_v0_keys_rerun_the_drop() {
    let mut app = App::new(embedded("tennis"), false);
    press(&mut app, &[KeyCode::Char('d')]);
    let first = |app: &App| app.drop_view().sequence().unwrap().bounces[0];
    let before = first(&app);
    press(&mut app, &[KeyCode::Char('L'), KeyCode::Char('L')]);
    let after_lambda = first(&app);
    assert!(after_lambda.cor < before.cor, "softer recoil, lower e");
    press(&mut app, &[KeyCode::Char('z')]);
    assert_ne!(first(&app).cor, after_lambda.cor);
    let h = app.drop_view().sequence().unwrap().setup.height;
    press(&mut app, &[KeyCode::Char('v')]);
    assert!(app.drop_view().sequence().unwrap().setup.height > h);
    // Tab leaves the drop view for the impact view, `d` too
    press(&mut app, &[KeyCode::Tab]);
    assert_eq!(app.view(), View::Impact);
    press(&mut app, &[KeyCode::Char('d'), KeyCode::Char('d')]);
    assert_eq!(app.view(), View::Impact);
}

#[test]
fn the_animation_runs_pauses_and_replays() {
    let mut app = App::new(embedded("tennis"), false).with_motion(true);
    press(&mut app, &[KeyCode::Char('d')]);
    assert!(app.animating());
    assert_eq!(app.drop_view().t, 0.0);
    assert!((app.drop_view().height_now() - 2.54).abs() < 1e-3);
    app.update(Action::Tick(0.25));
    assert_eq!(app.drop_view().t, 0.25);
    let falling = app.drop_view().height_now();
    assert!(falling < 2.54 && falling > 2.0, "{falling}");
    press(&mut app, &[KeyCode::Char(' ')]);
    assert!(!app.animating());
    app.update(Action::Tick(1.0));
    assert_eq!(app.drop_view().t, 0.25, "paused");
    press(&mut app, &[KeyCode::Char(' ')]);
    app.update(Action::Tick(100.0));
    let end = app.drop_view().duration();
    assert_eq!(app.drop_view().t, end);
    assert!(!app.animating(), "stops at the end");
    press(&mut app, &[KeyCode::Char('b')]);
    assert_eq!(app.drop_view().t, 0.0);
    assert!(app.animating());
    // ticks do nothing outside the drop view
    press(&mut app, &[KeyCode::Char('d')]);
    assert!(!app.animating());
}

#[test]
fn reduced_motion_shows_the_whole_sequence_still() {
    let mut app = App::new(embedded("football"), false).with_motion(false);
    press(&mut app, &[KeyCode::Char('d')]);
    let d = app.drop_view();
    assert!(!app.animating());
    assert_eq!(d.t, d.duration());
    press(&mut app, &[KeyCode::Char(' ')]);
    assert!(!app.animating(), "space does not start an animation");
    let text = format!("{:?}", draw(&app, 120, 36).backend());
    assert!(text.contains("reduced motion"), "{text}");
    assert!(text.contains("PASS"), "{text}");
}

/// The drop view of `app` in a `w` × `h` terminal: the screen's rows.
fn drop_screen(mut app: App, w: u16, h: u16) -> Vec<String> {
    app.update(Action::Resize(w, h));
    press(&mut app, &[KeyCode::Char('d')]);
    screen_text(&draw(&app, w, h))
}

/// Issue 29, item 9: at 60×20 and 80×24 the drop view showed no rebound and no verdict (its
/// seven-row readout held the setting only); its ticks read "0 0.716 1.43"; under NO_COLOR
/// the legend named two lines it drew alike. Now the verdict and the first rebound show at
/// every size, the ticks are round, and the legend carries each line's look.
#[test]
fn the_drop_view_shows_its_verdict_and_rebounds_at_small_sizes() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let s = drop_screen(App::new(embedded("tennis"), false), w, h).join("\n");
        assert!(s.contains("itf PASS"), "{w}×{h}: no verdict\n{s}");
        assert!(s.contains("1.410"), "{w}×{h}: no first rebound\n{s}");
        assert!(
            !s.contains("2.67") && !s.contains("5.34"),
            "{w}×{h}: ticks\n{s}"
        );
        // where the chart has room for its legend (ratatui hides it above half the chart)
        if w == 80 || w >= 120 {
            assert!(s.contains("┄ itf window"), "{w}×{h}: legend\n{s}");
        }
    }
}

/// The football's verdict, `fifa-quality-pro PASS margin +0.225 m`, is one column wider
/// than the readout at 120 × 40: the readout's wrap put the `m` alone on the next line. It
/// breaks between fields, the value and its unit kept together, at every size.
#[test]
fn the_verdict_keeps_its_margin_with_its_unit() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let s = drop_screen(App::new(embedded("football"), false), w, h).join("\n");
        assert!(
            s.contains("fifa-quality-pro PASS"),
            "{w}×{h}: no verdict\n{s}"
        );
        assert!(s.contains("margin +0.225 m"), "{w}×{h}: margin\n{s}");
    }
}

/// Issue 29 item 9: under reduced motion the ball at rest was an arc merged into the plate
/// (one row of dots over it at 60×20). It is a whole circle standing on the plate: at least
/// two rows of it above the plate's row, at every size.
#[test]
fn the_ball_at_rest_is_round_on_its_plate() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let app = App::new(embedded("superball"), false).with_motion(false);
        let rows = drop_screen(app, w, h);
        let top = rows.iter().position(|r| r.contains("┌ ball ")).unwrap();
        let x = rows[top].chars().collect::<Vec<_>>();
        let left = (0..x.len())
            .find(|&i| x[i] == '┌' && x[i + 1..].starts_with(&[' ', 'b', 'a', 'l', 'l']))
            .unwrap();
        let right = (left + 1..x.len()).find(|&i| x[i] == '┐').unwrap();
        let inner: Vec<String> = rows[top + 1..]
            .iter()
            .take_while(|r| r.chars().nth(left) == Some('│'))
            .map(|r| r.chars().skip(left + 1).take(right - left - 1).collect())
            .collect();
        let (plate, above) = inner.split_last().unwrap();
        assert!(
            plate.chars().all(|c| c != ' '),
            "{w}×{h}: the plate {plate:?}"
        );
        let drawn = above.iter().filter(|r| r.trim() != "").count();
        assert!(
            drawn >= 2,
            "{w}×{h}: the ball over its plate\n{}",
            inner.join("\n")
        );
    }
}

/// Above its terminal speed no drop reaches v0: the view says so in words and draws no
/// window, no legend and no verdict beside an empty chart (issue 51 item 5: it showed the
/// standard's window, its legend and "itf PASS" over nothing).
#[test]
fn above_the_terminal_speed_the_view_says_why_it_has_no_bounce() {
    let mut app = App::new(embedded("tennis"), false);
    press(&mut app, &[KeyCode::Char('v'), KeyCode::Char('=')]);
    app.update(Action::InputClear);
    type_keys(&mut app, "60");
    press(&mut app, &[KeyCode::Enter, KeyCode::Char('d')]);
    assert!(app.drop_view().sequence().is_none());
    for (w, h) in [(80, 24), (120, 40)] {
        let shown = screen_text(&draw(&app, w, h)).join("\n");
        assert!(shown.contains("no drop reaches"), "{w}x{h}\n{shown}");
        assert!(shown.contains("terminal"), "{w}x{h}\n{shown}");
        for bad in ["PASS", "FAIL", "window", "23.817"] {
            assert!(!shown.contains(bad), "{bad} at {w}x{h}\n{shown}");
        }
    }
}

/// Paused, the drop view says so, at every size (issue 51 item 6).
#[test]
fn the_drop_view_shows_paused() {
    let mut app = App::new(embedded("tennis"), false).with_motion(true);
    press(&mut app, &[KeyCode::Char('d')]);
    app.update(Action::Tick(0.25));
    for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)] {
        let shown = screen_text(&draw(&app, w, h)).join("\n");
        assert!(!shown.contains("paused"), "{w}x{h}\n{shown}");
    }
    press(&mut app, &[KeyCode::Char(' ')]);
    for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)] {
        let shown = screen_text(&draw(&app, w, h)).join("\n");
        assert!(shown.contains("paused"), "{w}x{h}\n{shown}");
    }
}

/// Issue 51 item 4: the drop view's air line wrote its drag coefficient as a typed string,
/// "C_d 0.47", two digits beside the readout's four and apart from the constant the drop
/// uses; it is the constant, in the one format: "C_d 0.4700".
#[test]
fn the_drop_view_writes_the_drag_coefficient_it_uses_in_four_digits() {
    use bouncelab::drop::flight::SPHERE_DRAG_COEFFICIENT;
    let mut app = App::new(embedded("tennis"), false);
    press(&mut app, &[KeyCode::Char('d')]);
    let s = screen_text(&draw(&app, 120, 36)).join("\n");
    let c_d = format!(
        "C_d {}",
        bouncelab::tui::format::value(SPHERE_DRAG_COEFFICIENT)
    );
    assert_eq!(c_d, "C_d 0.4700");
    assert!(s.contains(&c_d), "{c_d:?} in\n{s}");
}
