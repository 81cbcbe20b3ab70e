//! Sessions (issue 29 item 3): `S` asks for a file and hands the loop the session's TOML; the
//! TOML read back opens an explorer in the same state — ball and every parameter, law, v0,
//! the target, the pins, the view, the selected parameter; `bouncelab --session FILE` reads
//! it, and a file that does not read is one line FILE:LINE:COLUMN, exit 2.

use crate::common;
use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect};
use bouncelab::tui::session::Session;
use ratatui::crossterm::event::KeyCode;
use std::path::Path;
use tui_common::*;

fn golf() -> App {
    App::new(Preset::embedded().remove(1), false)
}

/// A state with something of everything: λ and ζ moved, another law, two pins (one of
/// another ball), a moving target, the sweeps view, v0 selected.
fn worked() -> App {
    let mut a = golf();
    press(&mut a, &chars("llp3zzcp"));
    a.update(Action::LoadPreset(1));
    press(&mut a, &chars("vvc"));
    press(&mut a, &[KeyCode::Char('m')]);
    press(&mut a, &[KeyCode::Esc]);
    press(&mut a, &[KeyCode::Right, KeyCode::Right, KeyCode::Tab]);
    a
}

#[test]
fn s_saves_and_the_file_restores_the_same_state() {
    let mut a = worked();
    assert_eq!(a.pins().len(), 2);
    // S, Enter on the suggested name: the loop is handed the session's text
    press(&mut a, &[KeyCode::Char('S')]);
    let effects = a.update(Action::InputSubmit);
    let [Effect::SaveSession { path, text, .. }] = effects.as_slice() else {
        panic!("{effects:?}")
    };
    assert_eq!(path, Path::new("bouncelab-session.toml"));
    assert_eq!(*text, a.session().to_toml());
    let read = Session::parse(path, text).unwrap();
    assert_eq!(read, a.session());
    let b = golf().with_session(&read).unwrap();
    assert_eq!(b.setting(), a.setting());
    assert_eq!((b.view(), b.selected()), (a.view(), a.selected()));
    let pins = |x: &App| {
        x.pins()
            .iter()
            .map(|g| g.setting.clone())
            .collect::<Vec<_>>()
    };
    assert_eq!(pins(&b), pins(&a));
    assert_eq!(b.run().unwrap().cor, a.run().unwrap().cor);
    assert_eq!(
        b.undo_depth(),
        0,
        "a restored session starts the undo history"
    );
}

#[test]
fn a_target_and_infinities_read_back() {
    let mut a = golf();
    let mut s = a.session();
    s.ball.target_mass = 0.8;
    s.ball.target_stiffness = 4e4;
    s.ball.target_damping = 5.0;
    a = a.with_session(&s).unwrap();
    let text = a.session().to_toml();
    assert!(text.contains("target_stiffness = 40000"), "{text}");
    let wall = golf().session().to_toml();
    assert!(wall.contains("target_mass = inf"), "{wall}");
    let back = Session::parse(Path::new("x.toml"), &wall).unwrap();
    assert_eq!(back.ball.target_mass, f64::INFINITY);
}

