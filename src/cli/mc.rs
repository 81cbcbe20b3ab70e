//! `bouncelab mc`: a Monte Carlo over a ball's parameter tolerances — quantiles, mean, sd and
//! extremes of the COR, peak force and contact time (docs/scale.md). The library samples
//! ([`crate::analysis::mc`]); this file reads the options, checks the work limit, runs the
//! samples in blocks with a progress bar and Ctrl-C, and writes.

use super::ball::BallArgs;
use super::budget::Progress;
use super::mc_text;
use super::output::{self, TextJson, csv_row, given, num};
use super::outputs::{check as check_writable, report_then_commit};
use crate::analysis::mc::{
    Dist, McError, McSpec, McStats, Sampler, Samples, parse_correlate, parse_vary, summary,
};
use crate::analysis::work;
use crate::api::{Ball, McReport};
use crate::atomic::Outputs;
use crate::figure::{Axis, histogram, svg};
use crate::model::contact::ContactLaw;
use clap::{Args, ValueEnum};
use std::io::Write;
use std::path::PathBuf;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DistArg {
    Normal,
    Uniform,
    Lognormal,
}

impl From<DistArg> for Dist {
    fn from(d: DistArg) -> Dist {
        match d {
            DistArg::Normal => Dist::Normal,
            DistArg::Uniform => Dist::Uniform,
            DistArg::Lognormal => Dist::Lognormal,
        }
    }
}

#[derive(Debug, Clone, Args)]
pub struct McArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// `mc --shot`: a shot's launch spread (src/cli/mc_shot.rs, docs/flight.md §7)
    #[command(flatten)]
    pub shot: super::mc_shot::ShotMcArgs,
    /// Nominal impact speed v0 (m/s) [default: the preset's measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Parameters and relative spreads, comma-separated: NAME=SPREAD with NAME one of k_p, c,
    /// k_r, z_p, k_h, m, v0, pressure (an inflated ball's gauge pressure), temperature (of the
    /// absolute temperature, kelvin: 1% is about 3 K) and SPREAD a percentage (5%) or a
    /// fraction (0.05); or `fit`: the multivariate normal of a fitted preset's own covariance
    /// (its `[fit]` table)
    #[arg(long, value_name = "NAME=SPREAD,…", allow_hyphen_values = true)]
    pub vary: String,
    /// Distribution of each varied parameter: normal (sd = spread), uniform (± spread) or
    /// lognormal (mean and sd as the normal's) [default: normal]
    #[arg(long, value_enum)]
    pub dist: Option<DistArg>,
    /// Correlations between varied parameters, comma-separated: A:B=RHO (e.g. k_p:c=0.5); the
    /// matrix must be positive definite
    #[arg(long, value_name = "A:B=RHO,…", allow_hyphen_values = true)]
    pub correlate: Option<String>,
    /// Number of samples
    #[arg(
        long,
        value_name = "N",
        default_value_t = 10_000,
        value_parser = super::number::count,
        allow_hyphen_values = true
    )]
    pub samples: usize,
    /// Seed of the generator: the same seed gives the same answer on any number of threads
    #[arg(long, value_name = "S", default_value_t = 0)]
    pub seed: u64,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
    /// Write every sample (index, the varied parameters, cor, max_force, contact_time) as CSV
    #[arg(long, value_name = "FILE")]
    pub csv_out: Option<PathBuf>,
    /// Write a histogram of the COR with its 2.5 % and 97.5 % points as SVG
    #[arg(long, value_name = "FILE")]
    pub svg_out: Option<PathBuf>,
    /// Overwrite existing --csv-out and --svg-out files
    #[arg(long)]
    pub force: bool,
}

/// Samples solved between two looks at the bar and the Ctrl-C flag.
const STEP: usize = 1 << 16;

/// Bins of the SVG histogram.
const BINS: usize = 60;

