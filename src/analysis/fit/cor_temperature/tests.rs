//! The COR-temperature fit recovers a known shift from noisy data with honest intervals, and
//! says so when the data do not follow the law.

use super::*;
use chacha20::ChaCha8Rng;
use chacha20::rand_core::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

/// The superball's parameters (presets/superball.toml: m = 37.4 g, K_p = 5.45e4 N/m,
/// c = 140 kg/s, K_r = 7.08e4 N/m, z_p = 4 mm, v0 = 3.12 m/s): the springs the fit keeps.
fn ball() -> ImpactParams {
    crate::preset::Preset::embedded()
        .into_iter()
        .find(|p| p.name == "superball")
        .unwrap()
        .params()
}

const C_REF: f64 = 90.0;
const E_A: f64 = 40_000.0;
const T_REF: f64 = 23.0;

/// CORs at 0 … 45 °C and two speeds by the law with (C_REF, E_A), plus Gaussian noise `sd`.
fn data(sd: f64, seed: u64, state_sd: bool) -> Vec<CorTemperatureRow> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut points = Vec::new();
    for t in [0.0, 10.0, 23.0, 35.0, 45.0] {
        for v0 in [2.0, 4.0] {
            let c = shifted_damping(C_REF, E_A, T_REF, t);
            let p = ImpactParams {
                damping: c,
                v0,
                ..ball()
            };
            let e = simulate(&p, ContactLaw::Linear, &SolveOptions::default())
                .unwrap()
                .cor;
            let noise: f64 = StandardNormal.sample(&mut rng);
            points.push(CorTemperatureRow {
                temperature_c: t,
                v0,
                cor: e + sd * noise,
                sd: state_sd.then_some(sd),
                line: 0,
            });
        }
    }
    points
}

/// The closed form of the shift: at T_ref nothing moves; 10 K warmer at E_a = 40 kJ/mol,
/// exp[(40 000/8.314 462 618)(1/306.15 − 1/296.15)] = 0.588 24.
#[test]
fn the_arrhenius_shift() {
    assert_eq!(shifted_damping(90.0, E_A, 23.0, 23.0), 90.0);
    let a = shifted_damping(1.0, E_A, 23.0, 33.0);
    let expected = (40_000.0_f64 / 8.314_462_618 * (1.0 / 306.15 - 1.0 / 296.15)).exp();
    assert!((a - expected).abs() < 1e-15);
    assert!((a - 0.588_24).abs() < 1e-5, "{a}");
}

#[test]
fn exact_data_give_the_shift_back() {
    let fit =
        fit_cor_temperature(&ball(), ContactLaw::Linear, T_REF, &data(0.0, 1, false)).unwrap();
    verdict::assert_recovered(fit.c_ref.value, C_REF, 1e-5);
    verdict::assert_recovered(fit.activation.value, E_A, 1e-4);
    assert!(fit.no_answer.is_empty(), "{:?}", fit.no_answer);
}

/// Noisy data: the truth inside the 95 % intervals in most lots (binomial: 40 lots at 95 %
/// coverage miss 2 on average; more than 6 misses has probability below 1 %), and the
/// intervals stated.
#[test]
fn noisy_data_recover_the_shift_with_honest_intervals() {
    let mut missed = [0, 0];
    for seed in 0..40 {
        let fit = fit_cor_temperature(&ball(), ContactLaw::Linear, T_REF, &data(0.004, seed, true))
            .unwrap();
        assert!(fit.no_answer.is_empty(), "seed {seed}: {:?}", fit.no_answer);
        let [lo, hi] = fit.c_ref.ci95;
        missed[0] += usize::from(!(lo..=hi).contains(&C_REF));
        let [lo, hi] = fit.activation.ci95;
        missed[1] += usize::from(!(lo..=hi).contains(&E_A));
    }
    assert!(missed[0] <= 6 && missed[1] <= 6, "{missed:?}");
}

/// CORs that rise and fall twice over temperature cannot come from one Arrhenius shift: the
/// χ² test against their stated deviations says so, and the fit gives no answer.
#[test]
fn data_the_law_cannot_follow_are_refused() {
    let zigzag = [0.5, 0.8, 0.5, 0.8, 0.5, 0.8];
    let points: Vec<CorTemperatureRow> = zigzag
        .iter()
        .enumerate()
        .map(|(i, &cor)| CorTemperatureRow {
            temperature_c: 5.0 * i as f64,
            v0: 3.0,
            cor,
            sd: Some(0.005),
            line: 0,
        })
        .collect();
    let fit = fit_cor_temperature(&ball(), ContactLaw::Linear, T_REF, &points).unwrap();
    verdict::assert_refused_for_lack_of_fit(&fit.no_answer);
}

#[test]
fn bad_points_are_named() {
    let mut p = data(0.0, 1, false);
    p[2].cor = 1.5;
    let e = fit_cor_temperature(&ball(), ContactLaw::Linear, T_REF, &p).unwrap_err();
    assert_eq!(e.to_string(), "point 3: cor must lie in [0, 1]");
    let one_t: Vec<CorTemperatureRow> = data(0.0, 1, false)
        .into_iter()
        .filter(|p| p.temperature_c == 23.0)
        .collect();
    assert!(matches!(
        fit_cor_temperature(&ball(), ContactLaw::Linear, T_REF, &one_t),
        Err(CorTemperatureError::TooFew(2))
    ));
}
