//! The explorer's map view (issue 21), as drawn: the screen with and without colour, the grid
//! following the terminal, the targets entry, the export, every size, the colours and the
//! tick labels beside the cursor.

use crate::tui_common;
use bouncelab::map::Quantity;
use bouncelab::tui::action::{Action, Mode};
use bouncelab::tui::app::App;
use bouncelab::tui::views::map::cells::RAMP;
use bouncelab::tui::views::map::state as map_view;
use ratatui::crossterm::event::KeyCode;
use ratatui::style::Color;
use tui_common::*;

/// Type `text` and press Enter (the targets' entry, `t`).
fn type_and_enter(app: &mut App, text: &str) {
    press(app, &text.chars().map(KeyCode::Char).collect::<Vec<_>>());
    press(app, &[KeyCode::Enter]);
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
