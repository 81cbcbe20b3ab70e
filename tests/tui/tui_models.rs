//! The explorer's models view (Tab, Tab): the field's contact models calibrated to the ball,
//! drawn over the Christoforou–Yigit model (src/figure/explorer/models.rs,
//! src/tui/views/models/state.rs).
//! Snapshots at 120×40 and 80×24 with and without colour, the background calibration's
//! bookkeeping in `App::update` (results arrive, stale ones are dropped), the export equal to
//! the screen, and the calibrated damping on screen equal to `bouncelab peers`.

use crate::tui_common;

use crate::common;
use common::argv_with;

use bouncelab::peers::PeerModel;
use bouncelab::preset::Preset;
use bouncelab::text::sig;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect, View};
use bouncelab::tui::export;
use bouncelab::tui::theme::Theme;
use bouncelab::tui::ui::{self, Chart};
use bouncelab::tui::views::models::state::ModelsRequest;
use bouncelab::tui::widgets::plot::Plot;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;
use ratatui::style::Color;
use std::collections::HashSet;
use std::fs;

use tui_common::*;

const CHARTS: [Chart; 3] = [
    Chart::ModelsCorSpeed,
    Chart::ModelsForceTime,
    Chart::ModelsForceDisplacement,
];

/// Preset `i` on the models view, calibrations computed in `update` (as tests run them).
fn models_view(i: usize, color: bool) -> App {
    let mut app = App::new(Preset::embedded().remove(i), color);
    press(&mut app, &[KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Models);
    app
}

/// The calibrations the effects ask of the background worker (the last such effect).
fn asked(effects: &[Effect]) -> Option<Vec<ModelsRequest>> {
    effects.iter().rev().find_map(|e| match e {
        Effect::ComputeModels(r) => Some(r.clone()),
        _ => None,
    })
}

// Buffer's Debug lists each cell's colours and modifiers beside the text, so these snapshots
// hold the colours (and their absence under NO_COLOR) too.
// Each screen under the name its own test had, so the snapshot files stand as they were:
// (name, the preset's index in `Preset::embedded()`, colour, the terminal's size).
#[test]
fn models_view_with_and_without_colour() {
    for (name, i, color, (w, h)) in [
        ("models_view_120x40_colour", 0, true, (120, 40)),
        ("models_view_120x40_no_colour", 0, false, (120, 40)),
        ("models_view_80x24_colour", 1, true, (80, 24)),
        ("models_view_80x24_no_colour", 1, false, (80, 24)),
    ] {
        insta::assert_debug_snapshot!(name, draw(&models_view(i, color), w, h).backend().buffer());
    }
}

/// Without colour every cell is in the terminal's colours and the curves are told apart by
/// their letters, each on screen; with colour the five curves have five colours.
#[test]
fn without_colour_the_letters_tell_the_curves_apart() {
    for (w, h) in [(120, 40), (80, 24)] {
        let t = draw(&models_view(0, false), w, h);
        let buf = t.backend().buffer();
        for cell in buf.content() {
            assert_eq!((cell.fg, cell.bg), (Color::Reset, Color::Reset), "{cell:?}");
        }
        let app = models_view(0, false);
        let screen = ui::screen(&app, buf.area).unwrap();
        for (chart, rect) in &screen.charts {
            let inside: String = (rect.y..rect.bottom())
                .flat_map(|y| (rect.x..rect.right()).map(move |x| (x, y)))
                .map(|p| buf[p].symbol().to_string())
                .collect();
            for letter in ["C", "K", "N", "T", "H"] {
                assert!(inside.contains(letter), "{letter} on {chart:?} at {w}×{h}");
            }
        }
    }
    let t = draw(&models_view(0, true), 120, 40);
    let colours: HashSet<Color> = t
        .backend()
        .buffer()
        .content()
        .iter()
        .map(|c| c.fg)
        .collect();
    for c in [
        Color::Yellow,
        Color::Red,
        Color::Green,
        Color::Blue,
        Color::Magenta,
    ] {
        assert!(colours.contains(&c), "{c:?}");
    }
}

/// At the usual sizes every chart of the view has room for axes and a plot, and the table
/// shows every rule.
#[test]
fn readable_at_the_usual_sizes() {
    let app = models_view(0, true);
    for (w, h) in [(120, 40), (100, 30), (80, 24)] {
        let area = Rect::new(0, 0, w, h);
        let screen = ui::screen(&app, area).unwrap();
        assert_eq!(
            screen.charts.iter().map(|c| c.0).collect::<Vec<_>>(),
            CHARTS
        );
        for (chart, rect) in screen.charts {
            let fig = ui::figure(&app, chart);
            assert!(
                Plot::new(&fig, Theme::new(true)).layout(rect).is_some(),
                "{chart:?} at {w}×{h}"
            );
        }
        let s = buffer_text(draw(&app, w, h).backend().buffer());
        for rule in [
            "log-dec",
            "L–N",
            "Flores",
            "Gonthier",
            "rule → COR obtained",
        ] {
            assert!(s.contains(rule), "{rule} at {w}×{h}:\n{s}");
        }
    }
}

/// The table keeps its miss column Δe wherever it is shown (issue 51 item 6: at 100×30 and
/// 80×24 its 30 cells lost Δe to the width): the header and every rule's row carry it, and
/// the 100×30 screen is held as a snapshot.
#[test]
fn the_table_shows_the_miss_at_the_small_sizes() {
    let app = models_view(1, false);
    for (w, h) in [(80, 24), (100, 30)] {
        let s = buffer_text(draw(&app, w, h).backend().buffer());
        assert!(s.contains("Δe"), "no Δe at {w}×{h}:\n{s}");
        // every rule's row ends in its signed miss: `log-dec      17.66 0.8456 +0.005`
        for rule in ["exact", "log-dec", "Gonthier"] {
            let row = s
                .lines()
                .find(|l| l.contains(&format!(" {rule} ")))
                .unwrap();
            let cells: Vec<&str> = row.split('│').collect();
            let table = cells.iter().rev().find(|c| c.contains(rule)).unwrap();
            let last = table.split_whitespace().last().unwrap();
            assert!(
                last.starts_with(['+', '-']) && last.parse::<f64>().is_ok(),
                "{rule} at {w}×{h}: no miss in {table:?}"
            );
        }
        if (w, h) == (100, 30) {
            insta::assert_snapshot!("models_table_100x30", s);
        }
    }
}

/// The calibration runs on the worker: the view asks for it and keys go on acting meanwhile;
/// a result arrives and is drawn; a result for a ball the user has since changed is dropped.
#[test]
fn calibrations_arrive_from_the_worker_and_stale_ones_are_dropped() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    press(&mut app, &[KeyCode::Tab]);
    let effects = press(&mut app, &[KeyCode::Tab]);
    let first = asked(&effects).expect("the view asks for its calibration");
    assert_eq!(first.len(), 1);
    let first = first[0].clone();
    assert_eq!(app.models_request(), Some(&first));
    assert!(app.models().is_none(), "not computed on the UI thread");
    assert_eq!(first.target, app.run().unwrap().cor);
    let s = buffer_text(draw(&app, 120, 40).backend().buffer());
    assert!(s.contains("calibrating…"), "{s}");

    // the user moves on before it comes back: a new request replaces it
    let effects = press(&mut app, &[KeyCode::Char('v')]);
    let second = asked(&effects).unwrap()[0].clone();
    assert_ne!(second, first);
    app.update(Action::ModelsReady(first.clone(), first.run()));
    assert!(app.models().is_none(), "a stale result is dropped");
    assert_eq!(app.models_request(), Some(&second));

    let data = second.run().unwrap();
    app.update(Action::ModelsReady(second.clone(), Ok(data.clone())));
    assert_eq!(app.models(), Some(&data));
    assert!(app.models_request().is_none());
    assert!(
        app.message().is_none(),
        "an answer leaves the message line alone"
    );
    let s = buffer_text(draw(&app, 120, 40).backend().buffer());
    assert!(!s.contains("calibrating…"), "{s}");

    // v0 up again, then undone: the calibration held stays, the one sent out is called off,
    // and its late answer does not displace the one held
    let effects = press(&mut app, &[KeyCode::Char('v')]);
    let third = asked(&effects).unwrap()[0].clone();
    let effects = press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(asked(&effects), Some(vec![]));
    assert_eq!(app.models(), Some(&data));
    app.update(Action::ModelsReady(third.clone(), third.run()));
    assert_eq!(app.models(), Some(&data), "a late answer is dropped");
    assert!(app.models_request().is_none());

    // undoing v0 goes back to the first ball: asked again, the second's answer is not shown
    let effects = press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(asked(&effects), Some(vec![first.clone()]));
    assert!(app.models().is_none());
    // leaving the view drops the request that is out
    let effects = press(&mut app, &[KeyCode::BackTab]);
    assert_eq!(app.view(), View::Sweeps);
    assert_eq!(asked(&effects), Some(vec![]));
    assert!(app.models_request().is_none());
}

