//! Issue 18's remaining defects, each reproduced here first (TestBackend and `update`):
//! one range and one check for the explorer and `run` (2), measured values only at their speed
//! (3), curves told apart without colour (4), unique marker letters (7), messages on their own
//! line (8), the entry's cursor, unpinning and the legends (10). The charts' defects:
//! tui_issue18_charts.rs.

use crate::tui_common;
use bouncelab::figure::explorer::MeasuredOverlay;
use bouncelab::figure::{Sample, Style};
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Overlay};
use bouncelab::tui::param::{Dir, Param, V0_MIN};
use bouncelab::tui::ui::Chart;
use ratatui::crossterm::event::KeyCode;
use std::process::Command;
use tui_common::*;

/// Select `param` and type `text` into its entry; the entry's reason when refused.
fn enter(app: &mut App, param: Param, text: &str) -> Option<String> {
    while app.selected() != param {
        press(app, &[KeyCode::Right]);
    }
    press(app, &[KeyCode::Char('=')]);
    press(app, &chars(text));
    press(app, &[KeyCode::Enter]);
    let why = match app.overlay() {
        Overlay::Input(i) => i.error.clone(),
        _ => None,
    };
    press(app, &[KeyCode::Esc]);
    why
}

fn flag(p: Param) -> &'static str {
    match p {
        Param::Lambda => "--lambda",
        Param::Zeta => "--zeta",
        Param::V0 => "--v0",
    }
}

/// Defect 2: a typed value is taken by the explorer exactly when `bouncelab run` takes it —
/// the command line read through its own argument parser, the explorer through its entry.
#[test]
fn the_explorer_takes_a_typed_value_exactly_when_run_does() {
    let cases = [
        (Param::Lambda, "5000"),
        (Param::Lambda, "1e6"),
        (Param::Lambda, "2e6"),
        (Param::Lambda, "1e-16"),
        (Param::Lambda, "0"),
        (Param::Zeta, "0"),
        (Param::Zeta, "1e-16"),
        (Param::Zeta, "5e5"),
        (Param::Zeta, "2e6"),
        (Param::V0, "500"),
        (Param::V0, "0.001"),
        (Param::V0, "-5"),
        (Param::V0, "1e16"),
    ];
    for (param, text) in cases {
        let status = Command::new(env!("CARGO_BIN_EXE_bouncelab"))
            .args(["run", "--preset", "superball", flag(param), text])
            .output()
            .unwrap()
            .status;
        let mut app = superball();
        let refused = enter(&mut app, param, text);
        assert_eq!(
            refused.is_none(),
            status.success(),
            "{} {text}: explorer {refused:?}, run exit {status}",
            param.symbol()
        );
        if let Some(why) = refused {
            assert!(why.contains(param.range().text), "{why}");
        } else {
            let want: f64 = text.parse().unwrap();
            let got = app.setting().get(param);
            assert!((got - want).abs() <= 1e-9 * want.abs(), "{got} {want}");
        }
    }
}

fn step(app: &mut App, param: Param, dir: Dir) {
    app.update(Action::Step {
        param,
        dir,
        coarse: true,
    });
}

/// Defect 2: the stepping keys stop at run's bounds (λ, ζ ≤ 1e6; v0 ≥ 1e-15 m/s) and say so.
#[test]
fn stepping_stops_at_runs_bounds_and_says_so() {
    let mut app = superball();
    assert_eq!(enter(&mut app, Param::Lambda, "999999.95"), None);
    step(&mut app, Param::Lambda, Dir::Up);
    assert_eq!(app.setting().get(Param::Lambda), 1e6);
    let said = &app.message().expect("a message").text;
    assert!(said.contains("λ held at") && said.contains("1e6"), "{said}");
    assert_eq!(enter(&mut app, Param::Zeta, "7e5"), None);
    step(&mut app, Param::Zeta, Dir::Up);
    assert!((app.setting().get(Param::Zeta) - 1e6).abs() < 1e-3);
    assert!(app.message().unwrap().text.contains("ζ held at"));
    assert_eq!(enter(&mut app, Param::V0, "0.05"), None);
    step(&mut app, Param::V0, Dir::Down);
    assert_eq!(app.setting().get(Param::V0), V0_MIN);
    assert!(app.message().unwrap().text.contains("v0 held at"));
    // a step inside the range says nothing
    step(&mut app, Param::V0, Dir::Up);
    assert!(app.message().is_none());
}

