//! Helpers for the explorer's tests: keys sent through `action::from_key` and `App::update`
//! as the event loop sends them, and the screen drawn into a `TestBackend`.
#![allow(dead_code)]

use bouncelab::cli::Cli;
use bouncelab::tui::action;
use bouncelab::tui::app::{App, Effect, View};
use bouncelab::tui::export::ExportRequest;
use clap::Parser;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::{Path, PathBuf};

/// Press `keys` in turn (an upper-case letter with Shift, as a terminal sends it); the effects
/// `update` returned, in order.
pub fn press(app: &mut App, keys: &[KeyCode]) -> Vec<Effect> {
    let mut effects = Vec::new();
    for &code in keys {
        let m = match code {
            KeyCode::Char(c) if c.is_ascii_uppercase() => KeyModifiers::SHIFT,
            _ => KeyModifiers::NONE,
        };
        if let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) {
            effects.extend(app.update(a));
        }
    }
    effects
}

/// The explorer in colour on the embedded preset number `i` (0 superball, 1 golf, 2 baseball).
pub fn app(i: usize) -> App {
    App::new(bouncelab::preset::Preset::embedded().remove(i), true)
}

/// The superball in colour: `app(0)`.
pub fn superball() -> App {
    app(0)
}

/// The superball in the map view of a `w` × `h` terminal (every pass evaluated in `update`).
pub fn map_app(color: bool, w: u16, h: u16) -> App {
    let mut app = App::new(bouncelab::preset::Preset::embedded().remove(0), color);
    app.update(action::Action::Resize(w, h));
    press(&mut app, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Map);
    app
}

/// The explorer on the embedded preset `name`, without colour, after the key `view_key`,
/// which opens `view` (asserted): the start of a test of one view.
pub fn opened_on(name: &str, view_key: char, view: View) -> App {
    let mut app = App::new(crate::common::embedded(name), false);
    press(&mut app, &[KeyCode::Char(view_key)]);
    assert_eq!(app.view(), view, "{name} after {view_key:?}");
    app
}

/// Open the `m` form, go to `field`, type `text` over its value and press Enter: what the
/// message line says then. The form stays open (an accepted entry closes only the entry; a
/// refused one stays open too): the caller closes it.
pub fn type_into_form(app: &mut App, field: bouncelab::tui::physical::Field, text: &str) -> String {
    use bouncelab::tui::physical::Field;
    press(app, &[KeyCode::Char('m')]);
    let n = Field::ALL.iter().position(|&f| f == field).unwrap();
    press(app, &vec![KeyCode::Down; n]);
    press(app, &[KeyCode::Enter]);
    app.update(action::Action::InputClear);
    press(app, &chars(text));
    press(app, &[KeyCode::Enter]);
    app.message().map(|m| m.text.clone()).unwrap_or_default()
}

/// The keys of `s`, one character each.
pub fn chars(s: &str) -> Vec<KeyCode> {
    s.chars().map(KeyCode::Char).collect()
}

/// The whole explorer drawn at `w` × `h`.
pub fn draw(app: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).unwrap();
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    t
}

/// The screen's rows as text.
pub fn screen_text(t: &Terminal<TestBackend>) -> Vec<String> {
    let buf = t.backend().buffer();
    (0..buf.area.height)
        .map(|y| {
            (0..buf.area.width)
                .map(|x| buf[(x, y)].symbol())
                .collect::<String>()
        })
        .collect()
}

/// The export among `effects` (what `update` returned for `e`).
pub fn export_of(effects: Vec<Effect>) -> ExportRequest {
    effects
        .into_iter()
        .find_map(|e| match e {
            Effect::Export(r) => Some(r),
            _ => None,
        })
        .expect("an export")
}

/// The files' names, without their folder.
pub fn file_names(files: &[PathBuf]) -> Vec<String> {
    files
        .iter()
        .map(|f| f.file_name().unwrap().to_string_lossy().into_owned())
        .collect()
}

/// The explorer `LINE` opens (`bouncelab …`, split at its spaces), as the binary would.
pub fn explorer_from(line: &str) -> App {
    let cli =
        Cli::try_parse_from(line.split_whitespace()).unwrap_or_else(|e| panic!("{line}: {e}"));
    match cli.explore.app(&cli.choice, false) {
        Ok((app, _)) => app,
        Err(e) => panic!("{line}: {e}"),
    }
}

/// Why the explorer refuses to open on `LINE` (`bouncelab …`, split at its spaces).
pub fn explorer_refuses(line: &str) -> String {
    let cli =
        Cli::try_parse_from(line.split_whitespace()).unwrap_or_else(|e| panic!("{line}: {e}"));
    match cli.explore.app(&cli.choice, false) {
        Ok(_) => panic!("{line}: the explorer opened"),
        Err(e) => e.to_string(),
    }
}

/// Whether `a` and `b` agree to 1e-12 relative (1e-12 absolute near zero): the explorer's
/// numbers against its command line's, which run the same code.
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1.0)
}

/// The oblique view's answer (speed, angle and spin out, normal COR) is the one its command
/// line `line` printed as JSON, `j`, to [`close`].
pub fn assert_oblique_answer_is(app: &App, j: &serde_json::Value, line: &str) {
    let keys = ["v_out", "angle_out_deg", "spin_out", "cor_normal"];
    assert_oblique_numbers_are(app, j, line, &keys);
}

