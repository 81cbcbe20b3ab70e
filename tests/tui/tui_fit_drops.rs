//! A drop-test fit in the explorer carries its assumption: the drops are taken in vacuum (no
//! drag correction, `Flight::vacuum()` in `tui::views::fit::state::request`, as `bouncelab
//! fit --drop-test` takes them without `--drag-coefficient`), and the fit pane says so, as the
//! command line's report says how it weighed the drops. A COR table's pane does not; a saved
//! session reads the drop-test fit back with its line.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::{App, Effect};
use bouncelab::tui::session::Session;
use bouncelab::tui::views::fit::state::{self as measured, FitRequest};
use std::path::Path;

use tui_common::*;

/// Three drops of a ball like the golf ball (e ≈ 0.83 at 3–6 m/s).
const DROPS: &str = "drop_height_m,rebound_height_m\n0.5,0.35\n1.0,0.69\n2,1.36\n";

const LINE: &str = "drops taken in vacuum (no drag correction) · weighed by their rebound readings";

/// The golf ball with `text` loaded as `name`, fitted (`f`, the worker's part run here), in
/// the sweeps view.
fn fitted(name: &str, text: &str) -> App {
    let mut app = App::new(Preset::embedded().remove(1), false);
    app.update(Action::MeasuredLoaded {
        path: name.into(),
        data: bouncelab::measured::parse_any(text).unwrap(),
    });
    app.update(Action::NextView);
    let r: FitRequest = match app.update(Action::Fit).as_slice() {
        [Effect::Fit(r)] => r.clone(),
        other => panic!("expected one fit effect, got {other:?}"),
    };
    app.update(Action::FitReady(r.id, measured::run(&r).into()));
    app
}

/// The drop-test fit's pane at 120×40 (snapshot) holds the line; a COR table's does not.
#[test]
fn a_drop_test_fit_says_its_drops_were_taken_in_vacuum() {
    let app = fitted("drops.csv", DROPS);
    assert!(app.fit_pane().unwrap().drops);
    let t = draw(&app, 120, 40);
    let s = screen_text(&t).join("\n");
    assert!(s.contains(LINE), "{s}");
    assert!(s.contains("residual RMS"), "{s}");
    insta::assert_snapshot!("fit_pane_drops", t.backend());
    let table = fitted("cannon.csv", "v0,cor\n10,0.72\n20,0.66\n30,0.62\n40,0.6\n");
    assert!(!table.fit_pane().unwrap().drops);
    let s = screen_text(&draw(&table, 120, 40)).join("\n");
    assert!(!s.contains("in vacuum"), "{s}");
}

/// A session saved with a drop-test fit reads back with the pane's line; one with a COR
/// table's fit has no `drops` key (the files earlier versions wrote read as before).
#[test]
fn the_drops_line_reads_back_from_a_session() {
    let a = fitted("drops.csv", DROPS);
    let text = a.session().to_toml();
    assert!(text.contains("drops = true"), "{text}");
    let read = Session::parse(Path::new("s.toml"), &text).unwrap();
    let b = App::new(Preset::embedded().remove(1), false)
        .with_session(&read)
        .unwrap();
    assert!(b.fit_pane().unwrap().drops);
    let s = screen_text(&draw(&b, 120, 40)).join("\n");
    assert!(s.contains(LINE), "{s}");
    let table = fitted("cannon.csv", "v0,cor\n10,0.72\n20,0.66\n30,0.62\n40,0.6\n");
    let text = table.session().to_toml();
    assert!(!text.contains("drops"), "{text}");
}
