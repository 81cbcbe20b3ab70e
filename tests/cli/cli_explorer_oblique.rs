//! `bouncelab --angle DEG --spin W --friction MU` (docs/explorer.md, the oblique view): the
//! explorer opened on its oblique view, each value checked before the terminal as `oblique`
//! checks it (one line naming the field, exit 2); the state itself through `with_oblique`.

use crate::common;
use crate::common::embedded;

use bouncelab::tui::app::{App, View};

#[test]
fn bad_values_are_refused_before_the_terminal() {
    for (args, why) in [
        (
            ["--angle", "95"],
            "invalid angle: 95 (must lie in (0, 90] degrees)",
        ),
        (["--angle", "0"], "invalid angle: 0"),
        (["--friction", "-0.1"], "invalid friction: -0.1"),
        (["--spin", "nan"], "spin"),
    ] {
        let mut all = vec!["--preset", "tennis"];
        all.extend(args);
        let o = common::bl(&all);
        assert_eq!(o.code, 2, "{args:?}: {}", o.stderr);
        let err = o.stderr.trim();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(why), "{why}: {err}");
    }
    // good values get as far as the terminal
    let o = common::bl(&["--preset", "tennis", "--angle", "30", "--spin", "-200"]);
    assert!(o.stderr.contains("needs a terminal"), "{}", o.stderr);
    // they are state options: --session restores the whole state
    let o = common::bl(&["--session", "x.toml", "--friction", "0.3"]);
    assert_eq!(o.code, 2, "{}", o.stderr);
}

#[test]
fn the_explorer_opens_on_the_oblique_view_at_those_values() {
    let tennis = embedded("tennis");
    let app = App::new(tennis, false)
        .with_oblique([Some(30.0), None, Some(0.3)])
        .unwrap();
    assert_eq!(app.view(), View::Oblique);
    let o = app.oblique_view();
    // spin left at the view's default
    assert_eq!(
        (o.values.angle, o.values.spin, o.values.friction),
        (30.0, 0.0, 0.3)
    );
    let r = o.response().unwrap();
    assert_eq!(r.angle_in_deg, 30.0);
    assert!(
        app.command_line()
            .contains("--angle 30 --spin 0 --friction 0.3"),
        "{}",
        app.command_line()
    );
}
