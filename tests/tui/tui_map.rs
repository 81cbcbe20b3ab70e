//! The explorer's map view (issue 21): the screen with and without colour, the cursor moving
//! the ball, the quantity, the targets entry, the worker's passes (stale ones dropped), and
//! the cell under the cursor against `run` at the same (λ, ζ).

use crate::tui_common;

use bouncelab::map::Quantity;
use bouncelab::preset::Preset;
use bouncelab::solver::{SolveOptions, simulate};
use bouncelab::tui::action::{self, Action, Mode};
use bouncelab::tui::app::{App, Effect, View};
use bouncelab::tui::param::Param;
use bouncelab::tui::views::map::cells::RAMP;
use bouncelab::tui::views::map::state::{self as map_view, cell_of};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::style::Color;

use tui_common::*;

/// The superball in the map view of a `w` × `h` terminal (every pass evaluated in `update`).
fn map_app(color: bool, w: u16, h: u16) -> App {
    let mut app = App::new(Preset::embedded().remove(0), color);
    app.update(Action::Resize(w, h));
    press(&mut app, &[KeyCode::Tab, KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Map);
    app
}

/// Type `text` and press Enter (the targets' entry, `t`).
fn type_and_enter(app: &mut App, text: &str) {
    press(app, &text.chars().map(KeyCode::Char).collect::<Vec<_>>());
    press(app, &[KeyCode::Enter]);
}

fn point(app: &App) -> (f64, f64) {
    let s = app.setting();
    (s.get(Param::Lambda), s.get(Param::Zeta))
}

#[test]
fn map_view_in_colour_120x40() {
    let app = map_app(true, 120, 40);
    let t = draw(&app, 120, 40);
    insta::assert_snapshot!(t.backend());
    // the heat map's half blocks carry viridis colours, both halves
    let buf = t.backend().buffer();
    let rgb = buf
        .content()
        .iter()
        .filter(|c| c.symbol() == "▀" && matches!((c.fg, c.bg), (Color::Rgb(..), Color::Rgb(..))))
        .count();
    assert!(rgb > 60 * 30, "{rgb} coloured half-block cells");
}

#[test]
fn map_view_without_colour_120x40() {
    let mut app = map_app(false, 120, 40);
    press(&mut app, &[KeyCode::Char('t')]);
    type_and_enter(&mut app, "cor>=0.8");
    let t = draw(&app, 120, 40);
    insta::assert_snapshot!(t.backend());
    let buf = t.backend().buffer();
    assert!(
        buf.content()
            .iter()
            .all(|c| !matches!(c.fg, Color::Rgb(..)) && !matches!(c.bg, Color::Rgb(..))),
        "no colour under NO_COLOR"
    );
    // several shades of the ramp are on screen: the values stay readable
    let shades = RAMP
        .iter()
        .filter(|s| {
            buf.content()
                .iter()
                .any(|c| c.symbol() == **s && **s != " ")
        })
        .count();
    assert!(shades >= 3, "{shades} shades");
}

/// At 80×24, in colour and without: each screen under the name its own test had.
#[test]
fn map_view_80x24_in_colour_and_without() {
    for (name, color) in [
        ("map_view_in_colour_80x24", true),
        ("map_view_without_colour_80x24", false),
    ] {
        insta::assert_snapshot!(name, draw(&map_app(color, 80, 24), 80, 24).backend());
    }
}

/// The grid has one cell per half character of the heat map (one per character without
/// colour), so the cursor moves by what the eye sees.
#[test]
fn the_grid_follows_the_screen() {
    for (color, per) in [(true, 2), (false, 1)] {
        let app = map_app(color, 120, 40);
        let map = app.map_view().map().unwrap();
        let (rows, cols) = map_view::grid(Some((120, 40)), color, 0).unwrap();
        assert_eq!((map.lambdas.len(), map.zetas.len()), (rows, cols));
        assert_eq!(rows % per, 0);
        assert!(map.is_complete());
    }
}

#[test]
fn arrows_move_the_cursor_and_the_ball_one_undoable_cell_at_a_time() {
    let mut app = map_app(true, 120, 40);
    let depth = app.undo_depth();
    let generation = app.map_view().job.generation;
    let (i, j) = {
        let (l, z) = point(&app);
        cell_of(app.map_view().map().unwrap(), l, z)
    };
    press(&mut app, &[KeyCode::Right]);
    let map = app.map_view().map().unwrap().clone();
    // the ball holds K_r = λ K_p and c = √(m K_p)/(2ζ): λ and ζ read back from them are the
    // cell's to an ulp or two of the round trip
    let same = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    let (l, z) = point(&app);
    assert!(same(z, map.zetas[j + 1]), "ζ on the next column: {z}");
    assert!(same(l, map.lambdas[i]), "λ snapped to its row: {l}");
    press(&mut app, &[KeyCode::Up, KeyCode::Up]);
    assert!(same(point(&app).0, map.lambdas[i + 2]));
    assert_eq!(app.undo_depth(), depth + 3, "one change per step");
    // the impact (and so the impact view) follows the ball
    let run = app.run().unwrap();
    let (l, z) = point(&app);
    let want = simulate(
        &app.setting().params,
        app.setting().law,
        &SolveOptions::default(),
    )
    .unwrap();
    assert_eq!(run.cor, want.cor);
    assert!((l - map.lambdas[i + 2]).abs() < 1e-12 && (z - map.zetas[j + 1]).abs() < 1e-15);
    press(&mut app, &[KeyCode::Char('u')]);
    assert_eq!(point(&app).0, map.lambdas[i + 1], "undo: one cell back");
    // the same map all along: moving inside the window re-solves no map
    assert_eq!(app.map_view().job.generation, generation);
    // l / L still work in the map view, and the cursor follows
    press(&mut app, &[KeyCode::Char('l')]);
    assert_eq!(app.mode(), Mode::Map);
}

/// The cell under the cursor is `run` at that (λ, ζ): the map's cells and the impact the
/// readout shows are the same numbers.
#[test]
fn the_cell_under_the_cursor_is_run_at_that_point() {
    let mut app = map_app(true, 120, 40);
    press(&mut app, &[KeyCode::Left, KeyCode::Down, KeyCode::Down]);
    let (l, z) = point(&app);
    let map = app.map_view().map().unwrap();
    let (i, j) = cell_of(map, l, z);
    let cell = map.cell(i, j).unwrap();
    let run = simulate(
        &app.setting().params,
        app.setting().law,
        &SolveOptions::default(),
    )
    .unwrap();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1.0);
    assert!(close(cell.cor, run.cor), "{} vs {}", cell.cor, run.cor);
    assert!(close(cell.max_force, run.max_force));
    assert!(close(cell.contact_time.unwrap(), run.contact_time.unwrap()));
    let shown = app.run().unwrap();
    assert!(close(cell.cor, shown.cor) && close(cell.max_force, shown.max_force));
    // and at the same (λ, ζ) as `bouncelab run --lambda --zeta` sets them
    let p = Preset::embedded()[0]
        .params()
        .with_lambda_zeta(map.lambdas[i], map.zetas[j]);
    let cli = simulate(&p, app.setting().law, &SolveOptions::default()).unwrap();
    assert!(close(cell.cor, cli.cor));
}

