//! `bouncelab figure NAME --out FILE.svg [--csv-out FILE.csv]`: one of the paper's figures as
//! SVG, and its plotted series as CSV. The figures themselves are built in
//! [`crate::figure::paper`]; this file reads the options, solves, and writes the files.

use super::ball::BallArgs;
use crate::analysis::sweep::{lin_space, log_space};
use crate::atomic::Outputs;
use crate::figure::{Figure, csv, paper, svg};
use crate::model::contact::ContactLaw;
use crate::model::params::{Field, check_positive, validate_lambda_zeta};
use crate::preset::{ParamSource, Preset};
use crate::solver::{SolveOptions, simulate};
use clap::{Args, ValueEnum};
use std::io::Write;
use std::path::{Path, PathBuf};

pub mod balls;
mod overlay;
mod peers;

/// Points along a curve: enough for smooth curves on a log axis, few enough for a small file.
pub const ZETA_POINTS: usize = 400;
pub const VELOCITY_POINTS: usize = 200;
pub const HISTORY_SAMPLES: usize = 400;
pub const MAX_POINTS: usize = 20_000;

/// Peak indentation, in units of z_p, at the top of the default speed range of `cor-velocity`:
/// well past the onset of flattening (z_m = z_p), so the drop of the COR shows.
pub const SPEED_RANGE_ZP: f64 = 3.0;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FigureName {
    /// COR against ζ, one curve per λ (Fig. 2)
    CorZeta,
    /// Normalized peak force against ζ, one curve per λ (Fig. 3)
    ForceZeta,
    /// COR against impact speed for one ball (Fig. 4)
    CorVelocity,
    /// Contact force against time for one ball (Figs. 5, 7)
    ForceTime,
    /// Contact force against indentation and displacement for one ball (Figs. 6, 8)
    ForceDisplacement,
    /// The field's contact models calibrated to the ball: COR against speed (docs/peers.md)
    PeersCorVelocity,
    /// The field's contact models calibrated to the ball: force against time at v0
    PeersForceTime,
}

impl FigureName {
    pub fn name(self) -> &'static str {
        match self {
            FigureName::CorZeta => "cor-zeta",
            FigureName::ForceZeta => "force-zeta",
            FigureName::CorVelocity => "cor-velocity",
            FigureName::ForceTime => "force-time",
            FigureName::ForceDisplacement => "force-displacement",
            FigureName::PeersCorVelocity => "peers-cor-velocity",
            FigureName::PeersForceTime => "peers-force-time",
        }
    }
}

#[derive(Debug, Clone, Args)]
pub struct FigureArgs {
    /// Which figure
    #[arg(value_enum, value_name = "NAME")]
    pub name: FigureName,
    /// SVG file to write (an existing file is refused unless --force)
    #[arg(long, value_name = "FILE.svg")]
    pub out: PathBuf,
    /// Also write the plotted series as CSV (SI units; see docs/figures.md)
    #[arg(long, value_name = "FILE.csv")]
    pub csv_out: Option<PathBuf>,
    /// Renamed --csv-out (an output, easily mistaken for an input): refused
    #[arg(long, value_name = "FILE", hide = true)]
    pub data: Option<PathBuf>,
    /// Measured data to draw on the figure (force–time trace, COR table or drop test; CSV);
    /// repeatable, each labelled by its file name
    #[arg(long, value_name = "FILE")]
    pub measured: Vec<PathBuf>,
    /// Overwrite existing files
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub balls: balls::FigureBall,
    /// The first ball's options, from `balls` ([`FigureArgs::settle`]).
    #[arg(skip)]
    pub ball: BallArgs,
    /// The presets given after the first (`--preset` repeated).
    #[arg(skip)]
    pub more: Vec<String>,
    /// λ of the model curves, comma-separated (cor-zeta, force-zeta) [default: 0,0.4,1]; for
    /// the figures of one ball, its λ (changes K_r)
    #[arg(
        long,
        value_name = "L,L,...",
        value_delimiter = ',',
        value_parser = super::number::number,
        allow_hyphen_values = true,
    )]
    pub lambda: Option<Vec<f64>>,
    /// ζ of the ball (changes c; cor-velocity, force-time, force-displacement)
    #[arg(long, value_name = "Z", value_parser = super::number::number, allow_hyphen_values = true)]
    pub zeta: Option<f64>,
    /// Impact speed v0, m/s (force-time, force-displacement) [default: the preset's v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Lowest impact speed, m/s (cor-velocity) [default: 0.1 × the preset's v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub from: Option<f64>,
    /// Highest impact speed, m/s (cor-velocity) [default: where z_m = 3 z_p]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub to: Option<f64>,
    /// Points along each curve [default: 400 for ζ, 200 for speed, 400 samples in time]
    #[arg(long, value_name = "N")]
    pub points: Option<usize>,
}

