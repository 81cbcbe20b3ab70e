//! The explorer and the command line (issue 29 item 2): `bouncelab --preset golf --law hertz
//! --v0 3 --lambda 0.5 --mass 0.05 …` — every option `run` takes for a preset ball — opens the
//! explorer in the state `bouncelab run` with those options runs (its COR, F_m and t_f to
//! 1e-12), and the explorer's line `y` then shows (no `run`), fed back to the parser as it is,
//! gives the same state.

use crate::common;
use crate::tui_common;

use bouncelab::cli::Cli;
use bouncelab::tui::app::Overlay;
use bouncelab::tui::command::params_off;
use clap::Parser;
use common::{bad_each, f, json};
use ratatui::crossterm::event::KeyCode;
use tui_common::{explorer_from, explorer_refuses};

fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(String::from).collect()
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

const LINES: [&str; 5] = [
    "--preset golf --law hertz --v0 3 --lambda 0.5 --mass 0.05",
    "--preset superball --v0 2.5 --zeta 0.3 --radius 0.03",
    "--preset baseball --law elastic-plastic --k-p 2e5 --z-p 0.004 --damping 30 --k-r 1e5 --v0 5",
    "--preset golf --params materials --mass 0.046 --v0 10",
    "--preset tennis --law linear --lambda 2 --zeta 0.05",
];

#[test]
fn the_command_line_opens_the_explorer_in_runs_state() {
    for line in LINES {
        let app = explorer_from(&format!("bouncelab {line}"));
        let mut run_args = words(&format!("run {line} --format json"));
        run_args.retain(|w| !w.is_empty());
        let args: Vec<&str> = run_args.iter().map(String::as_str).collect();
        let r = json(&args);
        let run = app.run().expect("a run");
        for (key, got) in [
            ("cor", run.cor),
            ("max_force", run.max_force),
            ("contact_time", run.contact_time.unwrap()),
        ] {
            assert!(same(f(&r, key), got), "{line}: {key} {} {got}", f(&r, key));
        }
    }
}

#[test]
fn the_line_y_shows_gives_the_same_state_back() {
    for line in LINES {
        let mut app = explorer_from(&format!("bouncelab {line}"));
        tui_common::press(&mut app, &[KeyCode::Char('y')]);
        let Overlay::Command(shown) = app.overlay().clone() else {
            panic!("no command box")
        };
        assert!(!shown.contains('\n'), "{shown}");
        // the explorer's line, not `run`'s: its words are the explorer's arguments as they are
        let back = words(&shown);
        assert_eq!(back[0], "bouncelab", "{shown}");
        assert!(back[1].starts_with("--"), "no subcommand: {shown}");
        let again = explorer_from(&shown);
        let (a, b) = (app.setting(), again.setting());
        assert_eq!(
            (a.preset, a.law, a.radius),
            (b.preset, b.law, b.radius),
            "{shown}"
        );
        let (p, q) = (&a.params, &b.params);
        let off = params_off(p, q);
        assert!(off.is_empty(), "{line} → {shown}: {off:?}\n{p:?}\n{q:?}");
    }
}

/// Bad state options are `run`'s one-line errors, exit 2, before any terminal is needed; before
/// a subcommand they are refused by name.
#[test]
fn bad_state_options_are_one_line_and_exit_2() {
    bad_each(&[
        ("--preset golf --v0 -3", &["v0"]),
        ("--preset golf --lambda 0.5 --k-r 5", &["--k-r", "--lambda"]),
        (
            "--law hertz run --preset golf",
            &["--law", "before a subcommand"],
        ),
    ]);
}

