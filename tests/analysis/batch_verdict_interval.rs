//! A batch's ball carries its measured value's 95 % interval, and says when that interval
//! leaves its verdict open (src/api/batch.rs, docs/batch.md).

use bouncelab::Ball;
use bouncelab::analysis::fit::Param;
use bouncelab::api::BatchSetup;
use bouncelab::drop::standards;
use bouncelab::measured::parse_any;

/// One ball of `rebounds` (m), each dropped from the ITF's own 2.54 m, K_r fitted.
fn judged(rebounds: &[f64]) -> bouncelab::api::BallOutcome {
    let tennis = Ball::from_preset("tennis").unwrap();
    let free = [Param::KR];
    let setup = BatchSetup {
        standard: standards::find("itf").unwrap(),
        free: Some(&free),
        air: None,
        rebound_sd: None,
    };
    let rows: String = rebounds.iter().map(|r| format!("2.54,{r}\n")).collect();
    let data = parse_any(&format!("drop_height_m,rebound_height_m\n{rows}")).unwrap();
    tennis.judge_in_batch("B1", 2, &data, &setup)
}

/// Drops from the standard's own height: the verdict is on the readings themselves
/// (api::batch_reading), their mean and its Student interval, mean ± t₀.₉₇₅(n − 1) s/√n,
/// computed here by hand; the fitted ball's rebound (`model_measured`) is that mean to first
/// order (the fit averages the CORs √(R/H), not the heights, each drop weighed by its reading,
/// σ_e ∝ 1/√R, which shifts it at second order: here +1.7e-4 m against a half-width of
/// 0.033 m).
#[test]
fn drops_at_the_standards_height_give_the_readings_t_interval() {
    let r = [1.40, 1.42, 1.43, 1.45];
    let o = judged(&r);
    let ci = o
        .measured_ci95
        .expect("four drops, one parameter: three degrees of freedom");
    let n = r.len() as f64;
    let mean = r.iter().sum::<f64>() / n;
    let sd = (r.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    // t₀.₉₇₅(3) = 3.182446 (tables)
    let half = 3.182446 * sd / n.sqrt();
    let got = 0.5 * (ci[1] - ci[0]);
    assert!(
        (got - half).abs() < 0.01 * half,
        "{ci:?}: half-width {got} against {half}"
    );
    assert!(
        (0.5 * (ci[0] + ci[1]) - mean).abs() < 0.01 * half,
        "{ci:?} against {mean}"
    );
    assert_eq!(o.verdict, Some("PASS"));
    assert!(
        (o.model_measured.unwrap() - mean).abs() < 0.01 * half,
        "{o:?}"
    );
    assert!(
        o.warnings.iter().all(|w| !w.contains("not sure")),
        "{:?}",
        o.warnings
    );
}

/// Readings that straddle the window's upper bound, 1.47 m: the verdict stands (PASS: the
/// mean is inside) and a warning says the interval holds the bound; tight readings well
/// inside carry none. One drop has no interval (no degree of freedom left).
#[test]
fn a_verdict_the_interval_leaves_open_says_so() {
    let o = judged(&[1.44, 1.46, 1.48, 1.47]);
    let ci = o.measured_ci95.unwrap();
    assert!(ci[0] < 1.47 && 1.47 < ci[1], "{ci:?}");
    assert!(
        o.warnings
            .iter()
            .any(|w| w.contains("1.47 m") && w.contains("not sure")),
        "{:?}",
        o.warnings
    );
    let tight = judged(&[1.400, 1.401, 1.402]);
    assert!(
        tight.measured_ci95.is_some() && tight.warnings.iter().all(|w| !w.contains("not sure"))
    );
    assert_eq!(judged(&[1.41]).measured_ci95, None);
}