/// Defect 7: every ball's measured marker has its own letters (a user preset named
/// superball-custom beside the embedded superball, softball, tennis and table-tennis,
/// baseball and basketball), on the ζ charts and in their legends.
#[test]
fn measured_marker_letters_never_collide() {
    let mut custom = Preset::embedded().remove(0);
    custom.name = "superball-custom".into();
    let app = App::new(custom, true);
    for chart in [Chart::CorZeta, Chart::ForceZeta] {
        let fig = bouncelab::tui::ui::figure(&app, chart);
        let marks: Vec<String> = fig
            .series
            .iter()
            .filter(|s| s.id.starts_with("measured "))
            .map(|s| s.look.text.clone().unwrap())
            .collect();
        assert_eq!(marks.len(), app.presets().len(), "{marks:?}");
        let mut unique = marks.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), marks.len(), "{marks:?}");
        let legend = fig.legend();
        let Some(Sample::Marks(shown)) = legend
            .iter()
            .find(|e| e.key == "measured")
            .map(|e| e.sample.clone())
        else {
            panic!("no measured entry: {legend:?}")
        };
        assert_eq!(shown, marks);
        let keys: Vec<&str> = legend.iter().map(|e| e.key.as_str()).collect();
        let mut distinct = keys.clone();
        distinct.dedup();
        assert_eq!(distinct, keys, "legend entries unique");
    }
    // the current ball's mark on COR vs speed is its mark on the ζ charts
    let speed = bouncelab::tui::ui::figure(&app, Chart::CorSpeed);
    let mark = speed.series.iter().find(|s| s.id == "measured cor");
    assert_eq!(mark.and_then(|s| s.look.text.as_deref()), Some("SC"));
}

/// The readout panel of a 120×40 impact view (columns 85 to 116), its wrapped lines joined.
fn readout_panel(rows: &[String]) -> String {
    let line = |r: &String| r.chars().skip(85).take(32).collect::<String>();
    let lines: Vec<String> = rows.iter().map(|r| line(r).trim().to_string()).collect();
    lines.join(" ")
}

/// Defect 3: at 12 m/s the readout compares nothing with the peak force measured at 3.12 m/s
/// and says where it was measured; at 0.01 m/s a force trace measured at 3.12 m/s neither
/// draws on force–time nor stretches its force axis (the title says where the data is).
#[test]
fn measured_values_are_compared_and_drawn_only_at_their_speed() {
    let mut app = superball();
    assert_eq!(enter(&mut app, Param::V0, "12"), None);
    let rows = screen_text(&draw(&app, 120, 40));
    let text = rows.join("\n");
    assert!(
        readout_panel(&rows).contains("measured at v0 = 3.120 m/s: not compared"),
        "{text}"
    );
    assert!(
        !text.contains("121.8"),
        "F_m compared with 121.8 N at 12 m/s:\n{text}"
    );
    assert!(
        !text.contains('%'),
        "a difference at another speed:\n{text}"
    );

    let trace = MeasuredOverlay {
        label: "drop.csv".into(),
        chart: Chart::ForceTime,
        points: vec![(0.0, 0.0), (1e-3, 125.0), (2e-3, 0.0)],
        v0: Some(3.12),
    };
    let mut app = superball().with_measured(vec![trace]);
    let at_312 = bouncelab::tui::ui::figure(&app, Chart::ForceTime);
    assert!(at_312.series.iter().any(|s| s.id == "measured drop.csv"));
    assert_eq!(enter(&mut app, Param::V0, "0.01"), None);
    let fig = bouncelab::tui::ui::figure(&app, Chart::ForceTime);
    assert!(fig.series.iter().all(|s| !s.id.starts_with("measured")));
    let peak = app.run().unwrap().max_force;
    let (_, top) = fig.data_extent(false).unwrap();
    assert!(
        top <= peak * (1.0 + 1e-12),
        "axis stretched to {top} N, peak {peak} N"
    );
    assert!(
        fig.screen_title.contains("data at 3.12 m/s"),
        "{}",
        fig.screen_title
    );
}

