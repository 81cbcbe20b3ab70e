//! Axes read true (issue 51 item 1): every view with a chart drawn at the five sizes, every
//! labelled tick read back off the screen, and each label checked against the column (x) or
//! row (y) its value maps to on its axis — the axis' map fitted through all its labels, so one
//! misplaced label shows (the oblique forces axis once put `0 2 4 6` at columns 5, 62, 101,
//! 164: "2" marked 1.9 ms). Linear and decade (log) axes alike.

use crate::common::embedded;
use crate::tui_common;

use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::views::map::state::geometry;
use ratatui::crossterm::event::KeyCode;
use ratatui::layout::Rect;
use tui_common::*;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// One labelled tick read off the screen: its value and the cells its label takes along the
/// axis (columns of an x label, the row of a y label).
#[derive(Debug, Clone, Copy)]
struct Label {
    value: f64,
    from: f64,
    to: f64,
}

/// The screen as a grid of symbols.
fn grid(app: &App, w: u16, h: u16) -> Vec<Vec<String>> {
    let t = draw(app, w, h);
    let buf = t.backend().buffer();
    (0..h)
        .map(|y| (0..w).map(|x| buf[(x, y)].symbol().to_string()).collect())
        .collect()
}

/// The tokens of `row` between columns `lo` and `hi` (exclusive): (start, text).
fn tokens(row: &[String], lo: usize, hi: usize) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut cur: Option<(usize, String)> = None;
    for (x, cell) in row.iter().enumerate().take(hi.min(row.len())).skip(lo) {
        let blank = cell == " " || cell == "│";
        match (&mut cur, blank) {
            (Some((_, s)), false) => s.push_str(cell),
            (None, false) => cur = Some((x, cell.clone())),
            (Some(_), true) => out.push(cur.take().unwrap()),
            (None, true) => {}
        }
    }
    out.extend(cur);
    out
}

/// One axis read off the screen.
struct ScreenAxis {
    x: bool,
    /// The axes' corner `└`: (row, column).
    at: (usize, usize),
    labels: Vec<Label>,
    /// A y axis's top row (an x axis's own row).
    top: usize,
}

/// The numbers on an x axis's label row between columns `from` and `to`, each spanning the
/// cells its text covers.
fn x_labels(row: &[String], from: usize, to: usize) -> Vec<Label> {
    tokens(row, from, to)
        .into_iter()
        .filter_map(|(s, t)| {
            let w = t.chars().count();
            Some(Label {
                value: t.parse().ok()?,
                from: s as f64,
                to: (s + w - 1) as f64,
            })
        })
        .collect()
}

/// Every chart axis on the screen, found from the axes' corners `└` whose x axis runs right
/// (`─`, `┴`) to something other than a frame's corner `┘`.
fn axes(g: &[Vec<String>]) -> Vec<ScreenAxis> {
    let mut out = Vec::new();
    for (r, row) in g.iter().enumerate() {
        for (c, cell) in row.iter().enumerate() {
            if cell != "└" {
                continue;
            }
            let run = row[c + 1..]
                .iter()
                .take_while(|s| *s == "─" || *s == "┴" || *s == "┼")
                .count();
            let end = c + 1 + run;
            if run < 6 || row.get(end).is_some_and(|s| s == "┘") || r + 1 >= g.len() {
                continue;
            }
            // x labels: the row under the axis line, from a little left of the corner
            let xs = x_labels(&g[r + 1], c.saturating_sub(4), end);
            out.push(ScreenAxis {
                x: true,
                at: (r, c),
                labels: xs,
                top: r,
            });
            // y labels: left of the axis line, on each of its rows
            let mut ys = Vec::new();
            let mut y = r;
            while y > 0 && matches!(g[y - 1][c].as_str(), "│" | "┤" | "┼") {
                y -= 1;
                let left = tokens(&g[y], c.saturating_sub(12), c);
                if let Some((_, t)) = left.last()
                    && let Ok(value) = t.parse()
                {
                    ys.push(Label {
                        value,
                        from: y as f64,
                        to: y as f64,
                    });
                }
            }
            out.push(ScreenAxis {
                x: false,
                at: (r, c),
                labels: ys,
                top: y,
            });
        }
    }
    out
}