#[test]
fn n_cycles_the_quantity() {
    let mut app = map_app(true, 120, 40);
    assert_eq!(app.map_view().quantity, Quantity::Cor);
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::MaxForce);
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::ContactTime);
    let t = draw(&app, 120, 40);
    assert!(format!("{:?}", t.backend()).contains("t_f (ms)"));
    press(&mut app, &[KeyCode::Char('n')]);
    assert_eq!(app.map_view().quantity, Quantity::Cor);
    // outside the map view n and t do nothing
    press(&mut app, &[KeyCode::Tab]);
    assert_eq!(
        action::from_key(
            KeyEvent::new(KeyCode::Char('n'), KeyModifiers::NONE),
            app.mode()
        ),
        None
    );
}

#[test]
fn targets_are_set_refused_with_the_part_named_and_cleared() {
    let mut app = map_app(true, 120, 40);
    press(&mut app, &[KeyCode::Char('t')]);
    assert_eq!(app.mode(), Mode::Input);
    type_and_enter(&mut app, "cor>=0.8,max_force<=2000");
    assert_eq!(app.mode(), Mode::Map);
    let t = app.map_view().targets.clone().unwrap();
    assert_eq!(t.to_string(), "cor>=0.8,max_force<=2000");
    // a part that does not read: the entry stays open with the reason, targets kept
    press(&mut app, &[KeyCode::Char('t')]);
    assert_eq!(app.mode(), Mode::Input, "t reopens the entry");
    let back = [KeyCode::Backspace; 40];
    press(&mut app, &back);
    type_and_enter(&mut app, "cor>=0.8,force<=2");
    assert_eq!(app.mode(), Mode::Input);
    let msg = app.message().unwrap().text.clone();
    assert!(
        msg.starts_with("invalid where: 'force<=2' (unknown quantity"),
        "{msg}"
    );
    assert!(!msg.contains('\n'));
    assert_eq!(app.map_view().targets.as_ref(), Some(&t));
    // a part without its bound lists the quantities too, with their units here (issue 51
    // item 8: "expected QUANTITY>=VALUE or QUANTITY<=VALUE" named none)
    press(&mut app, &back);
    type_and_enter(&mut app, "cor=0.8");
    let msg = app.message().unwrap().text.clone();
    assert!(
        msg.contains("cor, max_force (N) or contact_time (ms)"),
        "{msg}"
    );
    // empty clears them
    press(&mut app, &back);
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.mode(), Mode::Map);
    assert!(app.map_view().targets.is_none());
}

