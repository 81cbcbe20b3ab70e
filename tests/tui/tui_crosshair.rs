//! The crosshair (`x`): it starts at the centre of a chart's data, moves in steps of the
//! data's span (Shift: ten), reads the chart's live curve at the nearest point, goes chart to
//! chart with Tab or `x`, and leaves with Esc. And the force–time chart's labelled peak force
//! and contact time, in the shared figure (screen and SVG).

use crate::tui_common;

use bouncelab::figure::explorer::{self, Chart};
use bouncelab::figure::{Axis, Figure, Kind, Look, Series, Style, Tone};
use bouncelab::preset::Preset;
use bouncelab::text::short;
use bouncelab::tui::action::{self, Mode};
use bouncelab::tui::app::App;
use bouncelab::tui::crosshair::{self, STEPS};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use tui_common::*;

fn key_with(app: &mut App, code: KeyCode, m: KeyModifiers) {
    if let Some(a) = action::from_key(KeyEvent::new(code, m), app.mode()) {
        app.update(a);
    }
}

fn key(app: &mut App, code: KeyCode) {
    key_with(app, code, KeyModifiers::NONE);
}

/// y = 2x at x = 0, 1, …, 10.
fn line_figure() -> Figure {
    let pts = (0..=10)
        .map(|i| (f64::from(i), 2.0 * f64::from(i)))
        .collect();
    let s = Series::new("model", "model", Kind::Model, Style::Solid, 0)
        .with_points(pts)
        .with_look(Look::new(Tone::Current, Some("model"), None));
    Figure::new(
        "y against x".into(),
        String::new(),
        Axis::linear("x (m)", "x", 1.0),
        Axis::linear("y (N)", "y", 1.0),
        vec![s],
    )
}

#[test]
fn on_a_known_curve_it_moves_by_steps_and_reads_the_nearest_point() {
    let fig = line_figure();
    let c = crosshair::start(0, &fig).unwrap();
    assert_eq!((c.x, c.y), (5.0, 10.0));
    // one step is a fiftieth of the span 0 … 10
    let c = c.step(&fig, 1.0, 0.0);
    assert!((c.x - (5.0 + 10.0 / STEPS)).abs() < 1e-12);
    assert!(crosshair::reading(&c, &fig).ends_with("model at x 5 m: y 10 N"));
    let c = c.step(&fig, 2.0, -1.0);
    assert!((c.x - 5.6).abs() < 1e-12 && (c.y - 9.6).abs() < 1e-12);
    assert_eq!(
        crosshair::reading(&c, &fig),
        "+ x 5.6 m, y 9.6 N · model at x 6 m: y 12 N"
    );
    // held inside the data
    let c = c.step(&fig, 1000.0, -1000.0);
    assert_eq!((c.x, c.y), (10.0, 0.0));
}

#[test]
fn x_reads_the_force_time_curve_of_the_run() {
    let mut a = App::new(Preset::embedded().remove(0), true);
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.mode(), Mode::Crosshair);
    let c0 = *a.crosshair().unwrap();
    assert_eq!(c0.chart, 0);
    key_with(&mut a, KeyCode::Right, KeyModifiers::SHIFT);
    let c = *a.crosshair().unwrap();
    let h = &a.run().unwrap().history;
    let (t_lo, t_hi) = (h.t[0], *h.t.last().unwrap());
    assert!(c.x > c0.x);
    // the force–time figure's x span is the run's (the measured lines reach no further here)
    let fig = explorer::figure(Chart::ForceTime, &a.scene());
    let want = crosshair::start(0, &fig).unwrap().step(&fig, 10.0, 0.0);
    assert_eq!(c, want);
    assert!(c.x > t_lo && c.x < t_hi.max(3e-3));
    // the reading is the history's point nearest in t
    let i = (0..h.t.len())
        .min_by(|&i, &j| (h.t[i] - c.x).abs().total_cmp(&(h.t[j] - c.x).abs()))
        .unwrap();
    let msg = a.message().unwrap().text.clone();
    let expect = format!(
        "model at t {} ms: F {} N",
        short(h.t[i] * 1e3, 4),
        short(h.force[i], 4)
    );
    assert!(msg.ends_with(&expect), "{msg} ≠ …{expect}");
    // up moves y only
    key(&mut a, KeyCode::Up);
    let d = *a.crosshair().unwrap();
    assert_eq!(d.x, c.x);
    assert!(d.y > c.y);
}

