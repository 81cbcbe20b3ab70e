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
    velocity_range,
};
use crate::api::Ball;
use crate::cli::ball::{BallArgs, PresetChanges, PresetChoice};
use crate::figure::history::OUTSIDE;
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

/// One ball's figure of cor-velocity, force-time or force-displacement, with what `run` and
/// `sweep velocity` warn of over its speeds (the calibration record's: [`Ball::speeds_warning`])
/// and the notes of what moved ([`Ball::moved_notes`]), which [`push_notes`] puts in the
/// subtitle once the balls are [`combine`]d.
pub(super) fn ball_figure(a: &FigureArgs, ball: &Ball) -> anyhow::Result<OneBall> {
    let b = ball.record();
    let (fig, (lo, hi)) = if a.name == FigureName::CorVelocity {
        let range = velocity_range(&b, a.from, a.to)?;
        let points = a.points.unwrap_or(VELOCITY_POINTS);
        let fig = velocity_figure(&b, Some(range.0), Some(range.1), points)?;
        (fig, range)
    } else {
        let (t, d) = history_figures(&b, a.points.unwrap_or(HISTORY_SAMPLES))?;
        let fig = if a.name == FigureName::ForceTime {
            t
        } else {
            d
        };
        (fig, (b.params.v0, b.params.v0))
    };
    Ok(OneBall {
        name: b.name,
        fig,
        warnings: ball.speeds_warning(lo, hi).into_iter().collect(),
        notes: ball.moved_notes(None, Some((lo, hi))),
    })
}

/// One ball's figure, before [`combine`]: its name, the figure, the warnings for stderr and
/// the subtitle's notes of what moved.
pub(super) struct OneBall {
    pub name: String,
    pub fig: Figure,
    pub warnings: Vec<String>,
    pub notes: Vec<String>,
}

/// The ball `args` of a one-ball figure, with the overrides, λ and ζ applied (and v0 for the
/// force figures).
pub(super) fn one_ball(a: &FigureArgs, args: &BallArgs) -> anyhow::Result<Ball> {
    let v0 = a.v0.filter(|_| a.name != FigureName::CorVelocity);
    let lambda = a.lambda.as_ref().filter(|l| l.len() == 1).map(|l| l[0]);
    args.resolve_tuned(v0, lambda, a.zeta)
}

/// The balls' notes of what moved ([`Ball::moved_notes`]) in the subtitle of their
/// [`combine`]d figure: one ball's as they are; of several, a note every ball has once, the
/// balls whose speeds pass their records named in one ("outside calibration: golf,
/// baseball": the note of a ball's speeds is its only one that begins so, and each ball's
/// numbers are its warning's on stderr, a subtitle having no room for several), and each
/// other after its ball's name.
pub(super) fn push_notes(fig: &mut Figure, balls: &[(String, Vec<String>)]) {
    if let [(_, notes)] = balls {
        fig.push_notes(notes);
        return;
    }
    const OUTSIDE: &str = "outside calibration: ";
    let shared = |n: &String| balls.iter().all(|(_, ns)| ns.contains(n));
    let mut notes: Vec<String> = Vec::new();
    for n in balls.iter().flat_map(|(_, ns)| ns).filter(|n| shared(n)) {
        if !notes.contains(n) {
            notes.push(n.clone());
        }
    }
    let mut outside = Vec::new();
    for (name, ns) in balls {
        for n in ns.iter().filter(|n| !shared(n)) {
            match n.starts_with(OUTSIDE) {
                true => outside.push(name.as_str()),
                false => notes.push(format!("{name}: {n}")),
            }
        }
    }
    if !outside.is_empty() {
        notes.push(format!("{OUTSIDE}{}", outside.join(", ")));
    }
    fig.push_notes(&notes);
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
