//! `shot --net DISTANCE[,HEIGHT]` and `mc --shot --net`, `mc --shot --after-bounce` (issue 57,
//! docs/cli.md `shot` and `mc`, docs/flight.md §6–7): the net's answer in text, JSON, CSV and
//! the SVG, the fraction of a Monte Carlo's shots that clear it, and a Monte Carlo's spread a
//! metre past each sample's bounce. Each fails on the old code (no such flags).

use crate::common;

const SERVE: &str =
    "shot --preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200 --friction 0.6";

fn json(line: &str) -> serde_json::Value {
    serde_json::from_str(&common::ok_calibrated(&common::argv(line))).expect("one JSON object")
}

/// The JSON's `net`: the serve of docs/flight.md §6 meets the net, at −5° it clears it; the
/// rest of the answer is the one without `--net`, key for key.
#[test]
fn the_json_says_whether_the_serve_clears_the_net() {
    let plain = json(&format!("{SERVE} --format json"));
    let low = json(&format!("{SERVE} --net 11.89 --format json"));
    let net = &low["net"];
    assert_eq!(
        (net["x"].as_f64(), net["height"].as_f64()),
        (Some(11.89), Some(0.914))
    );
    assert_eq!(net["cleared"], false);
    assert!(net["clearance"].as_f64().unwrap() < 0.0);
    assert_eq!(net["bounces_before"], 0);
    assert!(
        net["warnings"][0]
            .as_str()
            .unwrap()
            .contains("as if there were no net")
    );
    let mut without = low.clone();
    without.as_object_mut().unwrap().remove("net");
    assert_eq!(without, plain);
    let high = json(&format!(
        "{} --net 11.89,0.914 --format json",
        SERVE.replace("-6", "-5")
    ));
    assert_eq!(high["net"]["cleared"], true);
    assert_eq!(high["net"]["warnings"], serde_json::json!([]));
    // HEIGHT given: a higher net is met
    let tall = json(&format!(
        "{} --net 11.89,1.2 --format json",
        SERVE.replace("-6", "-5")
    ));
    assert_eq!(tall["net"]["cleared"], false);
}

/// CSV: the net's four columns after the shot's own, on every row; its warning on stderr
/// (it belongs to no row), as a time series' warnings are.
#[test]
fn the_csv_carries_the_net_and_its_warning_goes_to_stderr() {
    for extra in ["", "--samples 4"] {
        let line = format!("{SERVE} --net 11.89 --format csv {extra}");
        let o = common::bl(&common::argv(&line));
        assert_eq!(o.code, 0, "{}", o.stderr);
        let mut rows = o.stdout.lines();
        let head = rows.next().unwrap();
        assert!(
            head.ends_with(",net_x,net_height,net_clearance,net_cleared"),
            "{head}"
        );
        for row in rows {
            assert!(row.contains(",11.89,0.914,-0.0296"), "{row}");
            assert!(row.ends_with(",false"), "{row}");
        }
        assert!(
            o.stderr
                .lines()
                .any(|l| l.starts_with("bouncelab: warning: the ball meets the net at x = 11.89 m")),
            "{}",
            o.stderr
        );
    }
}

/// A trajectory's CSV (`--samples`) has no row for a bounce, so no cell for its warnings: they
/// go to stderr as the net's does, in the text's order (the serve's `outside calibration:
/// impact speed 9.585 m/s …` was in neither stdout nor stderr); one row per bounce keeps them
/// in its `warnings` column, not repeated on stderr.
#[test]
fn a_trajectory_csv_gives_the_bounces_warnings_on_stderr() {
    let text = common::bl(&common::argv(&format!("{SERVE} --net 11.89")));
    let said: Vec<&str> = (text.stdout.lines())
        .filter_map(|l| l.strip_prefix("warning: "))
        .collect();
    assert!(said[0].starts_with("outside calibration: impact speed 9.585 m/s"));
    assert_eq!(said.len(), 2, "{said:?}");
    let line = format!("{SERVE} --net 11.89 --samples 4 --format csv");
    let o = common::bl(&common::argv(&line));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let stderr: Vec<&str> = (o.stderr.lines())
        .filter_map(|l| l.strip_prefix("bouncelab: warning: "))
        .collect();
    assert_eq!(stderr, said);
    let rows = common::bl(&common::argv(&format!("{SERVE} --format csv")));
    assert!(rows.stdout.contains(said[0]), "{}", rows.stdout);
    assert_eq!(rows.stderr, "");
}