pub fn run(a: &McArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if a.shot.shot {
        let refused = [
            (a.v0.is_some(), "--v0"),
            (a.correlate.is_some(), "--correlate"),
            (a.csv_out.is_some(), "--csv-out"),
            (a.svg_out.is_some(), "--svg-out"),
            (a.dist == Some(DistArg::Lognormal), "--dist lognormal"),
        ];
        let mc = super::mc_shot::Mc {
            ball: &a.ball,
            vary: &a.vary,
            uniform: a.dist == Some(DistArg::Uniform),
            samples: a.samples,
            seed: a.seed,
            json: a.format == TextJson::Json,
            refused: &refused,
        };
        return super::mc_shot::run(&a.shot, &mc, out);
    }
    refuse_surface(&a.shot.surface)?;
    let ball = a.ball.resolve(a.v0)?;
    let spec = spec(a, &ball)?;
    ball.check_samples(spec.samples)?;
    ball.mc_conditions(&spec)?;
    let paths: Vec<&std::path::Path> = [&a.csv_out, &a.svg_out]
        .into_iter()
        .flatten()
        .map(PathBuf::as_path)
        .collect();
    check_writable(&paths, a.force)?;
    let sampler = ball.sampler(&spec);
    let samples = run_samples(&sampler, ball.law).map_err(|e| fit_domain(e, &spec, a))?;
    let s = summary(&spec, &samples);
    // both files or neither (crate::atomic), published once the report is out
    let mut files = Outputs::new(a.force);
    if let Some(p) = &a.csv_out {
        files.text(p, &samples_csv(&sampler, &samples)?)?;
    }
    if let Some(p) = &a.svg_out {
        let fig = cor_histogram(&ball, &spec, &samples, &s.stats);
        files.text(p, &svg::render(&fig)?)?;
    }
    let mut report = Vec::new();
    match a.format {
        TextJson::Json => {
            output::json_stated(&mut report, &McReport::new(&ball, &s), &ball.conditions)?
        }
        TextJson::Text => mc_text::text(&mut report, &ball, &spec, s.no_rebound, &s.stats)?,
    }
    report_then_commit(out, &report, files)?;
    Ok(())
}

/// `--vary fit`'s normal draw out of the domain: the spread is the fit's covariance, not one
/// the user gave, so the advice is `--dist lognormal` or more data, never a smaller spread.
fn fit_domain(e: anyhow::Error, spec: &McSpec, a: &McArgs) -> anyhow::Error {
    let domain = match e.downcast_ref::<crate::BallError>() {
        Some(crate::BallError::MonteCarlo(McError::Domain { index, reason })) => (*index, reason),
        _ => return e,
    };
    if a.vary.trim() != "fit" || spec.dist != Dist::Normal {
        return e;
    }
    crate::BallError::from(McError::Fit(format!(
        "sample {} draws an out-of-domain ball ({}): the fit's own covariance is this wide (the \
         data barely pin the parameter) and its normal crosses 0: use --dist lognormal (the \
         fit's means, sds and correlations, never below 0) or refit with more data",
        domain.0, domain.1
    )))
    .into()
}

/// Plain `mc` samples on the rigid plate (its JSON `surface`): the surface's flags go with
/// `--shot` only.
fn refuse_surface(s: &super::surface::SurfaceArgs) -> anyhow::Result<()> {
    let given = [
        (s.surface.is_some(), "--surface"),
        (s.surface_stiffness.is_some(), "--surface-stiffness"),
        (s.surface_damping.is_some(), "--surface-damping"),
        (s.surface_mass.is_some(), "--surface-mass"),
    ];
    match given.iter().find(|(g, _)| *g) {
        Some((_, flag)) => anyhow::bail!(
            "invalid {flag}: plain mc samples on the rigid plate; the surface goes with --shot"
        ),
        None => Ok(()),
    }
}

/// The spec of `--vary` (or `--vary fit`), `--dist` and `--correlate`.
fn spec(a: &McArgs, ball: &Ball) -> anyhow::Result<McSpec> {
    if a.vary.trim() == "fit" {
        let refuse = |what: &str| {
            crate::BallError::from(McError::Fit(format!(
                "{what} does not go with it: the fit's own covariance gives the distribution \
                 (normal, or --dist lognormal) and the correlations"
            )))
        };
        if a.dist == Some(DistArg::Uniform) {
            return Err(refuse("--dist uniform").into());
        }
        if a.correlate.is_some() {
            return Err(refuse("--correlate").into());
        }
        // lognormal: each parameter's mean and sd the fit's, its correlations on the logs
        // (the fits search ln p): the normal's to first order where the spread is narrow,
        // and never below 0 where the data barely pin a parameter (docs/cli.md, mc)
        let mut spec = ball.fit_spec(a.samples, a.seed)?;
        if a.dist == Some(DistArg::Lognormal) {
            spec.dist = crate::analysis::mc::Dist::Lognormal;
        }
        return Ok(spec);
    }
    let dist = a.dist.unwrap_or(DistArg::Normal).into();
    let spec = McSpec::new(parse_vary(&a.vary)?, dist, a.samples, a.seed)?;
    Ok(match &a.correlate {
        Some(text) => spec.with_correlation(parse_correlate(text)?)?,
        None => spec,
    })
}

