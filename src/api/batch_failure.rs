//! Why a ball of a batch has no fit, by kind: the batch's text summary groups its balls by it
//! (docs/batch.md), each ball's `fit_error` or `error` saying it in full.

use super::BallError;
use crate::analysis::fit::{FitError, MultiFitError};

/// Why a ball's fit gave no answer, as the text's summary groups the balls (each ball's
/// `fit_error` or `error` says it in full).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum FitFailure {
    /// Fewer data points than parameters fitted (`--free`): nothing to fit.
    TooFewPoints,
    /// The fit ran and gave no answer: the model cannot follow the data.
    NotFollowed,
    /// The fitted ball's run of the standard's test failed.
    TestFailed,
    /// Anything else (data that could not be turned into CORs).
    Other,
}

impl FitFailure {
    /// The summary's words for a group of balls that failed so.
    pub fn words(self) -> &'static str {
        match self {
            FitFailure::TooFewPoints => "fewer data points than the parameters fitted",
            FitFailure::NotFollowed => "the model cannot follow them",
            FitFailure::TestFailed => "the standard's test failed on the fitted ball",
            FitFailure::Other => "their data could not be fitted",
        }
    }
}

/// A fit's error in words, and its kind: too few points, or the model not following them.
pub(super) fn failure(e: BallError) -> (FitFailure, String) {
    let kind = match &e {
        BallError::MultiFit(MultiFitError::TooFew { .. }) => FitFailure::TooFewPoints,
        BallError::MultiFit(
            MultiFitError::NoAnswer | MultiFitError::Unanswered(_) | MultiFitError::OutOfReach(_),
        )
        | BallError::Fit(FitError::OutOfReach { .. }) => FitFailure::NotFollowed,
        _ => FitFailure::Other,
    };
    (kind, e.to_string())
}
