//! The explorer at its smallest promised sizes (60×20, 80×24; docs/explorer.md): chart
//! titles keep their axes before their names and are never a bare "…", the flight view's
//! short readout keeps the net's verdict and the bounce's way out, and a panel whose text
//! does not fit breaks it at words and ends in "…" (a newcomer's trial of the explorer).

use crate::tui_common;

use bouncelab::text::sig;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, View};
use bouncelab::tui::views::fit::state as measured;
use bouncelab::tui::views::flight::export::net_words;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

/// The explorer on the superball in a `w` × `h` terminal after `keys`.
fn at(w: u16, h: u16, keys: &[KeyCode]) -> App {
    let mut app = app(0);
    app.update(Action::Resize(w, h));
    press(&mut app, keys);
    app
}

/// The text of the panel whose top border holds `title`: its title row, then its inner rows
/// (between its side borders, trimmed at the right).
fn panel(t: &Terminal<TestBackend>, title: &str) -> (String, Vec<String>) {
    let buf = t.backend().buffer();
    let (w, h) = (buf.area.width, buf.area.height);
    let cell = |x: u16, y: u16| buf[(x, y)].symbol().to_string();
    let row = |y: u16, from: u16, to: u16| (from..to).map(|x| cell(x, y)).collect::<String>();
    for y in 0..h {
        let text = row(y, 0, w);
        let Some(at) = text.find(title) else { continue };
        // the corner left of the title, and the one that closes the border
        let col = text[..at].chars().count() as u16;
        let left = (0..=col).rev().find(|&x| cell(x, y) == "┌").unwrap();
        let right = (col..w).find(|&x| cell(x, y) == "┐").unwrap();
        let bottom = (y + 1..h).find(|&r| cell(left, r) == "└").unwrap();
        let inner = (y + 1..bottom)
            .map(|r| row(r, left + 1, right).trim_end().to_string())
            .collect();
        return (row(y, left, right + 1), inner);
    }
    panic!("no panel titled {title:?}");
}

/// The titles of every bordered panel on screen: the text after each top-left corner.
fn titles(rows: &[String]) -> Vec<String> {
    rows.iter()
        .flat_map(|r| r.split('┌').skip(1))
        .map(|t| t.trim_matches(|c| "─┐ ".contains(c)).to_string())
        .collect()
}

/// Issue: at 60×20 the sweeps view's chart was titled "Normalized peak force…" (its axes and
/// units gone, its name kept) and the oblique view's slip and spin charts just "…".
#[test]
fn small_titles_keep_the_axes_before_the_names_and_are_never_a_bare_ellipsis() {
    let rows = screen_text(&draw(&at(60, 20, &[KeyCode::Tab]), 60, 20));
    let s = rows.join("\n");
    assert_eq!(at(60, 20, &[KeyCode::Tab]).view(), View::Sweeps);
    assert!(s.contains("Fm/(m v0 ω0)") && s.contains("ζ"), "{s}");
    assert!(!s.contains("Normalized peak force…"), "{s}");
    let app = at(60, 20, &[KeyCode::Char('i')]);
    let rows = screen_text(&draw(&app, 60, 20));
    let s = rows.join("\n");
    let all = titles(&rows);
    assert!(all.iter().any(|t| t.starts_with("v_c")), "{all:?}\n{s}");
    assert!(all.iter().any(|t| t.starts_with("ω")), "{all:?}\n{s}");
    for (w, h) in [(60, 20), (80, 24)] {
        for keys in [
            vec![],
            vec![KeyCode::Tab],
            vec![KeyCode::Tab, KeyCode::Tab],
            vec![KeyCode::Char('i')],
            vec![KeyCode::Char('h')],
        ] {
            let rows = screen_text(&draw(&at(w, h, &keys), w, h));
            for t in titles(&rows) {
                assert!(
                    t != "…",
                    "{w}×{h} {keys:?}: a bare … title\n{}",
                    rows.join("\n")
                );
            }
        }
    }
}

/// Issue: at 60×20 the flight view's readout stopped after "H 2.800 m … leaves": μ, the
/// net's verdict and the bounce's way out were missing, with no sign of it.
#[test]
fn the_short_flight_readout_keeps_the_verdict_and_the_way_out() {
    for name in ["superball", "tennis"] {
        let mut app = opened_on(name, 'h', View::Flight);
        app.update(Action::Resize(60, 20));
        let r = app.flight_view().report().expect("a shot").clone();
        let b = &r.bounces[0];
        let t = draw(&app, 60, 20);
        let s = screen_text(&t).join("\n");
        let n = r.net.as_ref().expect("a net");
        for needle in [
            format!("net {} m: {}", sig(n.x, 4), net_words(n)),
            "μ ".to_string(),
            format!("{} m/s at {}°", sig(b.v_out, 4), sig(b.angle_out, 4)),
            format!("ω {} rad/s", sig(b.spin_out, 4)),
            "leaves".to_string(),
        ] {
            assert!(s.contains(&needle), "{name}: {needle:?} missing\n{s}");
        }
        // what is left out is marked
        let shown_all = s.contains("lands again") && s.contains(&sig(b.v_in, 4));
        assert!(
            shown_all || s.contains('…'),
            "{name}: a cut without a mark\n{s}"
        );
    }
}

