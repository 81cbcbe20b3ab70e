//! The contact stiffness of an inflated ball from its gauge pressure (docs/model.md §10.1).
//!
//! A thin ball pressed flat by d against a plate has a flat of radius a, a² = 2Rd − d², whose
//! area carries the gas's gauge pressure: F = π a² p ≈ 2πR p d, a linear spring of stiffness
//! 2πR p (Bridge, Phys. Educ. 33, 236 (1998); Cross, Am. J. Phys. 67, 222 (1999), §V). The
//! shell adds its own bending stiffness K_shell, independent of p to first order, so
//!
//!   K_p(p) = K_shell + 2πR p,
//!
//! and K_shell = K_p(p₀) − 2πR p₀ from the preset calibrated at its nominal gauge pressure p₀:
//! at p₀ the preset's K_p, and so its answers, do not move. The recoil spring keeps its ratio
//! λ = K_r/K_p (the presets hold it, docs/presets.md) and the dashpot c is the material's,
//! kept. The gas compressed as the ball flattens is the next order: the cap's volume
//! π d²(3R − d)/3 ≈ πR d², compressed adiabatically (an impact lasts milliseconds), raises the
//! pressure by γ p_abs · 3d²/(4R²), a force term (3πγ p_abs/2R) d³ that a linear contact element
//! cannot hold; [`Inflated::gas_share`] says how large it is at a deflection.

use super::ConditionsError;

/// Air's ratio of specific heats (diatomic ideal gas, 7/5).
pub const GAMMA_AIR: f64 = 1.4;

/// An inflated ball's contact stiffness as a function of its gauge pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inflated {
    /// The ball's radius, m.
    pub radius: f64,
    /// The shell's own stiffness, N/m (K_p at zero gauge pressure).
    pub shell: f64,
}

impl Inflated {
    /// The model calibrated to `k_p0` N/m at the nominal gauge pressure `p0` Pa: K_shell =
    /// K_p0 − 2πR p0, taken as 0 within 1e-4 of the membrane term (the presets whose K_p is
    /// the membrane estimate, football and basketball, round it to the newton: 55 202 against
    /// 55 201.6 N/m). Refused when the preset's stiffness is below the membrane term alone by
    /// more than that, which no shell could give.
    pub fn calibrated(radius: f64, k_p0: f64, p0: f64) -> Result<Self, ConditionsError> {
        let membrane = membrane_stiffness(radius, p0);
        let shell = k_p0 - membrane;
        let rounding = 1e-4 * membrane.abs();
        if !shell.is_finite() || shell < -rounding {
            return Err(ConditionsError::Pressure {
                field: "pressure",
                value: p0,
                why: "the ball's K_p is below the membrane stiffness 2πR p at its nominal pressure",
            });
        }
        Ok(Inflated {
            radius,
            shell: if shell.abs() <= rounding { 0.0 } else { shell },
        })
    }

    /// K_p at the gauge pressure `p` Pa: K_shell + 2πR p. Refused where it is not positive (a
    /// ball without shell stiffness at zero or negative gauge pressure is flat).
    pub fn k_p(&self, p: f64) -> Result<f64, ConditionsError> {
        let k = self.shell + membrane_stiffness(self.radius, p);
        if !p.is_finite() || k <= 0.0 {
            return Err(ConditionsError::Pressure {
                field: "pressure",
                value: p,
                why: "the ball has no contact stiffness at this gauge pressure (it is flat)",
            });
        }
        Ok(k)
    }

    /// The share of the force at flattening `d` m that the gas's compression adds to the
    /// linear membrane's (the next-order term the linear law leaves out), at gauge pressure
    /// `p` Pa against the atmosphere `p_atm`: (3γ p_abs/(4 p)) (d/R)² relative to 2πR p d.
    pub fn gas_share(&self, p: f64, p_atm: f64, d: f64) -> f64 {
        let r = self.radius;
        GAMMA_AIR * (p + p_atm) * 3.0 * d * d / (4.0 * r * r) / p
    }
}

/// 2πR p: the membrane's stiffness, N/m.
pub fn membrane_stiffness(radius: f64, p: f64) -> f64 {
    2.0 * std::f64::consts::PI * radius * p
}

/// The force, N, of a thin ball of radius `radius` at gauge pressure `p` (atmosphere `p_atm`)
/// flattened by `d` against a plate, by the flat's exact area and the gas's adiabatic
/// compression, without the shell: π(2Rd − d²) (p + Δp), Δp = p_abs ((V/(V − V_cap))^γ − 1),
/// V_cap = π d² (3R − d)/3. The reference the linear model is compared with (tests).
pub fn membrane_force(radius: f64, p: f64, p_atm: f64, d: f64) -> f64 {
    use std::f64::consts::PI;
    let v = 4.0 / 3.0 * PI * radius.powi(3);
    let cap = PI * d * d * (3.0 * radius - d) / 3.0;
    let dp = (p + p_atm) * ((v / (v - cap)).powf(GAMMA_AIR) - 1.0);
    PI * (2.0 * radius * d - d * d) * (p + dp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::conditions::STANDARD_ATMOSPHERE;

    /// The football preset's K_p is the membrane estimate at 0.8 bar (presets/football.toml):
    /// no shell term, and K_p proportional to the gauge pressure.
    #[test]
    fn the_football_preset_is_its_membrane() {
        let (r, k0) = (0.10982, 55_202.0);
        let ball = Inflated::calibrated(r, k0, 80_000.0).unwrap();
        assert_eq!(ball.shell, 0.0);
        assert!((ball.k_p(80_000.0).unwrap() - k0).abs() < 1.0);
        let half = ball.k_p(40_000.0).unwrap();
        assert!((half - k0 / 2.0).abs() < 1.0, "{half}");
        assert!(ball.k_p(0.0).is_err());
    }

    #[test]
    fn a_shell_keeps_its_stiffness_and_the_nominal_does_not_move() {
        let ball = Inflated::calibrated(0.0335, 24_713.0, 82_737.0).unwrap();
        let membrane = 2.0 * std::f64::consts::PI * 0.0335 * 82_737.0;
        assert!((ball.shell - (24_713.0 - membrane)).abs() < 1e-9);
        assert!((ball.k_p(82_737.0).unwrap() - 24_713.0).abs() < 1e-9);
        assert!((ball.k_p(0.0).unwrap() - ball.shell).abs() < 1e-12);
        assert!(Inflated::calibrated(0.0335, 1000.0, 82_737.0).is_err());
    }

    /// The linear membrane is the first term of the exact flat-and-gas force: within 1e-3 at
    /// d/R = 1e-3, and the gas share predicts the rest to second order at d/R = 0.05.
    #[test]
    fn the_linear_membrane_is_the_small_deflection_limit() {
        let (r, p, atm) = (0.11, 80_000.0, STANDARD_ATMOSPHERE);
        let ball = Inflated {
            radius: r,
            shell: 0.0,
        };
        let d = 1e-3 * r;
        let exact = membrane_force(r, p, atm, d);
        let linear = membrane_stiffness(r, p) * d;
        assert!((exact / linear - 1.0).abs() < 1e-3, "{}", exact / linear);
        let d = 0.05 * r;
        let exact = membrane_force(r, p, atm, d);
        let linear = membrane_stiffness(r, p) * d;
        // the flat's own −d² and the cap's −d terms are first order in d/R: take them out
        let geometric = 1.0 - d / (2.0 * r);
        let share = exact / (linear * geometric) - 1.0;
        let predicted = ball.gas_share(p, atm, d);
        assert!(
            (share / predicted - 1.0).abs() < 0.1,
            "{share} vs {predicted}"
        );
    }
}