/// With the worker: a new map's first pass is in `update`, the rest is asked for; a pass of
/// an older map is dropped, one of the current map taken; leaving the view stops the work.
#[test]
fn passes_come_from_the_worker_and_stale_ones_are_dropped() {
    let mut app = App::new(Preset::embedded().remove(0), true).with_background_sweeps();
    app.update(Action::Resize(120, 40));
    app.update(Action::NextView);
    app.update(Action::NextView);
    let effects = app.update(Action::NextView);
    let job = effects
        .iter()
        .find_map(|e| match e {
            Effect::Map(job) => Some(job.clone()),
            _ => None,
        })
        .expect("the rest of the map asked of the worker");
    assert!(app.map_pending());
    let coarse = app.map_view().map().unwrap().clone();
    assert!(
        !coarse.is_complete() && coarse.nearest(0, 0).is_some(),
        "a coarse picture"
    );
    // the worker's answer, done here: the whole map of that job
    let mut full = job.work.clone();
    while full.refine().is_some() {}
    // the ball changes (v0): a new map, the old job cancelled
    press(&mut app, &[KeyCode::Char('v')]);
    assert!(
        job.cancel.load(std::sync::atomic::Ordering::Relaxed),
        "stale job cancelled"
    );
    let now = app.map_view().job.generation;
    assert_eq!(now, job.generation + 1);
    app.update(Action::MapPass {
        generation: job.generation,
        map: Box::new(full),
    });
    assert!(
        !app.map_view().map().unwrap().is_complete(),
        "stale pass dropped"
    );
    assert_eq!(
        app.map_view().job.generation,
        now,
        "the map held is untouched"
    );
    let mut fresh = app.map_view().map().unwrap().clone();
    while fresh.refine().is_some() {}
    app.update(Action::MapPass {
        generation: now,
        map: Box::new(fresh.clone()),
    });
    assert_eq!(app.map_view().map(), Some(&fresh));
    assert!(!app.map_pending(), "complete: nothing out");
    // leaving the view while a map is out stops it
    press(&mut app, &[KeyCode::Char('v')]);
    assert!(app.map_pending());
    press(&mut app, &[KeyCode::Tab]);
    assert!(!app.map_pending());
}

