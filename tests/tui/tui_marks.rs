//! A chart's markers and their labels never write over each other: a marker's glyph stays on
//! its point, and another marker's label keeps off it (src/tui/widgets/plot.rs, `draw_marks`).

use crate::tui_common;

use bouncelab::figure::{Kind, Look, Marker as Shape, Series, Style as Stroke, Tone};
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

fn labelled(text: &str, at: (f64, f64), shape: Shape) -> Series {
    Series::new(text, text, Kind::Model, Stroke::Markers(shape), 1)
        .with_points(vec![at])
        .with_look(Look::new(Tone::Highlight, None, Some(text)))
}

/// Two labelled markers on the x axis, the second's point inside the first's label: the
/// first's label shows whole (the second's glyph wrote "▲z_f 3●.9 mm" before), and both
/// glyphs show.
#[test]
fn a_marker_glyph_keeps_off_another_markers_label() {
    let fig = hand_figure(
        "F vs z",
        vec![
            labelled("▲z_f 30.9 mm", (30.9, 0.0), Shape::Diamond),
            labelled("●spring left 1901 mJ", (39.0, 0.0), Shape::Circle),
            // a curve to set the axes' ranges
            Series::new("model", "model", Kind::Model, Stroke::Solid, 0)
                .with_points(vec![(0.0, 0.0), (30.0, 1500.0), (60.0, 0.0)])
                .with_look(Look::new(Tone::Current, Some("model"), None)),
        ],
    );
    for (w, h) in [(40, 20), (60, 20), (80, 24)] {
        let s = chart_text(&fig, w, h);
        assert!(s.contains("z_f 30.9 mm"), "{w}×{h}: the label cut\n{s}");
        assert!(s.contains("spring left 1901 mJ"), "{w}×{h}: no label\n{s}");
        assert!(
            s.contains('▲') && s.contains('●'),
            "{w}×{h}: a glyph missing\n{s}"
        );
    }
}

/// The screen where it was seen: the tennis ball under the elastic–plastic law at 40 m/s, its
/// permanent indentation's label and the open loop's ● on the hysteresis chart. At every size
/// the explorer promises the label shows whole (on the chart or in its legend).
#[test]
fn the_permanent_indentation_label_shows_whole() {
    // the embedded balls' order: superball, golf, baseball, tennis (src/preset.rs)
    let tennis = Preset::embedded_all().remove(3);
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let mut a = App::new(tennis.clone(), true);
        a.update(Action::Resize(w, h));
        // v0 = 40 m/s, then the law cycled to elastic–plastic
        press(
            &mut a,
            &[KeyCode::Right, KeyCode::Right, KeyCode::Char('=')],
        );
        press(&mut a, &chars("40"));
        press(&mut a, &[KeyCode::Enter, KeyCode::Char('c')]);
        let run = a.run().unwrap_or_else(|| {
            panic!(
                "{w}×{h}: no run\n{}",
                screen_text(&draw(&a, w, h)).join("\n")
            )
        });
        assert!(run.permanent_indentation > 0.0);
        let label = format!(
            "z_f {} mm",
            bouncelab::text::short(run.permanent_indentation * 1e3, 3)
        );
        let s = screen_text(&draw(&a, w, h)).join("\n");
        assert!(s.contains("elastic-plastic"), "{w}×{h}: the law\n{s}");
        assert!(s.contains(&label), "{w}×{h}: no whole '{label}'\n{s}");
    }
}

/// Issue 51 item 6: the COR chart's texts never run together ("◆nowS", "◇nowSSC"): at the
/// five sizes, with each embedded ball, every marker's or tag's text has a blank (or a line's
/// dot) beside it, never another letter.
#[test]
fn marker_texts_never_run_together() {
    let glued = |row: &str| {
        let c: Vec<char> = row.chars().collect();
        (0..c.len().saturating_sub(3)).any(|i| {
            let now = c[i..i + 3].iter().collect::<String>() == "now";
            let before = i.checked_sub(1).map(|j| c[j]);
            let after = c.get(i + 3).copied();
            let letter = |x: Option<char>| x.is_some_and(|x| x.is_alphanumeric());
            now && (letter(after) || letter(before))
        })
    };
    for preset in Preset::embedded() {
        let name = preset.name.clone();
        let app = App::new(preset, false);
        for (w, h) in [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)] {
            let rows = screen_text(&draw(&app, w, h));
            for row in &rows {
                assert!(!glued(row), "{name} {w}×{h}: '{row}'\n{}", rows.join("\n"));
            }
        }
    }
}