/// Defect 8: a message has its own line(s) under the charts, wrapped at spaces, and leaves the
/// header's title whole; the readout's long notes wrap too.
#[test]
fn messages_have_their_own_line_and_wrap() {
    for (w, h) in [(120, 40), (80, 24), (60, 20)] {
        let mut app = superball();
        app.update(Action::Resize(w, h));
        press(&mut app, &[KeyCode::Char('=')]);
        // a refusal long enough to wrap at 80 columns
        press(&mut app, &chars("1e7"));
        press(&mut app, &[KeyCode::Enter]);
        let msg = app.message().expect("the refusal's message").text.clone();
        assert!(
            w > 80 || msg.chars().count() > usize::from(w),
            "a long message: {msg}"
        );
        let rows = screen_text(&draw(&app, w, h));
        let s = bouncelab::tui::ui::screen(&app, ratatui::layout::Rect::new(0, 0, w, h)).unwrap();
        // the compact readout's screens name the surface in the header, in shorter words
        // where the whole line does not fit (tui_surface.rs)
        let title = if s.side_panel {
            " bouncelab · superball · linear law · view 1/4 impact"
        } else if w >= 80 {
            " bouncelab · superball on steel-plate · linear law · view 1/4 impact"
        } else {
            " bouncelab · superball on steel-plate · linear · 1/4 impact"
        };
        assert_eq!(rows[0].trim_end(), title, "{w}×{h}");
        let shown: Vec<&str> = (s.message.y..s.message.bottom())
            .map(|y| rows[usize::from(y)].trim())
            .collect();
        assert_eq!(shown.join(" "), msg, "{w}×{h}");
        assert!(s.message.bottom() == s.status.y && s.message.y >= 1);
    }
    // the readout's note at λ = 0, ζ = 1000 (no rebound) wraps inside the panel
    let mut app = superball();
    assert_eq!(enter(&mut app, Param::Lambda, "0"), None);
    assert_eq!(enter(&mut app, Param::Zeta, "1000"), None);
    let rows = screen_text(&draw(&app, 120, 40));
    assert!(
        readout_panel(&rows).contains("no rebound: the ball sinks into the dashpot"),
        "{}",
        rows.join("\n")
    );
}

/// Defect 4: without colour the λ = 0, 0.4, 1 and current curves differ in the figure (line
/// style, a name at the curve's end) — the description the SVG export draws too — and so do
/// contact z and ball α; the legend's samples differ as well.
#[test]
fn curves_are_told_apart_without_colour() {
    let mut app = App::new(Preset::embedded().remove(0), false);
    assert_eq!(enter(&mut app, Param::Lambda, "0.001"), None);
    assert_eq!(enter(&mut app, Param::Zeta, "10"), None);
    for chart in [Chart::CorZeta, Chart::ForceZeta] {
        let fig = bouncelab::tui::ui::figure(&app, chart);
        let curves: Vec<_> = fig
            .series
            .iter()
            .filter(|s| s.id.starts_with("model lambda="))
            .map(|s| (s.style, s.look.text.clone().expect("a name at the end")))
            .collect();
        assert_eq!(curves.len(), 4, "{curves:?}");
        let mut names: Vec<&String> = curves.iter().map(|c| &c.1).collect();
        names.dedup();
        assert_eq!(names.len(), 4, "{curves:?}");
        // the current λ solid, every fixed one not
        let solid = curves.iter().filter(|c| c.0 == Style::Solid).count();
        assert_eq!(solid, 1, "{curves:?}");
        let samples: Vec<_> = fig.legend().into_iter().map(|e| e.sample).collect();
        assert!(samples.contains(&Sample::Dashed) && samples.contains(&Sample::Dotted));
    }
    let fig = bouncelab::tui::ui::figure(&app, Chart::Hysteresis);
    let style = |id: &str| fig.series.iter().find(|s| s.id == id).unwrap().style;
    assert_ne!(style("model indentation"), style("model displacement"));
    // and on a screen without colour: the names at the curves' ends, the dashed sample
    let text = screen_text(&draw(&app, 120, 40)).join("\n");
    for shown in ["λ=0.4", "now", "╍ λ=0", "┄ λ=0.4", "╍ ball α"] {
        assert!(text.contains(shown), "{shown} missing:\n{text}");
    }
}

