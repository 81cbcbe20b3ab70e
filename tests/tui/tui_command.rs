//! "Copy as command" (`y`) and the energy budget: the explorer's line `y` shows, as `run`'s
//! options, runs, through the real command line, to the COR and energy budget on screen; the same
//! line and the parameters head every CSV an export writes.

use crate::common;
use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::export;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use serde_json::Value;
use std::fs;
use std::path::Path;
use tui_common::{app, export_of, type_keys};

/// The line `y` shows.
fn shown(app: &mut App) -> String {
    type_keys(app, "y");
    let Overlay::Command(line) = app.overlay().clone() else {
        panic!("y shows the command: {:?}", app.overlay());
    };
    type_keys(app, "\u{1b}");
    assert_eq!(app.overlay(), &Overlay::None, "Esc closes it");
    line
}

/// Run `line` (plain words, no quoting needed) through the binary, as JSON.
fn run_json(line: &str, config_home: &Path) -> Value {
    let words: Vec<&str> = line.split(' ').collect();
    // `y` shows the explorer's line: `run` with the same options runs the same ball
    assert_eq!(words[0], "bouncelab");
    assert!(words[1].starts_with("--"), "the explorer's line: {line}");
    let mut args = vec!["run"];
    args.extend(&words[1..]);
    args.extend(["--format", "json"]);
    let o = common::bl_in(config_home, &args);
    assert_eq!(o.code, 0, "{line}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

/// The screen's run and `run`'s agree: COR, peak force, law, and every term of the budget.
fn assert_same_run(app: &App, v: &Value) {
    let r = app.run().expect("a run on screen");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1e-300);
    let f = |k: &str| common::f(v, k);
    assert!(close(r.cor, f("cor")), "COR {} vs {}", r.cor, f("cor"));
    assert!(close(r.max_force, f("max_force")));
    assert_eq!(v["law"], app.setting().law.name());
    let e = r.energy.expect("the explorer computes the budget");
    let ve = &v["energy"];
    for (mine, key) in [
        (e.initial_kinetic, "initial_kinetic"),
        (e.final_kinetic, "final_kinetic"),
        (e.dashpot, "dashpot"),
        (e.contact, "contact"),
        (e.spring, "spring"),
    ] {
        let theirs = common::f(ve, key);
        assert!(
            (mine - theirs).abs() <= 1e-12 * e.initial_kinetic,
            "{key}: {mine} vs {theirs}"
        );
    }
}

#[test]
fn y_shows_the_line_and_only_esc_or_the_help_keys_close_it() {
    let mut a = app(1);
    type_keys(&mut a, "y");
    assert_eq!(a.mode(), Mode::Help);
    let before = a.setting().clone();
    type_keys(&mut a, "lv");
    assert_eq!(a.setting(), &before, "keys under the box change nothing");
    let mut t = Terminal::new(TestBackend::new(80, 24)).unwrap();
    t.draw(|f| f.render_widget(&a, f.area())).unwrap();
    insta::assert_snapshot!(t.backend());
    a.update(Action::CloseHelp);
    assert_eq!(a.overlay(), &Overlay::None);
}

#[test]
fn the_preset_line_runs_to_the_screen() {
    let home = tempfile::tempdir().unwrap();
    let mut a = app(1);
    let line = shown(&mut a);
    assert_eq!(line, "bouncelab --preset golf --v0 1.47");
    assert_same_run(&a, &run_json(&line, home.path()));
}

#[test]
fn moved_parameters_and_law_run_to_the_screen() {
    let home = tempfile::tempdir().unwrap();
    for (ball, keys) in [
        (0, "lllZZvv"),
        (1, "LLzzzVc"),
        (2, "vvvvvcc"),
        (0, "cLLLLZ"),
    ] {
        let mut a = app(ball);
        type_keys(&mut a, keys);
        let line = shown(&mut a);
        assert!(line.contains(" --v0 "), "{line}");
        assert_same_run(&a, &run_json(&line, home.path()));
    }
}

/// A modulus typed in the form (`m`, E) is a K_p = 2π E z_p: the line says `--k-p` and runs to
/// the screen.
#[test]
fn a_typed_modulus_runs_to_the_screen() {
    use bouncelab::tui::physical::Field;
    let home = tempfile::tempdir().unwrap();
    let mut a = app(0);
    let code = |a: &mut App, c: KeyCode| {
        if let Some(act) = action::from_key(KeyEvent::new(c, KeyModifiers::NONE), a.mode()) {
            a.update(act);
        }
    };
    type_keys(&mut a, "m");
    while !matches!(a.overlay(), Overlay::Form(f) if f.selected == Field::E) {
        code(&mut a, KeyCode::Down);
    }
    type_keys(&mut a, "=");
    a.update(Action::InputClear);
    type_keys(&mut a, "3e6");
    code(&mut a, KeyCode::Enter);
    type_keys(&mut a, "\u{1b}");
    assert!(
        (a.setting().params.k_p / (2.0 * std::f64::consts::PI * 3e6 * 0.004) - 1.0).abs() < 1e-15
    );
    let line = shown(&mut a);
    assert!(line.contains(" --k-p "), "{line}");
    assert_same_run(&a, &run_json(&line, home.path()));
}

#[test]
fn a_start_preset_from_a_file_is_named_by_its_file() {
    let home = tempfile::tempdir().unwrap();
    let file = home.path().join("my ball.toml");
    fs::write(&file, common::SUPERBALL.replace("superball", "myball")).unwrap();
    let preset = Preset::parse(&fs::read_to_string(&file).unwrap(), "my ball.toml").unwrap();
    let mut a = App::new(preset, true).with_config(file.clone());
    type_keys(&mut a, "zz");
    let line = shown(&mut a);
    let quoted = format!("--config '{}'", file.display());
    assert!(line.contains(&quoted), "{line}");
    // the shell's reading of the quoted path
    let args: Vec<String> = std::iter::once("run".to_string())
        .chain(
            line.replace(&quoted, "--config FILE")
                .split(' ')
                .skip(1)
                .map(String::from),
        )
        .map(|w| match w.as_str() {
            "FILE" => file.display().to_string(),
            _ => w,
        })
        .chain(["--format".into(), "json".into()])
        .collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = common::bl_in(home.path(), &args);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert_same_run(&a, &serde_json::from_str(&o.stdout).unwrap());
    // another ball loaded is named by its name
    type_keys(&mut a, "2");
    assert!(shown(&mut a).starts_with("bouncelab --preset golf "));
}

#[test]
fn every_export_csv_starts_with_the_line_and_the_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let mut a = app(0);
    type_keys(&mut a, "2vp1lll");
    let line = shown(&mut a);
    let effects = type_keys(&mut a, "e");
    let request = export_of(effects);
    let files = export::write(&request, dir.path()).unwrap();
    let csvs: Vec<_> = files
        .iter()
        .filter(|f| f.extension().unwrap() == "csv")
        .collect();
    assert_eq!(csvs.len(), 3);
    for f in csvs {
        let text = fs::read_to_string(f).unwrap();
        let head: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
        // the `run` line with `y`'s options: it reproduces the data
        assert_eq!(
            head[0],
            format!("# {}", line.replacen("bouncelab ", "bouncelab run ", 1))
        );
        assert_eq!(head[1], "# ball superball (adopted parameters), linear law");
        assert!(head[2].starts_with("# lambda ") && head[2].contains(", k_r "));
        assert_eq!(head[3], "# pinned 1: bouncelab run --preset golf --v0 1.57");
        assert_eq!(head.len(), 4);
        let first = text.lines().nth(4).unwrap();
        assert!(first.starts_with("series,kind,"), "{first}");
    }
}