/// Decade labels (0.01 0.1 1 10 …, three or more): a log axis, read in log10 of the values
/// (or any labels, when the axis is known to be log: `log`).
fn positions(labels: &[Label], log: bool) -> Vec<(f64, f64, f64)> {
    let decade = |v: f64| v > 0.0 && (v.log10() - v.log10().round()).abs() < 1e-9;
    let log = log || labels.len() >= 3 && labels.iter().all(|l| decade(l.value));
    labels
        .iter()
        .map(|l| {
            let v = if log { l.value.log10() } else { l.value };
            (v, l.from, l.to)
        })
        .collect()
}

/// The labels that do not sit at their value's place (±1 cell) on the line fitted through
/// all of them (least squares of the label's middle against its value).
fn misplaced(labels: &[Label]) -> Vec<String> {
    misplaced_on(labels, false)
}

/// [`misplaced`], the values read on a log scale when `log` (else when they are decades).
fn misplaced_on(labels: &[Label], log: bool) -> Vec<String> {
    let p = positions(labels, log);
    if p.len() < 3 {
        return Vec::new();
    }
    let n = p.len() as f64;
    let mid = |&(_, a, b): &(f64, f64, f64)| 0.5 * (a + b);
    let (mv, mc) = (
        p.iter().map(|q| q.0).sum::<f64>() / n,
        p.iter().map(mid).sum::<f64>() / n,
    );
    let sxy: f64 = p.iter().map(|q| (q.0 - mv) * (mid(q) - mc)).sum();
    let sxx: f64 = p.iter().map(|q| (q.0 - mv).powi(2)).sum();
    let slope = sxy / sxx;
    p.iter()
        .filter(|&&(v, a, b)| {
            let at = mc + slope * (v - mv);
            at < a - 1.0 || at > b + 1.0
        })
        .map(|&(v, a, b)| {
            format!(
                "{v} at {a}…{b}, its value's place {:.1}",
                mc + slope * (v - mv)
            )
        })
        .collect()
}

/// A y axis labelled below its top row but not on it: the top end's value unread (the
/// sweeps' COR axis at 200×60 ran to 1.05 over a top row left blank above `1.0`).
fn unlabelled_top(x: bool, labels: &[Label], top: usize) -> Option<String> {
    let labelled = |row: usize| labels.iter().any(|l| l.from as usize == row);
    (!x && labels.len() >= 2 && !labelled(top)).then(|| format!("top row {top} has no label"))
}

/// Checks every axis of `app` at the five sizes; the number of axes with three or more
/// labels checked.
fn check(name: &str, app: &mut App) -> usize {
    let mut checked = 0;
    for (w, h) in SIZES {
        app.update(Action::Resize(w, h));
        let g = grid(app, w, h);
        for ScreenAxis { x, at, labels, top } in axes(&g) {
            let mut bad = misplaced(&labels);
            bad.extend(unlabelled_top(x, &labels, top));
            let screen: Vec<String> = g.iter().map(|r| r.concat()).collect();
            assert!(
                bad.is_empty(),
                "{name} {w}×{h}: {} axis at {at:?}: {bad:?}\n{}",
                if x { "x" } else { "y" },
                screen.join("\n")
            );
            checked += usize::from(labels.len() >= 3);
        }
    }
    checked
}

/// The map view's two log axes (its own widget, no `└` corner): λ labels in the gutter left
/// of the heat map, one per row, ζ labels on the row under it. The panel found by its
/// title, its parts by the widget's own layout (`views::map::state::geometry`); the labels'
/// values then checked against their rows and columns as every other chart's.
fn map_axes(g: &[Vec<String>]) -> Option<[ScreenAxis; 2]> {
    let (r0, c0) = g.iter().enumerate().find_map(|(r, row)| {
        let line = row.concat();
        let at = line.find("┌ map of")?;
        Some((r, line[..at].chars().count()))
    })?;
    let width = g[r0][c0 + 1..].iter().position(|s| s == "┐")? + 2;
    let height = g[r0 + 1..].iter().position(|row| row[c0] == "└")? + 2;
    let area = Rect::new(c0 as u16, r0 as u16, width as u16, height as u16);
    let geo = geometry(area)?;
    let (gx, gw) = (usize::from(geo.gutter.x), usize::from(geo.gutter.width));
    let mut ys = Vec::new();
    for y in geo.plot.y..geo.plot.bottom() {
        // the gutter's last cell is the cursor's ▶
        if let Some((_, t)) = tokens(&g[usize::from(y)], gx, gx + gw - 1).last()
            && let Ok(value) = t.parse()
        {
            let y = f64::from(y);
            ys.push(Label {
                value,
                from: y,
                to: y,
            });
        }
    }
    let row = usize::from(geo.x_labels.y);
    let xs = x_labels(&g[row], gx, usize::from(geo.plot.right()) + 2);
    let at = (row, usize::from(geo.plot.x));
    Some([
        ScreenAxis {
            x: true,
            at,
            labels: xs,
            top: row,
        },
        ScreenAxis {
            x: false,
            at,
            labels: ys,
            top: usize::from(geo.plot.y),
        },
    ])
}

