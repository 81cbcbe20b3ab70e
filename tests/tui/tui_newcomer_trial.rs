//! The explorer's defects a newcomer's trial found (late evening of 2026-12-07): the export's
//! header and `y` name one command, which runs the ball on screen (`collide` on a target, the
//! surface carried); `q` after `S` asks only for what the session does not hold; typed
//! conditions are conditions (the library's warning, the comparison withheld), in the oblique
//! view too; a preset saved away from its record's conditions claims no measurement; table
//! tennis is marked `TT`.

use crate::common;
use crate::tui_common;

use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect};
use bouncelab::tui::physical::Field;
use common::embedded;
use ratatui::crossterm::event::KeyCode;
use serde_json::Value;
use std::path::PathBuf;
use tui_common::*;

fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(String::from).collect()
}

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// The export's first CSV line, without its `# `.
fn header_command(app: &mut App) -> String {
    let request = export_of(press(app, &[KeyCode::Char('e')]));
    let first = request.header[0].clone();
    first.strip_prefix("# ").expect("a # line").to_string()
}

/// `line` (`bouncelab SUBCOMMAND …`) run by the binary as JSON: its COR and peak force are
/// the screen's, to 1e-12.
fn assert_runs_to_the_screen(app: &App, line: &str) -> Value {
    let mut args: Vec<String> = words(line)[1..].to_vec();
    args.extend(["--format".into(), "json".into()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::bl(&args);
    assert_eq!(out.code, 0, "{line}: {}", out.stderr);
    let j: Value = serde_json::from_str(&out.stdout).unwrap();
    let run = app.run().expect("a run on screen");
    for (k, v) in [("cor", run.cor), ("max_force", run.max_force)] {
        let f = j[k].as_f64().unwrap();
        assert!(same(f, v), "{line}: {k} {f} on the line, {v} on screen");
    }
    j
}

/// The header's line is the `y` line's words after the subcommand that computes them.
fn assert_header_is_y_s_words(app: &App, header: &str, sub: &str) {
    let y = app.command_line();
    let (h, y) = (words(header), words(&y));
    assert_eq!(
        h[..2],
        ["bouncelab".to_string(), sub.to_string()],
        "{header}"
    );
    assert_eq!(h[2..], y[1..], "header {header:?}, y {y:?}");
}

/// Item 1 and 2: on a target of 300 g the export's header ran the superball against the wall
/// (`bouncelab run --preset superball --v0 3.12`: F_m 117.3 N, not the screen's 111.5 N), and
/// `y`'s words after `bouncelab run` were refused (`--target-mass`).
#[test]
fn on_a_target_the_header_and_y_name_collide_and_run_the_screen_s_pair() {
    let mut app = superball();
    type_into_form(&mut app, Field::TargetMass, "300");
    press(&mut app, &[KeyCode::Esc]);
    app.refresh();
    let header = header_command(&mut app);
    assert!(header.contains("--target-mass 0.3"), "{header}");
    assert_header_is_y_s_words(&app, &header, "collide");
    let j = assert_runs_to_the_screen(&app, &header);
    assert!((j["max_force"].as_f64().unwrap() - 111.5).abs() < 0.05);
    // λ moved too: `collide` takes no --lambda, --zeta; the line gives K_r and c
    press(&mut app, &[KeyCode::Char('l')]);
    app.refresh();
    let header = header_command(&mut app);
    assert!(
        header.contains("--k-r") && !header.contains("--lambda"),
        "{header}"
    );
    assert_header_is_y_s_words(&app, &header, "collide");
    assert_runs_to_the_screen(&app, &header);
    // and `y`'s line still opens the explorer on the same pair
    let again = explorer_from(&app.command_line());
    assert_eq!(again.setting().target, app.setting().target);
    assert!(
        bouncelab::tui::command::params_off(&again.setting().params, &app.setting().params)
            .is_empty()
    );
}

/// Item 1: tennis on clay (`G`): `y` said `--surface clay`, the header ran the plate.
#[test]
fn on_a_surface_the_header_carries_it_and_runs_the_screen() {
    let mut app = App::new(embedded("tennis"), false);
    let empty = tempfile::tempdir().unwrap();
    pick_surface(&mut app, empty.path(), "clay");
    let header = header_command(&mut app);
    assert!(header.contains("--surface clay"), "{header}");
    assert_header_is_y_s_words(&app, &header, "run");
    assert_runs_to_the_screen(&app, &header);
    // the surface's K_s moved in the form: the target's option, which `collide` takes
    type_into_form(&mut app, Field::TargetStiffness, "3e5");
    press(&mut app, &[KeyCode::Esc]);
    app.refresh();
    let header = header_command(&mut app);
    assert!(
        header.contains("--surface clay --target-stiffness 300000"),
        "{header}"
    );
    assert_header_is_y_s_words(&app, &header, "collide");
    assert_runs_to_the_screen(&app, &header);
}

/// Item 3: `S` saved the pin, and `q` still asked "Quit and lose 1 pin?".
#[test]
fn after_s_q_asks_only_for_what_the_session_does_not_hold() {
    let mut app = App::new(embedded("baseball"), false);
    press(&mut app, &[KeyCode::Char('p')]);
    assert_eq!(app.at_stake().as_deref(), Some("1 pin"));
    press(&mut app, &[KeyCode::Char('S')]);
    let effects = app.update(Action::InputSubmit);
    let [Effect::SaveSession { path, text, .. }] = effects.as_slice() else {
        panic!("{effects:?}")
    };
    app.update(Action::SessionSaved(path.clone()));
    assert_eq!(app.at_stake(), None);
    // the session opened again (`--session`) holds its pin too
    let read = bouncelab::tui::session::Session::parse(path, text).unwrap();
    let back = App::new(embedded("baseball"), false)
        .with_session(&read)
        .unwrap();
    assert_eq!(back.pins().len(), 1);
    assert_eq!(back.at_stake(), None);
    press(&mut app, &[KeyCode::Char('q')]);
    assert!(app.should_quit(), "nothing to lose: q quits at once");
    // a pin after the save is not in the file
    let mut app = App::new(embedded("baseball"), false);
    press(&mut app, &[KeyCode::Char('p')]);
    press(&mut app, &[KeyCode::Char('S')]);
    app.update(Action::InputSubmit);
    app.update(Action::SessionSaved(PathBuf::from(
        "bouncelab-session.toml",
    )));
    press(&mut app, &[KeyCode::Char('l'), KeyCode::Char('p')]);
    assert_eq!(
        app.at_stake().as_deref(),
        Some("1 pin, your changes (S saves them)")
    );
}

/// The tennis ball inflated to 0.7 bar in the form (`m`, p).
fn tennis_at_70_kpa() -> App {
    let mut app = App::new(embedded("tennis"), false);
    type_into_form(&mut app, Field::Pressure, "0.7bar");
    press(&mut app, &[KeyCode::Esc]);
    app.refresh();
    assert_eq!(app.setting().conditions.pressure, Some(70_000.0));
    app
}

/// Item 4: a typed pressure read as changed parameters ("k_p, c, k_r, k_h changed the ball"),
/// and the comparison with the measurement at 82.74 kPa stayed on screen, where `run` at the
/// same conditions names them and withholds it.
#[test]
fn typed_conditions_warn_as_run_warns_and_withhold_the_comparison() {
    let app = tennis_at_70_kpa();
    let line = app.run_line();
    assert!(
        line.contains("run --preset tennis --pressure 70000"),
        "{line}"
    );
    let j = line_json(&line);
    let run_says = common::outside_calibration(&j);
    assert_eq!(run_says.len(), 1, "{j}");
    assert!(run_says[0].contains("70 kPa gauge"), "{}", run_says[0]);
    assert!(!j["comparison_withheld"].is_null(), "{j}");
    assert_eq!(app.calibration().as_deref(), Some(run_says[0]));
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(!text.contains("changed the ball"), "{text}");
    // the tennis ball's measured COR, 0.7709, is not compared with the ball at 70 kPa
    assert!(!text.contains("0.7709"), "{text}");
    assert!(text.contains("measured at v0 = 6.906 m/s: not"), "{text}");
    // nor drawn on the COR-against-speed chart (the sweeps view), as at the record's
    for (mut app, drawn) in [(app, false), (App::new(embedded("tennis"), false), true)] {
        press(&mut app, &[KeyCode::Tab]);
        app.refresh();
        let request = export_of(press(&mut app, &[KeyCode::Char('e')]));
        let ids: Vec<&str> = request
            .charts
            .iter()
            .flat_map(|(_, fig)| fig.series.iter().map(|s| s.id.as_str()))
            .collect();
        assert_eq!(ids.contains(&"measured cor"), drawn, "{ids:?}");
    }
}

/// Item 5: opened in the oblique view at 25 m/s and 16°, the message line warned of "impact
/// speed 25 m/s" where the readout and `bouncelab oblique` warn of the normal 6.891 m/s.
#[test]
fn the_oblique_view_opens_with_the_oblique_answer_s_warning() {
    let app =
        explorer_from("bouncelab --preset tennis --v0 25 --angle 16 --spin 300 --friction 0.6");
    let said = app.message().expect("a warning").text.clone();
    assert_eq!(Some(&said), app.calibration().as_ref());
    assert!(said.contains("impact speed 6.891 m/s"), "{said}");
}

/// Item 6: `s` at 70 kPa wrote the measurement at 82.74 kPa as the new preset's own.
#[test]
fn a_preset_saved_at_other_conditions_claims_no_measurement() {
    let app = tennis_at_70_kpa();
    let tennis = embedded("tennis");
    let (p, header) = bouncelab::tui::save::preset_for(&tennis, app.setting(), "tennis-70");
    let m = &p.measured;
    assert_eq!((m.cor, m.max_force, m.contact_time), (None, None, None));
    assert!(m.drops.is_none());
    let text = header.join("\n");
    assert!(text.contains("82.74 kPa"), "{text}");
    assert!(text.contains("left out"), "{text}");
    // at the record's conditions they stay
    let here = App::new(embedded("tennis"), false);
    let (p, _) = bouncelab::tui::save::preset_for(&tennis, here.setting(), "tennis-same");
    assert_eq!(p.measured.cor, tennis.measured.cor);
}

/// Item 7: table tennis's measured point was `T`, tennis's letter (docs/explorer.md: `TT`).
#[test]
fn table_tennis_is_marked_tt() {
    let app = App::new(embedded("table-tennis"), false);
    let text = screen_text(&draw(&app, 200, 60)).join("\n");
    assert!(text.contains("S G B TT measured"), "{text}");
}

/// On a target the force–time chart drew the wall's measured peak force and contact time
/// beside the pair's pulse, a comparison the readout withholds ("a wall's, not compared with
/// the pair") and `collide` does not make; at the wall they are drawn.
#[test]
fn on_a_target_the_wall_s_measurements_are_not_drawn() {
    let measured_lines = |app: &App| {
        bouncelab::tui::ui::figure(app, bouncelab::figure::explorer::Chart::ForceTime)
            .series
            .iter()
            .filter(|s| s.id.starts_with("measured "))
            .count()
    };
    let mut app = superball();
    app.refresh();
    assert_eq!(
        measured_lines(&app),
        2,
        "the wall's F_m and t_f at the measured speed"
    );
    type_into_form(&mut app, Field::TargetMass, "300");
    press(&mut app, &[KeyCode::Esc]);
    app.refresh();
    assert_eq!(measured_lines(&app), 0);
}