/// The form's K_p and z_p are `run`'s --k-p and --z-p: with λ and ζ moved too, the line
/// still runs to the screen; so do a mass and a radius typed after them (`--mass`, `--radius`).
#[test]
fn form_values_run_to_the_screen() {
    use bouncelab::tui::physical::Field;
    let home = tempfile::tempdir().unwrap();
    let mut a = app(0);
    for (field, value) in [
        (Field::KP, 61000.0),
        (Field::ZP, 0.003),
        (Field::Lambda, 0.5),
    ] {
        let next = field.check(value, a.setting()).unwrap();
        set_setting(&mut a, field, value);
        assert_eq!(*a.setting(), next);
    }
    type_keys(&mut a, "z");
    let line = shown(&mut a);
    assert!(
        line.contains(" --k-p 61000 --z-p 0.003 --lambda "),
        "{line}"
    );
    assert_same_run(&a, &run_json(&line, home.path()));
    set_setting(&mut a, Field::Mass, 0.05);
    set_setting(&mut a, Field::Radius, 0.025);
    let line = shown(&mut a);
    assert!(line.contains(" --mass 0.05 --radius 0.025 --k-p 61000 --z-p 0.003 --lambda "));
    assert_same_run(&a, &run_json(&line, home.path()));
    let v = run_json(&line, home.path());
    assert_eq!(common::f(&v, "mass"), 0.05);
    type_keys(&mut a, "y");
    assert!(
        a.message().is_none(),
        "nothing left uncarried: {:?}",
        a.message()
    );
}

/// Issue 27: after a mass typed in the form (50 g), `y` printed `bouncelab run --preset superball
/// --v0 3.12`, which runs e 0.7506 where the screen shows 0.7395. The line now carries the
/// mass and runs to the screen's numbers.
#[test]
fn a_typed_mass_runs_to_the_screen() {
    use bouncelab::tui::physical::Field;
    let home = tempfile::tempdir().unwrap();
    let mut a = app(0);
    set_setting(&mut a, Field::Mass, 0.05);
    let on_screen = a.run().expect("a run").cor;
    assert!((on_screen - 0.7395).abs() < 5e-5, "{on_screen}");
    let line = shown(&mut a);
    assert_eq!(line, "bouncelab --preset superball --mass 0.05 --v0 3.12");
    assert_same_run(&a, &run_json(&line, home.path()));
}

/// Type `value` (SI) for `field` in the form (`m`), in the form's unit (g, mm), then close it.
fn set_setting(a: &mut App, field: bouncelab::tui::physical::Field, value: f64) {
    use bouncelab::tui::physical::Field;
    a.update(Action::OpenForm);
    let n = Field::ALL.iter().position(|&f| f == field).unwrap();
    for _ in 0..n {
        a.update(Action::FormMove(bouncelab::tui::action::Scroll::Down));
    }
    a.update(Action::FormEdit);
    a.update(Action::InputClear);
    for c in (value * field.screen().1).to_string().chars() {
        a.update(Action::InputChar(c));
    }
    a.update(Action::InputSubmit);
    a.update(Action::CloseHelp);
}