#[test]
fn the_svg_draws_the_net() {
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("serve.svg");
    let line = format!("{SERVE} --net 11.89 --svg-out {}", svg.display());
    common::ok_calibrated(&common::argv(&line));
    let text = std::fs::read_to_string(&svg).unwrap();
    roxmltree::Document::parse(&text).unwrap();
    assert!(
        text.contains("net (0.914 m; met)"),
        "the legend names the net"
    );
}

#[test]
fn a_net_without_a_distance_or_height_is_refused_by_name() {
    common::refused_each(
        &format!("{SERVE} --net"),
        &[
            ("0", "invalid --net: 0 (its distance must be positive)"),
            (
                "11.89,-1",
                "invalid --net: -1 (its height must be positive)",
            ),
            ("11.89,abc", "the net's height"),
            ("x", "the net's distance"),
        ],
    );
}

/// `mc --shot --net`: without spread every sample is the nominal shot, all in or all out;
/// with a spread of the elevation some clear it.
#[test]
fn mc_shot_gives_the_fraction_that_clears_the_net() {
    let mc = "mc --shot --preset tennis --height 2.8 --speed 50 --spin 200 --friction 0.6 \
              --net 11.89 --samples 100 --format json";
    for (elevation, fraction) in [("-6", 0.0), ("-5", 1.0)] {
        let j = json(&format!("{mc} --elevation {elevation} --vary speed=0"));
        assert_eq!(j["net"]["fraction"].as_f64(), Some(fraction), "{elevation}");
    }
    let j = json(&format!("{mc} --elevation -5.5 --vary elevation=0.5"));
    let f = j["net"]["fraction"].as_f64().unwrap();
    assert!(0.0 < f && f < 1.0, "{f}");
    let text = common::ok_calibrated(&common::argv(&format!(
        "{} --elevation -5.5 --vary elevation=0.5",
        mc.replace(" --format json", "")
    )));
    assert!(
        text.contains("net at x = 11.89 m, 0.914 m high: ") && text.contains("% clear it"),
        "{text}"
    );
}

/// `mc --shot --after-bounce 1`: without spread, the end is `shot --after-bounce 1`'s, its
/// height spread among the stats; refused as `shot`'s where it means nothing.
#[test]
fn mc_shot_spreads_where_the_ball_is_a_metre_past_its_bounce() {
    let shot = json(&format!(
        "{} --after-bounce 1 --format json",
        SERVE.replace("-6", "-5")
    ));
    let mc = json(
        "mc --shot --preset tennis --height 2.8 --speed 50 --elevation -5 --spin 200 \
         --friction 0.6 --after-bounce 1 --vary speed=0 --samples 20 --format json",
    );
    assert_eq!(mc["stats"]["end_x"]["q50"], shot["end"]["x"]);
    assert_eq!(mc["stats"]["end_y"]["q50"], shot["end"]["y"]);
    assert_eq!(mc["stats"]["end_t"]["q50"], shot["end"]["t"]);
    assert_eq!(mc["after_bounce"], 1.0);
    let o = common::bl(&common::argv(
        "mc --shot --preset tennis --height 2.8 --speed 50 --friction 0.6 --bounces 0 \
         --after-bounce 1 --vary speed=1%",
    ));
    assert_eq!(o.code, 2, "{}", o.stderr);
    assert!(
        o.stderr
            .contains("invalid --after-bounce: the shot makes no bounce")
    );
}
