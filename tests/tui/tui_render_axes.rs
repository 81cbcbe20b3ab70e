//! The charts' axes and frames as drawn: the log axis's decade labels, a plot area in every
//! chart at the usual sizes, a figure built by hand, and titles that keep their units.

use crate::tui_common;
use bouncelab::figure::{Kind, Look, Marker as Shape, Series, Style as Stroke, Tone};
use bouncelab::tui::theme::Theme;
use bouncelab::tui::ui::{self, Chart};
use bouncelab::tui::widgets::plot::Plot;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;
use tui_common::*;

/// The decade labels of the ζ axis sit over the columns where log10 ζ = −2 … 2 land.
#[test]
fn log_axis_decade_labels_sit_over_their_columns() {
    for (w, h) in [(120, 40), (100, 30), (80, 24), (200, 60)] {
        let a = app(0);
        let t = draw(&a, w, h);
        let buf = t.backend().buffer();
        let screen = ui::screen(&a, buf.area).unwrap();
        let (_, rect) = screen
            .charts
            .iter()
            .find(|c| c.0 == Chart::CorZeta)
            .unwrap();
        let fig = ui::figure(&a, Chart::CorZeta);
        let layout = Plot::new(&fig, Theme::new(true)).layout(*rect).unwrap();
        let p: Rect = layout.plot;
        assert_eq!(layout.x.bounds, [-2.0, 2.0]);
        let label_row = p.bottom() + 1;
        let row: Vec<&str> = (0..buf.area.width)
            .map(|x| buf[(x, label_row)].symbol())
            .collect();
        for (k, label) in [(-2, "0.01"), (-1, "0.1"), (0, "1"), (1, "10"), (2, "100")] {
            // Canvas puts x on braille dot round((x − lo)/(hi − lo) · (2w − 1)); two dots a cell
            let dot = ((f64::from(k) + 2.0) / 4.0 * (2.0 * f64::from(p.width) - 1.0)).round();
            let col = usize::from(p.x) + dot as usize / 2;
            assert_eq!(
                buf[(col as u16, p.bottom())].symbol(),
                "┴",
                "tick of {label} at {w}×{h}"
            );
            // the label's text covers that column
            let is_text = |c: usize| row[c] != " " && row[c] != "│";
            let start = (0..=col).rev().take_while(|&c| is_text(c)).last().unwrap();
            let end = (col..row.len()).take_while(|&c| is_text(c)).last().unwrap();
            assert_eq!(
                row[start..=end].concat(),
                label,
                "label at column {col}, {w}×{h}"
            );
            if (-1..=1).contains(&k) {
                assert!(
                    (start + end).abs_diff(2 * col) <= 1,
                    "{label} centred on {col}"
                );
            }
        }
    }
}

/// At the usual sizes every chart has room for axes and a plot (no chart falls back to a bare
/// frame).
#[test]
fn every_chart_has_a_plot_area_at_the_usual_sizes() {
    for (w, h) in [(120, 40), (80, 24), (60, 20)] {
        for tab in [false, true] {
            let mut a = app(0);
            if tab {
                press(&mut a, &[KeyCode::Tab]);
            }
            let area = Rect::new(0, 0, w, h);
            for (chart, rect) in ui::screen(&a, area).unwrap().charts {
                let fig = ui::figure(&a, chart);
                assert!(
                    Plot::new(&fig, Theme::new(true)).layout(rect).is_some(),
                    "{chart:?} at {w}×{h}"
                );
            }
        }
    }
}

/// A figure built by hand: a curve, a tagged threshold, two markers on one point, the
/// legend from the series' keys.
#[test]
fn a_figure_draws_its_curve_tag_markers_and_legend() {
    let curve = Series::new("model", "model", Kind::Model, Stroke::Solid, 0)
        .with_points(vec![(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)])
        .with_look(Look::new(Tone::Current, Some("model"), None));
    let threshold = Series::new("z_p", "z_p", Kind::Reference, Stroke::Dotted, 7)
        .with_points(vec![(1.5, 0.0), (1.5, 0.5)])
        .with_look(Look::new(Tone::Rule, None, Some("z_p")));
    let marker = |text: &str, kind| {
        Series::new(text, text, kind, Stroke::Markers(Shape::Diamond), 4)
            .with_points(vec![(0.5, 0.5)])
            .with_look(Look::new(Tone::Highlight, Some("here"), Some(text)))
    };
    let fig = hand_figure(
        "a chart",
        vec![
            curve,
            threshold,
            marker("◆", Kind::ThisRun),
            marker("S", Kind::ThisRun),
        ],
    );
    let s = chart_text(&fig, 60, 20);
    assert!(s.starts_with("┌ a chart "), "{s}");
    assert!(s.contains("z_p"), "the threshold's tag:\n{s}");
    // a blank between them: two marks never read as one ("◆S", issue 51 item 6)
    assert!(
        s.contains("◆ S"),
        "a marker whose cell is taken moves right, a cell apart:\n{s}"
    );
    assert!(
        s.contains("━ model") && s.contains("◆ S here"),
        "legend:\n{s}"
    );
    assert!(
        s.contains('⠁') || s.contains('⠈') || s.contains('⡀'),
        "braille:\n{s}"
    );
}

/// Issue 29, item 5: a chart's title keeps its units at every size the explorer promises —
/// "F [N] vs t [ms" at 60×20 and "vs α, z [m" at 80×24 lost them; the rest of a title goes
/// first (`tui::widgets::title`).
#[test]
fn chart_titles_keep_their_units_at_every_size() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let mut a = app(0);
        for view in 0..4 {
            let t = draw(&a, w, h);
            let s = buffer_text(t.backend().buffer());
            for row in s.lines().filter(|r| r.contains('┌')) {
                let opened = row.matches('[').count();
                assert_eq!(
                    opened,
                    row.matches(']').count(),
                    "{w}×{h} view {view}: {row}"
                );
            }
            press(&mut a, &[KeyCode::Tab]);
        }
    }
}
