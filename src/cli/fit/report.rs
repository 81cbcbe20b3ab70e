//! The report of a multi-parameter fit: one JSON object (keys in docs/fitting.md) or a text
//! table with intervals, correlations and warnings.

use super::Loaded;
use crate::analysis::fit::verdict::LackOfFit;
use crate::analysis::fit::{Estimate, MultiFit};
use crate::api::Ball;
use crate::cli::output::{human, table};
use crate::model::params::ImpactParams;
use serde::Serialize;
use std::collections::BTreeMap;
use std::io::Write;

#[derive(Serialize)]
pub struct Report<'a> {
    preset: Option<&'a str>,
    origin: &'a str,
    parameters: &'a str,
    law: &'static str,
    data: &'static str,
    file: Option<&'a str>,
    free: Vec<&'static str>,
    k_p: f64,
    c: f64,
    k_r: f64,
    z_p: f64,
    k_h: f64,
    lambda: f64,
    zeta: f64,
    rms_residual: f64,
    points: usize,
    converged: bool,
    iterations: usize,
    condition_number: f64,
    fitted: BTreeMap<&'static str, &'a Estimate>,
    correlation: BTreeMap<&'static str, BTreeMap<&'static str, f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    time_offset: Option<f64>,
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    nuisance: BTreeMap<&'static str, &'a Estimate>,
    v0: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    target_cor: Option<f64>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    drops: Vec<DropRow>,
    /// Drop tests only: the air they were converted in, `null` for vacuum (the default).
    #[serde(skip_serializing_if = "Option::is_none")]
    air: Option<Option<AirRow>>,
    cor: f64,
    max_force: f64,
    contact_time: Option<f64>,
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
    let correlation = f
        .names
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
        .collect();
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
        correlation,
        time_offset: f.time_offset.as_ref().map(|e| e.value),
        nuisance,
        v0: p.v0,
        target_cor: (data.kind != "COR table" && data.trace.is_none() && data.joint.is_empty())
            .then(|| data.points.first().map(|q| q.cor))
            .flatten(),
        drops: data
            .drops
            .iter()
            .zip(&data.points)
            .map(|(&(h, r), q)| DropRow {
                drop_height: h,
                rebound_height: r,
                v0: q.v0,
                cor: q.cor,
                cor_sd: q.cor_sd,
            })
            .collect(),
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

/// "yes", or why the fit gave no answer (it then exits 1).
fn answered(f: &MultiFit) -> String {
    if f.identified {
        return "yes".into();
    }
    let mut why = crate::analysis::fit::verdict::no_answer_reasons(f.converged, &f.not_pinned);
    // (a joint fit whose data sets contradict each other: `analysis::fit::joint`)
    if why.is_empty() && f.lack_of_fit.is_some_and(|t| t.significant()) {
        why.push("the data sets contradict each other".into());
    }
    format!("NO ({})", why.join("; "))
}

/// The closing lines of a one-law fit's text (`fit --pressure-loss`, `--cor-temperature`): the
/// lack-of-fit test where there was one, and why there is no answer where there is none.
pub(super) fn write_verdict(
    out: &mut dyn Write,
    lack_of_fit: Option<&LackOfFit>,
    no_answer: &[String],
) -> std::io::Result<()> {
    if let Some(l) = lack_of_fit {
        writeln!(
            out,
            "  lack of fit: {} test, statistic {}, p = {}",
            l.test,
            human(l.statistic, 4),
            human(l.p_value, 3)
        )?;
    }
    if !no_answer.is_empty() {
        writeln!(out, "no answer: {}", no_answer.join("; "))?;
    }
    Ok(())
}

/// "1 point", "7 points".
pub fn points(n: usize) -> String {
    format!("{n} point{}", if n == 1 { "" } else { "s" })
}

/// The text in place of an interval for an exact solve.
pub const EXACT: &str = "exact: no residual to estimate it from";

/// The text in place of an interval of `f`, an exact solve: [`EXACT`], or, with degrees of
/// freedom left but every residual zero, that the data show no scatter.
pub fn exact_text(f: &MultiFit) -> &'static str {
    exact_words(f.no_scatter)
}

/// [`EXACT`], or, with every residual zero (`no_scatter`), that the data show no scatter: the
/// words of a multi-parameter and of an oblique fit's exact solve.
pub(super) fn exact_words(no_scatter: bool) -> &'static str {
    if no_scatter {
        "exact: no scatter to estimate it from"
    } else {
        EXACT
    }
}

/// The table of fitted parameters: a header, then a row an estimate (name, value, standard
/// error, 95 % interval as `interval` gives it, unit); an exact solve (`exact`: the words in
/// place of its interval) has no error to give, `–`.
pub(super) fn estimate_rows<'e>(
    estimates: impl IntoIterator<Item = &'e Estimate>,
    exact: Option<&'static str>,
    interval: fn(&Estimate) -> String,
) -> Vec<Vec<String>> {
    let mut rows = vec![vec![
        String::new(),
        "value".into(),
        "std. error".into(),
        "95 % interval".into(),
        "unit".into(),
    ]];
    for e in estimates {
        let (error, interval) = match exact {
            Some(words) => ("–".into(), words.into()),
            None => (human(e.std_error, 3), interval(e)),
        };
        rows.push(vec![
            e.name.into(),
            human(e.value, 5),
            error,
            interval,
            e.unit.into(),
        ]);
    }
    rows
}

