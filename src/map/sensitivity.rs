//! How fast the COR moves with λ and ζ at a point: ∂e/∂ln λ and ∂e/∂ln ζ, the relative
//! changes a designer makes (a 10 % stiffer recoil spring moves e by about 0.1 ∂e/∂ln λ).

use super::{MapError, MapSpec, cell_at};
use crate::model::params::validate_lambda_zeta;
use serde::Serialize;

/// ∂e/∂ln λ and ∂e/∂ln ζ at (λ, ζ).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sensitivity {
    /// The point's λ.
    pub lambda: f64,
    /// The point's ζ.
    pub zeta: f64,
    /// The COR at the point.
    pub cor: f64,
    /// ∂e/∂ln λ = λ ∂e/∂λ; 0 at λ = 0, its limit (e is smooth in λ there).
    pub d_ln_lambda: f64,
    /// ∂e/∂ln ζ = ζ ∂e/∂ζ; 0 at ζ = 0.
    pub d_ln_zeta: f64,
}

/// The step in ln λ and ln ζ of the central differences: their error is about h² e'''/6
/// ≈ 1e-9 from truncation and 1e-16/h ≈ 1e-12 from the solver's rounding.
const H: f64 = 1e-4;

/// The sensitivities of the COR at (λ, ζ) for the ball of `spec` (its axes are not used: the
/// point may lie anywhere in the domain), by central differences in ln λ and ln ζ through the
/// same solver as the map's cells. Across a kink (where the ball stops rebounding, e = 0) the
/// difference straddles it and the value is a one-sided mixture.
pub fn sensitivity(spec: &MapSpec, lambda: f64, zeta: f64) -> Result<Sensitivity, MapError> {
    validate_lambda_zeta(lambda, zeta).map_err(crate::api::BallError::Param)?;
    let mut probe = spec.base;
    crate::api::set_lambda_zeta(&mut probe, Some(lambda), Some(zeta))?;
    let e = |l: f64, z: f64| -> Result<f64, MapError> {
        let c = cell_at(spec, l, z).map_err(crate::api::BallError::Solve)?;
        Ok(c.cor)
    };
    let cor = e(lambda, zeta)?;
    let d = |x: f64, at: &dyn Fn(f64) -> Result<f64, MapError>| -> Result<f64, MapError> {
        if x == 0.0 {
            return Ok(0.0);
        }
        // stay inside the domain (≤ 1e6): a one-sided difference at the top
        let (up, down) = if x * H.exp() > 1e6 {
            (x, x * (-2.0 * H).exp())
        } else {
            (x * H.exp(), x * (-H).exp())
        };
        Ok((at(up)? - at(down)?) / (up.ln() - down.ln()))
    };
    Ok(Sensitivity {
        lambda,
        zeta,
        cor,
        d_ln_lambda: d(lambda, &|l| e(l, zeta))?,
        d_ln_zeta: d(zeta, &|z| e(lambda, z))?,
    })
}

#[cfg(test)]
mod tests {
    use super::super::{Axis, Param, Scale};
    use super::*;
    use crate::model::contact::ContactLaw;

    fn spec() -> MapSpec {
        let l = Axis::new(Param::Lambda, 0.0, 1.0, 2, Scale::Linear).unwrap();
        let z = Axis::new(Param::Zeta, 0.01, 1.0, 2, Scale::Log).unwrap();
        MapSpec::normalized(None, ContactLaw::Linear, l, z).unwrap()
    }

    /// Maxwell (λ = 0, Eq. 28): e = exp(−πζ/√(1−ζ²)), so ∂e/∂ln ζ = −π e ζ (1−ζ²)^(−3/2).
    #[test]
    fn maxwell_zeta_sensitivity_is_the_closed_form() {
        for zeta in [0.05, 0.3, 0.7] {
            let s = sensitivity(&spec(), 0.0, zeta).unwrap();
            let e = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
            let want = -std::f64::consts::PI * e * zeta * (1.0 - zeta * zeta).powf(-1.5);
            assert!((s.cor - e).abs() < 1e-12, "{} vs {e}", s.cor);
            assert!(
                (s.d_ln_zeta - want).abs() < 1e-7,
                "{} vs {want}",
                s.d_ln_zeta
            );
            assert_eq!(s.d_ln_lambda, 0.0);
        }
    }

    /// At fixed ζ a stiffer recoil spring keeps more energy (docs/model.md §4): ∂e/∂ln λ > 0.
    #[test]
    fn cor_rises_with_lambda() {
        let s = sensitivity(&spec(), 0.5, 0.3).unwrap();
        assert!(s.d_ln_lambda > 0.0, "{s:?}");
    }
}
