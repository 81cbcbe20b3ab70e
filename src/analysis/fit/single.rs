//! Fitting K_r (λ) to a measured COR at fixed ζ (docs/model.md §4): e increases with λ, so this is
//! a bracketed 1-D root find.

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::roots::brent;
use crate::solver::{SolveOptions, simulate};
use crate::text::number;
use serde::Serialize;
use std::fmt;

/// The fitted recoil spring.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Fit {
    /// K_r (N/m).
    pub k_r: f64,
    /// λ = K_r / K_p.
    pub lambda: f64,
    /// ζ, held fixed.
    pub zeta: f64,
    /// The model's COR at the fitted λ.
    pub cor: f64,
}

/// Why a fit failed.
#[derive(Debug, Clone, PartialEq)]
pub enum FitError {
    /// The measured COR is not a number in [0, 1].
    BadTarget(f64),
    /// The parameters themselves are invalid.
    Params(crate::ParamError),
    /// No λ ≥ 0 reaches the COR at this ζ: the model spans [low, high).
    OutOfReach {
        /// The measured COR asked for.
        target: f64,
        /// The ball's ζ = √(m K_p)/(2c), held fixed.
        zeta: f64,
        /// The COR at λ = 0 (Maxwell), the lowest the model gives at this ζ.
        low: f64,
        /// The COR at the largest λ tried (1e6, standing for λ → ∞).
        high: f64,
    },
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            // shortest round-trip form, exponent when tiny: 1e-320, not 324 digits
            FitError::BadTarget(e) => write!(
                f,
                "invalid cor: {} (a measured COR lies in [0, 1])",
                number(*e)
            ),
            FitError::Params(e) => write!(f, "{e}"),
            FitError::OutOfReach {
                target,
                zeta,
                low,
                high,
            } => {
                // a typed COR as typed (0.999999999999, never a rounded 1); one derived from
                // heights (0.44367825470805683: 16 digits and more) to six
                let given = number(*target);
                let shown = if given.len() > 15 {
                    crate::text::sig_trim(*target, 6)
                } else {
                    given
                };
                let (low, high) = (apart(*low, *target), apart(*high, *target));
                write!(
                    f,
                    "cor {shown} is out of reach at ζ = {zeta:.4}: the model spans {low} (λ = 0) to {high} (λ → ∞)"
                )
            }
        }
    }
}

impl std::error::Error for FitError {}

/// `bound` to 4 decimals, or to as many more as keep it on its side of `target`: the span's
/// end at λ = 1e6 (0.99999997) printed `1.0000` beside "cor 1 is out of reach"
/// (tests/cli/cli_odd_inputs.rs, `an_unreachable_cor_is_not_inside_the_span_shown`).
fn apart(bound: f64, target: f64) -> String {
    (4..=17)
        .map(|d| format!("{bound:.d$}"))
        .find(|s| {
            let shown: f64 = s.parse().unwrap_or(bound);
            (shown < target) == (bound < target)
        })
        .unwrap_or_else(|| number(bound))
}

/// Largest λ tried: beyond it K_r is rigid for any practical purpose.
const LAMBDA_MAX: f64 = 1e6;

/// Fit K_r so that the model's COR equals `target`, keeping m, K_p, c (so ζ), z_p and v0.
pub fn fit_k_r(params: &ImpactParams, law: ContactLaw, target: f64) -> Result<Fit, FitError> {
    if !(target.is_finite() && (0.0..=1.0).contains(&target)) {
        return Err(FitError::BadTarget(target));
    }
    params.validate().map_err(FitError::Params)?;
    let zeta = params.normalized().zeta;
    let cor = |lambda: f64| -> f64 {
        simulate(
            &ImpactParams {
                k_r: lambda * params.k_p,
                ..*params
            },
            law,
            &SolveOptions::default(),
        )
        .map_or(f64::NAN, |r| r.cor)
    };
    let low = cor(0.0);
    if target < low {
        return Err(FitError::OutOfReach {
            target,
            zeta,
            low,
            high: cor(LAMBDA_MAX),
        });
    }
    let mut hi = 1.0;
    let mut e_hi = cor(hi);
    while e_hi < target {
        if hi >= LAMBDA_MAX {
            return Err(FitError::OutOfReach {
                target,
                zeta,
                low,
                high: e_hi,
            });
        }
        hi = (hi * 4.0).min(LAMBDA_MAX);
        e_hi = cor(hi);
    }
    let lambda = if target == low {
        0.0
    } else {
        brent(
            |l| cor(l) - target,
            0.0,
            hi,
            low - target,
            e_hi - target,
            1e-13 * hi,
        )
    };
    // "exact" is verified: the root must reproduce the target (a COR that is not continuous
    // in λ, or a root find that stopped short, is refused rather than reported as a fit)
    let got = cor(lambda);
    let hit = (got - target).abs() <= super::verdict::EXACT_MISS * target.max(1e-300);
    if !hit {
        return Err(FitError::OutOfReach {
            target,
            zeta,
            low,
            high: e_hi,
        });
    }
    Ok(Fit {
        k_r: lambda * params.k_p,
        lambda,
        zeta,
        cor: got,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// fit(COR(λ)) returns λ.
    #[test]
    fn fit_inverts_the_model() {
        for zeta in [0.07, 0.16, 0.61, 3.0] {
            for lambda in [0.05, 0.4, 1.0, 1.3, 7.0] {
                let p = ImpactParams::from_normalized(lambda, zeta, f64::INFINITY);
                let e = simulate(&p, ContactLaw::Linear, &SolveOptions::default())
                    .unwrap()
                    .cor;
                let f = fit_k_r(&ImpactParams { k_r: 123.0, ..p }, ContactLaw::Linear, e).unwrap();
                assert!(
                    (f.lambda - lambda).abs() < 1e-8 * lambda.max(1.0),
                    "ζ={zeta}: {} vs {lambda}",
                    f.lambda
                );
                assert!((f.cor - e).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn out_of_reach_is_an_error() {
        let p = ImpactParams::from_normalized(1.0, 0.3, f64::INFINITY);
        // at ζ = 0.3 Maxwell (λ = 0) gives e = exp(−0.3π/√0.91) ≈ 0.37: nothing lower is reachable
        let err = fit_k_r(&p, ContactLaw::Linear, 0.2).unwrap_err();
        assert!(matches!(err, FitError::OutOfReach { .. }), "{err}");
        assert!(err.to_string().contains("out of reach"));
        assert!(matches!(
            fit_k_r(&p, ContactLaw::Linear, f64::NAN),
            Err(FitError::BadTarget(_))
        ));
        assert!(matches!(
            fit_k_r(&p, ContactLaw::Linear, 1.5),
            Err(FitError::BadTarget(_))
        ));
    }
}