/// An estimate's 95 % interval as the report's table gives it.
pub(super) fn interval(e: &Estimate) -> String {
    if e.ci95.iter().all(|v| v.is_finite()) {
        format!("{} … {}", human(e.ci95[0], 4), human(e.ci95[1], 4))
    } else {
        "not pinned by the data".into()
    }
}

pub fn text(
    out: &mut dyn Write,
    ball: &Ball,
    data: &Loaded,
    f: &MultiFit,
    r: &Report,
) -> anyhow::Result<()> {
    writeln!(out, "{}, {} law", ball.label(), r.law)?;
    if let Some(line) = ball.overrides_line() {
        writeln!(out, "{line}")?;
    }
    let what = match &data.file {
        Some(file) => format!("the {} {file}", data.kind),
        None => format!("the {} given", data.kind),
    };
    let free: Vec<&str> = r.free.clone();
    writeln!(
        out,
        "fitting {} to {what} ({}); the rest of the ball held",
        free.join(", "),
        points(f.points)
    )?;
    if !data.drops.is_empty() {
        writeln!(out, "{}", air_line(data.air))?;
    }
    if data.drops.len() > 1 {
        // how the drops were weighed (docs/fitting.md, "Each drop weighs by its reading")
        let how = match data.points[0].cor_sd {
            Some(_) => "each drop's COR carries its rebound height's reading error, σ_R ∂e/∂R",
            None => {
                "each drop weighed by its rebound height's reading (σ_e ∝ ∂e/∂R; \
                     --rebound-height-sd gives σ_R)"
            }
        };
        writeln!(out, "{how}")?;
    }
    if data.trace.is_some() {
        // the trace's speed is not in the data: say which one the fit assumed
        writeln!(
            out,
            "impact speed v0 = {} m/s (--v0 to change it), mass {} g",
            human(r.v0, 4),
            human(ball.params.mass * 1e3, 4)
        )?;
    }
    writeln!(out)?;
    let estimates = f.fitted.iter().chain(&f.time_offset).chain(&f.baseline);
    let exact = f.exact().then(|| exact_text(f));
    table(out, "  ", &estimate_rows(estimates, exact, interval))?;
    writeln!(out)?;
    writeln!(out, "  correlation")?;
    let mut rows = vec![
        std::iter::once(String::new())
            .chain(f.names.iter().map(|s| s.to_string()))
            .collect::<Vec<_>>(),
    ];
    for (i, a) in f.names.iter().enumerate() {
        rows.push(
            std::iter::once(a.to_string())
                .chain(f.correlation[i].iter().map(|c| {
                    if c.is_finite() {
                        format!("{c:+.3}")
                    } else {
                        "–".into()
                    }
                }))
                .collect(),
        );
    }
    table(out, "  ", &rows)?;
    writeln!(out)?;
    let unit = if !data.joint.is_empty() {
        " (in each set's standard deviations)"
    } else if data.trace.is_some() {
        " N"
    } else {
        " (COR)"
    };
    let mut rows = vec![
        vec![
            "λ = K_r/K_p, ζ".into(),
            format!("{}, {}", human(r.lambda, 4), human(r.zeta, 4)),
        ],
        vec![
            "rms residual".into(),
            format!("{}{unit}", human(r.rms_residual, 4)),
        ],
        vec![
            "iterations".into(),
            format!(
                "{}{}",
                r.iterations,
                if r.converged {
                    ", converged"
                } else {
                    ", NOT converged"
                }
            ),
        ],
        vec!["answered".into(), answered(f)],
        vec![
            format!("model at v0 = {} m/s", human(r.v0, 4)),
            format!(
                "COR {}, peak force {} N, contact time {} ms",
                human(r.cor, 4),
                human(r.max_force, 4),
                r.contact_time.map_or("–".into(), |t| human(t * 1e3, 4))
            ),
        ],
    ];
    // the intervals' scale where it is not the residuals' scatter (an rms of 0 beside an
    // interval would read as a contradiction)
    if f.stated_sd {
        // drops: their sds are σ_R ∂e/∂R, from --rebound-height-sd, which the user gave
        let from = if data.drops.is_empty() {
            "from each row's cor_sd, taken as known (not the residuals' scatter)"
        } else {
            "from the stated reading σ_R (--rebound-height-sd), taken as known (not the \
             residuals' scatter)"
        };
        rows.insert(2, vec!["uncertainty".into(), from.into()]);
    }
    table(out, "  ", &rows)?;
    Ok(crate::cli::output::warning_lines(out, &f.warnings)?)
}

/// The air a drop fit assumed, stated with its answer: in vacuum (the default) the fit reads
/// the drops' COR as √(R/H), while `bouncelab drop` falls through air unless `--no-drag`, so
/// the two disagree on the same ball (a tennis ball from 2.54 m: some 6 % of its rebound).
fn air_line(air: Option<crate::measured::Air>) -> String {
    match air {
        None => "drops taken in vacuum: no drag correction (--drag-coefficient 0.47 corrects \
                 for air, as `bouncelab drop` falls unless --no-drag)"
            .into(),
        Some(a) => format!(
            "drops corrected for air drag: C_d {}, air density {} kg/m³",
            human(a.drag_coefficient, 4),
            human(a.density, 4)
        ),
    }
}
