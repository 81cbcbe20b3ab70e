//! The pressure-loss fit recovers known leaks from noisy readings with honest intervals, and
//! says so when the readings do not follow the law.

use super::*;
use chacha20::ChaCha8Rng;
use chacha20::rand_core::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

const HOUR: f64 = 3600.0;

/// Readings every 6 h over 72 h of a ball inflated to `p0` leaking at `k`, each with Gaussian
/// noise of `sd` Pa (stated on every reading when `state_sd`).
fn readings(p0: f64, k: f64, sd: f64, seed: u64, state_sd: bool) -> Vec<PressureRow> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..=12)
        .map(|i| {
            let t = i as f64 * 6.0 * HOUR;
            let noise: f64 = StandardNormal.sample(&mut rng);
            PressureRow {
                time: t,
                gauge: p0 * (-k * t).exp() + sd * noise,
                sd: state_sd.then_some(sd),
                line: 0,
            }
        })
        .collect()
}

#[test]
fn exact_readings_give_the_leak_back() {
    let k = Leak::from_half_life(150.0 * HOUR).unwrap().rate;
    let fit = fit_pressure_loss(&readings(80_000.0, k, 0.0, 1, false)).unwrap();
    verdict::assert_recovered(fit.p0.value, 80_000.0, 1e-9);
    verdict::assert_recovered(fit.rate.value, k, 1e-7);
    assert!((fit.half_life[0] / (150.0 * HOUR) - 1.0).abs() < 1e-7);
}

/// Over 400 seeded lots of 13 readings (σ = 300 Pa, stated), the 95 % intervals of p₀ and k
/// hold the truth 95 % of the time: between 91 % and 98.5 % (the binomial's 99.9 % band for
/// 400 trials is ±3.6 %).
#[test]
fn intervals_cover_the_truth_at_their_level() {
    let (p0, k) = (80_000.0, Leak::losing(0.15, 72.0 * HOUR).unwrap().rate);
    let (mut hit_p, mut hit_k) = (0, 0);
    let trials = 400;
    for seed in 0..trials {
        let fit = fit_pressure_loss(&readings(p0, k, 300.0, seed, true)).unwrap();
        assert!(
            fit.no_answer.is_empty() || fit.lack_of_fit.is_some(),
            "{:?}",
            fit.no_answer
        );
        hit_p += usize::from(fit.p0.ci95[0] <= p0 && p0 <= fit.p0.ci95[1]);
        hit_k += usize::from(fit.rate.ci95[0] <= k && k <= fit.rate.ci95[1]);
    }
    let (cp, ck) = (hit_p as f64 / trials as f64, hit_k as f64 / trials as f64);
    assert!((0.91..=0.985).contains(&cp), "p0 coverage {cp}");
    assert!((0.91..=0.985).contains(&ck), "k coverage {ck}");
}

/// A ball that holds its pressure: k on its bound 0, the interval clipped at 0 and the
/// half-life's upper end infinite.
#[test]
fn a_sealed_ball_has_no_negative_leak() {
    let fit = fit_pressure_loss(&readings(80_000.0, 0.0, 200.0, 7, true)).unwrap();
    assert!(
        fit.no_answer.is_empty(),
        "a sealed ball is an answer: {:?}",
        fit.no_answer
    );
    assert!(fit.rate.value >= 0.0);
    assert_eq!(fit.rate.ci95[0].max(0.0), fit.rate.ci95[0]);
    assert!(fit.half_life[2].is_infinite() || fit.rate.ci95[0] > 0.0);
}

/// A ball whose valve let go at 36 h (a step, not a decay), read to 50 Pa: the law cannot
/// follow it, and the fit says so instead of giving a rate.
#[test]
fn readings_the_law_cannot_follow_are_refused() {
    let mut rs = readings(80_000.0, 0.0, 50.0, 3, true);
    for r in rs.iter_mut().filter(|r| r.time > 36.0 * HOUR) {
        r.gauge -= 30_000.0;
    }
    let fit = fit_pressure_loss(&rs).unwrap();
    let lof = fit.lack_of_fit.expect("χ² with stated deviations");
    assert!(lof.significant(), "{lof:?}");
    verdict::assert_refused_for_lack_of_fit(&fit.no_answer);
}

#[test]
fn bad_readings_are_refused_naming_the_row() {
    let one = [PressureRow {
        time: 0.0,
        gauge: 8e4,
        sd: None,
        line: 0,
    }];
    assert_eq!(
        fit_pressure_loss(&one).unwrap_err(),
        LeakFitError::TooFew(1)
    );
    let same_time = [one[0], one[0]];
    assert!(matches!(
        fit_pressure_loss(&same_time),
        Err(LeakFitError::TooFew(2))
    ));
    let neg = [
        one[0],
        PressureRow {
            time: -1.0,
            gauge: 7e4,
            sd: None,
            line: 0,
        },
    ];
    let e = fit_pressure_loss(&neg).unwrap_err().to_string();
    assert!(e.starts_with("reading 2: time"), "{e}");
    let sd0 = [
        one[0],
        PressureRow {
            time: 1.0,
            gauge: 7e4,
            sd: Some(0.0),
            line: 0,
        },
    ];
    assert!(
        fit_pressure_loss(&sd0)
            .unwrap_err()
            .to_string()
            .starts_with("reading 2: sd")
    );
}