/// `e` in the map view writes the map on screen: the SVG heat map of the quantity shown (the
/// code of `bouncelab map --format svg`) and its CSV, with the targets' column.
#[test]
fn e_exports_the_map_on_screen_as_svg_and_csv() {
    let mut app = map_app(true, 120, 40);
    press(&mut app, &[KeyCode::Char('n'), KeyCode::Char('t')]);
    type_and_enter(&mut app, "cor>=0.7");
    let effects = app.update(Action::Export);
    let request = export_of(effects);
    assert!(request.charts.is_empty());
    let m = request.map.as_ref().expect("the map");
    assert_eq!(m.quantity, Quantity::MaxForce);
    assert_eq!(&m.map, app.map_view().map().unwrap(), "the map on screen");
    let dir = tempfile::tempdir().unwrap();
    let files = bouncelab::tui::export::write(&request, dir.path()).unwrap();
    let names = file_names(&files);
    assert_eq!(
        names,
        [
            "bouncelab-superball-map-max_force-1.svg",
            "bouncelab-superball-map-max_force-1.csv"
        ]
    );
    let svg = std::fs::read_to_string(&files[0]).unwrap();
    assert!(svg.starts_with("<svg") || svg.contains("<svg"), "an SVG");
    assert!(
        svg.contains("F_m (N)") && svg.contains("cor&gt;=0.7"),
        "quantity and targets"
    );
    let csv = std::fs::read_to_string(&files[1]).unwrap();
    // the explorer's `#` lines first (the `y` command line and the parameters), then the map
    assert!(
        csv.starts_with("# bouncelab run --preset superball"),
        "{csv}"
    );
    let mut lines = csv.lines().skip_while(|l| l.starts_with('#'));
    assert_eq!(
        lines.next(),
        Some("lambda,zeta,cor,max_force,contact_time,feasible")
    );
    assert_eq!(lines.count(), m.map.cells().len());
    let map = &m.map;
    let data: String = csv
        .lines()
        .skip_while(|l| l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(
        data,
        bouncelab::map::csv::csv(map, app.map_view().targets.as_ref()),
        "the CSV of `bouncelab map`"
    );
}

/// Any terminal size draws without a panic, with and without colour, whatever size the map
/// was made for; values on screen are never NaN or inf.
#[test]
fn every_size_draws() {
    for color in [true, false] {
        let mut app = map_app(color, 120, 40);
        press(&mut app, &[KeyCode::Char('t')]);
        type_and_enter(&mut app, "cor>=0.7");
        for (w, h) in [
            (50, 16),
            (51, 17),
            (64, 20),
            (80, 24),
            (97, 31),
            (200, 60),
            (300, 90),
        ] {
            let t = draw(&app, w, h);
            let text = format!("{:?}", t.backend());
            assert!(!text.contains("NaN") && !text.contains("inf"), "{w}x{h}");
            app.update(Action::Resize(w, h));
            let t = draw(&app, w, h);
            assert!(!format!("{:?}", t.backend()).contains("NaN"));
        }
    }
}

/// Issue 29, item 11: the map's viridis cells were sent as 24-bit colour whatever the
/// terminal; one that does not announce it (COLORTERM) gets the 256 or 16 colours it has.
#[test]
fn the_map_uses_only_colours_the_terminal_shows() {
    use bouncelab::tui::palette::Depth;
    for depth in [Depth::TrueColor, Depth::Indexed, Depth::Ansi] {
        let a = map_app(true, 120, 40).with_color_depth(depth);
        let t = draw(&a, 120, 40);
        let cells = t.backend().buffer().content();
        let rgb = cells
            .iter()
            .filter(|c| matches!(c.fg, Color::Rgb(..)) || matches!(c.bg, Color::Rgb(..)))
            .count();
        let indexed = cells
            .iter()
            .filter(|c| matches!(c.bg, Color::Indexed(..)))
            .count();
        match depth {
            Depth::TrueColor => assert!(rgb > 100, "the map in 24-bit colour: {rgb}"),
            Depth::Indexed => assert!(rgb == 0 && indexed > 100, "{rgb} {indexed}"),
            Depth::Ansi => assert!(rgb == 0 && indexed == 0, "{rgb} {indexed}"),
        }
    }
}

/// Issue 29 item 4: the cursor's ▲ under the ζ axis never writes into a tick label
/// ("0.▲01"): at every cursor column each token of the label row is a whole number, the ▲
/// or the axis name.
#[test]
fn the_map_cursor_never_cuts_a_tick_label() {
    let mut app = map_app(false, 80, 24);
    press(&mut app, &[KeyCode::Left; 120]);
    for _ in 0..80 {
        let t = draw(&app, 80, 24);
        let buf = t.backend().buffer();
        let rows: Vec<String> = (0..24)
            .map(|y| (0..80).map(|x| buf[(x, y)].symbol()).collect())
            .collect();
        let labels = rows
            .iter()
            .rfind(|r| r.contains('▲'))
            .expect("the cursor's ▲ under the map");
        let inner = labels.trim_matches(|c| c == '│' || c == ' ');
        for token in inner.split_whitespace() {
            assert!(
                token == "▲" || token == "ζ" || token.parse::<f64>().is_ok(),
                "{token:?} in the label row {labels:?}"
            );
        }
        press(&mut app, &[KeyCode::Right]);
    }
}

/// Issue 29 item 11: the map and its readout show contact times in ms, but its targets entry
/// read seconds. It reads ms now (held in SI, as the library's targets and the export), and
/// shows them back in ms.
#[test]
fn map_targets_are_typed_in_the_units_the_map_shows() {
    let mut app = map_app(false, 120, 40);
    press(&mut app, &[KeyCode::Char('t')]);
    type_and_enter(&mut app, "contact_time>=2");
    let t = app.map_view().targets.clone().unwrap();
    assert_eq!(t.0[0].value, 0.002, "2 ms held as 0.002 s");
    let s = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(s.contains("where contact_time>=2"), "{s}");
    // t reopens the entry with the targets as typed
    press(&mut app, &[KeyCode::Char('t')]);
    press(&mut app, &[KeyCode::Enter]);
    assert_eq!(app.map_view().targets.as_ref(), Some(&t));
}

/// Issue 51 item 4: the map's cell line writes its numbers as the readout does, four
/// significant digits: it read "cell λ 1.45 ζ 0.17" (trailing zeros trimmed) and
/// "∂e/∂ln ζ -0.085" (three decimals, two digits) beside a readout's "ζ 0.1612".
#[test]
fn the_map_cell_line_writes_four_significant_digits() {
    use bouncelab::tui::format::value;
    let app = map_app(false, 120, 40);
    let map = app.map_view().map().unwrap();
    let (l, z) = point(&app);
    let (i, j) = cell_of(map, l, z);
    let s = screen_text(&draw(&app, 120, 40)).join("\n");
    let cell = format!("cell λ {} ζ {}", value(map.lambdas[i]), value(map.zetas[j]));
    assert!(s.contains(&cell), "{cell:?} in\n{s}");
    let line = s
        .lines()
        .find(|r| r.contains("∂e/∂ln λ"))
        .expect("the sensitivities' line");
    for part in line.split("∂e/∂ln ").skip(1) {
        let number = part.split_whitespace().nth(1).unwrap();
        let digits = number
            .trim_start_matches(['+', '-', '0', '.'])
            .replace('.', "");
        assert_eq!(digits.len(), 4, "{number:?} in {line:?}");
    }
}
