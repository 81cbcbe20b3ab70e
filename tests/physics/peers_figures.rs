//! `figure peers-cor-velocity` and `figure peers-force-time` (src/figure/peers.rs): SVG that
//! parses, and CSV series that say what docs/peers.md says.

use crate::common;
use common::{argv_with, bl, ok_calibrated};

fn series<'a>(csv: &'a str, id: &str) -> Vec<Vec<&'a str>> {
    csv.lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|f| f[0] == id)
        .collect()
}

/// `bouncelab FIGURE --out F.svg --csv-out F.csv` in a folder of its own: the SVG and the CSV
/// it wrote (stderr only the ball's calibration warnings, which figures now print).
fn svg_and_csv(figure: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let (svg, csv) = (dir.path().join("f.svg"), dir.path().join("f.csv"));
    let (s, c) = (svg.to_str().unwrap(), csv.to_str().unwrap());
    let line = format!("{figure} --out {{}} --csv-out {{}}");
    ok_calibrated(&argv_with(&line, &[s, c]));
    let read = |p| std::fs::read_to_string(p).unwrap();
    (read(svg), read(csv))
}

#[test]
fn peers_cor_velocity_flat_peers_falling_fixed_alpha() {
    let (svg, text) = svg_and_csv("figure peers-cor-velocity --preset superball");
    roxmltree::Document::parse(&svg).unwrap();
    assert_eq!(text.lines().next().unwrap(), "series,kind,v0,cor");
    for id in [
        "kelvin-voigt",
        "kelvin-voigt-no-tension",
        "tsuji",
        "hunt-crossley",
    ] {
        let rows = series(&text, id);
        assert_eq!(rows.len(), 200, "{id}");
        for r in &rows {
            let e: f64 = r[3].parse().unwrap();
            assert!((e - 0.75).abs() < 1e-9, "{id}: {e}");
        }
    }
    let fixed: Vec<f64> = series(&text, "hunt-crossley-fixed-alpha")
        .iter()
        .map(|r| r[3].parse().unwrap())
        .collect();
    assert!(fixed.windows(2).all(|w| w[1] < w[0]), "falls with speed");
    assert!(!series(&text, "christoforou-yigit").is_empty());
}

#[test]
fn peers_force_time_starts_and_ends_at_rest() {
    let (_, text) = svg_and_csv("figure peers-force-time --preset golf --points 50");
    for id in ["tsuji", "hunt-crossley", "kelvin-voigt-no-tension"] {
        let rows = series(&text, id);
        assert_eq!(rows.len(), 50, "{id}");
        // Hertz-type laws start from F = 0; the dashpot of Kelvin–Voigt jumps to η v0 at touch
        let first: f64 = rows[0][3].parse().unwrap();
        if id == "kelvin-voigt-no-tension" {
            assert!(first > 1.0, "{id}: {first}");
        } else {
            assert_eq!(first, 0.0, "{id}");
        }
        let last: f64 = rows[49][3].parse().unwrap();
        assert!(last.abs() < 1e-9, "{id} ends at F = 0: {last}");
    }
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("b.svg");
    let o = bl(&argv_with(
        "figure peers-force-time --preset golf --from 1 --out {}",
        &[svg.to_str().unwrap()],
    ));
    assert_eq!(o.code, 2, "{}", o.stderr);
}

/// The figures' target follows `peers`: a ball an override changed is not the measured one,
/// so its peers are calibrated to the Christoforou–Yigit COR of the ball as run (the tennis
/// ball with K_p 60 000 N/m drew its peers flat at the 0.7709 measured with 49 427 N/m).
#[test]
fn the_figures_target_a_changed_ball_s_own_cor() {
    let (_, text) = svg_and_csv("figure peers-cor-velocity --preset tennis --k-p 60000");
    let run = common::json(&common::argv(
        "run --preset tennis --k-p 60000 --format json",
    ));
    let own = run["cor"].as_f64().unwrap();
    assert!(
        (own - 0.7709).abs() > 1e-3,
        "the override moves the COR: {own}"
    );
    let rows = series(&text, "tsuji");
    let e: f64 = rows[0][3].parse().unwrap();
    assert!(
        (e - own).abs() < 1e-9,
        "tsuji flat at {e}, the ball's COR {own}"
    );
}