/// `y` shows the line on one row wherever the terminal is wider than it (a mouse selects it
/// whole) and, where the terminal takes OSC 52, asks the loop to copy it: ESC ] 52 ; c ;
/// base64(line) BEL; where it does not, nothing is sent and the box says to select it. The
/// line is kept to be printed on the main screen when the explorer ends.
#[test]
fn y_shows_one_unwrapped_row_and_copies_it_with_osc_52_where_allowed() {
    let line = LINES[2];
    let mut plain = explorer_from(&format!("bouncelab {line}"));
    assert_eq!(plain.last_command(), None);
    let effects = plain.update(bouncelab::tui::action::Action::ShowCommand);
    assert_eq!(
        effects,
        vec![],
        "no OSC 52 where the terminal is not known to take it"
    );
    let screen = tui_common::screen_text(&tui_common::draw(&plain, 200, 60)).join("\n");
    assert!(screen.contains("select it with the mouse"), "{screen}");
    let mut app = explorer_from(&format!("bouncelab {line}")).with_osc52(true);
    let effects = app.update(bouncelab::tui::action::Action::ShowCommand);
    let Overlay::Command(shown) = app.overlay().clone() else {
        panic!("no command box")
    };
    assert_eq!(
        effects,
        vec![bouncelab::tui::app::Effect::Copy(shown.clone())]
    );
    assert_eq!(app.last_command(), Some(shown.as_str()));
    assert!(shown.len() > 76, "longer than the old box: {shown}");
    // just wide enough, and wide
    let fit = shown.chars().count() as u16 + 2;
    for (w, h) in [(fit, 40), (200, 60)] {
        let screen = tui_common::screen_text(&tui_common::draw(&app, w, h)).join("\n");
        assert!(screen.contains(&shown), "{w}×{h}: {screen}");
    }
    let osc = bouncelab::tui::clipboard::osc52("bouncelab run --v0 3");
    assert_eq!(osc, "\x1b]52;c;Ym91bmNlbGFiIHJ1biAtLXYwIDM=\x07");
}

/// The `y` box at the five sizes, in colour (OSC 52 on: "copied") and without (off: "select
/// it"): the line on one row where the screen is wider than it, wrapped with "printed whole
/// when you quit" where it is not (60×20, 80×24).
#[test]
fn the_command_box_at_every_size() {
    let line = LINES[2];
    for (color, osc52) in [(true, true), (false, false)] {
        let cli = Cli::try_parse_from(words(&format!("bouncelab {line}"))).unwrap();
        let mut app = cli
            .explore
            .app(&cli.choice, color)
            .unwrap()
            .0
            .with_osc52(osc52);
        app.update(bouncelab::tui::action::Action::ShowCommand);
        let tag = if color { "color" } else { "no_color" };
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
            let t = tui_common::draw(&app, w, h);
            let text = tui_common::screen_text(&t).join("\n");
            let wide = w as usize > app.last_command().unwrap().chars().count() + 2;
            assert_eq!(text.contains("wider than the"), !wide, "{w}×{h}: {text}");
            insta::assert_snapshot!(format!("y_box_{tag}_{w}x{h}"), t.backend());
        }
    }
}

/// A target typed in the form is part of `y`'s line (`--target-mass`, `--target-speed`,
/// `--target-stiffness`, `--target-damping`, as `collide` takes them), and the line opens the
/// explorer on it again (issue 51 item 2: the line ran the ball at the wall and said so).
#[test]
fn the_target_is_part_of_the_line_y_shows() {
    let racket =
        "--preset tennis --v0 20 --target-mass 0.3 --target-stiffness 40000 --target-damping 5";
    let app = explorer_from(&format!("bouncelab {racket}"));
    let t = app.setting().target;
    assert_eq!(
        (t.mass, t.speed, t.stiffness, t.damping),
        (0.3, 0.0, 4e4, 5.0)
    );
    // typed in the form (M in g), then `y`
    let mut typed = explorer_from("bouncelab --preset tennis --v0 20");
    tui_common::press(&mut typed, &[KeyCode::Char('m')]);
    let to = bouncelab::tui::physical::Field::ALL
        .iter()
        .position(|&f| f == bouncelab::tui::physical::Field::TargetMass)
        .unwrap();
    tui_common::press(&mut typed, &vec![KeyCode::Down; to]);
    tui_common::press(&mut typed, &[KeyCode::Enter]);
    tui_common::type_keys(&mut typed, "300");
    tui_common::press(
        &mut typed,
        &[KeyCode::Enter, KeyCode::Esc, KeyCode::Char('y')],
    );
    let Overlay::Command(shown) = typed.overlay().clone() else {
        panic!("no command box")
    };
    assert!(shown.ends_with("--v0 20 --target-mass 0.3"), "{shown}");
    assert!(
        typed.message().is_none(),
        "nothing left uncarried: {:?}",
        typed.message()
    );
    let again = explorer_from(&shown);
    assert_eq!(again.setting().target, typed.setting().target);
    assert_eq!(again.run().unwrap().cor, typed.run().unwrap().cor);
    // refused as the form refuses it, naming the flag
    let e = explorer_refuses("bouncelab --preset tennis --target-mass 0");
    assert!(e.starts_with("--target-mass: invalid M: 0 g"), "{e}");
}