impl FigureArgs {
    /// After parsing: `ball` and `more` from the ball options given.
    pub fn settle(&mut self) -> anyhow::Result<()> {
        (self.ball, self.more) = self.balls.settle()?;
        Ok(())
    }
}

/// Options that only some figures take: naming the misplaced one beats ignoring it.
fn check_applicable(a: &FigureArgs) -> anyhow::Result<()> {
    use FigureName::*;
    if let Some(d) = &a.data {
        anyhow::bail!(
            "--data {} is refused: it is now --csv-out, the plotted series written as CSV (to \
             draw measured data on the figure, use --measured FILE)",
            d.display()
        );
    }
    let one_lambda = a.lambda.as_ref().is_some_and(|l| l.len() == 1);
    let lambda_for: &[FigureName] = if one_lambda {
        &[
            CorZeta,
            ForceZeta,
            CorVelocity,
            ForceTime,
            ForceDisplacement,
        ]
    } else {
        &[CorZeta, ForceZeta]
    };
    let ball_figures = &[CorVelocity, ForceTime, ForceDisplacement][..];
    let several = &[
        CorZeta,
        ForceZeta,
        CorVelocity,
        ForceTime,
        ForceDisplacement,
    ][..];
    let given = [
        ("a second --preset", !a.more.is_empty(), several),
        ("--lambda", a.lambda.is_some(), lambda_for),
        ("--zeta", a.zeta.is_some(), ball_figures),
        ("--measured", !a.measured.is_empty(), ball_figures),
        (
            "--v0",
            a.v0.is_some(),
            &[
                ForceTime,
                ForceDisplacement,
                PeersCorVelocity,
                PeersForceTime,
            ][..],
        ),
        (
            "--from",
            a.from.is_some(),
            &[CorVelocity, PeersCorVelocity][..],
        ),
        ("--to", a.to.is_some(), &[CorVelocity, PeersCorVelocity][..]),
    ];
    for (opt, present, valid) in given {
        if present && !valid.contains(&a.name) {
            let names: Vec<&str> = valid.iter().map(|n| n.name()).collect();
            anyhow::bail!(
                "{opt} does not apply to {} (only to {})",
                a.name.name(),
                names.join(" and ")
            );
        }
    }
    if let Some(n) = a.points
        && !(2..=MAX_POINTS).contains(&n)
    {
        anyhow::bail!("invalid points: {n} (must lie in 2 … {MAX_POINTS})");
    }
    Ok(())
}

/// The one check of every command's outputs (`cli::outputs`), under the name the commands
/// that came first call it by.
pub use super::outputs::{check as check_writable, commit};

/// Write `text` to `path` atomically (a temporary file renamed into place, see
/// [`crate::atomic`]); without `force` the file must not exist (checked again at the rename,
/// so a file that appeared meanwhile is still not overwritten).
pub fn write_file(path: &Path, text: &str, force: bool) -> anyhow::Result<()> {
    let mut files = Outputs::new(force);
    files.text(path, text)?;
    commit(files)?;
    Ok(())
}

