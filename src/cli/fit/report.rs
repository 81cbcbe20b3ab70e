//! The report of a multi-parameter fit: one JSON object (keys in docs/fitting.md); its text,
//! a table with intervals, correlations and warnings, is `report_text`.

use super::Loaded;
use crate::analysis::fit::{Estimate, MultiFit};
use crate::api::Ball;
use crate::model::params::ImpactParams;
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Serialize)]
pub struct Report<'a> {
    preset: Option<&'a str>,
    origin: &'a str,
    parameters: &'a str,
    pub(super) law: &'static str,
    data: &'static str,
    file: Option<&'a str>,
    pub(super) free: Vec<&'static str>,
    k_p: f64,
    c: f64,
    k_r: f64,
    z_p: f64,
    k_h: f64,
    pub(super) lambda: f64,
    pub(super) zeta: f64,
    pub(super) rms_residual: f64,
    points: usize,
    pub(super) converged: bool,
    pub(super) iterations: usize,
    condition_number: f64,
    fitted: BTreeMap<&'static str, &'a Estimate>,
    correlation: BTreeMap<&'static str, BTreeMap<&'static str, f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    time_offset: Option<f64>,
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    nuisance: BTreeMap<&'static str, &'a Estimate>,
    pub(super) v0: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    target_cor: Option<f64>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    drops: Vec<DropRow>,
    /// Drop tests only: the air they were converted in, `null` for vacuum (the default).
    #[serde(skip_serializing_if = "Option::is_none")]
    air: Option<Option<AirRow>>,
    pub(super) cor: f64,
    pub(super) max_force: f64,
    pub(super) contact_time: Option<f64>,
    warnings: &'a [String],
    /// Whether the fit answered: converged, every free parameter pinned by the data
    /// (docs/fitting.md); `false` exits 1.
    identified: bool,
    /// The free parameters the data do not pin.
    not_pinned: &'a [&'static str],
    /// The free parameters that ran to the bound of their search.
    on_bound: &'a [&'static str],
    /// The test of systematic residuals, where one applies.
    #[serde(skip_serializing_if = "Option::is_none")]
    lack_of_fit: Option<crate::analysis::fit::verdict::LackOfFit>,
    /// As many data as fitted quantities, or residuals all zero: an exact solve, with no
    /// residual (or no scatter) to estimate the uncertainty from (`std_error` and `ci95` are
    /// null then). Present only when true.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    exact: bool,
    /// Every row's `cor_sd` taken as known: the intervals scaled by them, not by the
    /// residuals' scatter (docs/fitting.md, "Stated standard deviations"). Present only when
    /// true.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    sd_stated: bool,
    /// The ball the fit started from (docs/cli.md, "The ball object").
    ball: crate::api::BallRecord,
}

#[derive(Serialize)]
struct DropRow {
    drop_height: f64,
    rebound_height: f64,
    v0: f64,
    cor: f64,
    /// The COR's standard deviation from `--rebound-height-sd` (σ_R ∂e/∂R), when given.
    #[serde(skip_serializing_if = "Option::is_none")]
    cor_sd: Option<f64>,
}

/// The air of a drop fit, as the JSON writes it.
#[derive(Serialize)]
struct AirRow {
    drag_coefficient: f64,
    air_density: f64,
}

pub fn report<'a>(
    ball: &'a Ball,
    data: &'a Loaded,
    f: &'a MultiFit,
    p: &ImpactParams,
    r: &crate::ImpactResponse,
) -> Report<'a> {
    let n = p.normalized();
    let nuisance = f
        .time_offset
        .iter()
        .chain(&f.baseline)
        .map(|e| (e.name, e))
        .collect();
    Report {
        preset: ball.name.as_deref(),
        origin: &ball.origin,
        parameters: ball.source,
        law: ball.law.name(),
        data: data.kind,
        file: data.file.as_deref(),
        free: f.fitted.iter().map(|e| e.name).collect(),
        k_p: p.k_p,
        c: p.damping,
        k_r: p.k_r,
        z_p: p.z_p,
        k_h: p.k_h,
        lambda: n.lambda,
        zeta: n.zeta,
        rms_residual: f.rms_residual,
        points: f.points,
        converged: f.converged,
        iterations: f.iterations,
        condition_number: f.condition,
        fitted: f.fitted.iter().map(|e| (e.name, e)).collect(),
        correlation: correlation(f),
        time_offset: f.time_offset.as_ref().map(|e| e.value),
        nuisance,
        v0: p.v0,
        target_cor: (data.kind != "COR table" && data.trace.is_none() && data.joint.is_empty())
            .then(|| data.points.first().map(|q| q.cor))
            .flatten(),
        drops: drop_rows(data),
        air: (!data.drops.is_empty()).then(|| {
            data.air.map(|a| AirRow {
                drag_coefficient: a.drag_coefficient,
                air_density: a.density,
            })
        }),
        cor: r.cor,
        max_force: r.max_force,
        contact_time: r.contact_time,
        warnings: &f.warnings,
        identified: f.identified,
        not_pinned: &f.not_pinned,
        on_bound: &f.on_bound,
        lack_of_fit: f.lack_of_fit,
        exact: f.exact(),
        sd_stated: f.stated_sd,
        ball: ball.record_json(),
    }
}

/// The fitted parameters' correlations, by name and name.
fn correlation(f: &MultiFit) -> BTreeMap<&'static str, BTreeMap<&'static str, f64>> {
    f.names
        .iter()
        .enumerate()
        .map(|(i, a)| {
            (
                *a,
                f.names
                    .iter()
                    .enumerate()
                    .map(|(j, b)| (*b, f.correlation[i][j]))
                    .collect(),
            )
        })
        .collect()
}

/// The drops fitted, each with its COR (and its sd, when the reading's is given).
fn drop_rows(data: &Loaded) -> Vec<DropRow> {
    data.drops
        .iter()
        .zip(&data.points)
        .map(|(&(h, r), q)| DropRow {
            drop_height: h,
            rebound_height: r,
            v0: q.v0,
            cor: q.cor,
            cor_sd: q.cor_sd,
        })
        .collect()
}
