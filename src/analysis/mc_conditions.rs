//! A Monte Carlo's spread in the conditions (`mc --vary pressure=…,temperature=…`,
//! docs/model.md §10): how a sample's gauge pressure and temperature move its ball, by the
//! same laws `api::Ball::at_conditions` applies to one ball.
//!
//! - An inflated ball sealed at the run's conditions (gauge `pressure` at `temperature_c`):
//!   a sample's pressure is its gauge pressure at the run's temperature, carried to the
//!   sample's temperature by the gas law at fixed volume (§10.2); K_p follows it as
//!   K_shell + 2πR p (§10.1), and K_r and c move by the same ratio (λ and the retardation
//!   time c/K_r kept).
//! - A solid ball with a stored temperature shift: c by Arrhenius's factor (§10.4).
//!
//! Both spreads are relative, as every `--vary` spread: the pressure's of the gauge pressure,
//! the temperature's of the absolute temperature (kelvin): `temperature=1%` is about 3 K at
//! 23 °C.

use super::fit::cor_temperature::shifted_damping;
use crate::conditions::ZERO_CELSIUS;
use crate::model::params::ImpactParams;

/// The run's conditions and the laws that carry a sample away from them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct McConditions {
    /// The run's temperature, °C (NaN where none is stated: then no temperature spread).
    pub temperature_c: f64,
    /// The run's gauge pressure, Pa, and the ball's stiffness law K_p(p) = k_shell +
    /// membrane · p: `(pressure, k_shell, membrane)`; `None` for a solid ball.
    pub inflated: Option<(f64, f64, f64)>,
    /// The atmosphere, Pa (the gas law works in absolute pressures).
    pub atmosphere_pa: f64,
    /// The activation energy of the dashpot's shift, J/mol; `None` for a ball without one.
    pub activation: Option<f64>,
}

impl McConditions {
    /// The run's temperature in kelvin, the nominal value a temperature spread is relative to.
    pub fn kelvin(&self) -> f64 {
        self.temperature_c + ZERO_CELSIUS
    }

    /// `p` moved to a sample's gauge pressure `pressure` (at the run's temperature; `None`:
    /// the run's) and absolute temperature `kelvin` (`None`: the run's). A pressure at which
    /// the ball is flat leaves K_p ≤ 0, which the sample's check refuses.
    pub fn apply(&self, p: &mut ImpactParams, pressure: Option<f64>, kelvin: Option<f64>) {
        if let Some((p0, k_shell, membrane)) = self.inflated {
            let sealed = pressure.unwrap_or(p0);
            let at_t = match kelvin {
                Some(t) => (sealed + self.atmosphere_pa) * t / self.kelvin() - self.atmosphere_pa,
                None => sealed,
            };
            let ratio = (k_shell + membrane * at_t) / (k_shell + membrane * p0);
            p.k_p *= ratio;
            p.k_r *= ratio;
            p.damping *= ratio;
        } else if let (Some(e_a), Some(t)) = (self.activation, kelvin) {
            p.damping *= shifted_damping(1.0, e_a, self.temperature_c, t - ZERO_CELSIUS);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball() -> ImpactParams {
        crate::Ball::from_preset("football").unwrap().params
    }

    /// At the run's own conditions nothing moves; a warmer sealed ball has a higher pressure
    /// by the gas law (K_p ∝ p with K_shell 0), a solid one a dashpot moved by Arrhenius.
    #[test]
    fn a_sample_moves_by_the_conditions_laws() {
        let c = McConditions {
            temperature_c: 20.0,
            inflated: Some((80_000.0, 0.0, 1.0)),
            atmosphere_pa: 101_325.0,
            activation: None,
        };
        let mut p = ball();
        c.apply(&mut p, None, None);
        assert_eq!(p, ball());
        let mut warm = ball();
        c.apply(&mut warm, None, Some(313.15));
        let p_warm = 181_325.0 * 313.15 / 293.15 - 101_325.0;
        assert!((warm.k_p / ball().k_p - p_warm / 80_000.0).abs() < 1e-12);
        assert!((warm.damping / ball().damping - p_warm / 80_000.0).abs() < 1e-12);
        let mut soft = ball();
        c.apply(&mut soft, Some(40_000.0), None);
        assert!((soft.k_r / ball().k_r - 0.5).abs() < 1e-12);
        let solid = McConditions {
            inflated: None,
            activation: Some(20_000.0),
            ..c
        };
        let mut cold = ball();
        solid.apply(&mut cold, Some(1.0), Some(283.15));
        let factor = (20_000.0_f64 / 8.314_462_618 * (1.0 / 283.15 - 1.0 / 293.15)).exp();
        assert!((cold.damping / ball().damping - factor).abs() < 1e-12);
        assert_eq!(cold.k_p, ball().k_p);
    }
}