/// Every word of `text`, its "…" and its closing punctuation taken off.
fn words(text: &str) -> Vec<String> {
    text.split_whitespace()
        .map(|w| w.trim_end_matches(['…', ':', ',']).to_string())
        .filter(|w| !w.is_empty())
        .collect()
}

/// The panel titled `title` at `small` against the same panel at 200×60: every word it shows
/// is a whole word of the large one (nothing cut mid-word), and where it shows fewer words of
/// the rows from the one holding `span.0` to the one holding `span.1` (all rows: `None`;
/// before and after them: lines that go where there is room, or say the same shorter), its
/// last row ends in "…".
fn assert_cut_at_words(app: &mut App, title: &str, span: Option<(&str, &str)>, small: (u16, u16)) {
    let rows = |inner: &[String], end: bool| {
        let (from, to) = span.map_or((0, inner.len()), |(a, b)| {
            let at = |m: &str| inner.iter().position(|r| r.contains(m));
            let to = if end { at(b).unwrap() + 1 } else { inner.len() };
            (at(a).unwrap(), to)
        });
        words(&inner[from..to].join(" "))
    };
    app.update(Action::Resize(200, 60));
    let (_, large) = panel(&draw(app, 200, 60), title);
    let whole: Vec<String> = words(&large.join(" "));
    let needed = rows(&large, true);
    app.update(Action::Resize(small.0, small.1));
    let t = draw(app, small.0, small.1);
    let (head, inner) = panel(&t, title);
    let s = screen_text(&t).join("\n");
    for w in words(&inner.join(" ")) {
        assert!(whole.contains(&w), "{small:?} {title}: {w:?} is cut\n{s}");
    }
    if rows(&inner, false).len() < needed.len() {
        let last = inner.iter().rev().find(|r| !r.trim().is_empty()).unwrap();
        assert!(
            last.ends_with('…'),
            "{small:?} {title}: cut without a mark\n{s}"
        );
    }
    // the title too: no word cut by the border
    let head_words = words(head.trim_matches(|c| "┌─┐ ".contains(c)));
    app.update(Action::Resize(200, 60));
    let (large_head, _) = panel(&draw(app, 200, 60), title);
    let large_head = words(&large_head);
    for w in head_words {
        assert!(
            large_head.contains(&w),
            "{small:?} {title}: title word {w:?} is cut\n{s}"
        );
    }
}

/// Issue: at 60×20 the models view's rule table stopped after the H–C row (L–N, Flores,
/// Gonthier and the legend missing) with no sign of it.
#[test]
fn a_short_rule_table_says_it_is_cut() {
    let mut app = at(60, 20, &[KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Models);
    assert_cut_at_words(
        &mut app,
        "rule → COR obtained",
        Some(("rule ", "◆ target")),
        (60, 20),
    );
}

/// The golf ball with a three-row COR table fitted (`o`, `f`), then changed (`L`: the fit
/// goes stale, and λ below 1 takes a digit more), in the models view (`Tab` ×2).
fn golf_fitted(dir: &std::path::Path) -> App {
    let mut app = App::new(crate::common::embedded("golf"), false);
    let path = dir.join("cor.csv");
    std::fs::write(&path, "v0,cor\n1,0.85\n2,0.83\n3,0.80\n").unwrap();
    let data = measured::load(&path).unwrap();
    app.update(Action::MeasuredLoaded { path, data });
    let r = match app.update(Action::Fit).as_slice() {
        [bouncelab::tui::app::Effect::Fit(r)] => r.clone(),
        other => panic!("expected one fit effect, got {other:?}"),
    };
    app.update(Action::FitReady(r.id, measured::run(&r).into()));
    press(&mut app, &[KeyCode::Char('L'), KeyCode::Tab, KeyCode::Tab]);
    assert_eq!(app.view(), View::Models);
    app
}

/// Issue: at 80×24 the fit pane was cut mid-word ("· k_r n", "wider than its va", "stale:
/// the ball changed since"), and the rule table's first line wrapped ("… v0 1.470" / "m/s"),
/// pushing the table down a row.
#[test]
fn the_fit_pane_and_the_table_break_at_words_at_80x24() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = golf_fitted(dir.path());
    assert_cut_at_words(&mut app, "fit to cor.csv", None, (80, 24));
    assert_cut_at_words(
        &mut app,
        "rule → COR obtained",
        Some(("rule ", "◆ target")),
        (80, 24),
    );
    let (_, table) = panel(&draw(&app, 80, 24), "rule → COR obtained");
    assert!(
        table[2].trim_start().starts_with("rule"),
        "the table's head is its third row: {table:#?}"
    );
}
