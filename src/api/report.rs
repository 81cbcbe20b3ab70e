//! What one impact and one COR fit report, as plain structs that serialize (serde) to the
//! command line's JSON, key for key: `bouncelab run --format json` is an [`ImpactReport`],
//! `bouncelab fit --cor E --format json` a [`FitReport`]. The command line writes them; the
//! Python package turns the same structs into its objects and dicts, so the two cannot drift.

use super::{Ball, ImpactSummary};
use crate::analysis::fit::Fit;
use crate::solver::{EnergyBudget, ImpactResponse, Method};
use serde::Serialize;

/// The keys every JSON document names its ball by (flattened into it, in this order).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BallHeader<'a> {
    /// The preset's name; `None` (JSON `null`) for the normalized ball and given parameters.
    pub preset: Option<&'a str>,
    /// [`Ball::origin`]: `"embedded"`, a preset file's path, `"normalized"` or `"parameters"`.
    pub origin: &'a str,
    /// [`Ball::source`]: the parameter set.
    pub parameters: &'a str,
    /// The contact law's name.
    pub law: &'static str,
}

impl Ball {
    /// The keys naming this ball in a JSON document.
    pub fn header(&self) -> BallHeader<'_> {
        BallHeader {
            preset: self.name.as_deref(),
            origin: &self.origin,
            parameters: self.source,
            law: self.law.name(),
        }
    }
}

/// What was measured on a preset, SI units (the report's `measured` object).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MeasuredAt {
    /// The speed it was measured at, m/s.
    pub v0: f64,
    /// Measured COR, if reported.
    pub cor: Option<f64>,
    /// Measured peak force, N, if reported.
    pub max_force: Option<f64>,
    /// Measured contact time, s, if reported.
    pub contact_time: Option<f64>,
}

/// The energy budget (J) and how well it closes (the report's `energy` object).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Energy {
    /// Where the energy went.
    #[serde(flatten)]
    pub budget: EnergyBudget,
    /// [`EnergyBudget::relative_residual`].
    pub relative_residual: f64,
}

/// One impact as `bouncelab run --format json` writes it, SI units: the ball, its parameters
/// and normalized numbers, the answer, what was measured, the energy budget, and the history
/// when asked for. Infinite z_p or c, and the contact time of a ball that does not rebound,
/// are JSON `null`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ImpactReport<'a> {
    /// Which ball.
    #[serde(flatten)]
    pub ball: BallHeader<'a>,
    /// The ball it ran, parameters and overrides (the JSON `ball` object, docs/cli.md).
    #[serde(rename = "ball")]
    pub record: super::BallRecord,
    /// Why the answer is not compared with `measured` (`None`: it may be): an override
    /// changed the ball the measurement was taken on.
    pub comparison_withheld: Option<String>,
    /// The solver that ran it.
    pub method: Method,
    /// m, kg.
    pub mass: f64,
    /// K_p, N/m.
    pub k_p: f64,
    /// K_r, N/m.
    pub k_r: f64,
    /// c, kg/s.
    pub c: f64,
    /// z_p, m.
    pub z_p: f64,
    /// K_h, N/m^{3/2}.
    pub k_h: f64,
    /// v0, m/s.
    pub v0: f64,
    /// R, m: the preset's radius (`None` for a ball that is no preset).
    pub radius: Option<f64>,
    /// ν, the preset material's Poisson ratio (`None` for a ball that is no preset).
    pub poisson_ratio: Option<f64>,
    /// λ = K_r/K_p.
    pub lambda: f64,
    /// ζ = √(m K_p)/(2c).
    pub zeta: f64,
    /// z̄_p = z_p ω0/v0.
    pub zp_bar: f64,
    /// e, rebound, F_m, t_f, z_m, z_f, F̄_m, τ_f.
    #[serde(flatten)]
    pub outcome: super::ImpactOutcome,
    /// What was measured (presets only).
    pub measured: Option<MeasuredAt>,
    /// The energy budget, when the run audited it.
    pub energy: Option<Energy>,
    /// What the caller should know about this answer ([`Ball::warnings`]); empty when
    /// nothing.
    pub warnings: Vec<String>,
    /// The outputs above its ball's record does not vouch for, by their keys
    /// ([`Ball::uncalibrated_outputs`]): the model's alone. `None` (JSON `null`) when the ball
    /// has no record or its record does not say what its data measured.
    pub uncalibrated_outputs: Option<Vec<crate::preset::Output>>,
    /// `cor_ci95`, `max_force_ci95`, `contact_time_ci95`: on a fitted preset only
    /// ([`Ball::intervals`]; set by the caller, `None` from [`ImpactReport::new`]).
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub intervals: Option<super::Intervals>,
    /// History times, s (with the history only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t: Option<&'a [f64]>,
    /// F(t), N (with the history only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub force: Option<&'a [f64]>,
    /// z(t), m (with the history only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub indentation: Option<&'a [f64]>,
    /// α(t), m (with the history only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub displacement: Option<&'a [f64]>,
}

