//! A COR table whose every row states its standard deviation (`cor_sd`) is fitted with that
//! sd taken as known, as SciPy's `curve_fit(..., absolute_sigma=True)`: the covariance is
//! (JᵀJ)⁻¹ of the residuals divided by their sd, not rescaled by their scatter, and the 95 %
//! interval is exp(θ ± 1.96 s_θ) (docs/fitting.md). Before, the scatter rescaled it: CORs the
//! model met exactly gave no interval although the stated sds give one.

use crate::common;
use crate::seeded;
use common::argv_with;

use bouncelab::analysis::fit::{FitData, MultiFit, Param, fit};
use bouncelab::measured::CorPoint;
use bouncelab::model::contact::ContactLaw;
use bouncelab::solver::{SolveOptions, simulate};
use bouncelab::{Ball, ImpactParams};
use seeded::Seeded;

/// Speeds below the superball's flattening (z_m < z_p up to about 5.8 m/s): the COR is the
/// same at each, so K_r alone is fitted.
const SPEEDS: [f64; 5] = [1.0, 2.0, 3.0, 4.0, 5.0];
const SD: f64 = 0.01;

fn truth() -> ImpactParams {
    Ball::from_preset("superball").unwrap().params
}

fn cor(p: &ImpactParams, v0: f64) -> f64 {
    let p = ImpactParams { v0, ..*p };
    simulate(&p, ContactLaw::Linear, &SolveOptions::default())
        .unwrap()
        .cor
}

fn fitted(cors: &[f64]) -> MultiFit {
    let points: Vec<CorPoint> = SPEEDS
        .iter()
        .zip(cors)
        .map(|(&v0, &e)| CorPoint {
            cor_sd: Some(SD),
            ..CorPoint::new(v0, e)
        })
        .collect();
    // started away from the truth
    let start = ImpactParams {
        k_r: 4e4,
        ..truth()
    };
    fit(
        &start,
        ContactLaw::Linear,
        FitData::Cor(&points),
        &[Param::KR],
    )
    .unwrap()
}

/// s_θ of θ = ln K_r with known sds: 1/√(Σ J_i²), J_i = (∂e_i/∂θ)/σ, by central differences.
fn stated_s_theta(k_r: f64) -> f64 {
    let h: f64 = 1e-5;
    let at = |k: f64| ImpactParams { k_r: k, ..truth() };
    let sum: f64 = SPEEDS
        .iter()
        .map(|&v| {
            let d = (cor(&at(k_r * h.exp()), v) - cor(&at(k_r * (-h).exp()), v)) / (2.0 * h);
            (d / SD).powi(2)
        })
        .sum();
    1.0 / sum.sqrt()
}

/// CORs the model meets exactly (every row the truth's COR): no scatter, yet the stated sds
/// give the interval exp(θ ± 1.96 s_θ), s_θ from the Jacobian alone.
#[test]
fn stated_sds_give_an_interval_without_scatter() {
    let p = truth();
    let cors: Vec<f64> = SPEEDS.iter().map(|&v| cor(&p, v)).collect();
    let f = fitted(&cors);
    assert!(f.identified, "{:?}", f.warnings);
    assert!(!f.no_scatter && !f.exact(), "{:?}", f.warnings);
    let e = &f.fitted[0];
    assert!((e.value / p.k_r - 1.0).abs() < 1e-6, "{e:?}");
    let [lo, hi] = e.ci95;
    assert!(lo.is_finite() && hi.is_finite(), "no interval: {e:?}");
    let half = (hi / lo).ln() / 2.0;
    let want = 1.959_963_984_540_054 * stated_s_theta(e.value);
    assert!((half / want - 1.0).abs() < 1e-3, "{half} against {want}");
    assert!(
        !f.warnings.iter().any(|w| w.contains("no scatter")),
        "{:?}",
        f.warnings
    );
}

/// Over 400 seeded data sets (each COR the truth's plus a normal error of the stated sd), the
/// 95 % interval of K_r covers the truth 90–99 % of the time (95 % of 400 is 380 ± 4.4), and
/// its half-width is the stated sds', whatever the set's scatter.
#[test]
fn stated_sd_intervals_cover_the_truth() {
    let p = truth();
    let exact: Vec<f64> = SPEEDS.iter().map(|&v| cor(&p, v)).collect();
    let mut rng = Seeded::new(20261127);
    let sets = 400;
    let mut covered = 0;
    for _ in 0..sets {
        let cors: Vec<f64> = exact.iter().map(|e| e + SD * rng.normal()).collect();
        let f = fitted(&cors);
        let [lo, hi] = f.fitted[0].ci95;
        covered += usize::from(lo <= p.k_r && p.k_r <= hi);
        let half = (hi / lo).ln() / 2.0;
        let want = 1.959_963_984_540_054 * stated_s_theta(f.fitted[0].value);
        assert!((half / want - 1.0).abs() < 1e-3, "{half} against {want}");
    }
    println!("covered {covered} of {sets}");
    let share = covered as f64 / sets as f64;
    assert!(
        (0.90..=0.99).contains(&share),
        "covered {covered} of {sets}"
    );
}

/// The report says where its intervals' scale comes from when it is not the residuals': an
/// `rms residual 0` beside an interval read as a contradiction. Text: an `uncertainty` line;
/// JSON: `sd_stated: true` (present only then); a table without `cor_sd` has neither.
#[test]
fn the_report_says_the_sds_were_taken_as_known() {
    let dir = tempfile::tempdir().unwrap();
    let rows = "v0,cor,cor_sd\n1,0.75,0.01\n2,0.75,0.01\n3,0.75,0.01\n4,0.75,0.01\n";
    std::fs::write(dir.path().join("sd.csv"), rows).unwrap();
    std::fs::write(
        dir.path().join("no.csv"),
        "v0,cor\n1,0.75\n2,0.751\n3,0.749\n",
    )
    .unwrap();
    let fit = |file: &str, tail: &[&str]| {
        let args = argv_with("fit --preset superball --cor-table {} --free k_r", &[file]);
        common::ok_at(dir.path(), &[&args[..], tail].concat())
    };
    let text = fit("sd.csv", &[]);
    assert!(text.contains("  rms residual             0 (COR)\n  uncertainty              from each row's cor_sd, taken as known"), "{text}");
    assert!(!text.contains("exact"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&fit("sd.csv", &["--format", "json"])).unwrap();
    assert_eq!(json["sd_stated"], true, "{json}");
    assert!(json["fitted"]["k_r"]["ci95"][0].is_f64(), "{json}");
    assert!(!fit("no.csv", &[]).contains("uncertainty"));
    let json: serde_json::Value =
        serde_json::from_str(&fit("no.csv", &["--format", "json"])).unwrap();
    assert!(json.get("sd_stated").is_none(), "{json}");
    // drop tests name the option the user gave, not a column they never wrote
    let drops = common::ok_at(
        dir.path(),
        &common::argv(
            "fit --preset superball --drop-height 0.5 --rebound-height 0.4 \
            --drop-height 1 --rebound-height 0.78 --rebound-height-sd 0.003 --free k_r",
        ),
    );
    let from = "uncertainty              from the stated reading σ_R (--rebound-height-sd)";
    assert!(drops.contains(from), "{drops}");
}