/// [`assert_oblique_answer_is`] in each of `keys`: the JSON's keys, each the number of the
/// view's answer (`ObliqueResponse`) of the same name.
pub fn assert_oblique_numbers_are(app: &App, j: &serde_json::Value, line: &str, keys: &[&str]) {
    let r = app.oblique_view().response().expect("an impact");
    for &k in keys {
        let v = match k {
            "v_out" => r.v_out,
            "angle_out_deg" => r.angle_out_deg,
            "spin_out" => r.spin_out,
            "cor_normal" => r.cor_normal,
            "cor_tangential" => r.cor_tangential.expect("a tangential COR"),
            "apparent_friction" => r.apparent_friction,
            "grip_time" => r.grip_time,
            "contact_time" => r.contact_time,
            "max_normal_force" => r.max_normal_force,
            "max_friction_force" => r.max_friction_force,
            "vx_out" => r.vx_out,
            "vy_out" => r.vy_out,
            _ => panic!("the oblique answer has no number {k}"),
        };
        let f = j[k]
            .as_f64()
            .unwrap_or_else(|| panic!("{line}: {k} is not a number"));
        assert!(close(f, v), "{line}: {k}: command line {f}, view {v}");
    }
}

/// A figure made by hand on linear axes `x` and `y` of unit scale, its chart titled `title`
/// on screen.
pub fn hand_figure(
    title: &str,
    series: Vec<bouncelab::figure::Series>,
) -> bouncelab::figure::Figure {
    use bouncelab::figure::{Axis, Figure};
    let mut fig = Figure::new(
        "t".into(),
        String::new(),
        Axis::linear("x", "x", 1.0),
        Axis::linear("y", "y", 1.0),
        series,
    );
    fig.screen_title = title.into();
    fig
}

/// `fig` drawn by the explorer's chart widget (`Plot`, no colour) into a `w` × `h` buffer:
/// its rows as text ([`buffer_text`]).
pub fn chart_text(fig: &bouncelab::figure::Figure, w: u16, h: u16) -> String {
    use ratatui::widgets::Widget;
    let area = ratatui::layout::Rect::new(0, 0, w, h);
    let mut buf = Buffer::empty(area);
    bouncelab::tui::widgets::plot::Plot::new(fig, bouncelab::tui::theme::Theme::new(false))
        .render(area, &mut buf);
    buffer_text(&buf)
}

/// Type `text` as the selected parameter's value: `=`, the keys, Enter.
pub fn enter(app: &mut App, text: &str) {
    press(app, &[KeyCode::Char('=')]);
    type_keys(app, text);
    press(app, &[KeyCode::Enter]);
}

/// [`enter`] `text`, refused: the entry stays open with `says` on the message line; then Esc
/// closes it.
pub fn assert_entry_refused(app: &mut App, text: &str, says: &str) {
    enter(app, text);
    assert_eq!(app.mode(), bouncelab::tui::action::Mode::Input, "{text}");
    assert_eq!(app.message().unwrap().text, says, "{text}");
    press(app, &[KeyCode::Esc]);
}

/// The explorer's `bouncelab …` line (its `y` line) run by the binary with `--format json`
/// added: the JSON it writes.
pub fn line_json(line: &str) -> serde_json::Value {
    let mut args: Vec<&str> = line.split_whitespace().skip(1).collect();
    args.extend(["--format", "json"]);
    crate::common::json(&args)
}

/// A buffer's rows as text, each ended by a newline.
pub fn buffer_text(buf: &Buffer) -> String {
    let a = buf.area;
    (a.y..a.bottom())
        .map(|y| {
            (a.x..a.right())
                .map(|x| buf[(x, y)].symbol())
                .collect::<String>()
                + "\n"
        })
        .collect()
}

/// Type `keys` as a terminal sends them: a letter (upper case with Shift), `\t` Tab, `\u{1b}`
/// Esc; the effects `update` returned, in order.
pub fn type_keys(app: &mut App, keys: &str) -> Vec<Effect> {
    let codes: Vec<KeyCode> = keys
        .chars()
        .map(|c| match c {
            '\t' => KeyCode::Tab,
            '\u{1b}' => KeyCode::Esc,
            c => KeyCode::Char(c),
        })
        .collect();
    press(app, &codes)
}

/// A force–time CSV (`time_ms,force_N`): a half-sine pulse of 100 N over 3 ms starting at
/// 1 ms, `samples` readings `step_ms` apart from 0.
pub fn half_sine_csv(samples: usize, step_ms: f64) -> String {
    let mut s = String::from("time_ms,force_N\n");
    for i in 0..samples {
        let t = i as f64 * step_ms;
        let x = (t - 1.0) / 3.0;
        let f = if (0.0..=1.0).contains(&x) {
            100.0 * (std::f64::consts::PI * x).sin()
        } else {
            0.0
        };
        s.push_str(&format!("{t},{f}\n"));
    }
    s
}

/// `G`, the loop's list of the surfaces with the user's of the config home `config`, the
/// highlight on `name`, Enter.
pub fn pick_surface(app: &mut App, config: &Path, name: &str) {
    let effects = press(app, &[KeyCode::Char('G')]);
    assert!(
        effects
            .iter()
            .any(|e| matches!(e, bouncelab::tui::app::Effect::ListSurfaces)),
        "{effects:?}"
    );
    let (entries, error) =
        bouncelab::tui::surface::list_in(Some(&config.join("bouncelab/surfaces")));
    assert_eq!(error, None);
    let at = entries.iter().position(|e| e.surface.name == name).unwrap();
    app.update(action::Action::SurfacesListed(entries, None));
    assert!(matches!(
        app.overlay(),
        bouncelab::tui::app::Overlay::Surfaces(_)
    ));
    app.update(action::Action::PickerMove(action::Scroll::Home));
    for _ in 0..at {
        app.update(action::Action::PickerMove(action::Scroll::Down));
    }
    app.update(action::Action::PickerChoose);
    app.refresh();
    assert!(matches!(app.overlay(), bouncelab::tui::app::Overlay::None));
}
