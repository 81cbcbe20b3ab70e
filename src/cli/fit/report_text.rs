//! The text of a multi-parameter fit's report (src/cli/fit/report.rs holds its JSON): the
//! fitted parameters with their intervals, their correlations and the fit's verdict, and the
//! pieces of it the other fits' texts and figures share.

use super::Loaded;
use super::report::Report;
use crate::analysis::fit::verdict::LackOfFit;
use crate::analysis::fit::{Estimate, MultiFit};
use crate::api::Ball;
use crate::cli::output::{human, table};
use std::io::Write;

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
    heading(out, ball, data, f, r)?;
    writeln!(out)?;
    let estimates = f.fitted.iter().chain(&f.time_offset).chain(&f.baseline);
    let exact = f.exact().then(|| exact_text(f));
    table(out, "  ", &estimate_rows(estimates, exact, interval))?;
    writeln!(out)?;
    writeln!(out, "  correlation")?;
    table(out, "  ", &correlation_rows(f))?;
    writeln!(out)?;
    table(out, "  ", &summary_rows(data, f, r))?;
    Ok(crate::cli::output::warning_lines(out, &f.warnings)?)
}

/// The ball, what is fitted to which data, and how the data were taken and weighed.
fn heading(
    out: &mut dyn Write,
    ball: &Ball,
    data: &Loaded,
    f: &MultiFit,
    r: &Report,
) -> std::io::Result<()> {
    writeln!(out, "{}, {} law", ball.label(), r.law)?;
    // the data are read as bounces on (or squeezes between) rigid plates, as the JSON says
    crate::cli::output::ball_lines(out, ball, crate::cli::output::Met::RigidPlate)?;
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
    Ok(())
}

/// The fitted parameters' correlation matrix, a row and a column each.
fn correlation_rows(f: &MultiFit) -> Vec<Vec<String>> {
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
    rows
}

/// The fit's summary: λ and ζ, the residual, the iterations, what answered and the model's
/// impact at v0.
fn summary_rows(data: &Loaded, f: &MultiFit, r: &Report) -> Vec<Vec<String>> {
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
    rows
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
