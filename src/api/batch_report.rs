//! What `bouncelab batch` reports over the whole lot (docs/batch.md, "The summary" and
//! "Outputs"): the standard as the JSON names it, the summary of every ball's verdict, the
//! report, and the exit-1 error of balls without a verdict.

use super::Ball;
use super::batch::{BallOutcome, quantity, quantity_range, within};
use super::batch_failure::FitFailure;
use crate::analysis::batch::{BatchStats, stats_in};
use crate::analysis::fit::Param;
use crate::drop::standards::Standard;
use serde::Serialize;

/// The standard a batch is judged against, as the JSON names it.
#[derive(Debug, Clone, Serialize)]
pub struct StandardRef {
    /// Its short name.
    pub name: &'static str,
    /// Its title.
    pub title: &'static str,
    /// What it measures: `rebound_height` or `cor`.
    pub quantity: &'static str,
    /// Its unit (`m`, or empty for the COR).
    pub unit: &'static str,
    /// [lo, hi]; `null` where unbounded.
    pub window: [Option<f64>; 2],
}

/// The batch's summary: the statistics of the measured values, and how the fits went.
#[derive(Debug, Clone, Serialize)]
pub struct BatchSummary {
    /// n, mean, sd, min, max, failures, cpk of the balls with a verdict.
    #[serde(flatten)]
    pub stats: BatchStats,
    /// Balls in the batch.
    pub balls: usize,
    /// Balls whose fit answered (converged, every free parameter pinned).
    pub identified: usize,
    /// Balls without a verdict (their `error` says why).
    pub no_answer: usize,
    /// Balls whose verdict their own 95 % interval leaves open (a bound of the window inside
    /// `measured_ci95`; each says so in its `warnings`).
    pub unsure: usize,
    /// Every parameter fitted in some ball, in the output's order.
    pub free: Vec<&'static str>,
    /// Balls judged on their own readings at the standard's condition (the others with a
    /// verdict, on their fitted ball).
    pub from_measurement: usize,
    /// Balls whose verdict stands on their readings but whose fit gave no answer (each says
    /// why in its `fit_error`).
    pub unfitted: usize,
}

/// `bouncelab batch --format json`: the ball it started from, the standard, the summary and
/// every ball.
#[derive(Debug, Serialize)]
pub struct BatchReport<'a> {
    /// Preset name (`None` for a ball given by its parameters).
    pub preset: Option<&'a str>,
    /// Contact law.
    pub law: &'static str,
    /// The standard.
    pub standard: StandardRef,
    /// The summary.
    pub summary: BatchSummary,
    /// Every ball, in the batch's order.
    pub balls: &'a [BallOutcome],
    /// The lot's: the standard's impact speed against the record of the ball the fits start
    /// from (what they hold fixed is that ball's; [`Ball::standard_calibration_warning`]).
    pub warnings: Vec<String>,
    /// The ball the fits start from (docs/cli.md, "The ball object").
    pub ball: super::BallRecord,
}

impl<'a> BatchReport<'a> {
    /// The report of `balls`, started from `ball`, against `standard`.
    pub fn new(ball: &'a Ball, standard: &'static Standard, balls: &'a [BallOutcome]) -> Self {
        let (quantity, unit) = quantity(standard);
        let values: Vec<f64> = balls.iter().filter_map(|b| b.measured).collect();
        let mut free: Vec<&'static str> = Param::ALL
            .iter()
            .map(|p| p.name())
            .filter(|n| balls.iter().any(|b| b.free.contains(n)))
            .collect();
        free.dedup();
        BatchReport {
            preset: ball.name.as_deref(),
            law: ball.law.name(),
            standard: StandardRef {
                name: standard.name,
                title: standard.title,
                quantity,
                unit,
                window: standard.window,
            },
            summary: BatchSummary {
                stats: stats_in(&values, standard.window, quantity_range(standard)),
                balls: balls.len(),
                identified: balls.iter().filter(|b| b.identified).count(),
                no_answer: balls.iter().filter(|b| b.verdict.is_none()).count(),
                unsure: balls
                    .iter()
                    .filter(|b| b.measured_ci95.is_some_and(|ci| within(standard, ci)))
                    .count(),
                free,
                from_measurement: balls
                    .iter()
                    .filter(|b| b.verdict_from == Some("measurement"))
                    .count(),
                unfitted: balls.iter().filter(|b| b.fit_error.is_some()).count(),
            },
            balls,
            warnings: ball
                .standard_calibration_warning(standard)
                .into_iter()
                .chain(ball.standard_ball_warning(standard))
                .collect(),
            ball: ball.record_json(),
        }
    }
}

/// The balls whose verdict stands on their readings without a fit, counted by why, in
/// the order of the kinds.
pub fn unfitted_by_reason(balls: &[BallOutcome]) -> Vec<(FitFailure, usize)> {
    let mut kinds: Vec<FitFailure> = balls
        .iter()
        .filter(|b| b.fit_error.is_some())
        .map(|b| b.fit_failure.unwrap_or(FitFailure::Other))
        .collect();
    kinds.sort();
    let mut counts: Vec<(FitFailure, usize)> = Vec::new();
    for k in kinds {
        match counts.last_mut() {
            Some((last, n)) if *last == k => *n += 1,
            _ => counts.push((k, 1)),
        }
    }
    counts
}

/// Some balls of a batch have no verdict: the command line's exit 1, after its report.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", if *balls == 1 {
    "the ball has no verdict: its row says why".to_string()
} else {
    format!(
        "{no_answer} of {balls} balls {} no verdict: their rows say why",
        if *no_answer == 1 { "has" } else { "have" }
    )
})]
pub struct BatchUnanswered {
    /// Balls without a verdict.
    pub no_answer: usize,
    /// Balls in the batch.
    pub balls: usize,
}
