//! `bouncelab fit` on several data sets at once — `--drop-test` (or `--drop-height`),
//! `--cor-table`, `--force-time`, `--static` — as one weighted least-squares fit with one
//! covariance ([`crate::analysis::fit::joint`], docs/fitting.md "Joint calibration"). The
//! report is the multi-parameter fit's (`report`), with each set's account after it (JSON:
//! `data_sets`); `--save` records every set in the preset's `[calibration]`.

use super::multi::{check_outputs, load, publish};
use super::{FitArgs, Loaded, Source};
use crate::analysis::fit::joint::{JointData, JointFit, JointSet, SetFit, fit_joint};
use crate::analysis::fit::{MultiFitError, Param};
use crate::cli::measured_file as files;
use crate::cli::output::{self, TextJson, human, table};
use crate::measured::StaticRow;
use crate::model::params::ImpactParams;
use crate::preset::CalibrationData;
use crate::solver::{SolveOptions, simulate};
use std::io::Write;

/// Whether the arguments ask for a joint fit: static deflections, or two or more of the
/// data sets a joint fit takes.
pub fn wanted(a: &FitArgs) -> bool {
    let sets = [
        a.drop_test.is_some() || !a.drop_height.is_empty(),
        a.cor_table.is_some(),
        a.force_time.is_some(),
        a.static_deflection.is_some(),
    ];
    a.static_deflection.is_some() || sets.iter().filter(|s| **s).count() > 1
}

/// The sets given, loaded, in the order drop tests, COR table, trace (static deflections
/// apart).
fn sources(a: &FitArgs) -> anyhow::Result<Vec<Source>> {
    if a.cor.is_some() || a.oblique.is_some() {
        anyhow::bail!(
            "a joint fit takes --drop-test (or --drop-height/--rebound-height), --cor-table, \
             --force-time and --static: put a single --cor in a COR table; --oblique fits \
             alone"
        );
    }
    if a.plot.is_some() {
        anyhow::bail!("--plot draws one data set: leave it out of a joint fit");
    }
    if a.drop_test.is_some() && !a.drop_height.is_empty() {
        anyhow::bail!("give drop tests once: --drop-test FILE or --drop-height/--rebound-height");
    }
    let dropped = a.drop_test.is_some() || !a.drop_height.is_empty();
    if !dropped && (a.drag_coefficient.is_some() || a.rebound_height_sd.is_some()) {
        anyhow::bail!(
            "--drag-coefficient and --rebound-height-sd are about drop tests: none given"
        );
    }
    let mut out = Vec::new();
    if let Some(p) = &a.drop_test {
        out.push(Source::DropFile(p.clone()));
    }
    if !a.drop_height.is_empty() {
        // (the pairs checked as `FitArgs::source` checks them)
        let one = FitArgs {
            static_deflection: None,
            cor_table: None,
            force_time: None,
            ..a.clone()
        };
        out.push(one.source()?);
    }
    if let Some(p) = &a.cor_table {
        out.push(Source::CorTable(p.clone()));
    }
    if let Some(p) = &a.force_time {
        out.push(Source::Trace(p.clone()));
    }
    Ok(out)
}

/// The defaults of each set's fit together (a trace's springs and dashpot, a table's K_r and
/// z_p), K_r for static deflections (which see the springs in series, docs/model.md §1–§3).
fn default_free(data: &[Loaded], statics: bool, law: crate::ContactLaw) -> Vec<Param> {
    let mut free: Vec<Param> = data
        .iter()
        .flat_map(|d| Param::defaults(d.trace.is_some(), d.points.len(), law))
        .collect();
    if statics {
        free.push(Param::KR);
    }
    free.sort();
    free.dedup();
    free
}

pub fn run(a: &FitArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let given = sources(a)?;
    check_outputs(a)?;
    let ball = a.ball.resolve(a.v0)?;
    let data: Vec<Loaded> = given
        .iter()
        .map(|s| load(a, s, &ball))
        .collect::<anyhow::Result<_>>()?;
    let statics: Option<(String, Vec<StaticRow>)> = match &a.static_deflection {
        Some(p) => Some((p.display().to_string(), files::statics(p)?)),
        None => None,
    };
    let has_trace = data.iter().any(|d| d.trace.is_some());
    if a.save.is_some() && data.is_empty() {
        anyhow::bail!(
            "--save: static deflections alone give no impact speed for the preset's \
             calibration range; fit them with impact data"
        );
    }
    let mut free = match a.free_params()? {
        Some(f) => f,
        None => default_free(&data, statics.is_some(), ball.law),
    };
    // a trace without --v0: its speed fitted too, as the fit of a trace alone does (`multi`)
    let speed_fitted = crate::api::Ball::free_trace_speed(&mut free, has_trace, a.v0.is_some());
    let mut sets: Vec<JointSet> = data
        .iter()
        .map(|d| JointSet {
            kind: d.kind,
            label: d.file.clone().unwrap_or_else(|| d.label.clone()),
            data: match &d.trace {
                Some(t) => JointData::Trace(t),
                None => JointData::Cor(&d.points),
            },
        })
        .collect();
    if let Some((file, rows)) = &statics {
        sets.push(JointSet {
            kind: "static deflection",
            label: file.clone(),
            data: JointData::Static(rows),
        });
    }
    let watch = crate::cli::budget::Watcher::new("model runs");
    let j = fit_joint(&ball.params, ball.law, &sets, &free, &watch).map_err(error)?;
    drop(watch);
    report_and_save(a, out, &ball, &data, statics.as_ref(), j, speed_fitted)
}

