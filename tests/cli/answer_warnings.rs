//! Warnings travel with the answer (issue 27, item 6): an indentation beyond the ball's radius
//! is said in run, sweep velocity, drop, peers, collide, bat, oblique and court (JSON
//! `warnings`, a `warning:` line in text, a `warnings` column in CSV rows, stderr beside a CSV
//! time series), and the explorer's readout no longer says "no flattening (z_m < z_p)" under the Hertz law,
//! which never flattens.

use crate::common;
use crate::tui_common;

use bouncelab::tui::app::App;
use common::*;
use ratatui::crossterm::event::KeyCode;
use tui_common::*;

const BEYOND: &str = "exceeds the ball's radius";

/// The warnings this file is about are the radius's: the "outside calibration:" warnings
/// (issue 52; tests/cli/calibration.rs) that the same answers now carry are taken out here.
fn json(args: &[&str]) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                for (k, x) in m.iter_mut() {
                    if let (true, Some(a)) = (k.as_str() == "warnings", x.as_array_mut()) {
                        a.retain(|w| {
                            !w.as_str()
                                .is_some_and(|w| w.contains("outside calibration:"))
                        });
                    }
                    strip(x);
                }
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v = common::json(args);
    strip(&mut v);
    v
}

/// Text without its "outside calibration:" lines (see [`json`]).
fn ok(args: &[&str]) -> String {
    common::ok(args)
        .lines()
        .filter(|l| !l.contains("warning: outside calibration:"))
        .map(|l| format!("{l}\n"))
        .collect()
}

/// The superball dropped 100 m without air: it meets the plate at 44 m/s, and its first
/// impact passes its radius.
const DROP_100_M: [&str; 6] = [
    "drop",
    "--preset",
    "superball",
    "--height",
    "100",
    "--no-drag",
];