/// Checks the map's two axes at the five sizes.
fn check_map(name: &str, app: &mut App) {
    for (w, h) in SIZES {
        app.update(Action::Resize(w, h));
        let g = grid(app, w, h);
        let screen: Vec<String> = g.iter().map(|r| r.concat()).collect();
        let axes = map_axes(&g);
        assert!(
            axes.is_some(),
            "{name} {w}×{h}: no map panel\n{}",
            screen.join("\n")
        );
        for ScreenAxis { x, at, labels, top } in axes.into_iter().flatten() {
            assert!(
                labels.len() >= 3,
                "{name} {w}×{h}: {labels:?}\n{}",
                screen.join("\n")
            );
            let mut bad = misplaced_on(&labels, true);
            bad.extend(unlabelled_top(x, &labels, top));
            assert!(
                bad.is_empty(),
                "{name} {w}×{h}: map {} axis at {at:?}: {bad:?}\n{}",
                if x { "ζ" } else { "λ" },
                screen.join("\n")
            );
        }
    }
}

#[test]
fn every_tick_label_sits_at_its_value_in_every_view_at_every_size() {
    for ball in ["tennis", "superball", "golf"] {
        let mut app = App::new(embedded(ball), false);
        assert!(check(&format!("{ball} impact"), &mut app) >= 10);
        press(&mut app, &[KeyCode::Tab]);
        assert_eq!(app.view(), View::Sweeps);
        assert!(check(&format!("{ball} sweeps"), &mut app) >= 10);
        press(&mut app, &[KeyCode::Tab]);
        assert_eq!(app.view(), View::Models);
        assert!(check(&format!("{ball} models"), &mut app) >= 10);
        press(&mut app, &[KeyCode::Tab]);
        assert_eq!(app.view(), View::Map);
        check(&format!("{ball} map"), &mut app);
        check_map(&format!("{ball} map"), &mut app);
        press(&mut app, &[KeyCode::Tab, KeyCode::Char('d')]);
        assert_eq!(app.view(), View::Drop);
        // the drop's chart: its two axes at each size
        assert!(check(&format!("{ball} drop"), &mut app) >= 5);
        press(&mut app, &[KeyCode::Char('d'), KeyCode::Char('i')]);
        assert_eq!(app.view(), View::Oblique);
        // the forces, slip and spin charts
        assert!(check(&format!("{ball} oblique"), &mut app) >= 10);
        press(&mut app, &[KeyCode::Char('i'), KeyCode::Char('h')]);
        assert_eq!(app.view(), View::Flight);
        // the shot's path: its two axes at each size
        assert!(check(&format!("{ball} flight"), &mut app) >= 5);
    }
}

/// The finder itself: labels evenly spread over an axis whose values are not (ratatui's
/// `Chart` spreads `0 2 4 6` over a 0…6.2 axis) are found misplaced; true ones are not.
#[test]
fn the_check_finds_a_misplaced_label() {
    let at = |value: f64, col: f64| Label {
        value,
        from: col,
        to: col,
    };
    let oblique = [at(0.0, 5.0), at(2.0, 62.0), at(4.0, 101.0), at(6.0, 164.0)];
    assert!(!misplaced(&oblique).is_empty());
    let true_ = [at(0.0, 5.0), at(2.0, 57.0), at(4.0, 110.0), at(6.0, 162.0)];
    assert!(misplaced(&true_).is_empty(), "{:?}", misplaced(&true_));
    let decades = [at(0.01, 3.0), at(0.1, 23.0), at(1.0, 43.0), at(10.0, 63.0)];
    assert!(misplaced(&decades).is_empty());
    // a y axis whose labels start a row below its top (rows 3, 9, 15; the axis from row 2)
    let rows = [at(1.0, 3.0), at(0.5, 9.0), at(0.0, 15.0)];
    assert!(unlabelled_top(false, &rows, 2).is_some());
    assert!(unlabelled_top(false, &rows, 3).is_none());
}