fn error(e: MultiFitError) -> anyhow::Error {
    match e {
        MultiFitError::Params(p) => p.into(),
        MultiFitError::NoAnswer => anyhow::Error::new(e),
        MultiFitError::Interrupted => crate::cli::budget::Interrupted.into(),
        e => anyhow::anyhow!("{e}"),
    }
}

/// Every set as one `Loaded` for the report and the preset: the COR points and drops of all,
/// the trace, and each set's calibration record.
fn combined(data: &[Loaded], statics: Option<&(String, Vec<StaticRow>)>) -> Loaded {
    let mut labels: Vec<String> = data.iter().map(|d| d.label.clone()).collect();
    let mut joint: Vec<CalibrationData> = data
        .iter()
        .map(|d| CalibrationData {
            source: d
                .file
                .clone()
                .unwrap_or_else(|| format!("{} given on the command line", d.label)),
            quantities: d.kind.to_string(),
            speeds: if d.trace.is_some() {
                vec![]
            } else {
                d.points.iter().map(|q| q.v0).collect()
            },
            heights: d.drops.iter().map(|x| x.0).collect(),
            loads: vec![],
            outputs: Some(super::save::measured_outputs(d)),
        })
        .collect();
    if let Some((file, rows)) = statics {
        labels.push(files::label(std::path::Path::new(file)));
        joint.push(CalibrationData {
            source: file.clone(),
            quantities: format!("static deflection under {} loads", rows.len()),
            speeds: vec![],
            heights: vec![],
            loads: rows.iter().map(|r| r.load_kg).collect(),
            outputs: Some(vec![crate::preset::Output::Deflection]),
        });
    }
    Loaded {
        kind: "data sets",
        file: Some(labels.join(" + ")),
        label: labels.join(" + "),
        trace: data.iter().find_map(|d| d.trace.clone()),
        points: data.iter().flat_map(|d| d.points.iter().copied()).collect(),
        drops: data.iter().flat_map(|d| d.drops.iter().copied()).collect(),
        air: data.iter().find_map(|d| d.air),
        end_line: 0,
        joint,
    }
}

/// The JSON report: the multi-parameter fit's keys, and each set's account.
#[derive(serde::Serialize)]
struct JointJson<'a> {
    #[serde(flatten)]
    report: super::report::Report<'a>,
    /// Each set, in the order fitted: kind, file, points, rms residual in its unit, the
    /// standard deviation it was weighed by, its lack of fit.
    data_sets: &'a [SetFit],
}

fn report_and_save(
    a: &FitArgs,
    out: &mut dyn Write,
    ball: &crate::api::Ball,
    data: &[Loaded],
    statics: Option<&(String, Vec<StaticRow>)>,
    j: JointFit,
    speed_fitted: bool,
) -> anyhow::Result<()> {
    let all = combined(data, statics);
    let mut f = j.fit;
    let speeds: Vec<f64> = match &all.trace {
        Some(_) => vec![f.params.v0],
        None => all.points.iter().map(|p| p.v0).collect(),
    };
    super::multi::fitted_warnings(ball, &mut f, &speeds, speed_fitted);
    // the model shown at the trace's speed, else the first COR's, else the ball's
    let v0 = match (&all.trace, all.points.first()) {
        (Some(_), _) | (None, None) => f.params.v0,
        (None, Some(q)) => q.v0,
    };
    let fitted = ImpactParams { v0, ..f.params };
    let r = simulate(&fitted, ball.law, &SolveOptions::default())?;
    let report = super::report::report(ball, &all, &f, &fitted, &r);
    let mut text = Vec::new();
    match a.format {
        TextJson::Json => output::json_on(
            &mut text,
            &JointJson {
                report,
                data_sets: &j.sets,
            },
            // the data's fit assumed the rigid plate (docs/cli.md, "The surface object")
            output::Met::RigidPlate,
            &ball.conditions,
        )?,
        TextJson::Text => {
            super::report_text::text(&mut text, ball, &all, &f, &report)?;
            sets_text(&mut text, &j.sets)?;
        }
    }
    if !f.identified {
        out.write_all(&text)?;
        let mut why = crate::analysis::fit::verdict::no_answer_reasons(f.converged, &f.not_pinned);
        if crate::analysis::fit::joint::contradicted(&j.sets) {
            why.push("the data sets contradict each other".into());
        }
        let refused = if a.save.is_some() {
            "; --save not written"
        } else {
            ""
        };
        return Err(MultiFitError::Unanswered(format!("{}{refused}", why.join("; "))).into());
    }
    publish(a, out, &text, (ball, &all, &f, &fitted))
}

/// Each set's account, after the report.
fn sets_text(out: &mut dyn Write, sets: &[SetFit]) -> anyhow::Result<()> {
    writeln!(out)?;
    writeln!(
        out,
        "  data sets, each weighed by its own standard deviation (stated, or estimated from \
         its misses)"
    )?;
    let mut rows = vec![vec![
        "set".into(),
        "points".into(),
        "rms residual".into(),
        "weighed by sd".into(),
        "lack of fit".into(),
    ]];
    for s in sets {
        let sd = match s.sd_estimated {
            Some(v) => format!("{} {} (estimated)", human(v, 3), s.unit),
            None => "stated".into(),
        };
        let lack = match s.lack_of_fit {
            Some(t) => format!(
                "{} {} p = {}{}",
                t.test,
                human(t.statistic, 3),
                crate::text::sig(t.p_value, 2),
                if t.significant() { "  CONTRADICTS" } else { "" }
            ),
            None => "–".into(),
        };
        rows.push(vec![
            format!("{} {}", s.kind, s.label),
            s.points.to_string(),
            format!("{} {}", human(s.rms_residual, 4), s.unit),
            sd,
            lack,
        ]);
    }
    table(out, "    ", &rows)?;
    Ok(())
}
