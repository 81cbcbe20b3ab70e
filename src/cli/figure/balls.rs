//! `figure --preset A --preset B …`: several balls on one figure. Only `figure` takes
//! `--preset` more than once: its ball options are declared here ([`FigureBall`]) rather than
//! through the shared [`crate::cli::ball::PresetChoice`], which every other subcommand keeps as
//! it is (one `--preset`, a repeat refused by clap). After parsing, [`FigureBall::settle`]
//! gives `figure` the usual [`BallArgs`] of its first ball (so `bouncelab --preset golf
//! figure …` merges as before) and the names of the others.
//!
//! The ζ figures already draw several balls (their measured markers); each preset given joins
//! the paper's three. The one-ball figures (cor-velocity, force-time, force-displacement) are
//! built once per ball and [`combine`]d: every series of a ball is labelled by its name in the
//! legend ("golf: model") and in the CSV `series` column ("golf model"), and its model curves
//! take the ball's own colour.

use super::{
    FigureArgs, FigureName, HISTORY_SAMPLES, VELOCITY_POINTS, history_figures, velocity_figure,
};
use crate::cli::ball::{BallArgs, PresetChanges, PresetChoice};
use crate::figure::history::OUTSIDE;
use crate::figure::paper;
use crate::figure::{Figure, Kind};
use clap::Args;
use std::path::PathBuf;

/// The ball options of `figure`: those of [`BallArgs`], with `--preset` repeatable.
#[derive(Debug, Clone, Default, Args)]
pub struct FigureBall {
    /// Preset by name, embedded or user [default: superball]; repeat it to draw several balls
    /// on one figure, each labelled by its name
    #[arg(long = "preset", value_name = "NAME", conflicts_with = "config")]
    pub presets: Vec<String>,
    /// Preset from a TOML file (same schema as the embedded presets)
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    #[command(flatten)]
    pub changes: PresetChanges,
}

impl FigureBall {
    /// The first ball's options, and the names of the other presets; a preset named twice is
    /// refused.
    pub fn settle(&self) -> anyhow::Result<(BallArgs, Vec<String>)> {
        for (i, p) in self.presets.iter().enumerate() {
            if self.presets[..i].contains(p) {
                anyhow::bail!("--preset {p} is given twice");
            }
        }
        let ball = BallArgs {
            choice: PresetChoice {
                preset: self.presets.first().cloned(),
                config: self.config.clone(),
            },
            changes: self.changes.clone(),
            conditions: Default::default(),
        };
        Ok((ball, self.presets.iter().skip(1).cloned().collect()))
    }
}

/// The options of each ball of the figure: `first`, then each of `more` with the same law,
/// parameter set and overrides.
pub fn each(first: &BallArgs, more: &[String]) -> Vec<BallArgs> {
    let mut all = vec![first.clone()];
    all.extend(more.iter().map(|name| {
        let mut b = first.clone();
        b.choice.preset = Some(name.clone());
        b
    }));
    all
}

/// One ball's figure of cor-velocity, force-time or force-displacement.
pub(super) fn ball_figure(a: &FigureArgs, b: &paper::Ball) -> anyhow::Result<Figure> {
    if a.name == FigureName::CorVelocity {
        return velocity_figure(b, a.from, a.to, a.points.unwrap_or(VELOCITY_POINTS));
    }
    let (t, d) = history_figures(b, a.points.unwrap_or(HISTORY_SAMPLES))?;
    Ok(if a.name == FigureName::ForceTime {
        t
    } else {
        d
    })
}

/// The ball `args` of a one-ball figure, with the overrides, λ and ζ applied (and v0 for the
/// force figures), and its origin.
pub(super) fn one_ball(a: &FigureArgs, args: &BallArgs) -> anyhow::Result<(paper::Ball, String)> {
    let v0 = a.v0.filter(|_| a.name != FigureName::CorVelocity);
    let lambda = a.lambda.as_ref().filter(|l| l.len() == 1).map(|l| l[0]);
    let b = args.resolve_tuned(v0, lambda, a.zeta)?;
    Ok((b.record(), b.origin))
}