/// An embedded preset on the chosen (or its own) parameter set.
pub fn embedded_ball(p: &Preset, source: Option<ParamSource>, law: ContactLaw) -> paper::Ball {
    paper::Ball::from_preset(p, source.unwrap_or(p.parameters), law)
}

/// Figs. 2 and 3 over ζ = 0.01 … 100.
pub fn zeta_figures(
    lambdas: &[f64],
    points: usize,
    law: ContactLaw,
    balls: &[paper::Ball],
) -> anyhow::Result<(Figure, Figure)> {
    for &l in lambdas {
        validate_lambda_zeta(l, 0.0)?;
    }
    let what = format!("{} λ values × {points} points", lambdas.len());
    super::budget::check(lambdas.len() * points, law, &what)?;
    let rows = super::budget::zeta_rows(lambdas, &log_space(0.01, 100.0, points), law)?;
    Ok((
        paper::cor_zeta(&rows, balls, law),
        paper::force_zeta(&rows, balls, law),
    ))
}

/// Fig. 4 from `from` (default 0.1 v0) to `to` (default: where z_m = 3 z_p, at least 1.2 v0 so
/// the measured point shows).
pub fn velocity_figure(
    b: &paper::Ball,
    from: Option<f64>,
    to: Option<f64>,
    points: usize,
) -> anyhow::Result<Figure> {
    super::budget::check(points, b.law, &format!("{points} points"))?;
    let onset = paper::speed_for_indentation(&b.params, b.law, 1.0)?;
    let (from, to) = velocity_range(b, from, to)?;
    let rows = super::budget::velocity_rows(&b.params, b.law, &lin_space(from, to, points))?;
    let mut fig = paper::cor_velocity(b, &rows, onset);
    crate::figure::history::push_speed_radius_note(&mut fig, b, &rows);
    Ok(fig)
}

/// The speeds of Fig. 4, (lowest, highest): `from` (default 0.1 v0) and `to` (default: where
/// z_m = 3 z_p, at least 1.2 v0 so the measured point shows), each checked.
pub fn velocity_range(
    b: &paper::Ball,
    from: Option<f64>,
    to: Option<f64>,
) -> anyhow::Result<(f64, f64)> {
    let v0 = b.params.v0;
    let far = paper::speed_for_indentation(&b.params, b.law, SPEED_RANGE_ZP)?;
    let from = from.unwrap_or(0.1 * v0);
    let to = to.unwrap_or_else(|| far.unwrap_or(3.0 * v0).max(1.2 * v0));
    check_positive(Field::From, from)?;
    check_positive(Field::To, to)?;
    if from >= to {
        anyhow::bail!("invalid speed range: --from {from} must be below --to {to}");
    }
    Ok((from, to))
}

/// Figs. 5–8 at the ball's v0: (force-time, force-displacement).
pub fn history_figures(b: &paper::Ball, samples: usize) -> anyhow::Result<(Figure, Figure)> {
    let r = simulate(
        &b.params,
        b.law,
        &SolveOptions::default().with_samples(samples),
    )?;
    if !r.rebound {
        anyhow::bail!(
            "{} does not rebound at v0 = {} m/s: there is no contact to draw",
            b.name,
            b.params.v0
        );
    }
    Ok((paper::force_time(b, &r), paper::force_displacement(b, &r)))
}

