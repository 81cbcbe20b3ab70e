//! Sweeps: COR, normalized peak force and contact time against ζ for several λ (Figs. 2–3),
//! and COR against impact speed for one ball (Fig. 4).

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::SolveError;
use crate::solver::{SolveOptions, simulate};
use rayon::prelude::*;
use serde::Serialize;

/// `n` points from `from` to `to`, evenly spaced in log10 (both ends included).
pub fn log_space(from: f64, to: f64, n: usize) -> Vec<f64> {
    let (a, b) = (from.log10(), to.log10());
    (0..n)
        .map(|i| {
            if n > 1 {
                10f64.powf(a + (b - a) * i as f64 / (n - 1) as f64)
            } else {
                from
            }
        })
        .collect()
}

/// `n` points from `from` to `to`, evenly spaced (both ends included).
pub fn lin_space(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if n > 1 {
                from + (to - from) * i as f64 / (n - 1) as f64
            } else {
                from
            }
        })
        .collect()
}

/// One point of a ζ sweep, normalized (m = K_p = v0 = 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ZetaPoint {
    /// λ = K_r/K_p.
    pub lambda: f64,
    /// ζ = √(m K_p)/(2c).
    pub zeta: f64,
    /// Coefficient of restitution e (0 when the ball does not rebound).
    pub cor: f64,
    /// Peak force F̄_m = F_m/(m v0 ω0).
    pub max_force_normalized: f64,
    /// τ_f; `None` when there is no rebound.
    pub contact_time_normalized: Option<f64>,
}

/// COR, F̄_m and τ_f against ζ for each λ (Figs. 2, 3), below flattening. Rows are grouped by
/// λ in the order given. The points are independent, so they run on all cores.
pub fn cor_vs_zeta(
    lambdas: &[f64],
    zetas: &[f64],
    law: ContactLaw,
) -> Result<Vec<ZetaPoint>, SolveError> {
    let grid: Vec<(f64, f64)> = lambdas
        .iter()
        .flat_map(|&l| zetas.iter().map(move |&z| (l, z)))
        .collect();
    grid.par_iter()
        .map(|&(lambda, zeta)| {
            let r =
                crate::solver::simulate_normalized(lambda, zeta, law, &SolveOptions::default())?;
            Ok(ZetaPoint {
                lambda,
                zeta,
                cor: r.cor,
                max_force_normalized: r.max_force_normalized,
                contact_time_normalized: r.contact_time_normalized,
            })
        })
        .collect()
}

/// One point of a speed sweep, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VelocityPoint {
    /// Impact speed, m/s.
    pub v0: f64,
    /// Coefficient of restitution e (0 when the ball does not rebound).
    pub cor: f64,
    /// Peak force, N.
    pub max_force: f64,
    /// Contact time, s; `None` when there is no rebound.
    pub contact_time: Option<f64>,
    /// Permanent indentation z_f (the flat the ball leaves with), m.
    pub permanent_indentation: f64,
    /// Peak indentation z_m, m.
    pub max_indentation: f64,
}

/// COR against impact speed for one ball (Fig. 4): flat until flattening starts, then falling.
pub fn cor_vs_velocity(
    params: &ImpactParams,
    law: ContactLaw,
    speeds: &[f64],
) -> Result<Vec<VelocityPoint>, SolveError> {
    speeds
        .par_iter()
        .map(|&v0| {
            let r = simulate(
                &ImpactParams { v0, ..*params },
                law,
                &SolveOptions::default(),
            )?;
            Ok(VelocityPoint {
                v0,
                cor: r.cor,
                max_force: r.max_force,
                contact_time: r.contact_time,
                permanent_indentation: r.permanent_indentation,
                max_indentation: r.max_indentation,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spaces() {
        let z = log_space(0.01, 100.0, 5);
        for (a, b) in z.iter().zip([0.01, 0.1, 1.0, 10.0, 100.0]) {
            assert!((a - b).abs() < 1e-12 * b);
        }
        assert_eq!(lin_space(1.0, 2.0, 3), vec![1.0, 1.5, 2.0]);
    }

    /// Fig. 2's shape: for λ > 0 the COR falls, reaches a minimum and climbs back towards 1;
    /// for λ = 0 it falls to 0 at ζ = 1; lower λ gives lower e at the same ζ.
    #[test]
    fn cor_vs_zeta_has_the_papers_shape() {
        let zetas = log_space(0.01, 100.0, 81);
        let rows = cor_vs_zeta(&[0.0, 0.4, 1.0], &zetas, ContactLaw::Linear).unwrap();
        let curve = |l: f64| {
            rows.iter()
                .filter(|r| r.lambda == l)
                .map(|r| r.cor)
                .collect::<Vec<_>>()
        };
        let (c0, c4, c1) = (curve(0.0), curve(0.4), curve(1.0));
        for c in [&c4, &c1] {
            let (imin, &min) = c
                .iter()
                .enumerate()
                .min_by(|a, b| a.1.total_cmp(b.1))
                .unwrap();
            assert!(
                imin > 5 && imin < 75 && min < 0.8,
                "interior minimum {min} at {imin}"
            );
            assert!(c[0] > 0.95 && c[80] > 0.95);
        }
        let at_one = zetas.iter().position(|&z| z >= 1.0).unwrap();
        assert!(c0[at_one..].iter().all(|&e| e == 0.0) && c0[at_one - 1] > 0.0);
        for i in 0..81 {
            assert!(c0[i] <= c4[i] && c4[i] <= c1[i], "at ζ = {}", zetas[i]);
        }
    }

    /// Fig. 4's shape: flat at low speed, falling once the ball flattens.
    #[test]
    fn cor_vs_velocity_drops_after_flattening() {
        let p = ImpactParams::from_normalized(1.3, 0.16, 0.5);
        let pts = cor_vs_velocity(&p, ContactLaw::Linear, &lin_space(0.05, 3.0, 40)).unwrap();
        assert!(
            (pts[0].cor - pts[1].cor).abs() < 1e-12,
            "flat before flattening"
        );
        assert!(pts[39].cor < pts[0].cor - 0.05);
        assert!(pts.windows(2).all(|w| w[1].cor <= w[0].cor + 1e-12));
    }
}
