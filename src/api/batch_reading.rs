//! A batch ball's verdict from its own measurement (docs/batch.md, "The verdict from the
//! measurement"): where the ball was tested at the standard's own condition — dropped from the
//! standard's release height, or fired at its speed — what the standard measures was read
//! off the ball itself, and the verdict is on that reading, whether or not the model can be
//! fitted to the ball. Six balls of a 40-ball lot that rebound to 1.20–1.30 m from 2.54 m
//! (out of the tennis preset's reach with K_r free) once had no verdict and fell out of the
//! lot's Cpk (issue 52 item 9; tests/cli/cli_batch_readings.rs).
//!
//! The value is the mean of the readings at the standard's condition, its 95 % interval
//! from their uncertainty: a stated one (`--rebound-height-sd` σ_R for drops, a COR table's
//! `cor_sd`) taken as known, x̄ ± z₀.₉₇₅ σ_x̄ with σ_x̄ = (Σ 1/σᵢ²)^(−½) and x̄ the
//! inverse-variance weighted mean; unknown, Student's t over the readings' scatter
//! (x̄ ± t₀.₉₇₅(n − 1) s/√n, none for one reading), as the fit's intervals do
//! (docs/fitting.md, "Stated standard deviations").

use super::{Ball, BatchSetup};
use crate::analysis::batch::mean_interval;
use crate::drop::standards::Test;
use crate::measured::{Data, Flight};
use statrs::distribution::{ContinuousCDF, Normal};

/// A drop counts as made from the standard's release height within this (m): a tape
/// measure's millimetre, the precision docs/fitting.md takes drop heights to.
pub const HEIGHT_TOLERANCE: f64 = 1e-3;
/// A COR counts as measured at the standard's speed within this share of it (1 %: 60 mph
/// ± 0.6 mph, finer than the ±1 mph ASTM F1887 allows its cannon).
pub const SPEED_TOLERANCE: f64 = 0.01;

/// What the standard measures, read off the ball at the standard's condition.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The mean reading (m in the standard's convention, or a COR).
    pub value: f64,
    /// Its 95 % interval (`None`: one reading and no stated uncertainty).
    pub ci95: Option<[f64; 2]>,
    /// How many readings were at the standard's condition.
    pub count: usize,
    /// The measured COR at the standard's impact speed (a drop reading's through the flight
    /// of the ball in the batch's air).
    pub cor: f64,
}

/// The ball's reading at `setup.standard`'s condition, `None` where none of its data were
/// taken there (a trace; drops from another height; CORs at other speeds) or the ball lacks
/// what the standard's convention needs (a radius for heights read at the top).
pub fn reading(ball: &Ball, data: &Data, setup: &BatchSetup<'_>) -> Option<Reading> {
    let s = setup.standard;
    match (s.test, data) {
        (Test::Drop { rebound_ref, .. }, Data::Drop(d)) => {
            let dball = ball.drop_ball();
            let h = s.release_height(dball.radius).filter(|h| h.is_finite())?;
            let offset = rebound_ref.offset(dball.radius);
            let rebounds: Vec<f64> = d
                .drops
                .iter()
                .filter(|x| (x.0 - h).abs() <= HEIGHT_TOLERANCE)
                .map(|x| x.1)
                .collect();
            let sds = vec![setup.rebound_sd; rebounds.len()];
            let (mean, ci95) = mean_of(&rebounds, &sds)?;
            let flight = Flight::new(dball.params.mass, dball.radius, setup.air);
            let cor = crate::measured::drop_to_cor(h, mean, &flight).1;
            let ci95 = ci95.map(|[lo, hi]| [(lo + offset).max(offset), hi + offset]);
            Some(Reading {
                value: mean + offset,
                ci95,
                count: rebounds.len(),
                cor,
            })
        }
        (Test::Cor { speed }, Data::Cor(_) | Data::Drop(_)) => {
            let points = match data {
                Data::Cor(t) => t.points.clone(),
                Data::Drop(d) => {
                    let pairs: Vec<(f64, f64)> = d.drops.iter().map(|d| (d.0, d.1)).collect();
                    ball.drops_to_cor_read(&pairs, setup.air, setup.rebound_sd)
                        .ok()?
                }
                Data::Trace(_) => return None,
            };
            let at: Vec<_> = points
                .iter()
                .filter(|p| (p.v0 - speed).abs() <= SPEED_TOLERANCE * speed)
                .collect();
            let cors: Vec<f64> = at.iter().map(|p| p.cor).collect();
            let sds: Vec<Option<f64>> = at.iter().map(|p| p.cor_sd).collect();
            let (mean, ci95) = mean_of(&cors, &sds)?;
            Some(Reading {
                value: mean,
                ci95: ci95.map(|[lo, hi]| [lo.max(0.0), hi.min(1.0)]),
                count: cors.len(),
                cor: mean,
            })
        }
        _ => None,
    }
}

/// The mean of `x` and its 95 % interval (see the module comment): every `sd` stated, the
/// inverse-variance weighted mean and the normal quantile; else the plain mean and Student's
/// t (none below two values). `None` for no values.
pub fn mean_of(x: &[f64], sd: &[Option<f64>]) -> Option<(f64, Option<[f64; 2]>)> {
    if x.is_empty() {
        return None;
    }
    let n = x.len();
    if let Some(sd) = sd.iter().copied().collect::<Option<Vec<f64>>>() {
        let w: Vec<f64> = sd.iter().map(|s| 1.0 / (s * s)).collect();
        let sum_w: f64 = w.iter().sum();
        let mean = x.iter().zip(&w).map(|(x, w)| x * w).sum::<f64>() / sum_w;
        let half = Normal::standard().inverse_cdf(0.975) / sum_w.sqrt();
        return Some((mean, Some([mean - half, mean + half])));
    }
    let mean = x.iter().sum::<f64>() / n as f64;
    if n < 2 {
        return Some((mean, None));
    }
    let s = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
    let (_, ci) = mean_interval(n, mean, s);
    Some((mean, Some(ci)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two readings 1.43 and 1.44: x̄ 1.435, s/√2 = 0.005, t₀.₉₇₅(1) = 12.706.
    #[test]
    fn student_without_a_stated_sd_normal_with_one() {
        let (m, ci) = mean_of(&[1.43, 1.44], &[None, None]).unwrap();
        let ci = ci.unwrap();
        assert!((m - 1.435).abs() < 1e-12);
        assert!((ci[1] - m - 12.706_2 * 0.005).abs() < 1e-4, "{ci:?}");
        let (m, ci) = mean_of(&[1.43, 1.44], &[Some(0.01), Some(0.01)]).unwrap();
        let half = ci.unwrap()[1] - m;
        assert!(
            (half - 1.959_964 * 0.01 / 2f64.sqrt()).abs() < 1e-6,
            "{half}"
        );
        // weighted: the precise reading pulls the mean
        let (m, _) = mean_of(&[1.0, 2.0], &[Some(0.1), Some(0.2)]).unwrap();
        assert!((m - (1.0 * 100.0 + 2.0 * 25.0) / 125.0).abs() < 1e-12);
        assert_eq!(mean_of(&[1.4], &[None]), Some((1.4, None)));
        assert_eq!(mean_of(&[], &[]), None);
    }
}