#[test]
fn a_bad_session_is_one_line_with_file_line_and_column_exit_2() {
    let text = golf().session().to_toml();
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            text.replace("view = \"impact\"", "view = 3"),
            "invalid type",
        ),
        (
            text.replace("law = \"linear\"", "law = \"plastic\""),
            "unknown law",
        ),
        (format!("colour = 1\n{text}"), "unknown field"),
        (text.replace("version = 3", "version = 7"), "version 7"),
        // it was taken, and the readout said "α_max 0.853 mm > R -1000 mm (×-0.000853)"
        (
            text.lines()
                .map(|l| {
                    if l.starts_with("radius = ") {
                        "radius = -1"
                    } else {
                        l
                    }
                })
                .collect::<Vec<_>>()
                .join("\n"),
            "invalid radius: -1 (must not be negative)",
        ),
        // a preset this bouncelab does not have: the error did not name the session file
        // (issue 51 item 8)
        (
            text.replace("preset = \"golf\"", "preset = \"nosuch\""),
            "nosuch",
        ),
    ];
    for (i, (bad, why)) in cases.iter().enumerate() {
        let file = dir.path().join(format!("s{i}.toml"));
        std::fs::write(&file, bad).unwrap();
        let o = common::bl(&["--session", file.to_str().unwrap()]);
        assert_eq!(o.code, 2, "{why}: {}", o.stderr);
        let err = o.stderr.trim();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(why), "{why}: {err}");
        // every refusal names the session file (issue 51 item 8)
        assert!(
            err.contains(&file.display().to_string()),
            "names the file: {err}"
        );
        if !["unknown law", "invalid radius", "nosuch"]
            .iter()
            .any(|w| why.starts_with(w))
        {
            // the field's place in the file: FILE:LINE:COLUMN
            let at = format!("{}:", file.display());
            let rest = &err[err.find(&at).expect(err) + at.len()..];
            let mut nums = rest.split(':').take(2).map(|n| n.parse::<usize>());
            assert!(nums.all(|n| n.is_ok_and(|n| n > 0)), "{err}");
        }
    }
    // a good one reads and gets as far as the terminal
    let good = dir.path().join("good.toml");
    std::fs::write(&good, &text).unwrap();
    let o = common::bl(&["--session", good.to_str().unwrap()]);
    assert!(o.stderr.contains("needs a terminal"), "{}", o.stderr);
    let o = common::bl(&["--session", good.to_str().unwrap(), "--law", "hertz"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
}

/// Issue 29 item 3: the session also keeps the fit pane's fit (the fitted ball, estimates,
/// residual, verdict: the pane reads the same, `F` applies it) and the map view's quantity,
/// targets and window, so the map's cursor comes back on the same cell of the same map.
#[test]
fn the_fit_and_the_map_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("cannon.csv");
    std::fs::write(&data, "v0,cor\n10,0.72\n20,0.66\n30,0.62\n40,0.6\n").unwrap();
    let mut a = golf();
    a.update(Action::MeasuredLoaded {
        path: data.clone(),
        data: bouncelab::tui::views::fit::state::load(&data).unwrap(),
    });
    let asked = a.update(Action::Fit);
    let [Effect::Fit(r)] = asked.as_slice() else {
        panic!("no fit asked")
    };
    a.update(Action::FitReady(
        r.id,
        bouncelab::tui::views::fit::state::run(r).into(),
    ));
    // the map: contact time, a target, the cursor two cells right of the window's centre
    press(&mut a, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Tab]);
    press(&mut a, &chars("nnt"));
    type_keys(&mut a, "cor>=0.5");
    press(&mut a, &[KeyCode::Enter]);
    assert!(a.map_view().targets.is_some());
    press(&mut a, &[KeyCode::Right, KeyCode::Right, KeyCode::Up]);
    let window = a.map_view().window;
    assert!(window.is_some());
    let text = a.session().to_toml();
    assert!(text.contains("[fit]") && text.contains("[map]"), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    assert_eq!(read.to_toml(), text);
    let b = golf().with_session(&read).unwrap();
    let pane = |x: &App| format!("{:?}", x.fit_pane().map(|p| (&p.label, &p.status, p.law)));
    assert_eq!(pane(&b), pane(&a));
    assert!(matches!(
        b.fit_pane().unwrap().status,
        bouncelab::tui::views::fit::state::FitStatus::Done(Ok(_))
    ));
    assert_eq!(b.fit_standing(), a.fit_standing());
    let (ma, mb) = (a.map_view(), b.map_view());
    assert_eq!(
        (mb.quantity, &mb.targets, mb.window),
        (ma.quantity, &ma.targets, window)
    );
    let cell = |x: &App| {
        let s = x.setting();
        let (l, z) = (
            s.get(bouncelab::tui::param::Param::Lambda),
            s.get(bouncelab::tui::param::Param::Zeta),
        );
        bouncelab::tui::views::map::state::cell_of(x.map_view().map().unwrap(), l, z)
    };
    assert_eq!(cell(&b), cell(&a));
    // the same screen: map, cursor, targets
    assert_eq!(
        screen_text(&draw(&b, 120, 40)),
        screen_text(&draw(&a, 120, 40))
    );
}

/// `S` onto a file that exists asks y/n inside the explorer (n keeps the file, y replaces
/// it); a write that fails keeps the entry open, holding the name, with the system's reason
/// (issue 51 item 2: the loop refused an existing file with "use --force", which the
/// explorer has not, and a failure closed the entry).
#[test]
fn s_onto_an_existing_file_asks_and_a_failed_write_keeps_the_entry() {
    use bouncelab::tui::app::{Ask, Overlay};
    let mut a = golf();
    let path = std::path::PathBuf::from("/tmp/s.toml");
    a.update(Action::SessionExists {
        path: path.clone(),
        text: "t".into(),
    });
    assert!(matches!(a.overlay(), Overlay::Ask(Ask::Session { .. })));
    let screen = screen_text(&draw(&a, 100, 30)).join("\n");
    assert!(
        screen.contains("overwrite it with this session? y/n"),
        "{screen}"
    );
    let effects = a.update(Action::ConfirmYes);
    assert!(
        matches!(
            effects.as_slice(),
            [Effect::SaveSession { replace: true, .. }]
        ),
        "{effects:?}"
    );
    a.update(Action::SessionExists {
        path: path.clone(),
        text: "t".into(),
    });
    assert!(a.update(Action::ConfirmNo).is_empty());
    assert!(a.message().unwrap().text.contains("kept"));
    let why = "cannot write /nowhere/s.toml: No such file or directory (os error 2)";
    a.update(Action::SessionFailed {
        path: "/nowhere/s.toml".into(),
        why: why.into(),
    });
    let Overlay::Input(input) = a.overlay() else {
        panic!("the entry closed")
    };
    assert_eq!(input.text, "/nowhere/s.toml");
    assert_eq!(input.error.as_deref(), Some(why));
}
