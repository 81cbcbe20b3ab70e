//! What the explorer draws: snapshots of whole screens (TestBackend), the log axis's decade
//! labels, colour off under NO_COLOR, and no panic at any size.

use crate::tui_common;

use bouncelab::figure::{Kind, Look, Marker as Shape, Series, Style as Stroke, Tone};
use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use bouncelab::tui::theme::Theme;
use bouncelab::tui::ui::{self, Chart};
use bouncelab::tui::widgets::plot::Plot;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;
use ratatui::style::Color;

use tui_common::*;

fn app(i: usize) -> App {
    App::new(Preset::embedded().remove(i), true)
}

/// The whole explorer, opened on the embedded preset `ball` (0 superball, 1 golf, 2 baseball),
/// after `keys`, drawn at `size`: each screen its snapshot `name` (the name its own test had,
/// so the snapshot files stand as they were).
struct Screen {
    name: &'static str,
    ball: usize,
    keys: Vec<KeyCode>,
    size: (u16, u16),
}

fn screens() -> Vec<Screen> {
    use KeyCode::{Backspace, Char, Enter, Right, Tab};
    let screen = |name, ball, keys: &[&[KeyCode]], size| Screen {
        name,
        ball,
        keys: keys.concat(),
        size,
    };
    vec![
        screen("first_screen_superball", 0, &[], (120, 40)),
        screen("first_screen_golf", 1, &[], (120, 40)),
        screen("first_screen_baseball", 2, &[], (120, 40)),
        screen("help_overlay", 0, &[&[Char('?')]], (120, 40)),
        screen("sweeps_view", 0, &[&[Tab]], (120, 40)),
        screen("small_terminal_60x20", 0, &[], (60, 20)),
        screen("common_terminal_80x24", 0, &[], (80, 24)),
        screen("too_small", 0, &[], (30, 10)),
        screen(
            "after_lambda_up_three_times_and_zeta_down_twice",
            0,
            &[&chars("lll"), &chars("ZZ")],
            (120, 40),
        ),
        screen(
            "value_entry_refusing_text",
            0,
            &[&[Right, Char('=')], &chars("abc"), &[Enter]],
            (120, 40),
        ),
        screen(
            "save_prompt_refusing_a_name_with_a_space",
            0,
            &[&chars("ls"), &[Backspace; 6], &chars(" mine"), &[Enter]],
            (120, 40),
        ),
        screen(
            "flattened_superball_with_a_pinned_ghost",
            0,
            &[&[Char('p'), Right, Right, Char('=')], &[Char('8'), Enter]],
            (120, 40),
        ),
    ]
}

/// Each of [`screens`] drawn as its snapshot holds it (insta names the snapshot that differs).
#[test]
fn screens_after_keys() {
    for Screen {
        name,
        ball,
        keys,
        size: (w, h),
    } in screens()
    {
        let mut a = app(ball);
        press(&mut a, &keys);
        insta::assert_snapshot!(name, draw(&a, w, h).backend());
    }
}

#[test]
fn overwrite_question() {
    let mut a = app(0);
    press(&mut a, &[KeyCode::Char('s'), KeyCode::Enter]);
    // what the event loop answers when the name is taken, here by a file that holds a preset
    // of another name (a fixed path, so that the picture does not depend on the machine)
    a.update(Action::SaveExists {
        path: "/home/user/.config/bouncelab/presets/superball-custom.toml".into(),
        holds: Some("old-superball".into()),
    });
    insta::assert_snapshot!(draw(&a, 120, 40).backend());
}

/// A preset without measurements (as the explorer saves one at another speed) claims none.
#[test]
fn no_measured_speed_without_measurements() {
    let text_of = |p: Preset| buffer_text(draw(&App::new(p, true), 120, 40).backend().buffer());
    let mut p = Preset::embedded().remove(0);
    assert!(text_of(p.clone()).contains("measured at v0 = 3.120 m/s"));
    p.name = "unmeasured".into();
    (
        p.measured.cor,
        p.measured.max_force,
        p.measured.contact_time,
    ) = (None, None, None);
    assert!(!text_of(p).contains("measured at"));
}

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

#[test]
fn no_color_draws_without_colours() {
    for i in 0..3 {
        let mut a = App::new(Preset::embedded().remove(i), false);
        press(
            &mut a,
            &[KeyCode::Char('p'), KeyCode::Char('l'), KeyCode::Char('?')],
        );
        for keys in [vec![], vec![KeyCode::Esc, KeyCode::Tab]] {
            press(&mut a, &keys);
            let t = draw(&a, 120, 40);
            for cell in t.backend().buffer().content() {
                assert_eq!((cell.fg, cell.bg), (Color::Reset, Color::Reset), "{cell:?}");
            }
        }
    }
    // and with colour there is some
    let t = draw(&app(0), 120, 40);
    assert!(
        t.backend()
            .buffer()
            .content()
            .iter()
            .any(|c| c.fg != Color::Reset)
    );
}

#[test]
fn never_nan_or_inf_on_screen() {
    let mut a = app(0);
    // λ = 0, ζ = 1000: no rebound
    for keys in ["]LLLLLLLLLLLLLLL", "zzzzzzzzzzzzz", "?"] {
        let mut codes: Vec<KeyCode> = keys.chars().map(KeyCode::Char).collect();
        if keys == "?" {
            codes = vec![KeyCode::Tab];
        }
        press(&mut a, &codes);
        let s = buffer_text(draw(&a, 120, 40).backend().buffer());
        for bad in ["NaN", "nan", "inf"] {
            assert!(!s.contains(bad), "{bad} on screen:\n{s}");
        }
    }
    assert!(!a.run().unwrap().rebound);
}

#[test]
fn every_tiny_size_draws() {
    let mut apps = vec![app(0), app(1)];
    let mut help = app(2);
    press(&mut help, &[KeyCode::Char('?')]);
    let mut input = app(0);
    press(&mut input, &[KeyCode::Char('p'), KeyCode::Char('=')]);
    let mut sweeps = app(0);
    press(&mut sweeps, &[KeyCode::Tab]);
    apps.extend([help, input, sweeps]);
    for a in &apps {
        for w in 1..=20 {
            for h in 1..=10 {
                draw(a, w, h);
            }
        }
    }
    let s = buffer_text(draw(&apps[0], 20, 3).backend().buffer());
    assert!(s.starts_with("enlarge the"), "{s}");
}

#[test]
fn resize_storm() {
    let mut a = app(0);
    press(&mut a, &[KeyCode::Char('p'), KeyCode::Char('L')]);
    let mut t = Terminal::new(TestBackend::new(120, 40)).unwrap();
    let mut seed: u32 = 12345;
    for i in 0..600 {
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
        let w = 1 + (seed >> 8) as u16 % 220;
        let h = 1 + (seed >> 20) as u16 % 70;
        t.backend_mut().resize(w, h);
        let keys: &[KeyCode] = match i % 50 {
            10 => &[KeyCode::Tab],
            20 => &[KeyCode::Char('?')],
            30 => &[KeyCode::Esc, KeyCode::Char('=')],
            40 => &[KeyCode::Esc],
            _ => &[],
        };
        press(&mut a, keys);
        t.draw(|f| f.render_widget(&a, f.area())).unwrap();
        assert_eq!(t.backend().buffer().area, Rect::new(0, 0, w, h));
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

/// Issue 29 item 7: the readout never wraps a value — at v0 = 1e-15 m/s its energy line put
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
