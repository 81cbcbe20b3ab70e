//! The gauge pressure's decay by permeation through the bladder (docs/model.md §10.3).
//!
//! Steady permeation through a wall carries a molar flow proportional to the difference of
//! the gas's partial pressures across it (the permeance of ASTM D1434's gas-transmission
//! test: flow per area per unit pressure difference). For air leaking into air that
//! difference is the gauge pressure p, and at fixed volume and temperature the gas's absolute
//! pressure follows its amount, so dp/dt = −k p: the gauge pressure decays exponentially,
//!
//!   p(t) = p₀ e^(−k t),   half-life t½ = ln 2 / k.
//!
//! k lumps the wall's permeability, area and thickness, the ball's volume and the
//! temperature; it is the ball's own, fitted from pressure readings
//! (`analysis::fit::pressure_loss`).

use super::ConditionsError;

/// A ball's leak: the rate k of its gauge pressure's exponential decay.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Leak {
    /// k, 1/s.
    pub rate: f64,
}

impl Leak {
    /// A leak of rate `rate` 1/s: finite and not negative.
    pub fn new(rate: f64) -> Result<Self, ConditionsError> {
        if !rate.is_finite() || rate < 0.0 {
            return Err(ConditionsError::Time {
                field: "leak-rate",
                value: rate,
                why: "must be a finite rate ≥ 0 per second",
            });
        }
        Ok(Leak { rate })
    }

    /// The leak that halves the gauge pressure in `half_life` s (positive; infinite: none).
    pub fn from_half_life(half_life: f64) -> Result<Self, ConditionsError> {
        if half_life.is_nan() || half_life <= 0.0 {
            return Err(ConditionsError::Time {
                field: "half-life",
                value: half_life,
                why: "must be a positive time",
            });
        }
        Ok(Leak {
            rate: std::f64::consts::LN_2 / half_life,
        })
    }

    /// The leak that loses the fraction `lost` (0 ≤ lost < 1) of the gauge pressure in
    /// `time` s: k = −ln(1 − lost)/time (a standard's limit as a rate: FIFA's ≤ 20 % in 72 h).
    pub fn losing(lost: f64, time: f64) -> Result<Self, ConditionsError> {
        if !(0.0..1.0).contains(&lost) || !time.is_finite() || time <= 0.0 {
            return Err(ConditionsError::Time {
                field: "pressure-loss",
                value: lost,
                why: "a fraction in [0, 1) over a positive time",
            });
        }
        Self::new(-(1.0 - lost).ln() / time)
    }

    /// t½ = ln 2 / k, s (infinite without a leak).
    pub fn half_life(&self) -> f64 {
        std::f64::consts::LN_2 / self.rate
    }

    /// The gauge pressure `after` s from `gauge0` Pa: gauge0 e^(−k t).
    pub fn gauge_after(&self, gauge0: f64, after: f64) -> Result<f64, ConditionsError> {
        if !after.is_finite() || after < 0.0 {
            return Err(ConditionsError::Time {
                field: "after",
                value: after,
                why: "must be a finite time ≥ 0",
            });
        }
        Ok(gauge0 * (-self.rate * after).exp())
    }

    /// The fraction of the gauge pressure lost in `time` s: 1 − e^(−k t).
    pub fn lost_in(&self, time: f64) -> f64 {
        -(-self.rate * time).exp_m1()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HOUR: f64 = 3600.0;

    #[test]
    fn half_life_and_loss_agree() {
        let leak = Leak::from_half_life(100.0 * HOUR).unwrap();
        assert!((leak.half_life() - 100.0 * HOUR).abs() < 1e-6);
        let p = leak.gauge_after(80_000.0, 100.0 * HOUR).unwrap();
        assert!((p - 40_000.0).abs() < 1e-9, "{p}");
        assert!((leak.lost_in(200.0 * HOUR) - 0.75).abs() < 1e-12);
        // FIFA Quality Pro's limit: at most 20 % of 0.8 bar lost in 72 h
        let fifa = Leak::losing(0.2, 72.0 * HOUR).unwrap();
        let after = fifa.gauge_after(80_000.0, 72.0 * HOUR).unwrap();
        assert!((after - 64_000.0).abs() < 1e-9, "{after}");
        assert!(
            (fifa.half_life() / HOUR - 223.65).abs() < 0.01,
            "{}",
            fifa.half_life()
        );
    }

    #[test]
    fn no_leak_keeps_the_pressure_and_bad_times_are_refused() {
        let none = Leak::new(0.0).unwrap();
        assert_eq!(none.gauge_after(8e4, 1e9).unwrap(), 8e4);
        assert!(none.half_life().is_infinite());
        assert!(Leak::new(-1.0).is_err());
        assert!(Leak::from_half_life(0.0).is_err());
        assert!(Leak::losing(1.0, 10.0).is_err());
        let e = none.gauge_after(8e4, -1.0).unwrap_err();
        assert!(e.to_string().starts_with("invalid after"), "{e}");
    }
}
