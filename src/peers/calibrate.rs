//! The damping that gives a requested COR: exactly, by a bracketed root find on the model's
//! own impact, and by each published rule, with the COR each really produces
//! (docs/peers.md §4). Also: a COR table in least squares, and the Christoforou–Yigit model
//! of the same ball as the target.

use super::rules::{self, Rule};
use super::{PeerBall, PeerError, PeerModel, cor, impact};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::roots::brent;
use crate::solver::{ImpactResponse, SolveError, SolveOptions, simulate};

/// The COR tolerance the exact calibration promises (tests/physics/peers_calibration.rs).
pub const COR_TOL: f64 = 1e-9;

fn check_target(e: f64) -> Result<(), PeerError> {
    if e.is_finite() && (0.0..=1.0).contains(&e) {
        Ok(())
    } else {
        Err(PeerError::Invalid {
            field: "cor",
            value: e,
            reason: "a coefficient of restitution lies in [0, 1]",
        })
    }
}

/// The normalized damping (laws.rs) whose COR is `target`. Every model's COR falls
/// monotonically from 1 at d = 0 towards 0 (tests/physics/peers_calibration.rs sweeps it), so a
/// bracket grown from the log-decrement or Gonthier guess and Brent's method find it; the root
/// is resolved to 1e-13 in d, far inside `COR_TOL`.
pub fn exact(model: PeerModel, target: f64) -> Result<f64, PeerError> {
    check_target(target)?;
    if target == 1.0 {
        return Ok(0.0);
    }
    if target == 0.0 {
        // Kelvin–Voigt with tension stops rebounding at ζ = 1; the others rebound at any d
        return match model {
            PeerModel::KelvinVoigt => Ok(1.0),
            _ => Err(PeerError::OutOfReach { model, target }),
        };
    }
    let guess = match model {
        PeerModel::HuntCrossley => rules::approximate(model, Rule::Gonthier, target),
        _ => rules::approximate(model, Rule::LogDecrement, target),
    }
    .unwrap_or(1.0);
    let f = |d: f64| cor(model, d).map(|e| e - target);
    let (mut lo, mut hi) = (guess / 1.2, guess * 1.2);
    let (mut flo, mut fhi) = (f(lo)?, f(hi)?);
    while flo < 0.0 {
        (hi, fhi) = (lo, flo);
        lo /= 2.0;
        flo = f(lo)?;
    }
    while fhi > 0.0 {
        (lo, flo) = (hi, fhi);
        hi *= 2.0;
        if hi > 1e12 {
            return Err(PeerError::OutOfReach { model, target });
        }
        fhi = f(hi)?;
    }
    let mut failure = None;
    let d = brent(
        |d| {
            f(d).unwrap_or_else(|e| {
                failure = Some(e);
                0.0
            })
        },
        lo,
        hi,
        flo,
        fhi,
        1e-13 * hi,
    );
    match failure {
        Some(e) => Err(e),
        None => Ok(d),
    }
}

/// An exact row is re-solved: the ball's impact at the calibrated damping must give the
/// target to [`COR_TOL`] relative, or the target is out of reach (docs/peers.md §4).
fn verify(model: PeerModel, target: f64, r: &ImpactResponse) -> Result<(), PeerError> {
    if (r.cor - target).abs() <= COR_TOL * target {
        return Ok(());
    }
    Err(PeerError::Missed {
        model,
        target,
        got: r.cor,
    })
}

/// One model calibrated by one rule, run at the ball's v0.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibrated {
    /// The peer model.
    pub model: PeerModel,
    /// The rule that turned the target COR into its damping.
    pub rule: Rule,
    /// The normalized damping (ζ, α or χ).
    pub damping_normalized: f64,
    /// The SI damping (η in kg/s or kg/(s·m^0.25); χ for Hunt–Crossley).
    pub damping: f64,
    /// The impact at v0 with that damping: its `cor` is what the rule really gives.
    pub response: ImpactResponse,
}

/// Every model under every rule published for it, calibrated to `target` at `ball.v0`, with
/// `samples` history points per impact.
pub fn compare(ball: &PeerBall, target: f64, samples: usize) -> Result<Vec<Calibrated>, PeerError> {
    ball.validate()?;
    check_target(target)?;
    let mut rows = Vec::new();
    for model in PeerModel::ALL {
        for &rule in Rule::for_model(model) {
            let d = match rule {
                Rule::Exact => exact(model, target)?,
                r => match rules::approximate(model, r, target) {
                    Some(d) if d.is_finite() => d,
                    // e = 0 sends Flores' and Gonthier's χ to ∞: no finite damping to show
                    _ => continue,
                },
            };
            let damping = ball.damping_si(model, d);
            let response = impact(model, ball, damping, samples)?;
            if rule == Rule::Exact {
                verify(model, target, &response)?;
            }
            rows.push(Calibrated {
                model,
                rule,
                damping_normalized: d,
                damping,
                response,
            });
        }
    }
    Ok(rows)
}

/// A least-squares fit of a model to a table of (v0, COR).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableFit {
    /// The normalized damping.
    pub damping_normalized: f64,
    /// The model's COR (the same at every speed).
    pub cor: f64,
    /// √(mean squared COR residual).
    pub rms: f64,
}

/// Fit `model` to CORs measured at several speeds. None of the peers' COR depends on v0
/// (laws.rs), so Σ (e − e_i)² is least at the mean of the e_i, and the damping is the exact
/// calibration to that mean (tests/physics/peers_calibration.rs checks it is a minimum).
pub fn fit_table(model: PeerModel, table: &[(f64, f64)]) -> Result<TableFit, PeerError> {
    if table.is_empty() {
        return Err(PeerError::Invalid {
            field: "table",
            value: 0.0,
            reason: "needs at least one (v0, COR) pair",
        });
    }
    for &(v, e) in table {
        super::positive("v0", v)?;
        check_target(e)?;
    }
    let n = table.len() as f64;
    let mean = table.iter().map(|p| p.1).sum::<f64>() / n;
    let d = exact(model, mean)?;
    let e = cor(model, d)?;
    let rms = (table.iter().map(|p| (p.1 - e).powi(2)).sum::<f64>() / n).sqrt();
    Ok(TableFit {
        damping_normalized: d,
        cor: e,
        rms,
    })
}

/// The Christoforou–Yigit model's COR for the same ball at `v0` (docs/model.md §2).
pub fn christoforou_yigit_cor(
    params: &ImpactParams,
    law: ContactLaw,
    v0: f64,
) -> Result<f64, SolveError> {
    let p = ImpactParams { v0, ..*params };
    simulate(&p, law, &SolveOptions::default()).map(|r| r.cor)
}

/// The Christoforou–Yigit COR-vs-speed curve at `speeds`, as a table for [`fit_table`].
pub fn christoforou_yigit_curve(
    params: &ImpactParams,
    law: ContactLaw,
    speeds: &[f64],
) -> Result<Vec<(f64, f64)>, SolveError> {
    speeds
        .iter()
        .map(|&v| christoforou_yigit_cor(params, law, v).map(|e| (v, e)))
        .collect()
}