/// Defect 10: the entry's cursor moves with ← → Home End; typing, Backspace and Delete act at
/// it (the value typed is the one taken).
#[test]
fn the_entry_cursor_moves_and_edits_in_place() {
    let mut app = superball();
    press(&mut app, &[KeyCode::Char('=')]);
    press(&mut app, &chars("0.5"));
    press(&mut app, &[KeyCode::Home, KeyCode::Char('1'), KeyCode::End]);
    press(&mut app, &chars("9"));
    press(
        &mut app,
        &[KeyCode::Left, KeyCode::Left, KeyCode::Backspace],
    );
    let text = |app: &App| match app.overlay() {
        Overlay::Input(i) => (i.text.clone(), i.cursor),
        other => panic!("no entry: {other:?}"),
    };
    // 0.5 → 10.5 (Home, 1) → 10.59 (End, 9) → 1059 (two left, Backspace took the '.')
    assert_eq!(text(&app), ("1059".into(), 2));
    press(&mut app, &[KeyCode::Delete]);
    assert_eq!(text(&app), ("109".into(), 2));
    press(&mut app, &[KeyCode::Right, KeyCode::Right, KeyCode::Right]);
    assert_eq!(text(&app), ("109".into(), 3), "stops at the end");
    press(&mut app, &[KeyCode::Home, KeyCode::Delete, KeyCode::Right]);
    press(&mut app, &chars("."));
    assert_eq!(text(&app), ("0.9".into(), 2));
    // drawn with the cursor on the 9
    let rows = screen_text(&draw(&app, 120, 40));
    assert!(
        rows.iter().any(|r| r.contains("λ = 0.9 ")),
        "{}",
        rows.join("\n")
    );
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.setting().get(Param::Lambda), 0.9);
}

/// Defect 10: a second `P` with nothing pinned says so.
#[test]
fn unpinning_with_nothing_pinned_says_so() {
    let mut app = superball();
    press(&mut app, &chars("pP"));
    assert_eq!(app.message().unwrap().text, "pin cleared");
    press(&mut app, &chars("P"));
    let said = &app.message().expect("a message").text;
    assert!(said.contains("nothing pinned"), "{said}");
}

/// The drawn cells of `fig` its legend covers in an area `w`×`h`: the plot drawn with and
/// without a legend, compared.
fn covered_by_legend(fig: &bouncelab::figure::Figure, w: u16, h: u16) -> Vec<(u16, u16)> {
    use bouncelab::tui::theme::Theme;
    use bouncelab::tui::widgets::plot::Plot;
    use ratatui::widgets::Widget;
    let area = ratatui::layout::Rect::new(0, 0, w, h);
    let render = |f: &bouncelab::figure::Figure| {
        let mut buf = ratatui::buffer::Buffer::empty(area);
        Plot::new(f, Theme::new(false)).render(area, &mut buf);
        buf
    };
    let mut bare = fig.clone();
    for s in &mut bare.series {
        s.look.key = None;
    }
    let (with, without) = (render(fig), render(&bare));
    area.positions()
        .filter(|&p| without[p].symbol() != " " && with[p].symbol() != without[p].symbol())
        .map(|p| (p.x, p.y))
        .collect()
}

/// Defect 10: legends go to the corner where they cover the fewest curve cells: COR vs ζ at
/// λ = 0.001, ζ = 10 (the legend was over the "now" curve), force–time with the measured
/// peak line (the legend was over it).
#[test]
fn legends_sit_where_the_curves_are_not() {
    let mut app = superball();
    assert_eq!(enter(&mut app, Param::Lambda, "0.001"), None);
    assert_eq!(enter(&mut app, Param::Zeta, "10"), None);
    let fig = bouncelab::tui::ui::figure(&app, Chart::CorZeta);
    assert_eq!(covered_by_legend(&fig, 84, 20), []);
    // force–time: the measured peak force runs along the plot's top row (y = 1); the legend
    // leaves it whole (it was drawn top right, over it)
    let fig = bouncelab::tui::ui::figure(&superball(), Chart::ForceTime);
    assert!(fig.series.iter().any(|s| s.id == "measured max_force"));
    let covered = covered_by_legend(&fig, 42, 18);
    assert!(covered.iter().all(|&(_, y)| y != 1), "{covered:?}");
}
