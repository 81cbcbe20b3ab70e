//! `bouncelab --measured FILE`: the explorer draws the user's data on the charts it belongs
//! to, labelled by the file name; a bad file is refused before the terminal is asked for.

use crate::common;
use crate::tui_common;

use bouncelab::figure::explorer::{Chart, MeasuredOverlay};
use bouncelab::measured::parse_any;
use bouncelab::preset::Preset;
use bouncelab::tui::app::App;
use bouncelab::tui::ui::figure;
use common::*;

#[test]
fn the_explorer_draws_measured_data_on_its_charts() {
    let ball = Preset::embedded().remove(0);
    let p = ball.params();
    let data = parse_any(&tui_common::half_sine_csv(300, 0.02)).unwrap();
    let overlays = MeasuredOverlay::from_data(&data, "plate.csv", p.mass, p.v0).unwrap();
    let app = App::new(ball, false).with_measured(overlays);
    for chart in [Chart::ForceTime, Chart::Hysteresis] {
        let fig = figure(&app, chart);
        let s = fig
            .series
            .iter()
            .find(|s| s.label == "plate.csv")
            .expect("the data are drawn");
        assert!(s.points.len() > 100);
        assert!(
            !fig.series
                .iter()
                .any(|s| s.label.contains("plate") && s.label.contains("Cross"))
        );
    }
    // drawn on a screen: the legend names the file
    let screen = tui_common::screen_text(&tui_common::draw(&app, 160, 48)).concat();
    assert!(screen.contains("plate.csv"), "the legend names the file");
    // on the force–time chart the pulse starts at t = 0
    let fig = figure(&app, Chart::ForceTime);
    let s = fig.series.iter().find(|s| s.label == "plate.csv").unwrap();
    let first = s.points.iter().find(|p| p.1 > 1.0).unwrap();
    assert!(first.0.abs() < 1e-4, "{first:?}");
    // a COR table goes on COR against speed, not on the impact's charts
    let cor = parse_any("v0,cor\n1,0.8\n2,0.75\n").unwrap();
    let ov = MeasuredOverlay::from_data(&cor, "cannon.csv", p.mass, p.v0).unwrap();
    assert_eq!(ov.len(), 1);
    assert_eq!(ov[0].chart, Chart::CorSpeed);
    assert_eq!(ov[0].points, vec![(1.0, 0.8), (2.0, 0.75)]);
}

#[test]
fn a_bad_measured_file_is_refused_before_the_terminal() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.csv"), "t,F\n0,zero\n").unwrap();
    assert_bad(
        &bl_at(dir.path(), &["--measured", "bad.csv"]),
        &["bad.csv:2:3: force 'zero' is not a number"],
    );
    std::fs::write(
        dir.path().join("good.csv"),
        tui_common::half_sine_csv(300, 0.02),
    )
    .unwrap();
    assert_bad(
        &bl_at(dir.path(), &["--measured", "good.csv"]),
        &["needs a terminal"],
    );
    assert_bad(
        &bl_at(dir.path(), &["--measured", "good.csv", "run"]),
        &["--measured before a subcommand"],
    );
}
