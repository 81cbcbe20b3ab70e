//! μ and K_t (and κ when the outgoing spin is measured) fitted to measured oblique bounces
//! (docs/oblique.md §9), as `bouncelab fit --oblique FILE` and `bouncelab.fit_oblique` run it:
//! one function and one report, so that the command line's JSON and the Python dict are the
//! same document.

use super::{Ball, BallError, BallHeader, SOLID_INERTIA_FACTOR};
use crate::analysis::fit::oblique::{ObliqueFit, ObliqueStart, fit_oblique};
use crate::analysis::fit::{Estimate, MultiFitError};
use crate::analysis::work::Watch;
use crate::measured::ObliqueRow;
use crate::oblique::mindlin_ratio;
use serde::Serialize;
use std::collections::BTreeMap;

/// `fit --oblique --format json`: the ball, the fitted tangential model, its intervals and the
/// verdict (docs/oblique.md §9).
#[derive(Debug, Clone, Serialize)]
pub struct ObliqueFitReport<'a> {
    /// The ball the rows were bounced with.
    #[serde(flatten)]
    pub ball: BallHeader<'a>,
    /// `"oblique bounces"`.
    pub data: &'static str,
    /// The data's file as given (the Python package: `None` for arrays, JSON `null`).
    pub file: Option<String>,
    /// `friction`, `tangential_stiffness` and, with spins, `inertia_factor`.
    pub free: Vec<&'static str>,
    /// μ fitted.
    pub friction: f64,
    /// K_t fitted (N/m).
    pub tangential_stiffness: f64,
    /// κ, fitted or held.
    pub inertia_factor: f64,
    /// c_t fitted (kg/s), when a start for it was given; the key only then.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential_damping: Option<f64>,
    /// R (m).
    pub radius: f64,
    /// RMS miss of v_x,out (m/s).
    pub rms_vx: f64,
    /// RMS miss of ω_out (rad/s; `None` without spins).
    pub rms_spin: Option<f64>,
    /// The normal model's RMS miss of v_y,out (m/s; not fitted).
    pub rms_vy: f64,
    /// Residuals fitted.
    pub points: usize,
    /// The best start met a convergence test.
    pub converged: bool,
    /// Levenberg–Marquardt iterations over every start.
    pub iterations: usize,
    /// Condition number of the column-scaled Jacobian.
    pub condition_number: f64,
    /// Each fitted quantity: value, std_error, ci95.
    pub fitted: BTreeMap<&'static str, Estimate>,
    /// Their correlations.
    pub correlation: BTreeMap<&'static str, BTreeMap<&'static str, f64>>,
    /// What the caller should know, one line each.
    pub warnings: Vec<String>,
    /// Converged, every fitted quantity pinned, none on its bound (else the command line's
    /// exit 1).
    pub identified: bool,
    /// The fitted quantities the data do not pin.
    pub not_pinned: Vec<&'static str>,
    /// The fitted quantities on the bound of their search.
    pub on_bound: Vec<&'static str>,
    /// As many data as fitted quantities, or residuals all zero: an exact solve, with no
    /// residual (or no scatter) to estimate the uncertainty from (`std_error` and `ci95` are
    /// null then), as `fit --cor-table`'s key. Present only when true.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub exact: bool,
    /// The fit itself, for a caller's text (model values per row).
    #[serde(skip)]
    pub fit: ObliqueFit,
}

impl Ball {
    /// The tangential model fitted to `rows` (a file's, `measured::parse_oblique`): μ and K_t,
    /// and κ when every row gives `spin_out`, from the ball's Mindlin K_t and κ; the normal
    /// ball held. `file` names the data in the report. Each model run is reported to `watch`,
    /// which may stop the fit (`MultiFitError::Interrupted`). An unpinned fit is an answer
    /// (`identified` false), as on the command line, which then exits 1.
    pub fn fit_oblique_watched(
        &self,
        rows: &[ObliqueRow],
        file: Option<String>,
        watch: &dyn Watch,
    ) -> Result<ObliqueFitReport<'_>, BallError> {
        self.fit_oblique_damped_watched(rows, file, None, watch)
    }

    /// [`Ball::fit_oblique_watched`] fitting the tangential dashpot c_t too, from
    /// `tangential_damping` (kg/s, > 0; `None`: no dashpot, as `fit_oblique_watched`), as
    /// `bouncelab fit --oblique FILE --tangential-damping C0`.
    pub fn fit_oblique_damped_watched(
        &self,
        rows: &[ObliqueRow],
        file: Option<String>,
        tangential_damping: Option<f64>,
        watch: &dyn Watch,
    ) -> Result<ObliqueFitReport<'_>, BallError> {
        if let Some(c) = tangential_damping
            && !(c.is_finite() && c > 0.0)
        {
            return Err(BallError::Invalid {
                field: "tangential_damping",
                value: c,
                reason: "a fit's start must be positive and finite".into(),
            });
        }
        let radius = Some(self.radius()).filter(|r| r.is_finite());
        let radius = radius.ok_or(BallError::Oblique(crate::oblique::ObliqueError::Missing(
            "radius",
        )))?;
        let k_t = self
            .tangential_stiffness()
            .unwrap_or(mindlin_ratio(0.5) * self.params.k_p);
        let kappa = self
            .measured
            .as_ref()
            .and_then(|m| m.inertia_factor)
            .unwrap_or(SOLID_INERTIA_FACTOR);
        let start = ObliqueStart {
            params: self.params,
            law: self.law,
            radius,
            friction: None,
            tangential_stiffness: k_t,
            inertia_factor: kappa,
            tangential_damping,
        };
        let f = fit_oblique(&start, rows, watch)?;
        Ok(ObliqueFitReport {
            ball: self.header(),
            data: "oblique bounces",
            file,
            free: f.fitted.iter().map(|e| e.name).collect(),
            friction: f.fitted[0].value,
            tangential_stiffness: f.fitted[1].value,
            inertia_factor: f.inertia_factor,
            tangential_damping: f.tangential_damping,
            radius,
            rms_vx: f.rms_vx,
            rms_spin: f.rms_spin,
            rms_vy: f.rms_vy,
            points: f.points,
            converged: f.converged,
            iterations: f.iterations,
            condition_number: f.condition,
            fitted: f.fitted.iter().map(|e| (e.name, e.clone())).collect(),
            correlation: correlation(&f),
            warnings: f.warnings.clone(),
            identified: f.identified,
            not_pinned: f.not_pinned.clone(),
            on_bound: f.on_bound.clone(),
            exact: f.exact(),
            fit: f,
        })
    }
}

/// The correlations of the fitted quantities, by name.
fn correlation(f: &ObliqueFit) -> BTreeMap<&'static str, BTreeMap<&'static str, f64>> {
    f.fitted
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let row = f.fitted.iter().enumerate();
            (
                a.name,
                row.map(|(j, b)| (b.name, f.correlation[i][j])).collect(),
            )
        })
        .collect()
}

/// Whether an error of [`Ball::fit_oblique_watched`] is the rows' (too few for what is
/// fitted: named with the file by the command line) rather than the ball's, an interruption
/// or no answer.
pub fn is_data_error(e: &BallError) -> bool {
    matches!(e, BallError::MultiFit(m)
        if !matches!(m, MultiFitError::Interrupted | MultiFitError::NoAnswer))
}
