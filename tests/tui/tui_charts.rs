//! Pins of very different balls (issue 29 item 10): a 26 N table-tennis ball pinned beside a
//! 5 900 N softball flattens on the shared scale; `N` normalizes the chart in focus (F/F_m
//! against t/t_f, each run by its own), `+` / `-` zoom it from the lower-left corner, `0`
//! brings the whole data back; `x` then Tab moves the focus to another chart.

use crate::tui_common;

use bouncelab::figure::explorer::Chart;
use bouncelab::preset::Preset;
use bouncelab::tui::action::{Action, Scroll};
use bouncelab::tui::app::{App, Effect, Overlay};
use bouncelab::tui::chartview::ChartView;
use ratatui::crossterm::event::KeyCode;
use tui_common::{chars, draw, press, screen_text};

/// Load the embedded preset `name` through the picker (`g`).
fn pick(app: &mut App, name: &str) {
    let empty = tempfile::tempdir().unwrap();
    let asked = app.update(Action::OpenPicker);
    assert_eq!(asked, vec![Effect::ListPresets]);
    let (entries, error) = bouncelab::tui::picker::list_in(Some(empty.path()));
    app.update(Action::PresetsListed(entries, error));
    let Overlay::Picker(p) = app.overlay() else {
        panic!("no picker")
    };
    let k = p
        .entries
        .iter()
        .position(|e| e.preset.name == name)
        .unwrap();
    app.update(Action::PickerMove(Scroll::Home));
    for _ in 0..k {
        app.update(Action::PickerMove(Scroll::Down));
    }
    app.update(Action::PickerChoose);
    assert_eq!(app.preset().name, name);
}

/// The softball pinned, the table-tennis ball live.
fn two_balls(color: bool) -> App {
    let mut a = App::new(Preset::embedded().remove(0), color);
    pick(&mut a, "softball");
    press(&mut a, &chars("p"));
    pick(&mut a, "table-tennis");
    a
}

/// The largest force drawn for the live run and the pin, in the chart's units.
fn peaks(a: &App) -> (f64, f64) {
    let mut fig = bouncelab::tui::ui::figure(a, Chart::ForceTime);
    bouncelab::tui::chartview::apply(
        a.chart_views().get(Chart::ForceTime),
        Chart::ForceTime,
        &mut fig,
    );
    let peak = |id: &str| {
        fig.series
            .iter()
            .filter(|s| s.id == id)
            .flat_map(|s| &s.points)
            .map(|p| p.1 * fig.y.scale)
            .fold(0.0, f64::max)
    };
    (peak("model"), peak("pinned 1 model"))
}

#[test]
fn n_normalizes_the_chart_in_focus_and_the_small_ball_spans_it() {
    let mut a = two_balls(true);
    let (live, pin) = peaks(&a);
    assert!(
        live < 0.01 * pin,
        "the table-tennis pulse is flattened: {live} vs {pin}"
    );
    press(&mut a, &chars("N"));
    assert_eq!(
        a.chart_views().get(Chart::ForceTime),
        ChartView {
            normalized: true,
            zoom: 0
        }
    );
    let (live, pin) = peaks(&a);
    assert!(
        (live - 1.0).abs() < 1e-9 && (pin - 1.0).abs() < 1e-9,
        "{live} {pin}"
    );
    assert_eq!(a.chart_views().get(Chart::Hysteresis), ChartView::default());
    // the focus follows the crosshair: x, Tab → force–displacement
    press(
        &mut a,
        &[KeyCode::Char('x'), KeyCode::Tab, KeyCode::Char('N')],
    );
    assert!(a.chart_views().get(Chart::Hysteresis).normalized);
    assert_eq!(
        a.crosshair().map(|c| c.chart),
        Some(1),
        "the crosshair stays"
    );
    // the COR chart does not normalize, and says so
    press(&mut a, &[KeyCode::Tab, KeyCode::Char('N')]);
    assert!(!a.chart_views().get(Chart::CorZeta).normalized);
    assert!(a.message().unwrap().text.contains("only force charts"));
    // N again: absolute units
    press(&mut a, &[KeyCode::Esc, KeyCode::Char('N')]);
    assert!(!a.chart_views().get(Chart::ForceTime).normalized);
    let screen = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(screen.contains("F/F_m vs α/α_max"), "{screen}");
}

#[test]
fn plus_and_minus_zoom_and_zero_brings_the_whole_data_back() {
    let mut a = two_balls(true);
    press(&mut a, &chars("+++"));
    assert_eq!(a.chart_views().get(Chart::ForceTime).zoom, 3);
    press(&mut a, &chars("-"));
    assert_eq!(a.chart_views().get(Chart::ForceTime).zoom, 2);
    let screen = screen_text(&draw(&a, 120, 40)).join("\n");
    assert!(screen.contains("vs t [ms] ×4"), "{screen}");
    press(&mut a, &chars("0"));
    assert_eq!(a.chart_views().get(Chart::ForceTime), ChartView::default());
    press(&mut a, &chars("0-"));
    assert_eq!(
        a.chart_views().get(Chart::ForceTime).zoom,
        0,
        "not below the whole data"
    );
}

/// The two balls at the five sizes, in colour and without: as they were (flattened), and
/// force–time normalized with force–displacement zoomed ×4.
#[test]
fn the_two_balls_at_every_size() {
    for color in [true, false] {
        let tag = if color { "color" } else { "no_color" };
        let mut a = two_balls(color);
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
            insta::assert_snapshot!(format!("two_balls_{tag}_{w}x{h}"), draw(&a, w, h).backend());
        }
        press(&mut a, &chars("Nx"));
        press(&mut a, &[KeyCode::Tab]);
        press(&mut a, &chars("++"));
        press(&mut a, &[KeyCode::Esc]);
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
            insta::assert_snapshot!(
                format!("two_balls_normalized_zoomed_{tag}_{w}x{h}"),
                draw(&a, w, h).backend()
            );
        }
    }
}