/// No rebound: no peer reaches e = 0, so no calibration is asked for, and the table says why
/// in words (it said the calibration's refusal, with the model's command-line name).
#[test]
fn a_failed_calibration_says_why() {
    let mut app = App::new(Preset::embedded().remove(0), true);
    // λ = 0, ζ large: the ball does not rebound
    let mut keys = vec![KeyCode::Char(']')];
    keys.extend([KeyCode::Char('L'); 15]);
    keys.extend([KeyCode::Char('z'); 13]);
    keys.extend([KeyCode::Tab, KeyCode::Tab]);
    press(&mut app, &keys);
    assert!(!app.run().unwrap().rebound);
    assert!(app.models().is_none());
    assert_eq!(app.models_error(), None);
    assert!(app.models_request().is_none(), "not asked");
    let s = buffer_text(draw(&app, 120, 40).backend().buffer());
    assert!(s.contains("no rebound at this v0"), "{s}");
    for bad in ["NaN", "nan", "inf"] {
        assert!(!s.contains(bad), "{bad} on screen:\n{s}");
    }
}

/// `e` writes the very figures the screen draws, and waits for a calibration still out.
#[test]
fn the_export_is_what_is_on_screen() {
    let mut app = models_view(1, true);
    let effects = press(&mut app, &[KeyCode::Char('e')]);
    let request = effects
        .iter()
        .find_map(|e| match e {
            Effect::Export(r) => Some(r.clone()),
            _ => None,
        })
        .expect("an export");
    assert_eq!(app.view().charts(), CHARTS);
    let names: Vec<&str> = request.charts.iter().map(|c| c.0).collect();
    assert_eq!(
        names,
        [
            "peers-cor-velocity",
            "peers-force-time",
            "peers-force-displacement"
        ]
    );
    for (&chart, (_, fig)) in CHARTS.iter().zip(&request.charts) {
        assert_eq!(fig, &ui::figure(&app, chart), "{chart:?}");
        // every model is in it, under the ids of `bouncelab figure peers-*`, with its letter
        for id in [
            "christoforou-yigit",
            "kelvin-voigt",
            "kelvin-voigt-no-tension",
            "tsuji",
            "hunt-crossley",
        ] {
            assert!(fig.series.iter().any(|s| s.id == id), "{id} in {chart:?}");
            let letter = format!("{id} letter");
            assert!(fig.series.iter().any(|s| s.id == letter), "{letter}");
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let files = export::write(&request, dir.path()).unwrap();
    assert_eq!(files.len(), 6);
    for f in &files {
        let body = fs::read_to_string(f).unwrap();
        if f.extension().unwrap() == "svg" {
            roxmltree::Document::parse(&body).unwrap();
        } else {
            // the explorer's `#` lines (the `y` command line and the parameters), then the data
            let mut lines = body.lines().skip_while(|l| l.starts_with('#'));
            let header = lines.next().unwrap();
            assert!(header.starts_with("series,kind,"), "{header}");
        }
    }

    // with the worker: the export waits for the calibration, then goes
    let mut app = App::new(Preset::embedded().remove(1), true).with_background_sweeps();
    let effects = press(&mut app, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Char('e')]);
    assert!(!effects.iter().any(|e| matches!(e, Effect::Export(_))));
    assert!(app.message().unwrap().text.contains("waits"));
    let req = app.models_request().unwrap().clone();
    let effects = app.update(Action::ModelsReady(req.clone(), req.run()));
    assert!(effects.iter().any(|e| matches!(e, Effect::Export(_))));
}

/// Two paths: the damping the screen shows for each model and rule is what `bouncelab peers`
/// gives for the same ball and COR (the preset, its v0, the model's COR there as `--cor`).
#[test]
fn the_damping_on_screen_is_what_bouncelab_peers_gives() {
    for (i, name) in [(0, "superball"), (2, "baseball")] {
        let app = models_view(i, true);
        let data = app.models().unwrap();
        let v0 = app.setting().params.v0;
        let cli = common::json(&argv_with(
            "peers --preset {} --v0 {} --cor {} --format json",
            &[name, &v0.to_string(), &data.target.to_string()],
        ));
        assert_eq!(common::f(&cli, "target_cor"), data.target);
        let rows = cli["models"].as_array().unwrap();
        assert_eq!(rows.len(), data.rows.len() + 1, "and the C–Y row");
        let screen = buffer_text(draw(&app, 120, 40).backend().buffer());
        for c in &data.rows {
            let row = rows
                .iter()
                .find(|r| r["model"] == c.model.name() && r["rule"] == c.rule.name())
                .unwrap_or_else(|| panic!("{} {}", c.model, c.rule));
            let damping = common::f(row, "damping");
            assert!(
                (damping - c.damping).abs() <= 1e-12 * damping,
                "{name} {} {}: {damping} vs {}",
                c.model,
                c.rule,
                c.damping
            );
            assert!((common::f(row, "cor") - c.response.cor).abs() < 1e-12);
            // and the table prints it
            assert!(
                screen.contains(&sig(damping, 4)),
                "{} on screen",
                sig(damping, 4)
            );
        }
        assert!(data.exact(PeerModel::Tsuji).is_some());
    }
}

/// Tab goes impact → sweeps → models → impact, Shift+Tab the other way; from the drop view
/// both go to the impact view.
#[test]
fn the_tab_cycle_holds_the_models_view() {
    let mut app = App::new(Preset::embedded().remove(0), true);
    let mut seen = vec![app.view()];
    for _ in 0..4 {
        press(&mut app, &[KeyCode::Tab]);
        seen.push(app.view());
    }
    assert_eq!(
        seen,
        [
            View::Impact,
            View::Sweeps,
            View::Models,
            View::Map,
            View::Impact
        ]
    );
    press(&mut app, &[KeyCode::BackTab]);
    assert_eq!(app.view(), View::Map);
    press(&mut app, &[KeyCode::BackTab]);
    assert_eq!(app.view(), View::Models);
    for key in [KeyCode::Tab, KeyCode::BackTab] {
        press(&mut app, &[KeyCode::Char('d')]);
        assert_eq!(app.view(), View::Drop);
        press(&mut app, &[key]);
        assert_eq!(app.view(), View::Impact);
    }
}

/// Every size draws without a panic, down to the "enlarge" message, and nothing on screen is
/// NaN or infinite.
#[test]
fn every_size_draws() {
    let app = models_view(2, false);
    for w in (1..=130).step_by(3) {
        for h in (1..=45).step_by(2) {
            let s = buffer_text(draw(&app, w, h).backend().buffer());
            for bad in ["NaN", "nan", "inf"] {
                assert!(!s.contains(bad), "{bad} at {w}×{h}:\n{s}");
            }
        }
    }
}

/// Without a rebound (λ 0, ζ 10: the superball sinks into its dashpot) the readouts agree:
/// e 0 and nothing "out" in the energy budget (what is left is the ball still sinking), and
/// the models view says in words that there is no COR to calibrate to, where it said
/// "no calibration: invalid cor: 0 is out of reach of kelvin-voigt-no-tension" (issue 51
/// item 5, and item 4: no internal names on screen).
#[test]
fn without_a_rebound_the_readouts_say_so_and_agree() {
    let mut a = App::new(Preset::embedded().remove(0), false);
    // λ selected: typed 0; → selects ζ: typed 10
    for (text, next) in [("0", true), ("10", false)] {
        press(&mut a, &[KeyCode::Char('=')]);
        a.update(Action::InputClear);
        type_keys(&mut a, text);
        press(&mut a, &[KeyCode::Enter]);
        if next {
            press(&mut a, &[KeyCode::Right]);
        }
    }
    let run = a.run().expect("a run").clone();
    assert!(!run.rebound && run.cor == 0.0);
    let shown = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(shown.contains("out 0 "), "{shown}");
    assert!(shown.contains("still sinking"), "{shown}");
    press(&mut a, &[KeyCode::Tab, KeyCode::Tab]);
    let shown = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(shown.contains("no rebound at this v0"), "{shown}");
    assert!(
        !shown.contains("kelvin-voigt") && !shown.contains("calibrating"),
        "{shown}"
    );
}