/// Colours of the balls' model curves: the palette's first six (black and grey are for
/// measured values and reference lines).
const BALL_COLORS: usize = 6;

/// One figure from the figures of several balls, each given with its ball's name. One ball's
/// figure is returned as it is. The title names no ball (the legend does); the subtitle keeps
/// what the balls' subtitles share and each ball's note of its radius passed, named, and what
/// each says of its own ball goes into the label of its first model curve ("golf: model,
/// v0 = 1.47 m/s (measured speed)").
pub fn combine(mut figs: Vec<(String, Figure)>) -> Figure {
    if figs.len() == 1 {
        return figs.remove(0).1;
    }
    let mut out = figs[0].1.clone();
    let suffix = format!(": {}", figs[0].0);
    if let Some(stem) = out.title.strip_suffix(suffix.as_str()) {
        out.title = stem.to_string();
    }
    let subtitles: Vec<&str> = figs.iter().map(|(_, f)| f.subtitle.as_str()).collect();
    let (common, own) = split_subtitles(&subtitles);
    // each ball's note of its radius passed stays, named (`figure::history::push_radius_note`)
    let notes: String = figs
        .iter()
        .flat_map(|(name, f)| {
            f.subtitle
                .split("; ")
                .filter(|p| p.starts_with(OUTSIDE.trim_end_matches(": ")))
                .map(move |n| format!("; {name} {n}"))
        })
        .collect();
    out.subtitle = common + &notes;
    out.x.range = union(figs.iter().map(|(_, f)| f.x.range));
    out.y.range = union(figs.iter().map(|(_, f)| f.y.range));
    out.series.clear();
    let mut measured = Vec::new();
    for (i, ((name, fig), own)) in figs.into_iter().zip(own).enumerate() {
        let mut first_model = true;
        for mut s in fig.series {
            s.label = format!("{name}: {}", s.label);
            s.id = format!("{} {}", name.replace(',', "_"), s.id);
            if s.kind == Kind::Model && std::mem::take(&mut first_model) && !own.is_empty() {
                s.label = format!("{}, {own}", s.label);
            }
            // each ball's curves and lines in its colour; measured values stay black
            if matches!(s.kind, Kind::Model | Kind::Reference) {
                s.color = i % BALL_COLORS;
            }
            // measured values are drawn last, over every ball's curves
            if s.kind == Kind::Measured {
                measured.push(s);
            } else {
                out.series.push(s);
            }
        }
    }
    out.series.extend(measured);
    out
}

/// The smallest range holding every given one; `None` when one is automatic.
fn union(ranges: impl Iterator<Item = Option<(f64, f64)>>) -> Option<(f64, f64)> {
    ranges.reduce(|a, b| match (a, b) {
        (Some(a), Some(b)) => Some((a.0.min(b.0), a.1.max(b.1))),
        _ => None,
    })?
}

/// What the subtitles share (the longest prefix of whole ", "-separated parts), and what
/// each says after it up to its first "; " (a note after it, as force-displacement's
/// flattening, is left to the one-ball figure): "adopted parameters, linear law" and
/// ["v0 = 1.47 m/s (measured speed)", "v0 = 1.25 m/s …"].
fn split_subtitles(subtitles: &[&str]) -> (String, Vec<String>) {
    let first = subtitles[0];
    let mut common = 0;
    for (i, _) in first.match_indices(", ") {
        if subtitles.iter().all(|s| s.get(..i) == Some(&first[..i])) {
            common = i;
        }
    }
    let own = subtitles
        .iter()
        .map(|s| {
            let rest = if common > 0 { &s[common + 2..] } else { s };
            rest.split("; ").next().unwrap_or(rest).to_string()
        })
        .collect();
    (first[..common].to_string(), own)
}