/// Every sample, in blocks of [`STEP`] with the bar and the Ctrl-C check between them (the
/// blocks change no sample: each is a function of its index).
fn run_samples(sampler: &Sampler, law: ContactLaw) -> anyhow::Result<Samples> {
    let n = sampler.spec().samples;
    let unit_cost = match law {
        ContactLaw::Linear => 1.0 / work::SAMPLES_PER_IMPACT as f64,
        _ => work::cost(law) as f64,
    };
    let progress = Progress::new(n as u64, unit_cost, "samples");
    let mut all = Samples::zeroed(0, n);
    let mut done = 0usize;
    while done < n {
        progress.check()?;
        let count = STEP.min(n - done);
        sampler
            .samples_into(done as u64, all.columns_mut(done..done + count))
            .map_err(crate::BallError::from)?;
        done += count;
        progress.advance(count as u64);
    }
    progress.finish();
    Ok(all)
}

/// Rows of the samples' CSV formatted between two looks at the signal flag: some 3 ms idle
/// (a look costs an atomic load; at 16 384 rows a SIGINT into `mc --samples 1e7 --csv-out`
/// ended it 0.05–0.53 s later at load 20, the phase of the slowest not known).
const CSV_ROWS_PER_LOOK: usize = 1 << 12;

/// `index, <varied parameters>, cor, max_force, contact_time` (SI; contact_time empty where
/// the ball does not rebound). A SIGINT or SIGTERM stops it (`budget::Interrupted`): 10⁷ rows
/// took minutes on a loaded machine and the signal waited for them (issue 54 item 6).
fn samples_csv(sampler: &Sampler, s: &Samples) -> anyhow::Result<String> {
    let mut buf = Vec::new();
    let mut header = vec!["index".to_string()];
    header.extend(
        sampler
            .spec()
            .vary
            .iter()
            .map(|v| v.what.name().to_string()),
    );
    header.extend(["cor", "max_force", "contact_time"].map(String::from));
    // Ok(false): stopped by a signal
    let mut rows = || -> std::io::Result<bool> {
        csv_row(&mut buf, &header)?;
        for i in 0..s.len() {
            if i % CSV_ROWS_PER_LOOK == 0 && super::budget::interrupted() {
                return Ok(false);
            }
            let index = s.start + i as u64;
            let mut row = vec![index.to_string()];
            row.extend(sampler.inputs(index).into_iter().map(num));
            let t = s.contact_time[i];
            row.extend([num(s.cor[i]), num(s.max_force[i])]);
            row.push(if t.is_nan() { String::new() } else { num(t) });
            csv_row(&mut buf, &row)?;
        }
        Ok(true)
    };
    if !rows().expect("writing to memory") {
        return Err(super::budget::Interrupted.into());
    }
    Ok(String::from_utf8(buf).expect("CSV of ASCII and the given names"))
}

fn cor_histogram(
    ball: &Ball,
    spec: &McSpec,
    samples: &Samples,
    stats: &McStats,
) -> crate::figure::Figure {
    let vary: Vec<String> = spec
        .vary
        .iter()
        .map(|v| format!("{} ±{} %", v.what.name(), given(100.0 * v.spread, 6)))
        .collect();
    let subtitle = format!(
        "{} samples, {} ({}), seed {}",
        spec.samples,
        spec.dist.name(),
        vary.join(", "),
        spec.seed
    );
    let marks = [
        ("2.5 %", "q2.5", stats.cor.q.q2_5),
        ("97.5 %", "q97.5", stats.cor.q.q97_5),
    ];
    let mut fig = histogram::figure(
        &format!("COR of {}", ball.label()),
        &subtitle,
        Axis::linear("e", "cor", 1.0),
        &samples.cor,
        BINS,
        &marks,
    );
    // the nominal ball's changes from its preset and record, as every picture names them
    let v0 = ball.params.v0;
    fig.push_notes(&ball.moved_notes(None, Some((v0, v0))));
    fig
}