/// The figure `a` asks for, and what its balls' answers warn of (on stderr: a picture has
/// no place for them beyond its subtitle's notes).
fn build(a: &FigureArgs) -> anyhow::Result<(Figure, Vec<String>)> {
    use FigureName::*;
    match a.name {
        CorZeta | ForceZeta => {
            let changes = &a.ball.changes;
            let law = changes.law.map_or(ContactLaw::Linear, ContactLaw::from);
            let source = changes.params.map(ParamSource::from);
            let mut balls: Vec<paper::Ball> = Preset::embedded()
                .iter()
                .map(|p| embedded_ball(p, source, law))
                .collect();
            // the balls asked for join the three of the paper
            if a.ball.choice.is_given() {
                for args in balls::each(&a.ball, &a.more) {
                    let b = args.resolve(None)?.record();
                    if !balls.iter().any(|x| x.name == b.name) {
                        balls.push(b);
                    }
                }
            }
            let lambdas = a.lambda.clone().unwrap_or_else(|| vec![0.0, 0.4, 1.0]);
            if lambdas.is_empty() {
                anyhow::bail!("invalid lambda: no value given");
            }
            let points = a.points.unwrap_or(ZETA_POINTS);
            let (cor, force) = zeta_figures(&lambdas, points, law, &balls)?;
            // the normalized ball's curves, the balls' measured points: no ball is run
            Ok((if a.name == CorZeta { cor } else { force }, Vec::new()))
        }
        CorVelocity | ForceTime | ForceDisplacement => one_ball_figures(a),
        PeersCorVelocity | PeersForceTime => peers::figure(a),
    }
}

/// cor-velocity, force-time or force-displacement of each ball given, combined, with the
/// notes of what moved in its subtitle and the balls' warnings (each after its ball's name
/// when there are several).
fn one_ball_figures(a: &FigureArgs) -> anyhow::Result<(Figure, Vec<String>)> {
    let (mut figs, mut notes, mut warnings) = (Vec::new(), Vec::new(), Vec::new());
    let several = !a.more.is_empty();
    for args in balls::each(&a.ball, &a.more) {
        let ball = balls::one_ball(a, &args)?;
        let mut one = balls::ball_figure(a, &ball)?;
        overlay::relabel_user(&mut one.fig, &ball.origin);
        warnings.extend(one.warnings.iter().map(|w| named(w, &one.name, several)));
        notes.push((one.name.clone(), one.notes));
        figs.push((one.name, one.fig));
    }
    let mut fig = balls::combine(figs);
    balls::push_notes(&mut fig, &notes);
    Ok((fig, warnings))
}

/// A ball's warning `w` as a figure of `several` balls says it, named
/// ([`crate::api::warning_of`]); one ball's as it is.
fn named(w: &str, name: &str, several: bool) -> String {
    match several {
        true => crate::api::warning_of(name, w),
        false => w.to_string(),
    }
}

/// `build`, with the `--measured` files drawn on it (against the ball's m and v0).
fn build_all(a: &FigureArgs) -> anyhow::Result<(Figure, Vec<String>)> {
    // the files are read before any solving, once: a bad file fails fast, and what is drawn
    // is what was checked
    let measured = (a.measured.iter())
        .map(|path| Ok((path.as_path(), super::measured_file::any(path)?)))
        .collect::<anyhow::Result<Vec<_>>>()?;
    super::budget::stop_if_interrupted()?;
    let (mut fig, warnings) = build(a)?;
    if !a.measured.is_empty() {
        super::budget::stop_if_interrupted()?;
        let b = balls::one_ball(a, &a.ball)?;
        overlay::add_measured(&mut fig, a.name, &measured, b.params.mass, b.params.v0)?;
    }
    super::budget::stop_if_interrupted()?;
    Ok((fig, warnings))
}

pub fn run(a: &FigureArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    check_applicable(a)?;
    let mut paths = vec![a.out.as_path()];
    paths.extend(a.csv_out.as_deref());
    check_writable(&paths, a.force)?;
    let (fig, warnings) = build_all(a)?;
    let picture = svg::render(&fig)?;
    super::budget::stop_if_interrupted()?;
    // both files or neither (crate::atomic), and none when stdout cannot take their names
    let mut files = Outputs::new(a.force);
    files.text(&a.out, &picture)?;
    if let Some(d) = &a.csv_out {
        files.text(d, &csv::to_string(&fig))?;
    }
    let report: String = paths.iter().map(|p| format!("{}\n", p.display())).collect();
    super::outputs::report_then_commit(out, report.as_bytes(), files)?;
    // stdout names the files: the answers' warnings go to stderr, as a time series' do
    super::output::warnings_to_stderr(&warnings);
    Ok(())
}