#[test]
fn tab_and_x_go_chart_to_chart_and_esc_leaves() {
    let mut a = App::new(Preset::embedded().remove(0), true);
    key(&mut a, KeyCode::Char('x'));
    key(&mut a, KeyCode::Tab);
    assert_eq!(a.crosshair().unwrap().chart, 1);
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.crosshair().unwrap().chart, 2);
    // the COR–ζ chart is logarithmic in ζ: the start is the data's geometric centre
    let c = *a.crosshair().unwrap();
    key(&mut a, KeyCode::Right);
    let d = *a.crosshair().unwrap();
    assert!(d.x / c.x > 1.0);
    key(&mut a, KeyCode::Tab);
    assert!(a.crosshair().is_none());
    assert_eq!(a.mode(), Mode::Normal);
    assert_eq!(a.view(), bouncelab::tui::app::View::Impact);
    key(&mut a, KeyCode::Char('x'));
    key(&mut a, KeyCode::Esc);
    assert!(a.crosshair().is_none());
    assert!(!a.should_quit());
}

#[test]
fn the_force_time_chart_labels_peak_force_and_contact_time() {
    let a = App::new(Preset::embedded().remove(0), true);
    let r = a.run().unwrap();
    let fig = explorer::figure(Chart::ForceTime, &a.scene());
    let by = |id: &str| fig.series.iter().find(|s| s.id == id).unwrap();
    let peak = by("model max_force");
    assert_eq!(peak.points[0].1, r.max_force);
    assert_eq!(
        peak.annotations,
        [format!("F_m {} N", short(r.max_force, 4))]
    );
    let t_f = by("model contact_time");
    assert_eq!(t_f.points, [(r.contact_time.unwrap(), 0.0)]);
    let svg = bouncelab::figure::svg::render(&fig).unwrap();
    assert!(svg.contains(&format!(
        "t_f {} ms",
        short(r.contact_time.unwrap() * 1e3, 4)
    )));
}

#[test]
fn the_crosshair_at_120x40_and_80x24() {
    let mut a = App::new(Preset::embedded().remove(0), false);
    key(&mut a, KeyCode::Char('x'));
    for _ in 0..5 {
        key(&mut a, KeyCode::Left);
    }
    insta::assert_snapshot!("crosshair_120x40", draw(&a, 120, 40).backend());
    insta::assert_snapshot!("crosshair_80x24", draw(&a, 80, 24).backend());
}

/// A number without unit reads without one, and every quantity by its symbol on screen,
/// never its CSV column (`zeta`, `max_force_normalized`: issue 51 item 4).
#[test]
fn a_number_without_unit_reads_without_one() {
    let mut a = App::new(Preset::embedded().remove(0), true);
    for _ in 0..3 {
        key(&mut a, KeyCode::Char('x'));
    }
    let msg = a.message().unwrap().text.clone();
    assert!(msg.starts_with("+ ζ ") && !msg.contains('–'), "{msg}");
    assert!(!msg.contains("zeta") && !msg.contains("cor "), "{msg}");
    // the sweeps view's peak force against ζ
    let mut a = App::new(Preset::embedded().remove(0), true);
    key(&mut a, KeyCode::Tab);
    key(&mut a, KeyCode::Char('x'));
    let msg = a.message().unwrap().text.clone();
    assert!(!msg.contains("max_force_normalized"), "{msg}");
}

/// The labelled peak force and contact time are whole on screen at every size the explorer
/// lays out two panes a row or more: near the plot's right edge the label is written
/// mirrored ("t_f 2.6 ms▲"), its glyph still on its point, never cut ("▲t_").
#[test]
fn the_peak_force_and_contact_time_labels_are_never_cut() {
    let a = App::new(Preset::embedded().remove(0), false);
    let r = a.run().unwrap();
    let f_m = format!("F_m {} N", short(r.max_force, 4));
    let t_f = format!("t_f {} ms", short(r.contact_time.unwrap() * 1e3, 4));
    for (w, h) in [(80, 24), (100, 30), (120, 40), (200, 60)] {
        let t = draw(&a, w, h);
        let screen: String = t
            .backend()
            .buffer()
            .content()
            .chunks(usize::from(w))
            .map(|row| row.iter().map(|c| c.symbol()).collect::<String>() + "\n")
            .collect();
        for label in [&f_m, &t_f] {
            assert!(
                screen.contains(label.as_str()),
                "{w}×{h}: no '{label}' in\n{screen}"
            );
        }
    }
}

