//! The temperature shift of a solid ball's dashpot fitted from COR-against-temperature data
//! (docs/model.md §10.4, `fit --cor-temperature`). The dashpot c is the viscosity of the
//! ball's material times a geometric factor; a viscosity's temperature dependence is a shift
//! factor a_T (J. D. Ferry, *Viscoelastic Properties of Polymers*, 3rd ed., Wiley 1980,
//! ch. 11), here Arrhenius's:
//!
//!   c(T) = c_ref · a_T,   ln a_T = (E_a/R)(1/T − 1/T_ref)     (T, T_ref in kelvin)
//!
//! The springs K_p, K_r and z_p are kept (the data do not ask for more: a COR gives ζ and λ
//! alone on the linear law). c_ref and E_a are fitted by bounded Levenberg–Marquardt
//! ([`super::lm`]) from several starts in E_a (the COR is not monotone in c, §5: a dashpot
//! can be too stiff or too soft to lose), their intervals from the Jacobian
//! ([`super::stats`]), and the law's fit to the data judged ([`super::verdict`]).

use super::Estimate;
use super::lm::{self, Residuals};
use super::stats::{self, Spread};
use super::verdict::{self, LackOfFit};
use crate::conditions::{ZERO_CELSIUS, kelvin};
use crate::measured::CorTemperatureRow;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};

/// The molar gas constant, J/(mol K) (CODATA 2018, exact since the 2019 SI).
pub const GAS_CONSTANT: f64 = 8.314_462_618;

/// The fitted shift.
#[derive(Debug, Clone)]
pub struct TemperatureFit {
    /// The reference temperature, °C (the ball's calibration temperature, or the caller's).
    pub t_ref_c: f64,
    /// c at the reference temperature, kg/s.
    pub c_ref: Estimate,
    /// E_a, J/mol.
    pub activation: Estimate,
    /// Each point's COR by the fitted law.
    pub predicted: Vec<f64>,
    /// Degrees of freedom, n − 2.
    pub dof: usize,
    /// χ² against the stated deviations, or the runs test from 20 points; `None` when
    /// neither applies.
    pub lack_of_fit: Option<LackOfFit>,
    /// Why the fit gave no answer (empty when it answered).
    pub no_answer: Vec<String>,
}

/// Data the fit cannot start from.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CorTemperatureError {
    /// Fewer than three points, or fewer than two temperatures.
    #[error("a COR-temperature fit needs three points at two temperatures at least (got {0})")]
    TooFew(usize),
    /// A point out of its domain: row `row` (1-based).
    #[error("point {row}: {why}")]
    Point {
        /// 1-based row.
        row: usize,
        /// What is wrong.
        why: &'static str,
    },
    /// No start led the minimizer to an answer.
    #[error("the COR-temperature fit did not converge")]
    NoMinimum,
}

/// c at `t_c` °C for c_ref at `t_ref_c` and E_a (J/mol): c_ref exp[(E_a/R)(1/T − 1/T_ref)].
pub fn shifted_damping(c_ref: f64, activation: f64, t_ref_c: f64, t_c: f64) -> f64 {
    let (t, t_ref) = (t_c + ZERO_CELSIUS, t_ref_c + ZERO_CELSIUS);
    c_ref * (activation / GAS_CONSTANT * (1.0 / t - 1.0 / t_ref)).exp()
}

struct Problem<'a> {
    base: ImpactParams,
    law: ContactLaw,
    t_ref_c: f64,
    points: &'a [CorTemperatureRow],
    /// Without stated deviations, residuals are in COR (scale 1).
    stated: bool,
}

impl Problem<'_> {
    /// x = (ln(c_ref/c_base), E_a/(R T_ref)).
    fn values(&self, x: &[f64]) -> (f64, f64) {
        let t_ref = self.t_ref_c + ZERO_CELSIUS;
        (self.base.damping * x[0].exp(), x[1] * GAS_CONSTANT * t_ref)
    }

    fn cor(&self, c_ref: f64, activation: f64, p: &CorTemperatureRow) -> Option<f64> {
        let damping = shifted_damping(c_ref, activation, self.t_ref_c, p.temperature_c);
        let params = ImpactParams {
            damping,
            v0: p.v0,
            ..self.base
        };
        simulate(&params, self.law, &SolveOptions::default())
            .ok()
            .map(|r| r.cor)
    }
}

