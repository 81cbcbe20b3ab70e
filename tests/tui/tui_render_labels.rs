//! The numbers on screen at every size (issue 29): scaled tick labels at extreme speeds, value
//! labels beside legends, pins and markers, a readout that never wraps a value, one number
//! format, and the validity note's numbers with their units.

use crate::tui_common;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

/// Issue 29, item 7: at v0 = 1e-15 m/s every force tick read "0┤"; at 1e15 a tick label took
/// half the chart. The labels are written in a power of ten shown on the frame ("×10⁻¹⁵"),
/// short, distinct and never wrapped, at every size.
#[test]
fn extreme_speeds_get_scaled_tick_labels() {
    for v0 in ["1e-15", "1e15"] {
        for (w, h) in [(60, 20), (80, 24), (120, 40), (200, 60)] {
            let a = superball_typed_v0(v0);
            assert_eq!(a.setting().params.v0, v0.parse::<f64>().unwrap());
            let rows = screen_text(&draw(&a, w, h));
            let s = rows.join("\n");
            assert!(s.contains("×10"), "{w}×{h} v0 {v0}: no factor\n{s}");
            // the force–time chart's y labels: the cells left of its axis
            let labels: Vec<String> = rows
                .iter()
                .filter_map(|r| {
                    let (left, _) = r.split_once('┤')?;
                    let label = left.trim_start_matches('│').trim();
                    (!label.is_empty() && !label.contains('│')).then(|| label.to_string())
                })
                .collect();
            assert!(labels.len() >= 2, "{w}×{h} v0 {v0}: {labels:?}\n{s}");
            assert!(
                labels.iter().all(|l| l.chars().count() <= 6),
                "{w}×{h} v0 {v0}: long labels {labels:?}"
            );
            let mut distinct = labels.clone();
            distinct.dedup();
            assert_eq!(distinct.len(), labels.len(), "{w}×{h} v0 {v0}: {labels:?}");
        }
    }
}

/// Issue 29, item 4: labels never under a legend or another label — at 60×20 the legend
/// covered "F_m 117.3 N" ("m 117.3 N" showed), with pins "p2p▲t_f" ran together. Each value
/// label shows whole at every size, with and without pins.
#[test]
fn value_labels_show_whole_beside_legends_and_pins() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        for pins in [0, 3] {
            let mut a = app(0);
            a.update(Action::Resize(w, h));
            for _ in 0..pins {
                press(&mut a, &[KeyCode::Char('p'), KeyCode::Char('v')]);
            }
            let s = screen_text(&draw(&a, w, h)).join("\n");
            let run = a.run().unwrap();
            let f = format!("F_m {} N", bouncelab::text::sig(run.max_force, 4));
            let t = format!(
                "t_f {} ms",
                bouncelab::text::sig(run.contact_time.unwrap() * 1e3, 4)
            );
            assert!(s.contains(&f), "{w}×{h}, {pins} pins: no '{f}'\n{s}");
            assert!(s.contains(&t), "{w}×{h}, {pins} pins: no '{t}'\n{s}");
        }
    }
}

/// The superball with its speed typed in the readout (`=` on v0).
fn superball_typed_v0(v0: &str) -> App {
    let mut a = app(0);
    press(
        &mut a,
        &[KeyCode::Right, KeyCode::Right, KeyCode::Char('=')],
    );
    press(&mut a, &chars(v0));
    press(&mut a, &[KeyCode::Enter]);
    a
}

/// Issue 29 item 7: the readout never wraps a value — at v0 = 1e-15 m/s its energy line put
/// "1.053e-29" alone at the start of the next row, at 60×20 "law" and "N/m" stood alone. Every
/// row of the readout starts with a space inside its border: a long line breaks between its
/// fields and indents what follows, never at the border.
#[test]
fn readout_values_never_wrap() {
    for v0 in ["1e-15", "3.12", "1e15"] {
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
            let a = superball_typed_v0(v0);
            let rows = screen_text(&draw(&a, w, h));
            let top = rows
                .iter()
                .position(|r| r.contains("superball · adopted"))
                .expect("the readout's title");
            // the readout's frame: the last corner before its title
            let row: Vec<char> = rows[top].chars().collect();
            let title = rows[top].find("superball · adopted").unwrap();
            let title = rows[top][..title].chars().count();
            let x = (0..title).rev().find(|&i| row[i] == '┌').unwrap();
            for r in &rows[top + 1..] {
                let cells: Vec<char> = r.chars().skip(x).collect();
                if cells.first() != Some(&'│') {
                    break;
                }
                let first = cells.get(1).copied().unwrap_or(' ');
                assert!(
                    first == ' ' || first == '▶',
                    "{w}×{h} v0 {v0}: a wrapped readout row {r:?}\n{}",
                    rows.join("\n")
                );
            }
        }
    }
}