/// `x`, `N`, `+`, `-` read the oblique view's charts and the drop view's as they do the
/// others' (issue 51 item 3: they said "has no chart to read", then only where to look):
/// the crosshair comes on and reads, `+` zooms (the title says ×2), `N` normalizes the forces
/// and says why the height chart does not.
#[test]
fn chart_keys_read_the_oblique_and_drop_charts() {
    use bouncelab::tui::chartview::ChartId;
    for (view_key, first) in [('i', ChartId::ObliqueForces), ('d', ChartId::DropHeight)] {
        let mut app = App::new(Preset::embedded().remove(1), false);
        press(&mut app, &[KeyCode::Char(view_key)]);
        if view_key == 'd' {
            press(&mut app, &[KeyCode::Char(' ')]); // paused: the chart holds still
        }
        assert_eq!(app.chart_ids().first(), Some(&first), "{view_key}");
        press(&mut app, &[KeyCode::Char('x')]);
        let c = *app.crosshair().expect("the crosshair is on");
        assert_eq!((c.chart, app.mode()), (0, Mode::Crosshair), "{view_key}");
        let said = app.message().map(|m| m.text.clone()).unwrap_or_default();
        assert!(said.starts_with('+'), "{view_key} x: {said}");
        // the arrows move the crosshair, not the view's parameters
        key(&mut app, KeyCode::Right);
        assert!(app.crosshair().unwrap().x > c.x, "{view_key}");
        press(&mut app, &[KeyCode::Char('+')]);
        assert_eq!(app.chart_views().get(first).zoom, 1, "{view_key}");
        let fig = app.screen_figure(first).unwrap();
        assert!(fig.screen_title.contains("×2"), "{}", fig.screen_title);
        press(&mut app, &[KeyCode::Char('-'), KeyCode::Char('N')]);
        assert_eq!(app.chart_views().get(first).zoom, 0, "{view_key}");
        let said = app.message().map(|m| m.text.clone()).unwrap_or_default();
        if view_key == 'i' {
            assert!(app.chart_views().get(first).normalized, "{said}");
            let fig = app.screen_figure(first).unwrap();
            let f = fig.series[0].points.iter().map(|p| p.1).fold(0.0, f64::max);
            assert!((f - 1.0).abs() < 1e-9, "F_n peaks at {f}");
        } else {
            assert!(said.contains("only force charts normalize"), "{said}");
        }
        // and the screen draws the crosshair on that chart
        let shown = screen_text(&draw(&app, 120, 40)).join("\n");
        assert!(shown.contains("+("), "{shown}");
    }
}

/// A chart named in a message is named as its frame names it, not by its export file name
/// (issue 51 item 4: "peers-cor-velocity: only force charts normalize").
#[test]
fn chart_messages_name_the_chart_as_its_frame_does() {
    let mut app = App::new(Preset::embedded().remove(1), false);
    press(&mut app, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Char('N')]);
    let said = app.message().map(|m| m.text.clone()).unwrap_or_default();
    assert!(said.contains("only force charts normalize"), "{said}");
    assert!(
        !said.contains("peers-") && !said.contains("velocity"),
        "{said}"
    );
    let title = bouncelab::tui::ui::figure(&app, Chart::ModelsCorSpeed).screen_title;
    assert!(
        said.starts_with(title.split(" · ").next().unwrap()),
        "{said} / {title}"
    );
}

/// The chart's F_m label and the readout round alike (issue 51 item 4: `F_m 13268 N` on the
/// chart beside `13270` in the readout): at 400 m/s the superball's F_m has five digits.
#[test]
fn the_peak_force_label_reads_as_the_readout() {
    let mut a = App::new(Preset::embedded().remove(0), true);
    a.update(bouncelab::tui::action::Action::SelectNext);
    a.update(bouncelab::tui::action::Action::SelectNext);
    key(&mut a, KeyCode::Char('='));
    a.update(bouncelab::tui::action::Action::InputClear);
    for c in "400".chars() {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    let r = a.run().unwrap().clone();
    assert!(r.max_force >= 1e4, "{}", r.max_force);
    let readout = bouncelab::tui::format::value(r.max_force);
    let fig = explorer::figure(Chart::ForceTime, &a.scene());
    let peak = fig
        .series
        .iter()
        .find(|s| s.id == "model max_force")
        .unwrap();
    assert_eq!(peak.annotations, [format!("F_m {readout} N")]);
}

/// Every view switch takes the crosshair off, as it belongs to the charts it was put on: Tab,
/// Shift+Tab, `i`, `h` and `d`, into a view and out of the drop view (the drop key kept it on,
/// on a chart of the view it left).
#[test]
fn every_view_switch_takes_the_crosshair_off() {
    use bouncelab::tui::action::{Action, FlightKey, ObliqueKey};
    let switches = [
        Action::NextView,
        Action::PrevView,
        Action::ToggleDrop,
        Action::Oblique(ObliqueKey::Toggle),
        Action::Flight(FlightKey::Toggle),
    ];
    for switch in switches {
        let mut app = App::new(Preset::embedded().remove(1), false);
        app.update(Action::Crosshair);
        assert!(app.crosshair().is_some(), "{switch:?}");
        app.update(switch.clone());
        assert!(
            app.crosshair().is_none(),
            "{switch:?} into {:?}",
            app.view()
        );
    }
    // out of the drop view, its animation paused so the height chart holds still
    let mut app = App::new(Preset::embedded().remove(1), false);
    app.update(Action::ToggleDrop);
    app.update(Action::DropPause);
    app.update(Action::Crosshair);
    assert!(app.crosshair().is_some(), "on the drop view's chart");
    app.update(Action::ToggleDrop);
    assert!(app.crosshair().is_none(), "out of the drop view");
}
