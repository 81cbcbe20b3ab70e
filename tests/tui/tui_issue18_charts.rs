//! Issue 18's defects in the charts, each reproduced here first (TestBackend and `update`):
//! charts at 80×24 with their legends, stale sweeps drawn as refining (11), the flattening
//! onset marked, the force axis's top labelled.

use crate::tui_common;
use bouncelab::tui::action::Action;
use bouncelab::tui::ui::Chart;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

/// Defect 10: at 80×24 the impact view puts two panes a row (force–time and force–
/// displacement above, COR vs ζ and the readout below), so each chart is about half the width
/// and keeps its legend and units (three charts and the panel in a row left 22 columns each).
#[test]
fn at_80x24_charts_take_half_the_width_and_keep_their_legends() {
    let app = superball();
    let area = ratatui::layout::Rect::new(0, 0, 80, 24);
    let s = bouncelab::tui::ui::screen(&app, area).unwrap();
    assert_eq!(s.charts.len(), 3);
    for (chart, r) in &s.charts {
        assert!(r.width >= 38, "{chart:?} is {} columns", r.width);
    }
    let rows = screen_text(&draw(&app, 80, 24));
    let text = rows.join("\n");
    for shown in ["━ model", "━ contact z", "╍ ball α", "F [N] vs t [ms]"] {
        assert!(text.contains(shown), "{shown} missing:\n{text}");
    }
    // the readout still shows every result
    for shown in ["e 0.7506", "F_m 117.3", "t_f 2.743", "z_m 2.153"] {
        assert!(text.contains(shown), "{shown} missing:\n{text}");
    }
}

/// Defect 11: a slow COR-vs-speed sweep shows a coarse curve early, marked as being refined;
/// taking it does not cancel the sweep (no new request to the worker), and the finished curve
/// replaces it.
#[test]
fn a_coarse_sweep_is_drawn_as_refining_until_the_whole_one_comes() {
    use bouncelab::tui::app::Effect;
    let mut app = superball().with_background_sweeps();
    app.update(Action::NextView);
    let req = app.speed_requests()[0].clone();
    let mut coarse = Vec::new();
    let whole = req.run_refining(|| true, |c| coarse.push(c)).unwrap();
    let effects = app.update(Action::SpeedReady(req.clone(), Ok(coarse[0].clone())));
    assert!(
        !effects.iter().any(|e| matches!(e, Effect::Compute(_))),
        "the sweep was asked again (or dropped)"
    );
    assert_eq!(app.speed_requests(), std::slice::from_ref(&req));
    let fig = bouncelab::tui::ui::figure(&app, Chart::CorSpeed);
    assert!(
        fig.screen_title.ends_with(" · refining…"),
        "{}",
        fig.screen_title
    );
    let model = fig.series.iter().find(|s| s.id == "model").unwrap();
    assert_eq!(model.points.len(), coarse[0].points.len());
    app.update(Action::SpeedReady(req, whole));
    assert!(app.speed_requests().is_empty());
    let fig = bouncelab::tui::ui::figure(&app, Chart::CorSpeed);
    assert!(!fig.screen_title.contains('…'), "{}", fig.screen_title);
}

/// Defect 10: COR against speed marks where the elastic–plastic law starts to flatten (it
/// was drawn for the linear law only): between the sweep's last speed without a permanent
/// indentation and its first with one.
#[test]
fn the_flattening_onset_is_marked_for_the_elastic_plastic_law() {
    let mut app = superball();
    press(&mut app, &chars("c"));
    assert_eq!(app.setting().law.to_string(), "elastic-plastic");
    press(&mut app, &[KeyCode::Tab]);
    let fig = bouncelab::tui::ui::figure(&app, Chart::CorSpeed);
    let onset = fig
        .series
        .iter()
        .find(|s| s.id == "flattening_onset")
        .expect("the flattening onset")
        .points[0]
        .0;
    let curve = app.speed_curve().unwrap();
    let below = curve.points.iter().filter(|p| p.v0 < onset);
    let above = curve.points.iter().filter(|p| p.v0 > onset);
    assert!(below.clone().count() > 0 && above.clone().count() > 0);
    assert!(below.into_iter().all(|p| p.permanent_indentation == 0.0));
    assert!(above.into_iter().all(|p| p.permanent_indentation > 0.0));
}

/// Defect 10: the top of force–time's force axis is a labelled tick, at every size.
#[test]
fn the_top_of_the_force_axis_is_labelled() {
    use bouncelab::tui::theme::Theme;
    use bouncelab::tui::widgets::plot::Plot;
    let fig = bouncelab::tui::ui::figure(&superball(), Chart::ForceTime);
    for (w, h) in [(42, 18), (40, 11), (28, 8), (60, 30), (84, 20)] {
        let plot = Plot::new(&fig, Theme::new(false));
        let l = plot.layout(ratatui::layout::Rect::new(0, 0, w, h)).unwrap();
        let top = l.y.ticks.last().unwrap();
        assert_eq!(top.0, l.y.bounds[1], "{w}×{h}: {:?}", l.y);
        assert!(!top.1.is_empty());
        assert_eq!(l.row(top.0), Some(l.plot.y));
    }
}