/// Issue 29 item 4: with 8 pins the force–time chart's legend vanished (its entries, one per
/// pin, fit neither stacked nor in one line). The pins then share one entry ("p1–p8
/// pinned") and the legend stays, with the model's line.
#[test]
fn legends_stay_with_eight_pins() {
    for (w, h) in [(100, 30), (120, 40), (200, 60)] {
        let mut a = app(0);
        a.update(Action::Resize(w, h));
        for _ in 0..8 {
            press(&mut a, &[KeyCode::Char('p'), KeyCode::Char('v')]);
        }
        let rows = screen_text(&draw(&a, w, h));
        // the force–time chart: the rows under its title, up to its right border, its bottom
        // border too (where a legend that would hide the curves goes, issue 51 item 6)
        let top = rows.iter().position(|r| r.contains("F [N] vs t")).unwrap();
        let right = rows[top].chars().position(|c| c == '┐').unwrap();
        let bottom = top + rows[top..].iter().position(|r| r.starts_with('└')).unwrap();
        let chart: Vec<String> = rows[top..=bottom]
            .iter()
            .map(|r| r.chars().take(right).collect())
            .collect();
        let s = chart.join("\n");
        assert!(s.contains("━ model"), "{w}×{h}: no legend\n{s}");
        let each = (1..=8).all(|i| s.contains(&format!("p{i} superb")));
        assert!(
            each || s.contains("p1–p8 pinned"),
            "{w}×{h}: the pins are not in the legend\n{s}"
        );
    }
}

/// Issue 29 item 6: a fine step near 1000 was invisible ("1000.0 → 1000.0"), and one value
/// read "140" or "140.0" by the terminal's size. A stepped value shows the digits its step
/// needs, and every size writes a value alike.
#[test]
fn one_number_format_at_every_size() {
    let mut a = app(0);
    press(&mut a, &[KeyCode::Char('=')]);
    press(&mut a, &chars("1000"));
    press(&mut a, &[KeyCode::Enter, KeyCode::Up]);
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let s = screen_text(&draw(&a, w, h)).join("\n");
        assert!(
            s.contains("λ 1000.01") || s.contains("λ   1000.01"),
            "{w}×{h}\n{s}"
        );
        assert!(
            s.contains("c 140.0 kg/s") || s.contains("c   140.0 kg/s"),
            "{w}×{h}\n{s}"
        );
    }
}

/// Issue 29 item 4: a marker's glyph wrote over a pin's tag ("⢀●1⠒" for "p1" beside the
/// open loop's ●). Tags keep off the markers' cells, at every size.
#[test]
fn tags_keep_off_the_markers() {
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let mut a = app(0);
        a.update(Action::Resize(w, h));
        press(&mut a, &chars("pvpv"));
        let s = screen_text(&draw(&a, w, h)).join("\n");
        for cut in ["●1", "●2", "▲1", "▲2", "1●", "2●"] {
            assert!(!s.contains(cut), "{w}×{h}: {cut:?}\n{s}");
        }
    }
}

/// Issue 29 item 11: at 60 × 20 the sweeps view's readout (the full-width pane under the
/// charts) showed the parameters only, its four rows taken before e, F_m and t_f. It takes
/// the compact lines there, results included.
#[test]
fn the_sweeps_readout_keeps_its_results_at_60x20() {
    let mut a = app(0);
    a.update(Action::Resize(60, 20));
    press(&mut a, &[KeyCode::Tab]);
    let s = screen_text(&draw(&a, 60, 20)).join("\n");
    for needle in ["e 0.7506", "F_m 117.3", "t_f 2.743"] {
        assert!(s.contains(needle), "no {needle:?}\n{s}");
    }
}

/// The validity note keeps each number with its unit, at every size and speed: no readout row
/// starts with a unit its number left on the row before.
#[test]
fn the_validity_note_keeps_its_numbers_with_their_units() {
    for v0 in ["45", "60", "100"] {
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
            let a = superball_typed_v0(v0);
            let rows = screen_text(&draw(&a, w, h));
            let screen = rows.join("\n");
            // the small screens' readouts have no room for the note
            if !screen.contains("outside the model") {
                assert!(w < 100, "{w}×{h} v0 {v0}: no note\n{screen}");
                continue;
            }
            for r in &rows {
                for part in r.split('│') {
                    let t = part.trim_start();
                    assert!(
                        !t.starts_with("mm"),
                        "{w}×{h} v0 {v0}: a unit apart from its number {r:?}\n{screen}"
                    );
                }
            }
        }
    }
}