impl<'a> ImpactReport<'a> {
    /// The report of `r`, the impact of `ball`; the history arrays only when `history`.
    pub fn new(ball: &'a Ball, r: &'a ImpactResponse, history: bool) -> ImpactReport<'a> {
        let h = |v: &'a Vec<f64>| history.then_some(v.as_slice());
        ImpactReport {
            energy: r.energy.map(|budget| Energy {
                budget,
                relative_residual: budget.relative_residual(),
            }),
            warnings: ball.warnings(r),
            t: h(&r.history.t),
            force: h(&r.history.force),
            indentation: h(&r.history.indentation),
            displacement: h(&r.history.displacement),
            ..ImpactReport::of_summary(ball, &ImpactSummary::from(r))
        }
    }

    /// The report of an impact of `ball` known by its summary `s`, without what the summary
    /// does not hold: no energy budget, no warnings (one of them reads the budget), no
    /// history. Python's `run` fills the budget and the warnings in from [`ImpactReport::new`]
    /// on their first read (docs/python.md).
    pub fn of_summary(ball: &'a Ball, s: &ImpactSummary) -> ImpactReport<'a> {
        let p = &ball.params;
        let n = &s.normalized;
        ImpactReport {
            ball: ball.header(),
            record: ball.record_json(),
            comparison_withheld: ball.measurement_withheld(),
            method: s.method,
            mass: p.mass,
            k_p: p.k_p,
            k_r: p.k_r,
            c: p.damping,
            z_p: p.z_p,
            k_h: p.k_h,
            v0: p.v0,
            radius: Some(ball.radius()).filter(|r| r.is_finite()),
            poisson_ratio: ball.poisson_ratio,
            lambda: n.lambda,
            zeta: n.zeta,
            zp_bar: n.zp_bar,
            outcome: s.outcome,
            measured: ball.measured.as_ref().map(|m| MeasuredAt {
                v0: m.v0,
                cor: m.cor,
                max_force: m.max_force,
                contact_time: m.contact_time,
            }),
            energy: None,
            warnings: Vec::new(),
            uncalibrated_outputs: ball.uncalibrated_outputs(&crate::preset::Output::IMPACT),
            intervals: None,
            t: None,
            force: None,
            indentation: None,
            displacement: None,
        }
    }
}

/// The recoil spring fitted to one measured COR, as `bouncelab fit --cor E --format json`
/// writes it (docs/model.md §4), SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FitReport<'a> {
    /// Which ball.
    #[serde(flatten)]
    pub ball: BallHeader<'a>,
    /// The speed the COR was measured at, m/s.
    pub v0: f64,
    /// The measured COR.
    pub target_cor: f64,
    /// The fitted K_r, N/m.
    pub k_r: f64,
    /// The fitted λ = K_r/K_p.
    pub lambda: f64,
    /// ζ, held.
    pub zeta: f64,
    /// The model's COR at the fit.
    pub cor: f64,
    /// K_p, N/m, held.
    pub k_p: f64,
    /// The ball's own K_r before the fit, N/m.
    pub preset_k_r: f64,
    /// Its λ.
    pub preset_lambda: f64,
}

impl<'a> FitReport<'a> {
    /// The report of `fit`, the K_r that makes `ball`'s COR equal `target`.
    pub fn new(ball: &'a Ball, target: f64, fit: &Fit) -> FitReport<'a> {
        let p = &ball.params;
        FitReport {
            ball: ball.header(),
            v0: p.v0,
            target_cor: target,
            k_r: fit.k_r,
            lambda: fit.lambda,
            zeta: fit.zeta,
            cor: fit.cor,
            k_p: p.k_p,
            preset_k_r: p.k_r,
            preset_lambda: p.k_r / p.k_p,
        }
    }
}
