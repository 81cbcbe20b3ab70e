//! `bouncelab fit --oblique FILE` through the binary (docs/oblique.md §9): the report and its
//! JSON keys, exit 1 for data that cannot pin what is fitted, exit 2 for a bad file.

use crate::common;
use bouncelab::Ball;
use bouncelab::model::contact::ContactLaw;
use bouncelab::oblique::{self, Oblique, mindlin_ratio};
use common::{argv_with, assert_bad, bl, f};
use serde_json::Value;

/// A CSV of the tennis ball's bounces under μ and Mindlin's K_t at (v0, angle, spin), v_x,out
/// perturbed by ±`noise` in a fixed pattern.
fn bounces(mu: f64, cases: &[(f64, f64, f64)], noise: f64) -> String {
    let ball = Ball::from_preset("tennis").unwrap();
    let kt = mindlin_ratio(0.5) * ball.params.k_p;
    let mut csv = String::from("v0,angle_deg,spin_in,vx_out,vy_out\n");
    for (i, &(v0, angle, spin)) in cases.iter().enumerate() {
        let o = Oblique::new(angle, spin, mu, kt, 0.6105, 0.0335).unwrap();
        let r = oblique::solve_law(&ball.params, ContactLaw::Linear, v0, &o, 0).unwrap();
        let e = noise * [1.0, -0.6, 0.3, -1.2, 0.8, -0.2, 0.5][i % 7];
        csv += &format!("{v0},{angle},{spin},{},{}\n", r.vx_out + e, r.vy_out);
    }
    csv
}

fn mixed() -> Vec<(f64, f64, f64)> {
    let angles = [8.0, 14.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0];
    let spins = [-150.0, 200.0];
    angles
        .iter()
        .flat_map(|&a| spins.map(|s| (20.0, a, s)))
        .collect()
}

fn write(text: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bounces.csv");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap().to_string();
    (dir, p)
}

#[test]
fn fit_oblique_recovers_friction_with_its_interval() {
    let (_dir, path) = write(&bounces(0.55, &mixed(), 0.02));
    let o = bl(&argv_with(
        "fit --preset tennis --oblique {} --format json",
        &[&path],
    ));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(v["data"], "oblique bounces");
    assert_eq!(
        v["free"],
        serde_json::json!(["friction", "tangential_stiffness"])
    );
    assert_eq!(v["identified"], true);
    let ci = &v["fitted"]["friction"]["ci95"];
    let (lo, hi) = (ci[0].as_f64().unwrap(), ci[1].as_f64().unwrap());
    assert!(lo <= 0.55 && 0.55 <= hi, "{ci}");
    let kt = mindlin_ratio(0.5) * Ball::from_preset("tennis").unwrap().params.k_p;
    let ci = &v["fitted"]["tangential_stiffness"]["ci95"];
    assert!(
        ci[0].as_f64().unwrap() <= kt && kt <= ci[1].as_f64().unwrap(),
        "{ci}"
    );
    assert!((f(&v, "friction") - 0.55).abs() < 0.01);
    assert!(f(&v, "rms_vy") < 1e-9, "the normal model made the data");
    for key in [
        "rms_vx",
        "rms_spin",
        "points",
        "converged",
        "correlation",
        "warnings",
    ] {
        assert!(v.get(key).is_some(), "{key}");
    }
    let text = bl(&["fit", "--preset", "tennis", "--oblique", &path]);
    assert_eq!(text.code, 0, "{}", text.stderr);
    assert!(text.stdout.contains("friction"), "{}", text.stdout);
    assert!(text.stdout.contains("answered                 yes") || text.stdout.contains("yes"));
}

#[test]
fn bounces_that_only_slide_answer_nothing_exit_1() {
    let cases: Vec<_> = [5.0, 7.0, 9.0, 11.0, 13.0]
        .map(|a| (25.0, a, -300.0))
        .to_vec();
    let (_dir, path) = write(&bounces(0.2, &cases, 0.01));
    let o = bl(&["fit", "--preset", "tennis", "--oblique", &path]);
    assert_eq!(o.code, 1, "{} {}", o.stdout, o.stderr);
    assert!(
        o.stdout.contains("friction"),
        "the report comes first: {}",
        o.stdout
    );
    assert_eq!(o.stderr.lines().count(), 1, "{}", o.stderr);
    assert!(
        o.stderr
            .contains("tangential_stiffness not pinned by the data"),
        "{}",
        o.stderr
    );
}