impl Residuals for Problem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let (c_ref, activation) = self.values(x);
        self.points
            .iter()
            .map(|p| {
                let s = if self.stated {
                    p.sd.unwrap_or(1.0)
                } else {
                    1.0
                };
                self.cor(c_ref, activation, p).map(|e| (p.cor - e) / s)
            })
            .collect()
    }
    fn step(&self, _j: usize) -> f64 {
        1e-6
    }
    fn max_step(&self, j: usize) -> f64 {
        if j == 0 { 2.0 } else { 20.0 }
    }
}

fn check(points: &[CorTemperatureRow]) -> Result<(), CorTemperatureError> {
    for (i, p) in points.iter().enumerate() {
        let bad = |why| Err(CorTemperatureError::Point { row: i + 1, why });
        if kelvin("temperature", p.temperature_c).is_err() {
            return bad("temperature must be finite and above −273.15 °C");
        }
        if !p.v0.is_finite() || p.v0 <= 0.0 {
            return bad("v0 must be finite and positive");
        }
        if !p.cor.is_finite() || !(0.0..=1.0).contains(&p.cor) {
            return bad("cor must lie in [0, 1]");
        }
        if p.sd.is_some_and(|s| !s.is_finite() || s <= 0.0) {
            return bad("cor_sd must be finite and positive");
        }
    }
    let t0 = points.first().map(|p| p.temperature_c);
    if points.len() < 3 || points.iter().all(|p| Some(p.temperature_c) == t0) {
        return Err(CorTemperatureError::TooFew(points.len()));
    }
    Ok(())
}

/// Fit c(T) = c_ref a_T on the ball `base` (its springs and mass kept; its c the start) under
/// `law` to `points`, T_ref = `t_ref_c`.
pub fn fit_cor_temperature(
    base: &ImpactParams,
    law: ContactLaw,
    t_ref_c: f64,
    points: &[CorTemperatureRow],
) -> Result<TemperatureFit, CorTemperatureError> {
    check(points)?;
    kelvin("temperature", t_ref_c).map_err(|_| CorTemperatureError::Point {
        row: 0,
        why: "the reference temperature must lie above −273.15 °C",
    })?;
    let stated = points.iter().all(|p| p.sd.is_some());
    let problem = Problem {
        base: *base,
        law,
        t_ref_c,
        points,
        stated,
    };
    // starts across the branches: c from a tenth to ten times the ball's, E_a none or large
    // (the bounds let it take either sign: the data decide)
    let mut best: Option<lm::Solution> = None;
    for ln_c in [-2.3, 0.0, 2.3] {
        for a in [0.0, 30.0] {
            let Some(sol) = lm::minimize(
                &problem,
                &[ln_c, a],
                &[-25.0, -200.0],
                &[25.0, 200.0],
                lm::Options::default(),
            ) else {
                continue;
            };
            if best.as_ref().is_none_or(|b| sol.cost < b.cost) {
                best = Some(sol);
            }
        }
    }
    let sol = best.ok_or(CorTemperatureError::NoMinimum)?;
    let spread = if stated {
        Spread::Stated
    } else {
        Spread::Residuals
    };
    let unc = stats::uncertainty_by(&sol.jacobian, &sol.residuals, spread);
    let se = |j: usize| unc.covariance[(j, j)].max(0.0).sqrt();
    let (c_ref, activation) = problem.values(&sol.x);
    let rt = GAS_CONSTANT * (t_ref_c + ZERO_CELSIUS);
    // c_ref fitted as its logarithm: its interval exp(θ ± t s_θ) stays positive
    let c_ci = [
        c_ref * (-unc.t975 * se(0)).exp(),
        c_ref * (unc.t975 * se(0)).exp(),
    ];
    let a_se = se(1) * rt;
    let a_ci = [activation - unc.t975 * a_se, activation + unc.t975 * a_se];
    let predicted = points
        .iter()
        .map(|p| problem.cor(c_ref, activation, p).unwrap_or(f64::NAN))
        .collect();
    let dof = points.len() - 2;
    let (lack_of_fit, no_answer) = verdict::judge_law(
        &sol.residuals,
        dof,
        stated,
        sol.converged,
        "the CORs do not follow an Arrhenius shift of the dashpot (lack of fit)",
    );
    Ok(TemperatureFit {
        t_ref_c,
        c_ref: Estimate::new("c_ref", "kg/s", c_ref, c_ref * se(0), c_ci),
        activation: Estimate::new("activation_energy", "J/mol", activation, a_se, a_ci),
        predicted,
        dof,
        lack_of_fit,
        no_answer,
    })
}

mod turn;
pub use turn::{cor_turn, damping_temperature};

#[cfg(test)]
mod tests;
