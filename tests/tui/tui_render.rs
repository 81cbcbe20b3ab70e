//! What the explorer draws: snapshots of whole screens (TestBackend), colour off under
//! NO_COLOR, no NaN or inf on screen, and no panic at any size.

use crate::tui_common;
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;
use ratatui::style::Color;
use tui_common::*;

/// The whole explorer, opened on the embedded preset `ball` (0 superball, 1 golf, 2 baseball),
/// after `keys`, drawn at `size`: each screen its snapshot `name` (the name its own test had,
/// so the snapshot files stand as they were).
struct Screen {
    name: &'static str,
    ball: usize,
    keys: Vec<KeyCode>,
    size: (u16, u16),
}

fn screens() -> Vec<Screen> {
    use KeyCode::{Backspace, Char, Enter, Right, Tab};
    let screen = |name, ball, keys: &[&[KeyCode]], size| Screen {
        name,
        ball,
        keys: keys.concat(),
        size,
    };
    vec![
        screen("first_screen_superball", 0, &[], (120, 40)),
        screen("first_screen_golf", 1, &[], (120, 40)),
        screen("first_screen_baseball", 2, &[], (120, 40)),
        screen("help_overlay", 0, &[&[Char('?')]], (120, 40)),
        screen("sweeps_view", 0, &[&[Tab]], (120, 40)),
        screen("small_terminal_60x20", 0, &[], (60, 20)),
        screen("common_terminal_80x24", 0, &[], (80, 24)),
        screen("too_small", 0, &[], (30, 10)),
        screen(
            "after_lambda_up_three_times_and_zeta_down_twice",
            0,
            &[&chars("lll"), &chars("ZZ")],
            (120, 40),
        ),
        screen(
            "value_entry_refusing_text",
            0,
            &[&[Right, Char('=')], &chars("abc"), &[Enter]],
            (120, 40),
        ),
        screen(
            "save_prompt_refusing_a_name_with_a_space",
            0,
            &[&chars("ls"), &[Backspace; 6], &chars(" mine"), &[Enter]],
            (120, 40),
        ),
        screen(
            "flattened_superball_with_a_pinned_ghost",
            0,
            &[&[Char('p'), Right, Right, Char('=')], &[Char('8'), Enter]],
            (120, 40),
        ),
    ]
}

/// Each of [`screens`] drawn as its snapshot holds it (insta names the snapshot that differs).
#[test]
fn screens_after_keys() {
    for Screen {
        name,
        ball,
        keys,
        size: (w, h),
    } in screens()
    {
        let mut a = app(ball);
        press(&mut a, &keys);
        insta::assert_snapshot!(name, draw(&a, w, h).backend());
    }
}

#[test]
fn overwrite_question() {
    let mut a = app(0);
    press(&mut a, &[KeyCode::Char('s'), KeyCode::Enter]);
    // what the event loop answers when the name is taken, here by a file that holds a preset
    // of another name (a fixed path, so that the picture does not depend on the machine)
    a.update(Action::SaveExists {
        path: "/home/user/.config/bouncelab/presets/superball-custom.toml".into(),
        holds: Some("old-superball".into()),
    });
    insta::assert_snapshot!(draw(&a, 120, 40).backend());
}

/// A preset without measurements (as the explorer saves one at another speed) claims none.
#[test]
fn no_measured_speed_without_measurements() {
    let text_of = |p: Preset| buffer_text(draw(&App::new(p, true), 120, 40).backend().buffer());
    let mut p = Preset::embedded().remove(0);
    assert!(text_of(p.clone()).contains("measured at v0 = 3.120 m/s"));
    p.name = "unmeasured".into();
    (
        p.measured.cor,
        p.measured.max_force,
        p.measured.contact_time,
    ) = (None, None, None);
    assert!(!text_of(p).contains("measured at"));
}

#[test]
fn no_color_draws_without_colours() {
    for i in 0..3 {
        let mut a = App::new(Preset::embedded().remove(i), false);
        press(
            &mut a,
            &[KeyCode::Char('p'), KeyCode::Char('l'), KeyCode::Char('?')],
        );
        for keys in [vec![], vec![KeyCode::Esc, KeyCode::Tab]] {
            press(&mut a, &keys);
            let t = draw(&a, 120, 40);
            for cell in t.backend().buffer().content() {
                assert_eq!((cell.fg, cell.bg), (Color::Reset, Color::Reset), "{cell:?}");
            }
        }
    }
    // and with colour there is some
    let t = draw(&app(0), 120, 40);
    assert!(
        t.backend()
            .buffer()
            .content()
            .iter()
            .any(|c| c.fg != Color::Reset)
    );
}

#[test]
fn never_nan_or_inf_on_screen() {
    let mut a = app(0);
    // λ = 0, ζ = 1000: no rebound
    for keys in ["]LLLLLLLLLLLLLLL", "zzzzzzzzzzzzz", "?"] {
        let mut codes: Vec<KeyCode> = keys.chars().map(KeyCode::Char).collect();
        if keys == "?" {
            codes = vec![KeyCode::Tab];
        }
        press(&mut a, &codes);
        let s = buffer_text(draw(&a, 120, 40).backend().buffer());
        for bad in ["NaN", "nan", "inf"] {
            assert!(!s.contains(bad), "{bad} on screen:\n{s}");
        }
    }
    assert!(!a.run().unwrap().rebound);
}

#[test]
fn every_tiny_size_draws() {
    let mut apps = vec![app(0), app(1)];
    let mut help = app(2);
    press(&mut help, &[KeyCode::Char('?')]);
    let mut input = app(0);
    press(&mut input, &[KeyCode::Char('p'), KeyCode::Char('=')]);
    let mut sweeps = app(0);
    press(&mut sweeps, &[KeyCode::Tab]);
    apps.extend([help, input, sweeps]);
    for a in &apps {
        for w in 1..=20 {
            for h in 1..=10 {
                draw(a, w, h);
            }
        }
    }
    let s = buffer_text(draw(&apps[0], 20, 3).backend().buffer());
    assert!(s.starts_with("enlarge the"), "{s}");
}

#[test]
fn resize_storm() {
    let mut a = app(0);
    press(&mut a, &[KeyCode::Char('p'), KeyCode::Char('L')]);
    let mut t = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let mut seed: u32 = 12345;
    for i in 0..600 {
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
        let w = 1 + (seed >> 8) as u16 % 220;
        let h = 1 + (seed >> 20) as u16 % 70;
        t.backend_mut().resize(w, h);
        let keys: &[KeyCode] = match i % 50 {
            10 => &[KeyCode::Tab],
            20 => &[KeyCode::Char('?')],
            30 => &[KeyCode::Esc, KeyCode::Char('=')],
            40 => &[KeyCode::Esc],
            _ => &[],
        };
        press(&mut a, keys);
        t.draw(|f| f.render_widget(&a, f.area())).unwrap();
        assert_eq!(t.backend().buffer().area, Rect::new(0, 0, w, h));
    }
}
