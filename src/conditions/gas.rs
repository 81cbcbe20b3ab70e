//! The gas law at fixed volume (docs/model.md §10.2): a ball's gas, sealed at inflation,
//! keeps its amount and (nearly) its volume, so its absolute pressure is proportional to its
//! absolute temperature: p_abs(T) = p_abs(T₀) · T/T₀. A gauge reads p_abs − p_atm.
//!
//! The volume is held: a football's or basketball's cover stretches by well under 1 % between
//! 0 and 40 °C of gauge-pressure change (its stiffness is what makes it a ball), which moves
//! the pressure by less than the gauges the sports test with can read.

use super::{ConditionsError, atmosphere, kelvin};

/// The gauge pressure, Pa, at `t_c` °C of a ball inflated to `gauge0` Pa (gauge) at `t0_c`
/// °C, both against the atmosphere `p_atm` Pa:
/// (gauge0 + p_atm)·(t_c + 273.15)/(t0_c + 273.15) − p_atm.
///
/// Refused: temperatures at or below absolute zero, a non-finite gauge pressure, an
/// absolute pressure at inflation that is not positive.
pub fn gauge_at(gauge0: f64, t0_c: f64, t_c: f64, p_atm: f64) -> Result<f64, ConditionsError> {
    let p_atm = atmosphere(p_atm)?;
    let t0 = kelvin("inflated-at", t0_c)?;
    let t = kelvin("temperature", t_c)?;
    let absolute0 = gauge0 + p_atm;
    if !gauge0.is_finite() || absolute0 <= 0.0 {
        return Err(ConditionsError::Pressure {
            field: "pressure",
            value: gauge0,
            why: "the absolute pressure, gauge + atmosphere, must be positive",
        });
    }
    Ok(absolute0 * (t / t0) - p_atm)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::conditions::STANDARD_ATMOSPHERE;
    use crate::conditions::pressure::PSI;

    /// The case the issue names: a football inflated to 12.5 psi at 21.1 °C (70 °F) reads
    /// about 11.0 psi at 4.4 °C (40 °F). The expected value is worked in psi, independently of
    /// the code's pascals: (12.5 + 14.695 949) × 277.55/294.25 − 14.695 949 = 10.956 51 psi.
    #[test]
    fn a_cold_football_reads_about_eleven_psi() {
        let atm_psi = STANDARD_ATMOSPHERE / PSI; // 14.695 948 8 psi
        assert!((atm_psi - 14.695_948_8).abs() < 1e-7);
        let expected_psi = (12.5 + 14.695_948_8) * 277.55 / 294.25 - 14.695_948_8;
        let got = gauge_at(12.5 * PSI, 21.1, 4.4, STANDARD_ATMOSPHERE).unwrap();
        assert!((got - expected_psi * PSI).abs() < 1.0, "{got} Pa");
        assert!((got / PSI - 10.957).abs() < 1e-3, "{} psi", got / PSI);
    }

    #[test]
    fn the_same_temperature_keeps_the_pressure_and_warming_raises_it() {
        let p = gauge_at(80_000.0, 20.0, 20.0, STANDARD_ATMOSPHERE).unwrap();
        assert_eq!(p, 80_000.0);
        let warm = gauge_at(80_000.0, 20.0, 40.0, STANDARD_ATMOSPHERE).unwrap();
        // +20 K on 293.15 K: the absolute pressure rises by 6.82 %
        let expected = 181_325.0 * (313.15 / 293.15) - 101_325.0;
        assert!((warm - expected).abs() < 1e-9);
    }

    #[test]
    fn impossible_conditions_are_refused_naming_the_field() {
        let e = gauge_at(8e4, 20.0, -300.0, STANDARD_ATMOSPHERE).unwrap_err();
        assert!(e.to_string().starts_with("invalid temperature"), "{e}");
        let e = gauge_at(8e4, f64::NAN, 5.0, STANDARD_ATMOSPHERE).unwrap_err();
        assert!(e.to_string().starts_with("invalid inflated-at"), "{e}");
        let e = gauge_at(-2e5, 20.0, 5.0, STANDARD_ATMOSPHERE).unwrap_err();
        assert!(e.to_string().starts_with("invalid pressure"), "{e}");
        let e = gauge_at(8e4, 20.0, 5.0, 0.0).unwrap_err();
        assert!(e.to_string().starts_with("invalid atmosphere"), "{e}");
    }
}