/// `run --preset superball --v0 45` reported a peak indentation of 31 mm on a ball of
/// 21.6 mm radius without a word.
#[test]
fn run_says_when_the_indentation_passes_the_radius() {
    let v = json(&argv("run --preset superball --v0 45 --format json"));
    let w = v["warnings"].as_array().expect("a warnings array");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].as_str()
            .unwrap()
            .contains("31.05 mm exceeds the ball's radius 21.55 mm")
    );
    let text = ok(&["run", "--preset", "superball", "--v0", "45"]);
    assert!(
        text.contains(&format!("warning: peak indentation 31.05 mm {BEYOND}")),
        "{text}"
    );
    // at the measured speed nothing to say, and the key is still there
    let v = json(&["run", "--preset", "superball", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
    assert!(!ok(&["run", "--preset", "superball"]).contains("warning:"));
}

#[test]
fn sweep_rows_drop_and_peers_carry_their_warnings() {
    let v = json(&argv(
        "sweep velocity --preset superball --from 5 --to 45 --points 3 --format json",
    ));
    let rows = v["rows"].as_array().unwrap();
    // z_m grows with v0: 3.45 mm at 5 m/s, 31 mm at 45
    assert_eq!(rows[0]["warnings"], serde_json::json!([]));
    assert!(rows[0]["max_indentation"].as_f64().unwrap() > 0.0);
    assert!(rows[2]["warnings"][0].as_str().unwrap().contains(BEYOND));
    // a drop from 100 m without air meets the plate at 44 m/s: the superball's first impact
    // passes R
    let v = json(&[&DROP_100_M[..], &["--format", "json"]].concat());
    assert!(
        v["warnings"][0].as_str().unwrap().contains(BEYOND),
        "{}",
        v["warnings"]
    );
    let v = json(&["drop", "--preset", "tennis", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
    let v = json(&argv("peers --preset superball --v0 45 --format json"));
    assert!(v["warnings"][0].as_str().unwrap().contains(BEYOND));
    let v = json(&["peers", "--preset", "superball", "--format", "json"]);
    assert_eq!(v["warnings"], serde_json::json!([]));
}

/// The explorer under the Hertz law said "no flattening (z_m < z_p)" with z_m 11 mm > z_p
/// 6 mm (tennis, football, basketball, softball).
#[test]
fn the_readout_does_not_claim_z_m_below_z_p_under_hertz() {
    let tennis = embedded("tennis");
    let mut app = App::new(tennis, true);
    // c cycles the law: linear → elastic–plastic → Hertz
    while !screen_text(&draw(&app, 120, 40))
        .concat()
        .contains("law hertz")
    {
        press(&mut app, &[KeyCode::Char('c')]);
    }
    let screen = screen_text(&draw(&app, 120, 40)).join("\n");
    assert!(!screen.contains("no flattening (z_m < z_p)"), "{screen}");
    assert!(
        screen.contains("Hertz: elastic, never flattens"),
        "{screen}"
    );
}

/// The commands that said nothing of an indentation past the radius: `collide`, `bat`,
/// `oblique` and `court` (no `warnings` key, no line), and every CSV (`run`, `sweep velocity`
/// and `oblique` rows had no column for it; the time series of `run --history`, `oblique
/// --history` and `drop` say it on stderr). A table-tennis ball at 100 m/s flattens 23 mm on
/// a radius of 20 mm; softened to K_p = 200 N/m, 30 m/s at 16° (the court test) too.
#[test]
fn every_answer_and_every_format_carries_the_radius_warning() {
    let tt = ["--preset", "table-tennis", "--v0", "100"];
    // each command past the radius, then within it (the same command at the ball's own pace)
    let answers: [(&[&str], &[&str], &[&str]); 4] = [
        (&["collide", "--target-mass", "1"], &tt, &tt[..2]),
        (
            &["bat", "--bat-mass", "0.8"],
            &["--preset", "table-tennis", "--ball-speed", "100"],
            &argv("--preset table-tennis --ball-speed 10 --bat-speed 5"),
        ),
        (
            &["oblique", "--angle", "80", "--friction", "0.5"],
            &tt,
            &tt[..2],
        ),
        (
            &["court", "--friction", "0.5"],
            &["--preset", "table-tennis", "--k-p", "200"],
            &tt[..2],
        ),
    ];
    for (cmd, past, within) in answers {
        let args = [cmd, past].concat();
        let v = json(&[&args[..], &["--format", "json"]].concat());
        let w = v["warnings"]
            .as_array()
            .unwrap_or_else(|| panic!("{cmd:?}: {v}"));
        assert!(
            w.iter().any(|w| w.as_str().unwrap().contains(BEYOND)),
            "{cmd:?}: {w:?}"
        );
        let text = ok(&args);
        assert!(
            text.contains("\nwarning: ") && text.contains(BEYOND),
            "{cmd:?}"
        );
        let args = [cmd, within].concat();
        let v = json(&[&args[..], &["--format", "json"]].concat());
        // `bat` with another ball than the BBCOR standard's says so: not the reach
        let other_ball = |w: &str| w.starts_with("not the standard's ball:");
        let mut w = warnings(&v);
        w.retain(|w| !other_ball(w));
        assert!(w.is_empty(), "{cmd:?} within the radius: {w:?}");
        let text = ok(&args);
        let warned = text
            .lines()
            .filter_map(|l| l.strip_prefix("warning: "))
            .any(|w| !other_ball(w));
        assert!(!warned, "{cmd:?} within the radius");
    }
    // the CSV rows: a `warnings` column (before the surface's and the conditions' columns)
    let oblique = argv("oblique --angle 80 --friction 0.5 --format csv");
    let rows: [&[&str]; 3] = [
        &["run", "--format", "csv"],
        &argv("sweep velocity --from 90 --to 100 --points 2"),
        &oblique,
    ];
    for cmd in rows {
        let args = [cmd, &tt].concat();
        let csv = ok(&args);
        let mut lines = csv.lines();
        let head = lines.next().unwrap();
        assert!(head.split(',').any(|c| c == "warnings"), "{cmd:?}: {head}");
        let last = lines.last().unwrap();
        assert!(last.contains(BEYOND), "{cmd:?}: {last}");
    }
    // the time series: stderr, the series itself unchanged
    let oblique_series = [&oblique[..], &["--history"]].concat();
    let drop = [&DROP_100_M[..], &["--format", "csv"]].concat();
    let series: [&[&str]; 3] = [
        &["run", "--format", "csv", "--history"],
        &oblique_series,
        &drop,
    ];
    for cmd in series {
        let ball: &[&str] = if cmd[0] == "drop" { &[] } else { &tt };
        let args = [cmd, ball].concat();
        let o = bl(&args);
        assert_eq!(o.code, 0, "{cmd:?}: {}", o.stderr);
        assert!(
            o.stderr.starts_with("bouncelab: warning: peak indentation"),
            "{cmd:?}"
        );
        assert!(o.stderr.contains(BEYOND), "{cmd:?}: {}", o.stderr);
        assert!(o.stdout.starts_with("t,"), "{cmd:?}");
    }
}

/// `map` said nothing of cells past the radius. Its warning counts the cells whose peak
/// indentation (from each cell's peak force through the shared loading branch) passes R,
/// and `run` at each cell, another path, must agree on the count and the deepest.
#[test]
fn map_counts_the_cells_past_the_radius_as_run_finds_them() {
    for law in ["linear", "hertz", "elastic-plastic"] {
        let base = ["--preset", "superball", "--law", law, "--v0", "45"];
        let axes = ["--lambda", "0.1:10:3", "--zeta", "0.01:1:3"];
        let v = json(&[&["map"][..], &base, &axes, &["--format", "json"]].concat());
        let (mut past, mut deepest, mut centre) = (0, 0.0f64, 0);
        for row in v["rows"].as_array().unwrap() {
            let (l, z) = (
                row[0].as_f64().unwrap().to_string(),
                row[1].as_f64().unwrap().to_string(),
            );
            let r = json(
                &[
                    &["run"][..],
                    &base,
                    &["--lambda", &l, "--zeta", &z, "--format", "json"],
                ]
                .concat(),
            );
            let z_m = f(&r, "max_indentation");
            if z_m > 0.02155 {
                past += 1;
                deepest = deepest.max(z_m);
            }
            // the ball's centre past R by itself (tests/cli/answer_reach.rs): run says it too
            let warned = r["warnings"].as_array().unwrap().iter();
            centre += warned
                .filter(|w| w.as_str().unwrap().starts_with("peak displacement"))
                .count();
        }
        let w = v["warnings"].as_array().unwrap();
        assert!(
            past > 0 && past < 9,
            "{law}: the grid should straddle R ({past} of 9)"
        );
        let indentation =
            |w: &&serde_json::Value| w.as_str().unwrap().starts_with("peak indentation");
        let (z, alpha): (Vec<_>, Vec<_>) = w.iter().partition(indentation);
        assert_eq!(z.len(), 1, "{law}: {w:?}");
        assert_eq!(alpha.len(), usize::from(centre > 0), "{law}: {w:?}");
        if let Some(a) = alpha.first() {
            let counts = format!("in {} of 9 cells, {centre} of them", past + centre);
            assert!(
                a.as_str().unwrap().contains(&counts),
                "{law}: {a} against {counts}"
            );
        }
        let said = z[0].as_str().unwrap();
        assert!(
            said.contains(&format!("in {past} of 9 cells")),
            "{law}: {said}"
        );
        let up_to = format!("up to {} mm", bouncelab::text::sig(deepest * 1e3, 4));
        assert!(said.contains(&up_to), "{law}: {said} against {up_to}");
        // the CSV says it on stderr
        let o = bl(&[&["map"][..], &base, &axes].concat());
        assert!(
            o.stderr.contains(&format!("in {past} of 9 cells")),
            "{law}: {}",
            o.stderr
        );
    }
    let calm = json(&argv(
        "map --preset superball --format json --lambda 0.1:10:3 --zeta 0.01:1:3",
    ));
    assert_eq!(calm["warnings"], serde_json::json!([]));
}

/// `mc` warned only of its quantiles' intervals; a Monte Carlo around a ball pressed past
/// its radius now says so, at the nominal parameters (the samples' indentations are not
/// kept), in JSON and text, first.
#[test]
fn mc_says_when_its_nominal_ball_passes_the_radius() {
    let args = argv("mc --preset table-tennis --v0 100 --vary k_p=5% --samples 400 --seed 1");
    // this file's `json` and `ok`, which take out the calibration warnings (not the shared
    // `common::assert_warns_once_in_json_and_text`, which counts them)
    let v = json(&[&args[..], &["--format", "json"]].concat());
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1, "{w:?}");
    let said = w[0].as_str().unwrap();
    assert!(
        said.starts_with("at the nominal parameters: peak indentation 23.13 mm"),
        "{said}"
    );
    assert!(ok(&args).contains(&format!("warning: {said}")));
    let calm = json(&argv(
        "mc --preset table-tennis --vary k_p=5% --samples 400 --seed 1 --format json",
    ));
    assert_eq!(calm["warnings"], serde_json::json!([]));
}