#[test]
fn a_bad_file_is_one_line_exit_2() {
    let (_dir, path) = write("v0,angle_deg,spin_in,vx_out,vy_out\n20,95,0,10,5\n");
    let o = bl(&["fit", "--preset", "tennis", "--oblique", &path]);
    assert_bad(&o, &[&format!("{path}:2:4"), "angle_deg"]);
    let (_dir, path) = write("v0,angle_deg,spin_in,vx_out\n20,30,0,10\n");
    assert_bad(
        &bl(&["fit", "--preset", "tennis", "--oblique", &path]),
        &["vy_out"],
    );
    let (_dir, path) = write(&bounces(0.5, &mixed(), 0.0));
    assert_bad(
        &bl(&argv_with(
            "fit --preset tennis --oblique {} --free k_r",
            &[&path],
        )),
        &["--oblique", "--free"],
    );
}

fn bounces_at(mu: f64, kt: f64, cases: &[(f64, f64, f64)]) -> String {
    let ball = Ball::from_preset("tennis").unwrap();
    let mut csv = String::from("v0,angle_deg,spin_in,vx_out,vy_out\n");
    for &(v0, angle, spin) in cases {
        let o = Oblique::new(angle, spin, mu, kt, 0.6105, 0.0335).unwrap();
        let r = oblique::solve_law(&ball.params, ContactLaw::Linear, v0, &o, 0).unwrap();
        csv += &format!("{v0},{angle},{spin},{},{}\n", r.vx_out, r.vy_out);
    }
    csv
}

/// Bounces the model meets to the last bit leave no scatter to estimate an interval from: the
/// report said `± 5e-17` and an interval `0.5500 … 0.5500`, where `fit --cor-table` says
/// "exact: no scatter" (tests/cli/cli_fit_reports.rs). The tennis ball's bounces at μ 0.55 and
/// Mindlin's K_t, written as the model gives them, fit to within 1.6e-15 m/s; written again at
/// the values that fit returns (the same model run on the fit's own bits), every residual is
/// zero.
#[test]
fn bounces_the_model_meets_exactly_leave_no_scatter() {
    let ball = Ball::from_preset("tennis").unwrap();
    let (mut mu, mut kt) = (0.55, mindlin_ratio(0.5) * ball.params.k_p);
    let mut csv = bounces_at(mu, kt, &mixed());
    for _ in 0..4 {
        let rows = bouncelab::measured::parse_oblique(&csv).unwrap();
        let r = ball
            .fit_oblique_watched(&rows, None, &bouncelab::analysis::work::Unwatched)
            .unwrap();
        if r.rms_vx == 0.0 {
            break;
        }
        (mu, kt) = (r.friction, r.tangential_stiffness);
        csv = bounces_at(mu, kt, &mixed());
    }
    let (_dir, path) = write(&csv);
    let args = ["fit", "--preset", "tennis", "--oblique", &path];
    let o = bl(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert_eq!(f(&v, "rms_vx"), 0.0, "no exact fixed point found: {v}");
    for name in ["friction", "tangential_stiffness"] {
        let e = &v["fitted"][name];
        assert!(e["std_error"].is_null(), "{name}: {v}");
        assert!(
            e["ci95"][0].is_null() && e["ci95"][1].is_null(),
            "{name}: {v}"
        );
    }
    assert_eq!(v["exact"], true, "{v}");
    assert_eq!(v["identified"], true, "the values are determined: {v}");
    assert!(
        v["warnings"][0]
            .as_str()
            .unwrap()
            .contains("no scatter to estimate"),
        "{v}"
    );
    let text = bl(&args);
    assert_eq!(text.code, 0, "{}", text.stderr);
    assert!(
        text.stdout
            .contains("exact: no scatter to estimate it from"),
        "{}",
        text.stdout
    );
    assert!(!text.stdout.contains("0.5500 … 0.5500"), "{}", text.stdout);
    assert!(
        text.stdout.contains("warning: the residuals are all zero"),
        "{}",
        text.stdout
    );
    // noisy bounces keep their intervals, and no `exact` key
    let (_dir, path) = write(&bounces(0.55, &mixed(), 0.02));
    let o = bl(&argv_with(
        "fit --preset tennis --oblique {} --format json",
        &[&path],
    ));
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    assert!(v.get("exact").is_none(), "{v}");
    assert!(f(&v["fitted"]["friction"], "std_error") > 0.0, "{v}");
}
